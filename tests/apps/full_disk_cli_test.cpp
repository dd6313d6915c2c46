// Every writer on a full disk, and writers killed at many points. A full disk is RLIMIT_FSIZE in
// the child (with SIGXFSZ ignored, a write past the limit fails with EFBIG, as on a full disk):
// the command must exit 1 saying "write failed", with no file under the final name and no
// temporary left. A writer killed with SIGKILL leaves either nothing or the whole file under the
// final name, and its temporary is removed by the next run that writes there.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
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

// Starts rastrace with `arguments`, stdout to /dev/null and stderr to `err_file`, with files
// limited to `file_limit` bytes (0: no limit). Returns the child's pid.
pid_t start_rastrace(const std::vector<std::string>& arguments, const std::string& err_file, rlim_t file_limit) {
  std::vector<char*> argv;
  const std::string program = testing::rastrace_binary();
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open("/dev/null", O_WRONLY);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0) ::_exit(126);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    if (file_limit > 0) {
      ::signal(SIGXFSZ, SIG_IGN);  // ignored signals stay ignored across exec
      const rlimit limit{file_limit, file_limit};
      if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(126);
    }
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

int wait_exit_code(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every regular file under `folder`, as paths relative to it.
std::vector<std::string> files_under(const std::string& folder) {
  std::vector<std::string> names;
  if (!std::filesystem::exists(folder)) return names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) names.push_back(std::filesystem::relative(entry.path(), folder).string());
  return names;
}

// The temporaries of the atomic writers (names starting with ".tmp." or ending in ".tmp") of any
// kind anywhere under `folder`, as paths relative to it.
std::vector<std::string> temporaries(const std::string& folder) {
  std::vector<std::string> names;
  if (!std::filesystem::exists(folder)) return names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    const std::string base = entry.path().filename();
    if (base.starts_with(".tmp.") || base.ends_with(".tmp"))
      names.push_back(std::filesystem::relative(entry.path(), folder).string());
  }
  return names;
}

class FullDisk : public ::testing::Test {
 protected:
  // One small rendered trace and its CSV export for the suite (the inputs of the writers).
  static void SetUpTestSuite() {
    inputs_ = new TempDir;
    const std::string trace = inputs_->file("grid.rtrace");
    const auto render = run_rastrace({"render", "builtin:grid", "--size", "64x64", "-o", inputs_->file("grid.png"),
                                      "--trace", trace});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const auto convert = run_rastrace({"trace", "convert", trace, inputs_->file("grid.csv")});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
  }
  static void TearDownTestSuite() { delete inputs_; }

  // A writer of single files: under a limit of `limit` bytes per file it exits 1 saying "write
  // failed" with none of `outputs` and no temporary in `dir`; without the limit it writes them all.
  static void expect_refused_then_written(const TempDir& dir, const std::vector<std::string>& args,
                                          const std::vector<std::string>& outputs, rlim_t limit = 1024) {
    const std::string err = dir.file("stderr.txt");
    const std::string what = args.front() + " " + outputs.front();
    const int code = wait_exit_code(start_rastrace(args, err, limit));
    const std::string message = read_text(err);
    EXPECT_EQ(code, 1) << what << ": " << message;
    EXPECT_THAT(message, HasSubstr("write failed")) << what;
    for (const std::string& output : outputs) EXPECT_FALSE(std::filesystem::exists(dir.file(output))) << output;
    EXPECT_THAT(temporaries(dir.file("")), ::testing::IsEmpty()) << what;
    const int unlimited = wait_exit_code(start_rastrace(args, err, 0));
    EXPECT_EQ(unlimited, 0) << what << ": " << read_text(err);
    for (const std::string& output : outputs) {
      EXPECT_TRUE(std::filesystem::exists(dir.file(output))) << output;
      std::filesystem::remove_all(dir.file(output));
    }
  }

