// Text read on threads: a file's lines found piece by piece, then parsed in ranges side by
// side, with the same result and the same first error as one thread reading line by line.
#pragma once

#include <algorithm>
#include <cstring>
#include <exception>
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
    } catch (const std::system_error&) {
      guarded(k);
    }
  }
  if (pieces > 0) guarded(0);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

/// The lines of `text` that for_each_line visits, numbered as it numbers them: the text cut
/// just after line ends into pieces of a megabyte or more, each piece scanned on one of up to
/// `threads` threads, once to count its lines and once to place them.
inline std::vector<Line> split_lines(std::string_view text, unsigned threads) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte order mark
  const std::size_t pieces = std::clamp<std::size_t>(text.size() / kPieceBytes, 1, std::max(threads, 1u));
  std::vector<std::size_t> cut(pieces + 1, text.size());  // piece k: [cut[k], cut[k + 1])
  cut[0] = 0;
  for (std::size_t k = 1; k < pieces; ++k) {
    const std::size_t from = std::max(cut[k - 1], text.size() / pieces * k);
    const void* nl = from < text.size() ? std::memchr(text.data() + from, '\n', text.size() - from) : nullptr;
    cut[k] = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - text.data()) + 1 : text.size();
  }
  // Each piece scanned twice: to count its lines, then to put them in their places.
  std::vector<std::size_t> numbered(pieces + 1, 0), at(pieces + 1, 0);  // before piece k: lines, and lines kept
  auto piece = [&](std::size_t k) { return text.substr(cut[k], cut[k + 1] - cut[k]); };
  on_pieces(pieces, [&](std::size_t k) {
    std::size_t kept = 0;
    numbered[k + 1] = lines_of(piece(k), [&](std::size_t, std::string_view) { ++kept; });
    at[k + 1] = kept;
  });
  for (std::size_t k = 0; k < pieces; ++k) numbered[k + 1] += numbered[k], at[k + 1] += at[k];
  std::vector<Line> out(at[pieces]);
  on_pieces(pieces, [&](std::size_t k) {
    Line* to = out.data() + at[k];
    lines_of(piece(k), [&](std::size_t number, std::string_view l) { *to++ = {numbered[k] + number, l}; });
  });
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
