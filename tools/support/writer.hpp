// A file written whole or not at all: buffered output to a temporary name beside the target,
// renamed onto it by commit(); a device or a pipe is written in place instead. Every writer of
// the tools uses it (io_*.cpp, ridt-mpi).
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "io.hpp"
#include "temporaries.hpp"

namespace ridt::io {

/// A number that is not finite met by a writer of coordinates: never written, the file is
/// refused instead (a NaN or an infinity is not a number that a reader takes back).
class NotFinite : public IoError {
 public:
  explicit NotFinite(double v)
      : IoError(std::string("a number that is not finite (") +
                (std::isnan(v) ? "NaN"
                     : v > 0   ? "inf"
                               : "-inf") +
                ") cannot be written") {}
};

/// Where the bytes of an output named `path` go.
struct OutputTarget {
  std::string path;  ///< `path` with its symbolic links followed: the file that is written
  bool in_place = false;  ///< an existing file that is not a regular one (a device, a pipe): written in order
};

/// The target of `path`: a symbolic link is followed to its target (existing or not), so that
/// the target is written and the link kept; IoError where it is a directory or a loop of links.
inline OutputTarget output_target(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {  // the kernel follows the links, /proc's too
    if (S_ISDIR(st.st_mode)) throw IoError("cannot write " + path + ": it is a directory");
    if (!S_ISREG(st.st_mode)) return {path, true};
    const fs::path real = fs::canonical(path, ec);
    if (ec) throw IoError("cannot write " + path + ": " + ec.message());
    return {real.string(), false};
  }
  fs::path p = path;  // none there: a dangling link's target is made
  for (int hops = 0; fs::is_symlink(p, ec); ++hops) {
    if (hops == 40) throw IoError("cannot write " + path + ": " + std::strerror(ELOOP));
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw IoError("cannot write " + path + ": " + ec.message());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  return {p.string(), false};
}

/// Text formatted into memory, in the Writer's forms: a run of a file's lines that threads
/// format side by side (Writer::put_lines).
class TextPart {
 public:
  void put(std::string_view s) {
    std::memcpy(room(s.size()), s.data(), s.size());
    size_ += s.size();
  }
  void put(char c) {
    *room(1) = c;
    ++size_;
  }
  void put_int(std::int64_t v) {
    char* at = room(kNumberRoom);
    size_ = static_cast<std::size_t>(std::to_chars(at, at + kNumberRoom, v).ptr - buf_.get());
  }
  /// Shortest decimal form that reads back to exactly `v`; NotFinite for NaN or an infinity.
  void put_double(double v) {
    if (!std::isfinite(v)) throw NotFinite(v);
    char* at = room(kNumberRoom);
    size_ = static_cast<std::size_t>(std::to_chars(at, at + kNumberRoom, v).ptr - buf_.get());
  }
  std::string_view text() const { return {buf_.get(), size_}; }
  void clear() { size_ = 0; }

 private:
  static constexpr std::size_t kNumberRoom = 48;
  // Where the next n characters go, the buffer grown (doubled) first where they do not fit.
  char* room(std::size_t n) {
    if (capacity_ - size_ < n) {
      const std::size_t capacity = std::max({2 * capacity_, size_ + n, std::size_t{1} << 16});
      std::unique_ptr<char[]> bigger(new char[capacity]);
      if (size_ > 0) std::memcpy(bigger.get(), buf_.get(), size_);
      buf_ = std::move(bigger), capacity_ = capacity;
    }
    return buf_.get() + size_;
  }

  std::unique_ptr<char[]> buf_;
  std::size_t size_ = 0, capacity_ = 0;
};

/// Buffered output to a temporary file beside `path`'s target (output_target: a symbolic link
/// followed), renamed onto the target by commit(). If the writer is destroyed without a
/// successful commit the temporary file is removed, and a signal that ends the tool removes it
/// too (temporaries.hpp). A target that exists and is not a regular
/// file (a device such as /dev/stdout, a pipe) is written in place, in order, as the bytes come:
/// there an error midway cannot take back what was written.
class Writer {
 public:
  explicit Writer(const std::string& path) : path_(path), target_(output_target(path)) {
    if (target_.in_place) {
      fd_ = ::open(target_.path.c_str(), O_WRONLY | O_CLOEXEC);
    } else {
      tmp_ = temp_name(target_.path);
      registered_ = TemporaryName(tmp_);  // before the file exists: a signal never finds it unnamed
      fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    }
    if (fd_ < 0) fail(errno);
  }

  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  ~Writer() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_ && !tmp_.empty()) std::remove(tmp_.c_str());
    registered_.release();
  }

