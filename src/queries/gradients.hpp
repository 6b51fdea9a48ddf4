// The cubic's gradients (src/queries/gradients.cpp), solved on a renumbered field: shared by
// estimate_gradients and the cubic's grid call that estimates its own (queries/cubic.cpp).
#pragma once

#include <span>
#include <string>

#include "queries/field.hpp"

namespace ridt::detail {

/// The sweeps' arguments, checked before any work: InputError naming `who` for a tol that is
/// not positive or a maxiter below 1.
inline void check_sweeps(const char* who, double tol, int maxiter) {
  if (!(tol > 0)) throw InputError(std::string(who) + ": tol must be positive");
  if (maxiter < 1) throw InputError(std::string(who) + ": maxiter must be at least 1");
}

/// The minimum-norm network's gradients of each of the field's value components, in its
/// numbering: grad[2 * (v * m + k)] and the number after it are d/dx and d/dy of component k
/// at vertex v (m components; zero at a point in no triangle). Returns the most sweeps a
/// component took, or 0 when one did not settle within maxiter.
int solve_gradients(const Renumbered& field, double tol, int maxiter, unsigned threads, std::span<double> grad);

}  // namespace ridt::detail
