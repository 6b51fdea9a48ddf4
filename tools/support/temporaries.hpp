// The temporary files the tools are writing, named where a signal handler can find them: a tool
// interrupted (Ctrl-C, kill, a hang-up, an input cut short) removes them before it ends, so
// that no half-written file stays beside its target. Writers register a temporary name while
// they write under it and release it once it is renamed or removed.
//
// The list is a fixed array of slots, each a state and a copy of the path, so that
// remove_temporaries() reads it with nothing but atomic loads and unlink(2), both
// async-signal-safe. Header-only: the GDAL module (tools/gdal/module.cpp), loaded with its
// symbols private, keeps a list of its own, which it hands to the tool's as an extra remover.
#pragma once

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstring>
#include <string>
#include <utility>

namespace ridt::io {

namespace detail {

struct TemporarySlot {
  // 0: free; 1: being written or cleared (not to be read); 2: holds a path.
  std::atomic<int> state{0};
  char path[4096] = {};
};

// At most this many temporary files at once (`ridt mesh` writes four side by side, an
// out-of-core run keeps its parts until its index is written); past that a file is still
// removed by its writer on every path but a signal. Untouched slots cost no memory (zeroed).
inline constexpr std::size_t kTemporarySlots = 1024;
inline constinit std::array<TemporarySlot, kTemporarySlots> temporary_slots{};  // in zeroed memory
// Another list's remover (the GDAL module's), called by remove_temporaries().
inline std::atomic<void (*)() noexcept> other_temporaries{nullptr};
// Set while remove_temporaries() runs: a second signal, or the other list when it is this one
// (a module whose symbols resolved to the tool's), returns at once.
inline std::atomic<bool> removing_temporaries{false};
// What a SIGBUS prints (end_on_signals).
inline const char* bus_error_text = "";

}  // namespace detail

/// Unlinks every registered temporary file. Async-signal-safe: for a signal handler. (A slot
/// that another thread releases and takes again while this reads it may give a mix of two of
/// the tool's temporary names: a name that is no file.)
inline void remove_temporaries() noexcept {
  if (detail::removing_temporaries.exchange(true)) return;
  for (detail::TemporarySlot& s : detail::temporary_slots)
    if (s.state.load(std::memory_order_acquire) == 2) ::unlink(s.path);
  if (auto other = detail::other_temporaries.load(std::memory_order_acquire)) other();
  detail::removing_temporaries.store(false);
}

/// remove_temporaries() also calls `remover` (a module's own remove_temporaries).
inline void also_remove_temporaries(void (*remover)() noexcept) {
  detail::other_temporaries.store(remover, std::memory_order_release);
}

/// A temporary file's path, registered for remove_temporaries() while the object holds it.
class TemporaryName {
 public:
  TemporaryName() = default;
  explicit TemporaryName(const std::string& path) {
    if (path.size() >= sizeof(detail::TemporarySlot::path)) return;
    for (std::size_t k = 0; k < detail::kTemporarySlots; ++k) {
      detail::TemporarySlot& s = detail::temporary_slots[k];
      int free = 0;
      if (!s.state.compare_exchange_strong(free, 1, std::memory_order_acquire)) continue;
      std::memcpy(s.path, path.c_str(), path.size() + 1);
      s.state.store(2, std::memory_order_release);
      slot_ = static_cast<int>(k);
      return;
    }
  }
  TemporaryName(TemporaryName&& other) noexcept : slot_(std::exchange(other.slot_, -1)) {}
  TemporaryName& operator=(TemporaryName&& other) noexcept {
    if (this != &other) release(), slot_ = std::exchange(other.slot_, -1);
    return *this;
  }
  TemporaryName(const TemporaryName&) = delete;
  TemporaryName& operator=(const TemporaryName&) = delete;
  ~TemporaryName() { release(); }

  /// Forgets the path (renamed onto its target, or removed): a signal then leaves it be.
  void release() noexcept {
    if (slot_ < 0) return;
    detail::temporary_slots[static_cast<std::size_t>(std::exchange(slot_, -1))].state.store(0,
                                                                                            std::memory_order_release);
  }

 private:
  int slot_ = -1;
};

namespace detail {

// Set by the first ending signal's handler: a second one, on another thread, waits for the first
// to remove the files and end the process (the handlers block the others on their own thread).
inline std::atomic<bool> ending{false};

extern "C" inline void end_by_signal(int sig) {
  if (ending.exchange(true))
    for (;;) ::pause();
  remove_temporaries();
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // ends the process as the signal would have: a shell sees 128 + sig
}

extern "C" inline void end_by_bus_error(int) {
  if (ending.exchange(true))
    for (;;) ::pause();
  remove_temporaries();
  (void)!::write(STDERR_FILENO, bus_error_text, std::strlen(bus_error_text));
  ::_exit(2);
}

}  // namespace detail

/// How a tool ends on a signal: SIGINT, SIGTERM and SIGHUP remove the temporary files, then end
/// the process as they would have; SIGBUS (an input file mapped into memory and cut short
/// while it is read, or its storage failing) removes them, prints `bus_error` and exits with
/// status 2, where it would have dumped core; SIGXFSZ is ignored, so that a write past the
/// file size limit fails as an error (EFBIG) and its writer removes its file. `bus_error` must
/// outlive the process (a literal).
inline void end_on_signals(const char* bus_error) {
  detail::bus_error_text = bus_error;
  struct sigaction end {};
  sigemptyset(&end.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGBUS}) sigaddset(&end.sa_mask, sig);
  end.sa_handler = detail::end_by_signal;
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction before {};
    // One ignored when the tool started (a background job's SIGINT) stays ignored.
    if (sigaction(sig, nullptr, &before) == 0 && before.sa_handler != SIG_IGN) sigaction(sig, &end, nullptr);
  }
  end.sa_handler = detail::end_by_bus_error;
  sigaction(SIGBUS, &end, nullptr);
  signal(SIGXFSZ, SIG_IGN);
}

}  // namespace ridt::io