  /// Whether the file is written in place (a device, a pipe), not renamed: put_at takes only
  /// the bytes that come next.
  bool in_place() const { return target_.in_place; }
  /// The file written: the path with its symbolic links followed.
  const std::string& target() const { return target_.path; }

  void put(std::string_view s) {
    if (s.size() > kCapacity - pos_) {
      flush();
      if (s.size() > kCapacity) {
        write_through(s.data(), s.size());
        return;
      }
    }
    std::memcpy(buf_.get() + pos_, s.data(), s.size());
    pos_ += s.size();
  }

  void put(char c) {
    room(1);
    buf_[pos_++] = c;
  }

  /// Shortest decimal form that reads back to exactly `v`; NotFinite (as IoError naming the
  /// file) for NaN or an infinity.
  void put_double(double v) {
    if (!std::isfinite(v)) fail_not_finite(v);
    room(kNumberRoom);
    const auto r = std::to_chars(buf_.get() + pos_, buf_.get() + kCapacity, v);
    pos_ = static_cast<std::size_t>(r.ptr - buf_.get());
  }

  /// A value where NaN and infinities are meant (a fill value): "nan", "inf", "-inf", else as
  /// put_double.
  void put_value(double v) {
    if (std::isfinite(v)) return put_double(v);
    put(std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf");
  }

  /// `v` with at most `decimals` digits after the point, trailing zeros removed; IoError for NaN
  /// or an infinity, as put_double.
  void put_fixed(double v, int decimals) {
    if (!std::isfinite(v)) fail_not_finite(v);
    room(kNumberRoom + 320);  // fixed notation of a huge double is long
    char* const begin = buf_.get() + pos_;
    const auto r = std::to_chars(begin, buf_.get() + kCapacity, v, std::chars_format::fixed, decimals);
    char* end = r.ptr;
    if (std::memchr(begin, '.', static_cast<std::size_t>(end - begin))) {
      while (end[-1] == '0') --end;
      if (end[-1] == '.') --end;
    }
    if (end - begin == 2 && begin[0] == '-' && begin[1] == '0') {  // "-0" -> "0"
      begin[0] = '0';
      end = begin + 1;
    }
    pos_ = static_cast<std::size_t>(end - buf_.get());
  }

  void put_int(std::int64_t v) {
    room(kNumberRoom);
    const auto r = std::to_chars(buf_.get() + pos_, buf_.get() + kCapacity, v);
    pos_ = static_cast<std::size_t>(r.ptr - buf_.get());
  }

  void put_u32_le(std::uint32_t v) {
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
    room(4);
    std::memcpy(buf_.get() + pos_, &v, 4);
    pos_ += 4;
  }

  /// IoError for NaN or an infinity, as put_double.
  void put_f64_le(double d) {
    if (!std::isfinite(d)) fail_not_finite(d);
    put_value_f64_le(d);
  }

  /// A value where NaN and infinities are meant (a fill value), as it is.
  void put_value_f64_le(double d) {
    std::uint64_t v = std::bit_cast<std::uint64_t>(d);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
    room(8);
    std::memcpy(buf_.get() + pos_, &v, 8);
    pos_ += 8;
  }

  /// Writes `s` at byte `offset` of the file, past what put() buffers: from any thread, several
  /// at once (a file filled in stretches as they are ready; its size, their end).
  /// In place (a device, a pipe), only the bytes that come next are taken.
  void put_at(std::uint64_t offset, std::string_view s) {
    if (target_.in_place && offset != end_) fail(ESPIPE);
    while (!s.empty()) {
      const ssize_t n = target_.in_place ? ::write(fd_, s.data(), s.size())
                                         : ::pwrite(fd_, s.data(), s.size(), static_cast<off_t>(offset));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) fail(n < 0 ? errno : ENOSPC);
      s.remove_prefix(static_cast<std::size_t>(n));
      offset += static_cast<std::uint64_t>(n);
    }
  }

  /// Lines 0 .. count-1, `line(k, part)` formatting line k into a TextPart, in runs: on
  /// `threads` threads, waves of runs formatted side by side while this thread writes the
  /// wave before.
  template <class Line>
  void put_lines(std::size_t count, unsigned threads, Line&& line) {
    try {
      put_lines_on(count, threads, line);
    } catch (const NotFinite& e) {
      throw IoError("cannot write " + path_ + ": " + e.what());
    }
  }

