// The threads that on_threads parks between calls (parallel.hpp).
#include "parallel.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <mutex>

namespace ridt::detail {
namespace {

// Past this many parked threads a call starts its own.
constexpr unsigned kMostParked = 256;

thread_local bool tl_parked = false;  // this thread is one of the pool's

class Pool {
 public:
  bool run(unsigned count, TaskRef task) {
    if (tl_parked || count - 1 > kMostParked) return false;
    const std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return false;  // another call has them: it starts its own
    if (pid_ != ::getpid()) {
      // A child of fork() has none of the parent's threads: it parks its own.
      workers_.clear();
      pid_ = ::getpid();
    }
    const unsigned helpers = count - 1;
    try {
      while (workers_.size() < helpers) start_one();
    } catch (...) {  // no thread to be had: the caller's own attempt will say why
      return false;
    }
    task_ = task;
    pending_.store(helpers, std::memory_order_relaxed);
    // Release: the task, and all the caller wrote before, to each worker that wakes.
    for (unsigned i = 0; i < helpers; ++i) {
      workers_[i]->generation.fetch_add(1, std::memory_order_release);
      workers_[i]->generation.notify_one();
    }
    std::exception_ptr failure;
    try {
      task(0);
    } catch (...) {  // the others still read `task`'s body: wait for them first
      failure = std::current_exception();
    }
    // Acquire: all the workers wrote, before the caller reads it.
    for (std::uint32_t left; (left = pending_.load(std::memory_order_acquire)) != 0;)
      pending_.wait(left, std::memory_order_acquire);
    if (failure) std::rethrow_exception(failure);
    return true;
  }

 private:
  struct alignas(64) Worker {
    std::atomic<std::uint32_t> generation{0};  // one more for each task it is given
  };

  void start_one() {
    workers_.push_back(std::make_unique<Worker>());
    Worker* w = workers_.back().get();
    const auto index = static_cast<unsigned>(workers_.size());
    try {
      // Detached, and the pool is never destroyed: a parked thread at the process's exit
      // holds nothing that exit would wait for or free under it.
      std::thread([this, w, index] { park(*w, index); }).detach();
    } catch (...) {
      workers_.pop_back();
      throw;
    }
  }

  void park(Worker& w, unsigned index) {
    tl_parked = true;
    for (std::uint32_t seen = 0;;) {
      w.generation.wait(seen, std::memory_order_acquire);
      seen = w.generation.load(std::memory_order_acquire);
      task_(index);  // on_threads' bodies do not throw
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
    }
  }

  std::mutex mutex_;  // held by the call that uses the workers
  pid_t pid_ = ::getpid();
  std::vector<std::unique_ptr<Worker>> workers_;
  TaskRef task_{nullptr, nullptr};
  std::atomic<std::uint32_t> pending_{0};  // workers still running the task
};

}  // namespace

bool run_parked(unsigned count, TaskRef task) {
  static Pool* const pool = new Pool;  // never destroyed (see start_one)
  return pool->run(count, task);
}

}  // namespace ridt::detail
