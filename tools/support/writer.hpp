// A file written whole or not at all: buffered output to a temporary name beside the target,
// renamed onto it by commit(). Every writer of the tools uses it (io_*.cpp, ridt-mpi).
#pragma once

#include <unistd.h>

#include <atomic>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

#include "io.hpp"

namespace ridt::io {

/// Buffered output to a temporary file beside `path`, renamed onto `path` by commit(). If the
/// writer is destroyed without a successful commit the temporary file is removed.
class Writer {
 public:
  explicit Writer(const std::string& path) : path_(path), tmp_(temp_name(path)) {
    errno = 0;
    out_.open(tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) fail(errno);
    opened_ = true;
  }

  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  ~Writer() {
    if (opened_ && !committed_) {
      out_.close();
      std::remove(tmp_.c_str());
    }
  }

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

  /// Shortest decimal form that reads back to exactly `v`.
  void put_double(double v) {
    room(kNumberRoom);
    const auto r = std::to_chars(buf_.get() + pos_, buf_.get() + kCapacity, v);
    pos_ = static_cast<std::size_t>(r.ptr - buf_.get());
  }

  /// `v` with at most `decimals` digits after the point, trailing zeros removed.
  void put_fixed(double v, int decimals) {
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

  void put_f64_le(double d) {
    std::uint64_t v = std::bit_cast<std::uint64_t>(d);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
    room(8);
    std::memcpy(buf_.get() + pos_, &v, 8);
    pos_ += 8;
  }

  /// Writes out and closes the file under its temporary name (throws if that fails): what is
  /// left is the rename, which commit() does. For writers that must agree before any renames.
  void close() {
    if (closed_) return;
    flush();
    errno = 0;
    out_.close();
    if (out_.fail()) fail(errno);
    closed_ = true;
  }

  void commit() {
    close();
    errno = 0;
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail(errno);
    committed_ = true;
  }

 private:
  static constexpr std::size_t kCapacity = std::size_t{1} << 20;
  static constexpr std::size_t kNumberRoom = 48;

  static std::string temp_name(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(static_cast<long long>(::getpid())) + "-" +
        std::to_string(counter.fetch_add(1));
  }

  [[noreturn]] void fail(int err) const {
    throw IoError("cannot write " + path_ + ": " + (err != 0 ? std::strerror(err) : "unknown error"));
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
    errno = 0;
    out_.write(p, static_cast<std::streamsize>(n));
    if (!out_) fail(errno);
  }

  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  std::unique_ptr<char[]> buf_{new char[kCapacity]};
  std::size_t pos_ = 0;
  bool opened_ = false;
  bool committed_ = false;
  bool closed_ = false;
};

}  // namespace ridt::io
