// Progress for long work, on stderr, only when stderr is a terminal (quiet in pipes and CI).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace rastrace {

class Progress {
 public:
  Progress(std::string label, std::uint64_t total);
  ~Progress();
  // Thread-safe; redraws at most ten times a second.
  void advance(std::uint64_t amount = 1);
  void finish();

 private:
  void draw(std::uint64_t done);

  std::string label_;
  std::uint64_t total_;
  std::atomic<std::uint64_t> done_{0};
  bool enabled_;
  bool finished_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace rastrace
