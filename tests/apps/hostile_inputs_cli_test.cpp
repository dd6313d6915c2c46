// Regression tests for inputs that once crashed, hung, ran out of memory or were silently
// changed: each is the failing input, minimised, and the clear error it gets now (exit 1 for bad
// input, 2 for a bad option), in a short message that never echoes a whole hostile value.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;
using testing::run_rastrace;
using testing::TempDir;

const char* kTetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n";

// A scene whose `where` holds `value` (the rest is a valid one-object scene).
std::string scene_with(const std::string& viewport, const std::string& background, const std::string& eye) {
  return "{\"viewport\": {\"width\": " + viewport + ", \"height\": 64}, \"background\": " + background +
         ", \"camera\": {\"eye\": " + eye + ", \"target\": [0, 0, 0]}, \"objects\": [{\"mesh\": \"tet.off\"}]}";
}

TEST(HostileInputs, DeeplyNestedBracketsInSceneValuesAreRefusedWithAShortMessage) {
  const TempDir dir;
  dir.write("tet.off", kTetrahedron);
  const std::string nested = std::string(100000, '[') + std::string(100000, ']');
  const std::vector<std::string> scenes = {scene_with(nested, "[0, 0, 0]", "[0, 0, 3]"),
                                           scene_with("64", nested, "[0, 0, 3]"),
                                           scene_with("64", "[0, 0, 0]", nested)};
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::string path = dir.write("nested" + std::to_string(i) + ".json", scenes[i]);
    const auto run = run_rastrace({"info", path});
    EXPECT_EQ(run.exit_code, 1) << run.err.substr(0, 300);
    EXPECT_EQ(run.err, "rastrace: " + path + ":1: JSON nested deeper than 64 levels of [ and {\n");
  }
  // Nesting within the limit reaches the reader, whose message quotes a short prefix only.
  const std::string path = dir.write("shallow.json", scene_with(std::string(60, '[') + std::string(60, ']'),
                                                                "[0, 0, 0]", "[0, 0, 3]"));
  const auto run = run_rastrace({"info", path});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: " + path + ": viewport.width: expected an integer from 1 to 16384, found " +
                         std::string(40, '[') + "...\n");
}

TEST(HostileInputs, HugeTokensAreQuotedAsAShortPrefix) {
  const TempDir dir;
  dir.write("tet.off", kTetrahedron);
  const std::string scene = dir.write(
      "long.json", "{\"objects\": [{\"mesh\": \"tet.off\", \"transform\": {\"scale\": \"" + std::string(1000000, '7') +
                       "\"}}]}");
  auto run = run_rastrace({"info", scene});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_LT(run.err.size(), 400u) << run.err.substr(0, 300);
  EXPECT_THAT(run.err, HasSubstr("\"777777777777777777777777777777777777777..."));
  run = run_rastrace({"vcache", dir.file("tet.off"), "--seed", std::string(100000, '9')});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_LT(run.err.size(), 300u) << run.err.substr(0, 300);
  run = run_rastrace({"sweep", dir.file("none.rtrace"), "--cache", "size=" + std::string(100000, '1')});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_LT(run.err.size(), 400u) << run.err.substr(0, 300);
}

TEST(HostileInputs, JsonNumbersBeyondFloatRangeNameTheFileAndPlace) {
  const TempDir dir;
  dir.write("tet.off", kTetrahedron);
  const std::string huge = dir.write("huge.json", "{\n\"objects\": [{\"mesh\": \"tet.off\",\n \"transform\": {\"scale\": 1e400}}]}");
  auto run = run_rastrace({"info", huge});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: " + huge + ":3: invalid JSON: number 1e400 beyond the range of a double\n");
  const std::string big = dir.write("big.json", "{\"objects\": [{\"mesh\": \"tet.off\", \"transform\": {\"scale\": 1e300}}]}");
  run = run_rastrace({"info", big});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: " + big +
                         ": objects[0].transform.scale: expected a finite number within float range (magnitude at "
                         "most 3.4e38)\n");
}

