// The methods, one line each. A method is its own file in this folder, its line here and its
// name beside its enum (include/ridt/ridt.hpp); triangulate() plans and runs it from its entry.
#include <stdexcept>

#include "methods/method.hpp"

namespace ridt::detail {

void insert_walking(DelaunayTds& tds, const Insertion& run);  // methods/serial_walk.cpp
void insert_pessimistic(Kernel& kernel, const Insertion& run);  // methods/pessimistic.cpp
void insert_optimistic(Kernel& kernel, const Insertion& run);  // methods/optimistic.cpp
void insert_batch(Kernel& kernel, const Insertion& run);  // methods/batch.cpp
void insert_partition(DelaunayTds& tds, const Insertion& run);  // methods/partition.cpp

namespace {

// clang-format off
//                                  threaded  keys   on the DAG          walking
constexpr MethodEntry kMethods[] = {
    {Method::Serial,      false,    false,  insert_serial,      insert_walking},
    {Method::Pessimistic, true,     false,  insert_pessimistic, nullptr},
    {Method::Optimistic,  true,     false,  insert_optimistic,  nullptr},
    {Method::Batch,       true,     false,  insert_batch,       nullptr},
    {Method::Partition,   true,     true,   nullptr,            insert_partition},
};
// clang-format on

}  // namespace

std::span<const MethodEntry> methods() { return kMethods; }

const MethodEntry& method_entry(Method method) {
  for (const MethodEntry& m : kMethods)
    if (m.method == method) return m;
  throw InputError("method '" + std::string(to_string(method)) + "' is not registered");
}

}  // namespace ridt::detail
