// Paths to the real data that scripts/setup.sh brings, and to the built tool.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace rastrace::testing {

// A file under the data folder (e.g. "meshes/fandisk.off"). Missing data is a test failure, not
// a skip: the suite's numbers must come from the real meshes.
inline std::string data_file(const std::string& relative) {
  const std::filesystem::path path = std::filesystem::path(RASTRACE_DATA_DIR) / relative;
  EXPECT_TRUE(std::filesystem::exists(path)) << path << " is missing: run scripts/setup.sh";
  return path.string();
}

inline std::string rastrace_binary() { return RASTRACE_BINARY; }

}  // namespace rastrace::testing
