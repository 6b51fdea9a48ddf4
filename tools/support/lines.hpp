// Text read on threads: a file's lines found piece by piece, then parsed in ranges side by
// side, with the same result and the same first error as one thread reading line by line.
#pragma once

#include <algorithm>
#include <cstring>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "io_common.hpp"

namespace ridt::io::detail {

/// A line that for_each_line visits: its number (from 1) and its content.
struct Line {
  std::size_t number;
  std::string_view text;
};

/// Bytes of text, or lines, below which another thread is not worth starting.
inline constexpr std::size_t kPieceBytes = std::size_t{1} << 20;
inline constexpr std::size_t kRangeLines = std::size_t{1} << 15;

/// run(k) for each k in [0, pieces), each on a thread of its own (the first on this one; where
/// a thread cannot be started, its piece runs here too). Once all have ended, the exception
/// of the lowest k that threw is rethrown.
template <class Run>
void on_pieces(std::size_t pieces, Run&& run) {
  std::vector<std::exception_ptr> failed(pieces);
  auto guarded = [&](std::size_t k) {
    try {
      run(k);
    } catch (...) {
      failed[k] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(pieces);
  for (std::size_t k = 1; k < pieces; ++k) {
    try {
      workers.emplace_back(guarded, k);
    } catch (...) {  // no thread (std::system_error), or no memory for one
      guarded(k);
    }
  }
  if (pieces > 0) guarded(0);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

/// A text cut just after line ends into pieces of a megabyte or more, one for each of up to
/// `threads` threads, and each piece's lines counted (on those threads): so each line's place
/// among the lines for_each_line visits, and its number, are known before any is read.
class LinePieces {
 public:
  /// `before`: how many lines come before `text` in its file (its first is line before + 1).
  LinePieces(std::string_view text, unsigned threads, std::size_t before = 0) : text_(text) {
    const std::size_t pieces = std::clamp<std::size_t>(text.size() / kPieceBytes, 1, std::max(threads, 1u));
    cut_.assign(pieces + 1, text.size());  // piece k: [cut_[k], cut_[k + 1])
    cut_[0] = 0;
    for (std::size_t k = 1; k < pieces; ++k) {
      const std::size_t from = std::max(cut_[k - 1], text.size() / pieces * k);
      const void* nl = from < text.size() ? std::memchr(text.data() + from, '\n', text.size() - from) : nullptr;
      cut_[k] = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text.data()) + 1 : text.size();
    }
    numbered_.assign(pieces + 1, 0), at_.assign(pieces + 1, 0);  // before piece k: lines, and lines kept
    on_pieces(pieces, [&](std::size_t k) {
      std::size_t kept = 0;
      numbered_[k + 1] = lines_of(piece(k), [&](std::size_t, std::string_view) { ++kept; });
      at_[k + 1] = kept;
    });
    numbered_[0] = before;
    for (std::size_t k = 0; k < pieces; ++k) numbered_[k + 1] += numbered_[k], at_[k + 1] += at_[k];
  }

  /// The lines for_each_line visits.
  std::size_t size() const { return at_.back(); }

  /// visit(i, number, line) for each of them, i its place among them (from 0), each piece's
  /// lines in order on a thread of its own; an exception ends its piece. Once all pieces have
  /// ended, the exception of the first that threw is rethrown: where what visit checks
  /// depends on i and the line alone, the one a single pass in order would meet first.
  template <class Visit>
  void visit(Visit&& visit) const {
    on_pieces(cut_.size() - 1, [&](std::size_t k) {
      std::size_t i = at_[k];
      lines_of(piece(k), [&](std::size_t number, std::string_view line) { visit(i++, numbered_[k] + number, line); });
    });
  }

 private:
  std::string_view piece(std::size_t k) const { return text_.substr(cut_[k], cut_[k + 1] - cut_[k]); }

  std::string_view text_;
  std::vector<std::size_t> cut_, numbered_, at_;
};

/// The first line for_each_line visits in `text` (a byte order mark taken off where `file`, the
/// text starting a file) and the text after it, or none.
struct Head {
  Line line;
  std::string_view rest;
};
inline std::optional<Head> head_line(std::string_view text, bool file = true) {
  if (file) text = without_bom(text);
  for (std::size_t number = 1; !text.empty(); ++number) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = content_of(text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
    if (!line.empty()) return Head{{number, line}, text};
  }
  return std::nullopt;
}

/// The lines of `text` that for_each_line visits, numbered as it numbers them, found on up to
/// `threads` threads (LinePieces).
inline std::vector<Line> split_lines(std::string_view text, unsigned threads) {
  const LinePieces pieces(without_bom(text), threads);
  std::vector<Line> out(pieces.size());
  pieces.visit([&](std::size_t i, std::size_t number, std::string_view line) { out[i] = {number, line}; });
  return out;
}

/// parse(i) for each i in [begin, end), in ranges on up to `threads` threads, each range in
/// order; an exception ends its range. Once all have ended, the exception of the lowest range
/// that threw is rethrown: where parse(i) depends on i alone, the one a single pass in order
/// would meet first.
template <class Parse>
void parse_in_ranges(std::size_t begin, std::size_t end, unsigned threads, Parse&& parse) {
  const std::size_t count = end > begin ? end - begin : 0;
  const std::size_t ranges = std::clamp<std::size_t>(count / kRangeLines, 1, std::max(threads, 1u));
  on_pieces(ranges, [&](std::size_t r) {
    for (std::size_t i = begin + count * r / ranges, last = begin + count * (r + 1) / ranges; i < last; ++i) parse(i);
  });
}

/// The points of a .node file's lines (io_triangle.cpp), its header first: .poly's vertices
/// are read by it too.
PointFile read_node_lines(const std::string& path, std::span<const Line> lines, unsigned threads);

}  // namespace ridt::io::detail
