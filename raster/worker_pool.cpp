#include "raster/worker_pool.h"

#include <chrono>
#include <utility>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace rastrace {

namespace {

// How long a thread that waits for the pool (a worker for its next job, the caller for the
// workers) watches for it before it sleeps on the condition variable. A frame starts jobs one
// after another (the clear, each batch's tiles, each batch's copy), and a sleeping thread takes
// 60-80 microseconds to wake on this machine: the spider's frame on two threads, 1.6 ms, was 8-10%
// faster with waits watched this long (docs/PERFORMANCE.md). The watcher yields between looks, so
// a pool with more threads than cores leaves the cores to the threads that have work.
constexpr std::chrono::microseconds kWatch{200};

void pause() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// Returns once done() is true or kWatch has passed, whichever comes first.
template <typename Done>
void watch(Done&& done) {
  const auto until = std::chrono::steady_clock::now() + kWatch;
  for (;;) {
    for (int i = 0; i < 32; ++i) {
      if (done()) return;
      pause();
    }
    if (std::chrono::steady_clock::now() >= until) return;
    std::this_thread::yield();
  }
}

}  // namespace

WorkerPool::WorkerPool(unsigned threads) {
  for (unsigned w = 1; w < threads; ++w) threads_.emplace_back([this, w] { loop(w); });
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void WorkerPool::start(const std::function<void(unsigned)>& job) {
  {
    const std::lock_guard lock(mutex_);
    job_ = &job;
    running_.store(static_cast<unsigned>(threads_.size()), std::memory_order_relaxed);
    error_ = nullptr;
    generation_.fetch_add(1, std::memory_order_release);
  }
  start_.notify_all();
}

void WorkerPool::wait() {
  watch([this] { return running_.load(std::memory_order_acquire) == 0; });
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return running_.load(std::memory_order_relaxed) == 0; });
  job_ = nullptr;
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void WorkerPool::run(const std::function<void(unsigned)>& job) {
  start(job);
  std::exception_ptr own;
  try {
    job(0);
  } catch (...) {
    own = std::current_exception();
  }
  wait();
  if (own) std::rethrow_exception(own);
}

void WorkerPool::loop(unsigned worker) {
  std::uint64_t seen = 0;
  for (;;) {
    const std::function<void(unsigned)>* job;
    // The job and the generation are read under the lock either way; watching only decides
    // whether this thread sleeps before taking it.
    watch([&] { return generation_.load(std::memory_order_acquire) != seen; });
    {
      std::unique_lock lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || generation_.load(std::memory_order_relaxed) != seen; });
      if (stopping_) return;
      seen = generation_.load(std::memory_order_relaxed);
      job = job_;
    }
    std::exception_ptr error;
    try {
      (*job)(worker);
    } catch (...) {
      error = std::current_exception();
    }
    {
      const std::lock_guard lock(mutex_);
      if (error && !error_) error_ = error;
      running_.fetch_sub(1, std::memory_order_release);
    }
    done_.notify_one();
  }
}

}  // namespace rastrace
