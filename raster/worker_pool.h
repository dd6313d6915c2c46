// A fixed set of threads that run one job together and return: the calling thread is worker 0,
// so a pool of N threads starts N - 1. Jobs share their work through an atomic counter of their
// own; the pool only starts them and waits for all of them.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rastrace {

class WorkerPool {
 public:
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned size() const { return static_cast<unsigned>(threads_.size()) + 1; }
  // Calls job(worker) once on every worker (0 is the calling thread) and returns when all have
  // returned. An exception from a job is rethrown here (the first one).
  void run(const std::function<void(unsigned)>& job);
  // The same in two halves: start() has workers 1.. call job (which must outlive wait()) and
  // returns at once; the caller may call job(0) itself; wait() returns when they have all
  // returned, rethrowing the first exception.
  void start(const std::function<void(unsigned)>& job);
  void wait();

 private:
  void loop(unsigned worker);

  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const std::function<void(unsigned)>* job_ = nullptr;
  // Written under mutex_; atomic so that a waiting thread may watch them without it.
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<unsigned> running_{0};
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace rastrace
