// What ridt-mpi's ranks share (main.cpp): the records they send, the MPI calls they make
// (class Mpi: every error becomes one message on every rank), and each rank's share of the
// input file.
#pragma once

#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iterator>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "io.hpp"
#include "ridt/predicates.hpp"
#include "ridt/regions.hpp"
#include "ridt/ridt.hpp"
#include "writer.hpp"

namespace ridt::mpi {

using ridt::Point;
using Clock = std::chrono::steady_clock;

using io::Box;
using regions::Disc;
using regions::Site;

// What a rank asks another for: its points inside or on the circumcircle of the
// counter-clockwise triangle (a, b), (c, d), (e, f) (kind 0), its neighbour across the line
// from (a, b) to (c, d) (kind 1: a point strictly to its right), or all its points (kind 2).
struct Request {
  double kind, a, b, c, d, e, f;
};

// An error on one rank, to be shared with all.
struct Failure : std::exception {
  std::string message;
  explicit Failure(std::string m) : message(std::move(m)) {}
};

class Mpi {
 public:
  int rank = 0, size = 1;
  double comm_s = 0;  // time in communication calls
  std::uint64_t bytes_sent = 0;

  Mpi() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Type_contiguous(sizeof(Site), MPI_BYTE, &site_);
    MPI_Type_commit(&site_);
    MPI_Type_contiguous(sizeof(Request), MPI_BYTE, &request_);
    MPI_Type_commit(&request_);
  }
  ~Mpi() {
    MPI_Type_free(&site_);
    MPI_Type_free(&request_);
  }

  // Every rank calls this with its error, if any; all then know whether any rank failed, and
  // rank 0 prints the lowest failing rank's message once. Returns false when any failed.
  bool agree(const std::string& error) {
    const int mine = error.empty() ? size : rank;
    int first = size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == size) return true;
    int length = rank == first ? static_cast<int>(error.size()) : 0;
    MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD);
    std::string message = rank == first ? error : std::string(static_cast<std::size_t>(length), ' ');
    MPI_Bcast(message.data(), length, MPI_CHAR, first, MPI_COMM_WORLD);
    if (rank == 0)
      std::fprintf(stderr, "ridt-mpi: error: %s%s\n", size > 1 ? ("rank " + std::to_string(first) + ": ").c_str() : "",
                   message.c_str());
    return false;
  }

  // Sends out[q] to rank q and returns what each rank sent here, in rank order.
  template <class T>
  std::vector<T> exchange(const std::vector<std::vector<T>>& out) {
    std::vector<T> flat;
    std::vector<int> counts(static_cast<std::size_t>(size));
    for (int q = 0; q < size; ++q) {
      counts[static_cast<std::size_t>(q)] = static_cast<int>(out[static_cast<std::size_t>(q)].size());
      flat.insert(flat.end(), out[static_cast<std::size_t>(q)].begin(), out[static_cast<std::size_t>(q)].end());
    }
    return exchange(flat, counts);
  }

  // The same for what is already in rank order: the first send_counts[0] items to rank 0, the
  // next send_counts[1] to rank 1, and so on.
  template <class T>
  std::vector<T> exchange(const std::vector<T>& flat, std::vector<int> send_counts) {
    const auto t0 = Clock::now();
    const MPI_Datatype type = std::is_same_v<T, Site> ? site_ : request_;
    std::vector<int> recv_counts(size), send_at(size), recv_at(size);
    for (int q = 0, at = 0; q < size; ++q) {
      send_at[q] = at;
      at += send_counts[q];
      if (q != rank) bytes_sent += static_cast<std::uint64_t>(send_counts[q]) * sizeof(T);
    }
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::size_t total = 0;
    for (int q = 0; q < size; ++q) recv_at[q] = static_cast<int>(total), total += recv_counts[q];
    std::vector<T> in(total);
    MPI_Alltoallv(flat.data(), send_counts.data(), send_at.data(), type, in.data(), recv_counts.data(), recv_at.data(),
                  type, MPI_COMM_WORLD);
    comm_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return in;
  }

  // The same, keeping which rank each came from.
  template <class T>
  std::vector<std::vector<T>> exchange_by_rank(const std::vector<std::vector<T>>& out) {
    const auto t0 = Clock::now();
    const MPI_Datatype type = std::is_same_v<T, Site> ? site_ : request_;
    std::vector<int> send_counts(size), recv_counts(size);
    for (int q = 0; q < size; ++q) {
      send_counts[q] = static_cast<int>(out[q].size());
      if (q != rank) bytes_sent += out[q].size() * sizeof(T);
    }
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::vector<std::vector<T>> in(size);
    std::vector<MPI_Request> pending;
    for (int q = 0; q < size; ++q) {
      in[q].resize(static_cast<std::size_t>(recv_counts[q]));
      if (recv_counts[q] > 0) {
        pending.emplace_back();
        MPI_Irecv(in[q].data(), recv_counts[q], type, q, 7, MPI_COMM_WORLD, &pending.back());
      }
    }
    for (int q = 0; q < size; ++q)
      if (send_counts[q] > 0) {
        pending.emplace_back();
        MPI_Isend(out[q].data(), send_counts[q], type, q, 7, MPI_COMM_WORLD, &pending.back());
      }
    MPI_Waitall(static_cast<int>(pending.size()), pending.data(), MPI_STATUSES_IGNORE);
    comm_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return in;
  }

  std::uint64_t sum(std::uint64_t v) {
    const auto t0 = Clock::now();
    std::uint64_t s = 0;
    MPI_Allreduce(&v, &s, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
    comm_s += std::chrono::duration<double>(Clock::now() - t0).count();
    return s;
  }

 private:
  MPI_Datatype site_{}, request_{};
};

