// libassimp's own crashes stay outside rastrace: the assimp loader reads a file first in a child
// process (scenes/assimp_io.cpp), so a file that crashes libassimp is an InputError naming it.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/mesh_io.h"
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

}  // namespace
}  // namespace rastrace
