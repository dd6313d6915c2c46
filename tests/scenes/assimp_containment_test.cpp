// libassimp's own crashes stay outside rastrace: the assimp loader reads a file first in a child
// process (scenes/assimp_io.cpp), so a file that crashes libassimp is an InputError naming it.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/mesh_io.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

// assimp's RotatingCube.ASE test model with byte 1537 (offset 1536) changed to 0xF9: signal 11
// inside libassimp 5.2.5 when read in process.
TEST(AssimpContainment, AModelThatCrashesLibassimpIsAnErrorNamingTheFile) {
  const std::string path = std::string(RASTRACE_TEST_FILES_DIR) + "/scenes/data/rotating-cube-byte-1537.ase";
  try {
    load_mesh(path);
    FAIL() << "loaded a damaged model";
  } catch (const InputError& e) {
    // Signal 11 in a plain build; under AddressSanitizer its handler exits with status 1 instead.
    EXPECT_THAT(e.what(), HasSubstr(path + ": assimp crashed reading it ("));
  }
}

TEST(AssimpContainment, TheUndamagedModelStillLoads) {
  const Mesh mesh = load_mesh(testing::data_file("assimp/ASE/RotatingCube.ASE"));
  EXPECT_EQ(mesh.indices.size(), 36u);
}

// assimp's cube_triangulate.dae with its <triangles count="12"> changed to 1.5 billion: assimp
// sizes its buffers by the count before reading the indices. The child's address-space limit
// (or, under AddressSanitizer, its allocator) stops it: an error naming the file, at once, and
// rastrace's own memory never grows.
TEST(AssimpContainment, AColladaFileClaimingBillionsOfTrianglesIsAnErrorNamingTheFile) {
  std::ifstream in(testing::data_file("assimp/Collada/cube_triangulate.dae"));
  std::stringstream text;
  text << in.rdbuf();
  std::string dae = text.str();
  const std::string count = "<triangles count=\"12\"";
  const std::size_t at = dae.find(count);
  ASSERT_NE(at, std::string::npos);
  dae.replace(at, count.size(), "<triangles count=\"1500000000\"");
  const testing::TempDir dir;
  const std::string path = dir.file("cube-billions.dae");
  std::ofstream(path) << dae;
  try {
    load_mesh(path);
    FAIL() << "loaded a model of 1.5 billion triangles from 9 KB";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path + ": assimp "));
  }
}

// The child's CPU limit comes from RASTRACE_ASSIMP_CPU_SECONDS when set (the fuzz harness sets
// 1 s): a value outside 1 to 3600 whole seconds is an error naming the variable, not a silent
// default, and a valid one still loads the model.
TEST(AssimpContainment, TheChildsCpuLimitFromTheEnvironmentIsValidated) {
  const std::string cube = testing::data_file("assimp/ASE/RotatingCube.ASE");
  for (const char* bad : {"0", "3601", "-5", "2s", "99999999999999999999999"}) {
    ::setenv("RASTRACE_ASSIMP_CPU_SECONDS", bad, 1);
    try {
      load_mesh(cube);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "RASTRACE_ASSIMP_CPU_SECONDS=" + std::string(bad) + ": expected whole seconds from 1 to 3600");
    }
  }
  ::setenv("RASTRACE_ASSIMP_CPU_SECONDS", "30", 1);
  EXPECT_EQ(load_mesh(cube).indices.size(), 36u);
  ::unsetenv("RASTRACE_ASSIMP_CPU_SECONDS");
}

}  // namespace
}  // namespace rastrace