// This rank's share of a .bin file of float64 pairs: points [first, first + count).
inline std::vector<Site> read_share(Mpi& mpi, const std::string& path, std::uint64_t& n) {
  MPI_File f;
  std::string error;
  if (MPI_File_open(MPI_COMM_WORLD, path.c_str(), MPI_MODE_RDONLY, MPI_INFO_NULL, &f) != MPI_SUCCESS)
    throw Failure("cannot read " + path);
  MPI_Offset bytes = 0;
  MPI_File_get_size(f, &bytes);
  if (bytes % 16 != 0) error = path + ": " + std::to_string(bytes) + " bytes is not a whole number of float64 pairs";
  n = static_cast<std::uint64_t>(bytes) / 16;
  const std::uint64_t first = n * mpi.rank / mpi.size, last = n * (mpi.rank + 1) / mpi.size;
  std::vector<Site> out(last - first);
  // Read through a buffer of 2^20 points, every rank the same number of times (collective
  // calls), so that the raw share is never held beside the sites.
  constexpr std::uint64_t piece = 1u << 20;
  const std::uint64_t pieces = (n / mpi.size + 1 + piece - 1) / piece + 1;
  std::vector<double> raw(2 * std::min(piece, out.size()));
  for (std::uint64_t k = 0; k < pieces; ++k) {
    const std::uint64_t from = std::min(last - first, k * piece), to = std::min(last - first, (k + 1) * piece);
    MPI_File_read_at_all(f, static_cast<MPI_Offset>((first + from) * 16), raw.data(), static_cast<int>(2 * (to - from)),
                         MPI_DOUBLE, MPI_STATUS_IGNORE);
    for (std::uint64_t i = from; i < to; ++i) out[i] = {raw[2 * (i - from)], raw[2 * (i - from) + 1], first + i};
  }
  MPI_File_close(&f);
  if (!error.empty()) throw Failure(error);
  for (std::uint64_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
      throw Failure(path + ": point " + std::to_string(first + i) + " is not finite");
  return out;
}

}  // namespace ridt::mpi
