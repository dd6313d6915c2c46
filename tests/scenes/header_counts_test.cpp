// Every generated hostile header (tests/support/hostile_headers.h) through its loader: each must
// end in an InputError naming the file or in a mesh or scene read from the file's bytes, within a
// wall budget per case and under a memory limit. A loader that loops on a declared count fails
// here on the watchdog's timeout instead of hanging the suite.
#include <stdlib.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/sanitizers.h"
#include "scenes/mesh_io.h"
#include "scenes/scene_io.h"
#include "support/hostile_headers.h"
#include "support/temp_dir.h"

namespace rastrace {
namespace {

using testing::HostileFile;

// The slowest case takes 69 ms in Release; the budget leaves room for a loaded 2-core machine
// running ctest -j2, and sanitizers make every loop several times slower. A loop that trusts a
// count runs for minutes, far past either.
constexpr auto kBudget = std::chrono::seconds(RASTRACE_ASAN ? 30 : 10);

std::vector<HostileFile> all_files() {
  std::vector<HostileFile> all = testing::hostile_ply_files();
  for (auto* more : {&testing::hostile_off_files, &testing::hostile_obj_files, &testing::hostile_scene_files})
    for (HostileFile& f : more()) all.push_back(std::move(f));
  return all;
}

// What the loader did: "" for a result, else the InputError's message.
struct Outcome {
  std::string error;
  std::uint64_t records = 0;  // vertices + faces of a mesh, or objects of a scene
};

Outcome load(const std::string& path) {
  Outcome out;
  try {
    if (path.ends_with(".json")) {
      const Scene scene = load_scene(path);
      out.records = scene.objects.size();
    } else {
      const Mesh mesh = load_mesh(path);
      out.records = mesh.vertex_count() + mesh.face_count();
    }
  } catch (const InputError& e) {
    out.error = e.what();
  }
  return out;
}

// Runs load(path) on its own thread; on timeout the test fails and the process ends at once (a
// thread stuck in a loop cannot be stopped, and waiting for it would hang the suite).
Outcome load_within_budget(const std::string& path) {
  auto task = std::make_shared<std::packaged_task<Outcome()>>([path] { return load(path); });
  std::future<Outcome> result = task->get_future();
  std::thread([task] { (*task)(); }).detach();
  if (result.wait_for(kBudget) != std::future_status::ready) {
    ADD_FAILURE() << path << ": no answer within " << kBudget.count() << " s";
    std::fprintf(stderr, "%s: loader still running after %lld s: stopping\n", path.c_str(),
                 static_cast<long long>(kBudget.count()));
    std::_Exit(1);
  }
  return result.get();
}

class HeaderCounts : public ::testing::TestWithParam<HostileFile> {
 protected:
  // The fuzz harness's limit: whatever a loader allocates from a header passes checked_bytes().
  static void SetUpTestSuite() { ::setenv("RASTRACE_MEMORY_LIMIT", "268435456", 1); }
  static void TearDownTestSuite() { ::unsetenv("RASTRACE_MEMORY_LIMIT"); }
};

TEST_P(HeaderCounts, EveryDeclaredCountEndsInAnErrorNamingTheFileOrAResultWithinTheBudget) {
  const HostileFile& file = GetParam();
  testing::TempDir dir;
  const std::string path = dir.write(file.file_name, file.bytes);
  const auto start = std::chrono::steady_clock::now();
  const Outcome outcome = load_within_budget(path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, std::chrono::duration<double>(kBudget).count());
  if (outcome.error.empty()) {
    // A result holds only what the file's bytes hold (a procedural scene: one object per entry).
    EXPECT_GT(outcome.records, 0u);
    if (!path.ends_with(".json")) {
      EXPECT_LE(outcome.records, file.bytes.size());
    }
  } else {
    EXPECT_NE(outcome.error.find(file.file_name), std::string::npos) << outcome.error;
  }
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  // Peak resident memory of the whole test process (KiB): the 256 MiB limit plus the runtime.
  EXPECT_LT(usage.ru_maxrss, RASTRACE_ASAN ? 2L << 20 : 768L << 10);
}

INSTANTIATE_TEST_SUITE_P(Generated, HeaderCounts, ::testing::ValuesIn(all_files()),
                         [](const ::testing::TestParamInfo<HostileFile>& info) { return info.param.name; });

TEST(HeaderCountLimits, AGridOfCountsTimesShapesIsGenerated) {
  // 3 PLY encodings x 7 shapes, 6 OFF, 5 OBJ and 7 scene shapes, each at 6 counts.
  EXPECT_EQ(all_files().size(), (3u * 7u + 6u + 5u + 7u) * 6u);
}

TEST(HeaderCountLimits, APlyElementOfFourBillionEmptyRecordsIsAnErrorAtItsHeaderLine) {
  testing::TempDir dir;
  const std::string path =
      dir.write("e.ply",
                "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty uchar x\nproperty uchar y\n"
                "property uchar z\nelement e 4000000000\nend_header\n" +
                    std::string(3, '\0'));
  const Outcome outcome = load_within_budget(path);
  EXPECT_EQ(outcome.error, path +
                               ":7: element 'e': 4000000000 records of no bytes each: expected at most 65536 "
                               "(records that carry no data, yet each is a pass of the reader)");
}

TEST(HeaderCountLimits, EmptyRecordsUpToTheLimitAreRead) {
  testing::TempDir dir;
  const std::string path = dir.write("e.ply",
                                     "ply\nformat ascii 1.0\nelement e 65536\nelement vertex 1\nproperty float x\n"
                                     "property float y\nproperty float z\nend_header\n1 2 3\n");
  const Mesh mesh = load_mesh(path);
  ASSERT_EQ(mesh.vertex_count(), 1u);
  EXPECT_EQ(mesh.positions[0].z, 3.0f);
}

}  // namespace
}  // namespace rastrace
