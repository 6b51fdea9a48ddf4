// Waiting and timing on threads: a spin lock, a randomized back-off, and a clock cheap enough
// to time each insertion. The library's parallel loops are in runtime/parallel.hpp.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>

#include "order/random.hpp"
#include "runtime/parallel.hpp"

namespace ridt::detail {

using Clock = std::chrono::steady_clock;

inline double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

/// A cheap clock for timing each insertion: the time-stamp counter on x86 (constant-rate on
/// every processor of the last decade; a read costs a few nanoseconds where the steady clock
/// costs some 25 in a virtual machine), else the steady clock in nanoseconds. A duration is
/// taken on one thread, so counters that differ between cores do not matter. TickRate
/// converts ticks to seconds, calibrated against the steady clock over a whole run.
inline std::uint64_t ticks() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_ia32_rdtsc();
#else
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count());
#endif
}

class TickRate {
 public:
  TickRate() : clock_(Clock::now()), ticks_(ticks()) {}
  /// Seconds per tick over the time since construction.
  double seconds_per_tick() const {
    const std::uint64_t elapsed = ticks() - ticks_;
    return elapsed > 0 ? seconds(Clock::now() - clock_) / static_cast<double>(elapsed) : 0.0;
  }

 private:
  Clock::time_point clock_;
  std::uint64_t ticks_;
};

/// The pessimistic critical section lasts about a microsecond: a thread that finds the lock
/// taken spins (reading, not writing, so the line stays shared) instead of sleeping in the
/// kernel, which costs more than the wait. After a while it yields, so oversubscribed runs
/// still progress.
class SpinLock {
 public:
  void lock() {
    for (int spins = 0;; ++spins) {
      // acquire: the holder's changes to the triangulation happen before ours.
      if (!locked_.exchange(true, std::memory_order_acquire)) return;
      while (locked_.load(std::memory_order_relaxed)) {
        if (++spins < kSpinsBeforeYield) {
          cpu_relax();
        } else {
          std::this_thread::yield();
          spins = 0;
        }
      }
    }
  }
  // release: our changes to the triangulation happen before the next holder's.
  void unlock() { locked_.store(false, std::memory_order_release); }

 private:
  static constexpr int kSpinsBeforeYield = 4096;  // a few microseconds of pause instructions
  alignas(64) std::atomic<bool> locked_{false};  // its own cache line
};

/// Randomized exponential back-off after a failed try-lock: two threads that collided wait
/// different times, so they do not collide again in step. Yields once the wait is long, so an
/// oversubscribed machine lets the owner run.
class Backoff {
 public:
  explicit Backoff(std::uint64_t seed) : rng_(seed, /*stream=*/7) {}
  void pause() {
    const std::uint64_t spins = 1 + rng_.below(std::uint64_t{1} << exponent_);
    if (exponent_ < kMaxExponent) ++exponent_;
    if (exponent_ >= kYieldExponent) std::this_thread::yield();
    for (std::uint64_t i = 0; i < spins; ++i) cpu_relax();
  }
  void reset() { exponent_ = kMinExponent; }

 private:
  // 2^4 pauses (tens of nanoseconds) first: most conflicts end within one insertion, about a
  // microsecond; 2^12 at most.
  static constexpr int kMinExponent = 4, kYieldExponent = 10, kMaxExponent = 12;
  Rng rng_;
  int exponent_ = kMinExponent;
};

}  // namespace ridt::detail