TEST(HostileInputs, DevicesAndNamedPipesAreRefusedNotRead) {
  const TempDir dir;
  const std::string fifo = dir.file("pipe.off");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto run = run_rastrace({"info", fifo});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: " + fifo + ": is not a regular file (a device, FIFO or socket), expected a file\n");
  const std::string fifo_trace = dir.file("pipe.rtrace");
  ASSERT_EQ(::mkfifo(fifo_trace.c_str(), 0600), 0);
  run = run_rastrace({"replay", fifo_trace, "--cache", "entries=16"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("is not a regular file"));
  const std::string scene = dir.write(
      "zero.json", "{\"objects\": [{\"mesh\": {\"procedural\": \"plane\"}, \"material\": {\"texture\": \"/dev/zero\"}}]}");
  run = run_rastrace({"info", scene});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: /dev/zero: is not a regular file (a device, FIFO or socket), expected a file\n");
}

TEST(HostileInputs, NumericOptionsOutsideTheirRangeAreUsageErrorsNamingTheRange) {
  const TempDir dir;
  const std::string tet = dir.write("tet.off", kTetrahedron);
  const struct {
    std::vector<std::string> args;
    std::string error;
  } cases[] = {
      {{"adjacency", tet, "--iterations", "1e18"}, "--iterations: expected a whole number from 0 to 100000000, found '1e18'"},
      {{"adjacency", tet, "--iterations", "18446744073709551616"},
       "--iterations: expected a whole number from 0 to 100000000, found '18446744073709551616'"},
      {{"adjacency", tet, "--iterations", "-5"}, "--iterations: expected a whole number from 0 to 100000000, found '-5'"},
      {{"reorder", tet, "--algo", "local", "--time-budget", "nan", "-o", dir.file("x.off")},
       "--time-budget: expected a finite number from 0 to 1e+06, found 'nan'"},
      {{"vcache", tet, "--time-budget", "inf"}, "--time-budget: expected a finite number from 0 to 1e+06, found 'inf'"},
      {{"vcache", tet, "--seed", "18446744073709551616"},
       "--seed: expected a whole number from 0 to 9223372036854775807, found '18446744073709551616'"},
      {{"vcache", tet, "--target", "0"}, "--target: expected a whole number from 1 to 65536, found '0'"},
      {{"sweep", tet, "--threads", "-1", "--cache", "entries=4"}, "--threads: expected a whole number from 0 to 1024, found '-1'"},
  };
  for (const auto& c : cases) {
    const auto run = run_rastrace(c.args);
    EXPECT_EQ(run.exit_code, 2) << c.args[0] << " " << c.args[2];
    EXPECT_THAT(run.err, HasSubstr(c.error));
  }
}

TEST(HostileInputs, TextAndUtf16FilesAreNotEmptyObjMeshesAndIndexInt64MinIsOutOfRange) {
  const TempDir dir;
  const std::string text = dir.write("notes.obj", "These are notes, not a mesh.\nv 0 0 0\n");
  auto run = run_rastrace({"info", text});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: " + text + ": no faces: expected an OBJ mesh with at least one 'f' statement\n");
  const std::string utf16 = dir.write("utf16.obj", std::string("\xff\xfev\0 \0" "0\0", 8));
  run = run_rastrace({"info", utf16});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err,
            "rastrace: " + utf16 + ": byte 3: NUL byte: expected OBJ text (ASCII or UTF-8), not UTF-16 or binary data\n");
  const std::string minimum = dir.write("min.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n");
  run = run_rastrace({"info", minimum});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: " + minimum +
                         ":4: vertex index -9223372036854775808 out of range: 3 vertices defined so far\n");
}

