// The out-of-core triangulation's files (regions/out_of_core.cpp): a file written whole or not
// at all (a temporary name beside it, renamed once complete), and the messages its readers and
// writers give.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ridt/ridt.hpp"

namespace ridt::detail {

inline std::string errno_text(int err) { return std::strerror(err); }

/// A file's extension in lower case.
inline std::string extension_of(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return e;
}

/// Bytes written to a temporary name beside `path` through a buffer, renamed onto it by
/// commit(); removed unless committed. IoError where the file cannot be written. `announce`,
/// where set, is told the temporary name as soon as the file is there, and the final name just
/// before the rename puts it there (a caller removes them where a signal stops the process: no
/// moment is left in which a file stands that the caller has not been told of).
class FileOut {
 public:
  explicit FileOut(const std::string& path, const std::function<void(const std::string&)>& announce = {})
      : path_(path), tmp_(path + ".tmp-" + std::to_string(::getpid())), announce_(announce) {
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) throw IoError("cannot write " + path_ + ": " + errno_text(errno));
    if (announce) announce(tmp_);
    buffer_.reserve(kBuffer);
  }
  FileOut(const FileOut&) = delete;
  FileOut& operator=(const FileOut&) = delete;
  ~FileOut() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(tmp_.c_str());
  }

  void put(std::string_view bytes) {
    if (buffer_.size() + bytes.size() > kBuffer) flush();
    if (bytes.size() > kBuffer) return write_all(bytes);
    buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  }
  void put_u32_le(std::uint32_t v) {
    const char b[4] = {static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
                       static_cast<char>(v >> 24)};
    put({b, 4});
  }
  void commit() {
    flush();
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw IoError("cannot write " + path_ + ": " + errno_text(errno));
    if (announce_) announce_(path_);
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
      throw IoError("cannot write " + path_ + ": " + errno_text(errno));
    committed_ = true;
  }

 private:
  static constexpr std::size_t kBuffer = std::size_t{1} << 20;
  void flush() {
    write_all({buffer_.data(), buffer_.size()});
    buffer_.clear();
  }
  void write_all(std::string_view bytes) {
    for (std::size_t done = 0; done < bytes.size();) {
      const ssize_t put = ::write(fd_, bytes.data() + done, bytes.size() - done);
      if (put <= 0) throw IoError("cannot write " + path_ + ": " + errno_text(put == 0 ? ENOSPC : errno));
      done += static_cast<std::size_t>(put);
    }
  }

  std::string path_, tmp_;
  int fd_ = -1;
  bool committed_ = false;
  std::function<void(const std::string&)> announce_;
  std::vector<char> buffer_;
};

}  // namespace ridt::detail