  // A writer of a folder of files (report, texsweep --plot): under the limit it exits 1 saying
  // "write failed", leaves no temporary anywhere in the folder, and every file it did leave is
  // whole: byte-identical to the same file of an unlimited run. `args` ends with the folder.
  static void expect_folder_refused_whole_files_only(const TempDir& dir, std::vector<std::string> args,
                                                     const std::string& index_file) {  // "" if none
    const std::string err = dir.file("stderr.txt");
    const std::string limited = dir.file("limited"), whole = dir.file("whole");
    args.push_back(limited);
    const int code = wait_exit_code(start_rastrace(args, err, 1024));
    const std::string message = read_text(err);
    EXPECT_EQ(code, 1) << args.front() << ": " << message;
    EXPECT_THAT(message, HasSubstr("write failed")) << args.front();
    EXPECT_THAT(temporaries(limited), ::testing::IsEmpty()) << args.front();
    if (!index_file.empty()) {
      EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(limited) / index_file)) << index_file;
    }
    args.back() = whole;
    ASSERT_EQ(wait_exit_code(start_rastrace(args, err, 0)), 0) << read_text(err);
    ASSERT_FALSE(files_under(whole).empty());
    for (const std::string& name : files_under(limited)) {
      ASSERT_TRUE(std::filesystem::exists(std::filesystem::path(whole) / name)) << name;
      EXPECT_EQ(read_text((std::filesystem::path(limited) / name).string()),
                read_text((std::filesystem::path(whole) / name).string()))
          << name << " was left incomplete";
    }
  }
  static std::string input(const std::string& name) { return inputs_->file(name); }

 private:
  static inline TempDir* inputs_ = nullptr;
};

TEST_F(FullDisk, EveryWriterExitsOneWithWriteFailedAndLeavesNoFileAndNoTemporary) {
  const TempDir dir;
  const std::string trace = input("grid.rtrace");
  const struct {
    std::vector<std::string> args;
    std::string output;  // the file that must not appear
  } writers[] = {
      {{"render", "builtin:grid", "--size", "64x64", "-o", dir.file("frame.png")}, "frame.png"},
      {{"render", "builtin:grid", "--size", "64x64", "-o", dir.file("f.png"), "--trace", dir.file("t.rtrace")},
       "t.rtrace"},
      {{"trace", "convert", input("grid.csv"), dir.file("c.rtrace")}, "c.rtrace"},
      {{"trace", "convert", trace, dir.file("c.csv")}, "c.csv"},
      {{"sweep", trace, "--cache", "size=1KiB..64KiB", "-o", dir.file("sweep.md")}, "sweep.md"},
      {{"sweep", trace, "--cache", "size=1KiB..64KiB", "--plot", dir.file("sweep.png")}, "sweep.png"},
      {{"sweep", trace, "--cache", "size=1KiB..64KiB", "--plot", dir.file("sweep.svg")}, "sweep.svg"},
      {{"replay", trace, "--cache", "size=1KiB..64KiB", "-o", dir.file("replay.json"), "--format", "json"},
       "replay.json"},
  };
  const std::string err = dir.file("stderr.txt");
  for (const auto& w : writers) {
    const int code = wait_exit_code(start_rastrace(w.args, err, 1024));
    const std::string message = read_text(err);
    EXPECT_EQ(code, 1) << w.output << ": " << message;
    EXPECT_THAT(message, HasSubstr("write failed")) << w.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file(w.output))) << w.output;
    EXPECT_THAT(temporaries(dir.file("")), ::testing::IsEmpty()) << w.output;
    // The same command without the limit writes the file (the limit was what failed).
    const int unlimited = wait_exit_code(start_rastrace(w.args, err, 0));
    EXPECT_EQ(unlimited, 0) << w.output << ": " << read_text(err);
    EXPECT_TRUE(std::filesystem::exists(dir.file(w.output))) << w.output;
    std::filesystem::remove(dir.file(w.output));
    for (const char* extra : {"frame.png", "f.png", "t.rtrace"}) std::filesystem::remove(dir.file(extra));
  }
}