  /// Writes out and closes the file under its temporary name (throws if that fails): what is
  /// left is the rename, which commit() does. For writers that must agree before any renames.
  void close() {
    if (fd_ < 0) return;
    flush();
    if (::close(std::exchange(fd_, -1)) != 0) fail(errno);
  }

  void commit() {
    close();
    // An input mapped where it lay shrank while it was read: what was made of it is not kept.
    if (detail::any_mapping_shrank())
      throw IoError("cannot write " + target_.path +
                    ": an input file shrank while it was read (truncated or "
                    "rewritten by another process); nothing is written");
    errno = 0;
    if (!target_.in_place && std::rename(tmp_.c_str(), target_.path.c_str()) != 0) fail(errno);
    committed_ = true;
    registered_.release();
  }

 private:
  static constexpr std::size_t kCapacity = std::size_t{1} << 20;
  static constexpr std::size_t kNumberRoom = 48;

  template <class Line>
  void put_lines_on(std::size_t count, unsigned threads, Line& line) {
    constexpr std::size_t kRun = std::size_t{1} << 15;
    const std::size_t runs = (count + kRun - 1) / kRun;
    auto format = [&](TextPart& part, std::size_t run) {
      part.clear();
      for (std::size_t k = run * kRun, end = std::min(count, (run + 1) * kRun); k < end; ++k) line(k, part);
    };
    threads = static_cast<unsigned>(std::clamp<std::size_t>(runs, 1, std::max(threads, 1u)));
    if (threads == 1) {
      TextPart part;
      for (std::size_t run = 0; run < runs; ++run) format(part, run), put(part.text());
      return;
    }
    // Wave w's runs in slots (w % 2) * threads + t; each worker formats in a part of its own,
    // moved out of the array (neighbouring parts' sizes would share a cache line).
    std::vector<TextPart> parts(2 * std::size_t{threads});
    std::vector<std::exception_ptr> failed(parts.size());
    // Wave w's workers; where one cannot be started, those that were are joined first.
    auto start = [&](std::size_t w) {
      std::vector<std::thread> workers;
      try {
        for (std::size_t t = 0, run = w * threads; t < threads && run < runs; ++t, ++run)
          workers.emplace_back([&, slot = (w % 2) * threads + t, run] {
            TextPart part = std::move(parts[slot]);
            try {
              format(part, run);
            } catch (...) {
              failed[slot] = std::current_exception();
            }
            parts[slot] = std::move(part);
          });
      } catch (...) {
        for (std::thread& t : workers) t.join();
        throw;
      }
      return workers;
    };
    const std::size_t waves = (runs + threads - 1) / threads;
    std::vector<std::thread> current = start(0);
    for (std::size_t w = 0; w < waves; ++w) {
      for (std::thread& t : current) t.join();
      current = w + 1 < waves ? start(w + 1) : std::vector<std::thread>{};
      try {
        for (std::size_t t = 0, run = w * threads; t < threads && run < runs; ++t, ++run) {
          const std::size_t slot = (w % 2) * threads + t;
          if (failed[slot]) std::rethrow_exception(failed[slot]);
          put(parts[slot].text());
        }
      } catch (...) {
        for (std::thread& t : current) t.join();
        throw;
      }
    }
  }

  static std::string temp_name(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(static_cast<long long>(::getpid())) + "-" +
        std::to_string(counter.fetch_add(1));
  }

  [[noreturn]] void fail(int err) const {
    throw IoError("cannot write " + path_ + ": " + (err != 0 ? std::strerror(err) : "unknown error"));
  }

  [[noreturn]] void fail_not_finite(double v) const {
    throw IoError("cannot write " + path_ + ": " + NotFinite(v).what());
  }

  void room(std::size_t n) {
    if (kCapacity - pos_ < n) flush();
  }

  void flush() {
    if (pos_ == 0) return;
    write_through(buf_.get(), pos_);
    pos_ = 0;
  }

  void write_through(const char* p, std::size_t n) {
    put_at(end_, std::string_view(p, n));
    end_ += n;
  }

  std::string path_;
  OutputTarget target_;
  std::string tmp_;  // empty in place
  TemporaryName registered_;  // tmp_, for a signal that ends the tool
  int fd_ = -1;
  std::uint64_t end_ = 0;  // what put() has written out
  std::unique_ptr<char[]> buf_{new char[kCapacity]};
  std::size_t pos_ = 0;
  bool committed_ = false;
};

}  // namespace ridt::io
