// The threads that on_threads parks between calls (runtime/parallel.hpp).
#include "runtime/parallel.hpp"

#include <pthread.h>
#include <sched.h>
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>

namespace ridt::detail {
namespace {

// Past this many parked threads a call starts its own.
constexpr unsigned kMostParked = 256;

// How long a thread that has nothing to do watches for more before it sleeps. A
// triangulation's parallel parts follow one another within microseconds to a millisecond. A
// thread that sleeps between them is woken on whichever core the scheduler picks, often the
// waker's own when the machine's cores look far apart to it (each in a cache domain of its
// own, as on virtual machines): the two then share one core until the load balancer moves one,
// and a run of 10^6 points on 2 threads took as long as on one, in one run of five on a
// 16-core virtual machine. A thread that watches keeps its core. Only while the threads of
// the last call were no more than the machine's: more of them would take cores from those
// still at work.
constexpr std::chrono::microseconds kWatch{500};

// Whether ready() became true within kWatch, checked all the while.
template <class Ready>
bool watch(Ready&& ready) {
  const auto until = std::chrono::steady_clock::now() + kWatch;
  for (unsigned i = 1;; ++i) {
    if (ready()) return true;
    cpu_relax();
    if (i % 64 == 0 && std::chrono::steady_clock::now() > until) return false;
  }
}

// The cores the process may run on (its affinity, which a container or taskset narrows), else
// the machine's.
unsigned allowed_cores() {
#ifdef __linux__
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) > 0)
    return static_cast<unsigned>(CPU_COUNT(&allowed));
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

// The core the calling thread runs on, or -1 where that is not known.
int current_core() {
#ifdef __linux__
  return sched_getcpu();
#else
  return -1;
#endif
}

// Some systems put a thread that is woken, or new, on the core of the thread that woke or made
// it, and leave the two there, taking turns, for milliseconds (virtual machines whose cores
// each look like a cache domain of their own). Triangulating 20,000 points on 2 threads of 2
// such cores, four times in each of 30 processes: 24 of the 90 later calls took over 6 ms where
// most take 3 (a mean of 5.1 ms); with this, 4 (a mean of 3.4 ms). A parked thread that finds
// itself on its caller's core, while the call's threads are no more than the cores, moves off
// it: its allowed cores narrowed to the others, then set back to those it had.
void leave_core(int caller) {
#ifdef __linux__
  cpu_set_t allowed;
  if (caller < 0 || sched_getcpu() != caller || sched_getaffinity(0, sizeof allowed, &allowed) != 0) return;
  if (!CPU_ISSET(caller, &allowed) || CPU_COUNT(&allowed) < 2) return;
  cpu_set_t others = allowed;
  CPU_CLR(caller, &others);
  if (sched_setaffinity(0, sizeof others, &others) == 0) sched_setaffinity(0, sizeof allowed, &allowed);
#else
  (void)caller;
#endif
}

thread_local bool tl_parked = false;  // this thread is one of the pool's
thread_local bool tl_holding = false;  // this thread is running a call on the pool's threads

class Pool {
 public:
  bool run(unsigned count, TaskRef task) {
    // A part that calls again, on a parked thread or on the caller's (which holds the mutex,
    // and may not try it again), starts threads of its own.
    if (tl_parked || tl_holding || count - 1 > kMostParked) return false;
    const std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return false;  // another call has them: it starts its own
    const unsigned helpers = count - 1;
    try {
      while (workers_.size() < helpers) start_one();
    } catch (...) {  // no thread to be had: the caller's own attempt will say why
      return false;
    }
    task_ = task;
    static const unsigned cores = allowed_cores();
    watching_.store(count <= cores, std::memory_order_relaxed);
    caller_core_ = count <= cores ? current_core() : -1;
    pending_.store(helpers, std::memory_order_relaxed);
    // Release: the task, and all the caller wrote before, to each worker that wakes.
    for (unsigned i = 0; i < helpers; ++i) {
      workers_[i]->generation.fetch_add(1, std::memory_order_release);
      workers_[i]->generation.notify_one();
    }
    std::exception_ptr failure;
    tl_holding = true;
    try {
      task(0);
    } catch (...) {  // the others still read `task`'s body: wait for them first
      failure = std::current_exception();
    }
    tl_holding = false;
    // Acquire: all the workers wrote, before the caller reads it.
    if (watching_.load(std::memory_order_relaxed)) watch([&] { return pending_.load(std::memory_order_acquire) == 0; });
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
    // A parked thread takes no signal sent to the process: those are the application's
    // threads' to take, whichever thread first made the pool. (A new thread starts with its
    // creator's mask, set back at once.)
    sigset_t all, before;
    sigfillset(&all);
    for (const int fault : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP, SIGABRT, SIGSYS})
      sigdelset(&all, fault);  // raised by the thread itself: its handler must still run
    pthread_sigmask(SIG_SETMASK, &all, &before);
    try {
      // Detached, and the pool is never destroyed: a parked thread at the process's exit
      // holds nothing that exit would wait for or free under it.
      std::thread([this, w, index] { park(*w, index); }).detach();
    } catch (...) {
      pthread_sigmask(SIG_SETMASK, &before, nullptr);
      workers_.pop_back();
      throw;
    }
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
  }

  void park(Worker& w, unsigned index) {
    tl_parked = true;
    for (std::uint32_t seen = 0;;) {
      if (!watching_.load(std::memory_order_relaxed) ||
          !watch([&] { return w.generation.load(std::memory_order_acquire) != seen; }))
        w.generation.wait(seen, std::memory_order_acquire);
      seen = w.generation.load(std::memory_order_acquire);
      leave_core(caller_core_);
      task_(index);  // on_threads' bodies do not throw
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
    }
  }

  std::mutex mutex_;  // held by the call that uses the workers
  std::vector<std::unique_ptr<Worker>> workers_;
  TaskRef task_{nullptr, nullptr};
  std::atomic<std::uint32_t> pending_{0};  // workers still running the task
  std::atomic<bool> watching_{false};  // whether idle threads watch before they sleep (watch)
  int caller_core_ = -1;  // the calling thread's core, for leave_core (-1: stay)
};

// The process's pool. A child of fork() has none of its parent's threads, and its copy of the
// pool may even be held by a call that was running in the parent: the child starts from a
// new pool (the old one is left as it is, never freed), set while the child still has one
// thread.
Pool* g_pool = nullptr;

Pool& pool() {
  static const bool made = [] {
    g_pool = new Pool;
    pthread_atfork(nullptr, nullptr, [] { g_pool = new Pool; });
    return true;
  }();
  (void)made;
  return *g_pool;
}

}  // namespace

bool run_parked(unsigned count, TaskRef task) { return pool().run(count, task); }

}  // namespace ridt::detail