TEST_F(FullDisk, MeshImageAndBinaryWritersExitOneWithWriteFailedAndLeaveNothing) {
  const TempDir dir;
  const std::string trace = input("grid.rtrace");
  expect_refused_then_written(dir, {"reorder", "grid:16x16", "--algo", "tipsy", "-o", dir.file("r.off")}, {"r.off"});
  expect_refused_then_written(dir, {"reorder", "grid:16x16", "--algo", "tipsy", "-o", dir.file("r.ply")}, {"r.ply"});
  expect_refused_then_written(dir, {"reorder", "grid:16x16", "--algo", "tipsy", "-o", dir.file("r.obj")}, {"r.obj"});
  expect_refused_then_written(dir, {"adjacency", "grid:16x16", "-o", dir.file("a.adj.bin")}, {"a.adj.bin"});
  expect_refused_then_written(dir, {"adjacency", "grid:16x16", "--edges", "--lines", dir.file("l.png")}, {"l.png"});
  expect_refused_then_written(
      dir, {"meshlets", "grid:16x16", "--order", "tipsy", "--builder", "greedy", "-o", dir.file("m.meshlets.json")},
      {"m.meshlets.json"});
  expect_refused_then_written(
      dir, {"vcache", "grid:16x16", "--algo", "kcache", "--cache", "entries=16", "--miss-image", dir.file("mi.png")},
      {"mi.png"});
  // The miss map is an image and its legend, both refused (small: a lower limit).
  expect_refused_then_written(dir,
                              {"replay", trace, "--cache", "size=1KiB,layout=block4", "--miss-map", dir.file("mm.png")},
                              {"mm.png", "mm.png.txt"}, 256);
  expect_refused_then_written(dir,
                              {"render", "builtin:grid", "--size", "64x64", "-o", dir.file("g.png"), "--tcache",
                               "size=1KiB,layout=block4", "--miss-map", dir.file("rm.png")},
                              {"g.png", "rm.png", "rm.png.txt"}, 256);
}

TEST_F(FullDisk, TableAndPlotWritersExitOneWithWriteFailedAndLeaveNothing) {
  const TempDir dir;
  const std::string trace = input("grid.rtrace");
  expect_refused_then_written(dir, {"vcache", "grid:16x16", "--model", "all", "--plot", dir.file("vc.png")},
                              {"vc.png"});
  expect_refused_then_written(dir, {"vipm", "grid:16x16", "-o", dir.file("v.md")}, {"v.md"});
  expect_refused_then_written(dir, {"vipm", "grid:16x16", "--plot", dir.file("v.png")}, {"v.png"});
  expect_refused_then_written(
      dir, {"texsweep", "builtin:grid", "--order", "strip", "--tcache", "size=1KiB..4KiB", "-o", dir.file("t.md")},
      {"t.md"});
  expect_refused_then_written(dir, {"reproduce", "--paper", "castano", "-o", dir.file("rp.md")}, {"rp.md"});
  // A sweep's parts and their merge.
  expect_refused_then_written(
      dir, {"sweep", trace, "--cache", "size=1KiB..4KiB", "--shard", "1/2", "-o", dir.file("p1.json")}, {"p1.json"});
  ASSERT_EQ(wait_exit_code(start_rastrace(
                {"sweep", trace, "--cache", "size=1KiB..4KiB", "--shard", "1/2", "-o", dir.file("p1.json")},
                dir.file("stderr.txt"), 0)),
            0);
  ASSERT_EQ(wait_exit_code(start_rastrace(
                {"sweep", trace, "--cache", "size=1KiB..4KiB", "--shard", "2/2", "-o", dir.file("p2.json")},
                dir.file("stderr.txt"), 0)),
            0);
  expect_refused_then_written(dir, {"merge", dir.file("p1.json"), dir.file("p2.json"), "-o", dir.file("merged.md")},
                              {"merged.md"}, 256);
}

