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

// The names in `folder` that start with ".tmp." (temporaries of the atomic writers).
std::vector<std::string> temporaries(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename();
    if (name.starts_with(".tmp.") || name.ends_with(".tmp")) names.push_back(name);
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

TEST_F(FullDisk, AWriterKilledAtAnyPointLeavesNothingOrTheWholeFileAndTheNextRunRemovesItsTemporary) {
  const TempDir dir;
  const std::string csv = input("grid.csv");
  const std::string out = dir.file("out.rtrace");
  const std::string err = dir.file("stderr.txt");
  // The whole file, written without interruption, to compare with what a killed run leaves.
  ASSERT_EQ(wait_exit_code(start_rastrace({"trace", "convert", csv, dir.file("whole.rtrace")}, err, 0)), 0);
  const std::string whole = read_text(dir.file("whole.rtrace"));
  int complete = 0, absent = 0;
  for (int delay_ms = 0; delay_ms < 400; delay_ms += 40) {
    std::filesystem::remove(out);
    const pid_t pid = start_rastrace({"trace", "convert", csv, out}, err, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::kill(pid, SIGKILL);
    wait_exit_code(pid);
    if (std::filesystem::exists(out)) {
      ++complete;
      EXPECT_EQ(read_text(out), whole) << "killed after " << delay_ms << " ms";
    } else {
      ++absent;
    }
    // The next writer to the same path removes a killed run's temporary and writes the file.
    ASSERT_EQ(wait_exit_code(start_rastrace({"trace", "convert", csv, out}, err, 0)), 0) << read_text(err);
    EXPECT_THAT(temporaries(dir.file("")), ::testing::IsEmpty()) << "killed after " << delay_ms << " ms";
    EXPECT_EQ(read_text(out), whole);
  }
  EXPECT_EQ(complete + absent, 10);
}

}  // namespace
}  // namespace rastrace
