// Runs the built rastrace binary with arguments, for the command-line tests of every module.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "support/test_data.h"

namespace rastrace::testing {

struct CommandRun {
  int status = -1;  // the exit code; -1 when the tool did not exit normally
  std::string out;  // stdout, and stderr unless left out
};

inline CommandRun run_rastrace(const std::string& arguments, bool with_stderr = true) {
  CommandRun result;
  const std::string command = rastrace_binary() + " " + arguments + (with_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace rastrace::testing