TEST_F(FullDisk, FolderWritersLeaveOnlyWholeFilesAndNoTemporary) {
  const TempDir dir;
  expect_folder_refused_whole_files_only(
      dir, {"texsweep", "builtin:grid", "--order", "strip", "--tcache", "size=1KiB..4KiB", "--plot"}, "");
  expect_folder_refused_whole_files_only(dir,
                                         {"report", "builtin:grid", "--order", "original", "--vcache-order", "original",
                                          "--model-order", "original", "--tcache",
                                          "size=1KiB,policy=lru,layout=linear", "-o"},
                                         "report.md");
}

// Kills `args` (which writes `outputs` in `dir`) with SIGKILL after each of `delays_ms`: every
// output is then absent or byte-identical to an uninterrupted run's, and the next run that writes
// there removes the killed run's temporaries.
void expect_kills_leave_nothing_or_the_whole_file(const TempDir& dir, const std::vector<std::string>& args,
                                                  const std::vector<std::string>& outputs,
                                                  const std::vector<int>& delays_ms) {
  const std::string err = dir.file("stderr.txt");
  ASSERT_EQ(wait_exit_code(start_rastrace(args, err, 0)), 0) << read_text(err);
  std::vector<std::string> whole;
  for (const std::string& output : outputs) whole.push_back(read_text(dir.file(output)));
  int complete = 0, absent = 0;
  for (const int delay_ms : delays_ms) {
    for (const std::string& output : outputs) std::filesystem::remove(dir.file(output));
    const pid_t pid = start_rastrace(args, err, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::kill(pid, SIGKILL);
    wait_exit_code(pid);
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      if (std::filesystem::exists(dir.file(outputs[i]))) {
        ++complete;
        EXPECT_EQ(read_text(dir.file(outputs[i])), whole[i]) << outputs[i] << " killed after " << delay_ms << " ms";
      } else {
        ++absent;
      }
    }
    // The next writer to the same paths removes a killed run's temporaries and writes the files.
    ASSERT_EQ(wait_exit_code(start_rastrace(args, err, 0)), 0) << read_text(err);
    EXPECT_THAT(temporaries(dir.file("")), ::testing::IsEmpty()) << "killed after " << delay_ms << " ms";
    for (std::size_t i = 0; i < outputs.size(); ++i) EXPECT_EQ(read_text(dir.file(outputs[i])), whole[i]);
  }
  EXPECT_EQ(complete + absent, static_cast<int>(delays_ms.size() * outputs.size()));
}

TEST_F(FullDisk, AWriterKilledAtAnyPointLeavesNothingOrTheWholeFileAndTheNextRunRemovesItsTemporary) {
  const TempDir dir;
  const std::string csv = input("grid.csv");
  expect_kills_leave_nothing_or_the_whole_file(dir, {"trace", "convert", csv, dir.file("out.rtrace")}, {"out.rtrace"},
                                               {0, 40, 80, 120, 160, 200, 240, 280, 320, 360});
}

// The renderer's trace is written by a thread of its own, beside the image; the sweep writes a
// table after replaying. Both killed anywhere leave nothing or whole files.
TEST_F(FullDisk, RenderAndSweepKilledAtAnyPointLeaveNothingOrWholeFiles) {
  const TempDir dir;
  expect_kills_leave_nothing_or_the_whole_file(
      dir, {"render", "builtin:grid", "--size", "256x256", "-o", dir.file("f.png"), "--trace", dir.file("t.rtrace")},
      {"f.png", "t.rtrace"}, {0, 60, 120, 180, 240, 300, 400, 600});
  expect_kills_leave_nothing_or_the_whole_file(
      dir, {"sweep", input("grid.rtrace"), "--cache", "size=1KiB..64KiB,assoc=1/2/4/full", "-o", dir.file("s.md")},
      {"s.md"}, {0, 60, 120, 180, 240, 300, 400, 600});
}

}  // namespace
}  // namespace rastrace
