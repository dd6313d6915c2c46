// Every committed fuzz input, run through its target (fuzz/fuzz_target.h) in the ordinary build
// and under ASan + UBSan: the seeds (fuzz/corpus/<target>/) and every input that ever failed
// (fuzz/regressions/<target>/, docs/RELIABILITY.md) must end in a clean InputError or succeed;
// a crash, a sanitizer report or any other exception fails the test, naming the file.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/fuzz_target.h"

namespace {

namespace fs = std::filesystem;

const fs::path kFuzzDir = fs::path(RASTRACE_TEST_FILES_DIR).parent_path() / "fuzz";

std::vector<fs::path> files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  if (fs::is_directory(folder))
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs every file of `folder` through `target`; returns how many ran.
std::size_t run_folder(const rastrace::fuzz::Target& target, const fs::path& folder) {
  std::size_t ran = 0;
  for (const fs::path& file : files_in(folder)) {
    const std::string bytes = read_bytes(file);
    SCOPED_TRACE(file.string());
    try {
      target.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const std::exception& e) {
      ADD_FAILURE() << "escaped the parser (not an InputError): " << e.what();
    }
    ++ran;
  }
  return ran;
}

TEST(FuzzInputs, EveryTargetIsLinkedAndHasSeeds) {
  const auto& targets = rastrace::fuzz::targets();
  EXPECT_EQ(targets.size(), 11u);
  for (const auto& target : targets)
    EXPECT_FALSE(files_in(kFuzzDir / "corpus" / target.name).empty()) << "no seeds for " << target.name;
}

TEST(FuzzInputs, EverySeedEndsInAResultOrACleanError) {
  std::size_t ran = 0;
  for (const auto& target : rastrace::fuzz::targets()) ran += run_folder(target, kFuzzDir / "corpus" / target.name);
  EXPECT_GT(ran, 0u);
}

TEST(FuzzInputs, EveryInputThatEverFailedNowEndsInACleanError) {
  for (const auto& target : rastrace::fuzz::targets()) run_folder(target, kFuzzDir / "regressions" / target.name);
}

}  // namespace
