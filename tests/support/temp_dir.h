// A fresh temporary folder per test: a unique name under the system temporary folder (mkdtemp),
// removed with everything in it by the destructor, so a failed assertion leaves nothing behind.
// Every test that writes a file writes it here, never to a fixed path.
#pragma once

#include <stdlib.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace rastrace::testing {

class TempDir {
 public:
  TempDir() {
    // The test's name in the folder name tells whose files a leftover folder holds.
    // (A suite-wide folder, made in SetUpTestSuite, has the suite's name.)
    const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
    const auto* test = unit.current_test_info();
    const auto* suite = unit.current_test_suite();
    std::string name = test    ? std::string(test->test_suite_name()) + "." + test->name()
                       : suite ? std::string(suite->name())
                               : std::string("test");
    for (char& c : name)
      if (c == '/') c = '_';
    std::string pattern = (std::filesystem::temp_directory_path() / ("rastrace-" + name + "-XXXXXX")).string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) == nullptr)
      throw std::filesystem::filesystem_error("mkdtemp", pattern, {errno, std::generic_category()});
    path_ = buffer.data();
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // The path of name inside the folder (the file need not exist).
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // Writes contents to name inside the folder and returns its path.
  std::string write(const std::string& name, const std::string& contents) const {
    std::ofstream out(file(name), std::ios::binary);
    out << contents;
    return file(name);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The whole contents of a file (empty if it cannot be read).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace rastrace::testing