TEST(HostileInputs, SizesTheMachineCannotHoldAreClearErrorsNotBadAlloc) {
  const TempDir dir;
  const std::string csv =
      dir.write("far.csv", "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,"
                           "address,label,mask\nvertex,,,,4294967295,1,,,,,,,,,,\nvertex,,,,1,0,,,,,,,,,,\n");
  auto run = run_rastrace({"sweep", csv, "--cache", "entries=16..32"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("per-vertex FIFO stamps (vertex index 4294967295): needs "));
  EXPECT_THAT(run.err, HasSubstr("more than the limit of"));
  run = run_rastrace({"sweep", csv, "--cache", "size=1KiB..8589934592GiB"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("the simulators of all 54 caches: needs 4611686018427387648 bytes"));
  const std::string scene = dir.write(
      "textures.json",
      "{\"objects\": [{\"mesh\": {\"procedural\": \"plane\"}, \"uv_projection\": \"planar_z\", \"material\": "
      "{\"texture\": {\"procedural\": \"checker\", \"size\": 16384}}}]}");
  // The limit is an environment setting: a 1 GiB machine refuses a 16384^2 texture up front.
  ::setenv("RASTRACE_MEMORY_LIMIT", "1073741824", 1);
  run = run_rastrace({"info", scene});
  ::unsetenv("RASTRACE_MEMORY_LIMIT");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("procedural textures: needs 1431655765 bytes"));
}

TEST(HostileInputs, CacheValuesThatWouldBeSilentlyChangedAreRefused) {
  const TempDir dir;
  const std::string csv = dir.write("a.din", "0 1000\n0 2000\n");
  const struct {
    std::string spec;
    std::string error;
  } cases[] = {
      {"size=16KiB,line=64B,assoc=4294967300", "assoc=4294967300: expected at most 2147483648"},
      {"16KiB,64B,4294967300way,lru", "write size=16KiB,line=64B,assoc=4294967300,policy=lru"},
      {"16KiB,64B,0way,lru", "write size=16KiB,line=64B,assoc=0,policy=lru"},
      {"size=16KiB,line=64B,assoc=0", "assoc=0: expected a number of ways >= 1 or full"},
      {"size=1KiB,line=4KiB", "capacity is not a whole number of lines"},
      {"size=16KiB,line=64B,align=9223372036854775808", "align=9223372036854775808: expected an alignment of at most 1GiB"},
      {"12,,16", "empty item"},
  };
  for (const auto& c : cases) {
    const auto run = run_rastrace({"replay", csv, "--cache", c.spec});
    EXPECT_EQ(run.exit_code, 1) << c.spec;
    EXPECT_THAT(run.err, HasSubstr(c.error)) << c.spec;
  }
}

TEST(HostileInputs, TraceConvertIntoADirectoryLeavesNothing) {
  const TempDir dir;
  const std::string din = dir.write("a.din", "0 1000\n1 2000\n");
  std::filesystem::create_directory(dir.file("out.csv"));
  const auto run = run_rastrace({"trace", "convert", din, dir.file("out.csv")});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("is a directory"));
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file(""))) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"a.din", "out.csv"}));
}

TEST(HostileInputs, PlotIntoAMissingFolderIsAnErrorWithoutImageBytesOnStderr) {
  const TempDir dir;
  const std::string din = dir.write("a.din", "0 1000\n1 2000\n");
  const auto run = run_rastrace({"sweep", din, "--cache", "size=1KiB..4KiB", "--plot", dir.file("missing/plot.png")});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "rastrace: --plot " + dir.file("missing/plot.png") + ": folder " + dir.file("missing") +
                         " does not exist\n");
}

TEST(HostileInputs, StaleTemporariesOfDeadWritersAreRemovedByTheNextWriter) {
  const TempDir dir;
  const std::string din = dir.write("a.din", "0 1000\n1 2000\n");
  // A pid that is surely dead: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const std::string stale = dir.write(".tmp." + std::to_string(child) + ".out.rtrace", "half a trace");
  const std::string alive = dir.write(".tmp." + std::to_string(::getpid()) + ".out.rtrace", "being written");
  const std::string other = dir.write(".tmp." + std::to_string(child) + ".other.rtrace", "another file's");
  const auto run = run_rastrace({"trace", "convert", din, dir.file("out.rtrace")});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(alive));  // its writer (this test) is still running
  EXPECT_TRUE(std::filesystem::exists(other));  // not the path being written
  EXPECT_TRUE(std::filesystem::exists(dir.file("out.rtrace")));
}

}  // namespace
}  // namespace rastrace
