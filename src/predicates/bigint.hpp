// Exact integers for the predicates' last resort (predicates/exact.cpp, predicates/power_exact.cpp).
//
// Every double is an integer multiple of its unit in the last place; within one predicate call
// all coordinates are integer multiples of the smallest such unit U = 2^emin among them. The
// determinants are homogeneous polynomials in coordinate differences, so their sign equals the
// sign of the same polynomial evaluated on the integers x / U.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace ridt::detail::exact {

// Sign-magnitude integer with a fixed capacity and no heap use.
class BigInt {
 public:
  static constexpr int kCap = 140;  // 4 * 34 limbs for a degree-4 product, plus carries

  BigInt() {}  // the limbs are left uninitialized on purpose: only [0, n_) is ever read

  // x / 2^emin, where x is an integer multiple of 2^emin.
  static BigInt from_double(double x, int emin) {
    BigInt r;
    if (x == 0) return r;
    int e = 0;
    const double f = std::frexp(std::fabs(x), &e);  // |x| = f * 2^e, f in [0.5, 1)
    auto mant = static_cast<std::uint64_t>(std::ldexp(f, 53));
    const int shift = e - 53 - emin;  // >= 0 by the choice of emin
    const int limb = shift / 64, bit = shift % 64;
    for (int i = 0; i < limb; ++i) r.w_[i] = 0;
    r.w_[limb] = mant << bit;
    r.n_ = limb + 1;
    if (bit != 0 && (mant >> (64 - bit)) != 0) r.w_[r.n_++] = mant >> (64 - bit);
    r.neg_ = x < 0;
    return r;
  }

  int sign() const { return n_ == 0 ? 0 : (neg_ ? -1 : 1); }

  // The value as m * 2^(exponent + emin) with |m| in [1, 2^64) (0 for zero), m within a
  // relative 2^-62 of the truth: the top three limbs, each rounded once, the rest dropped.
  double scaled(int emin, int& exponent) const {
    exponent = emin;
    if (n_ == 0) return 0;
    double m = static_cast<double>(w_[n_ - 1]);
    if (n_ >= 2) m += std::ldexp(static_cast<double>(w_[n_ - 2]), -64);
    if (n_ >= 3) m += std::ldexp(static_cast<double>(w_[n_ - 3]), -128);
    exponent += 64 * (n_ - 1);
    return neg_ ? -m : m;
  }

  friend BigInt operator+(const BigInt& a, const BigInt& b) { return add(a, b, b.neg_); }
  friend BigInt operator-(const BigInt& a, const BigInt& b) { return add(a, b, !b.neg_); }

  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    BigInt r;
    if (a.n_ == 0 || b.n_ == 0) return r;
    r.n_ = a.n_ + b.n_;
    std::fill(r.w_, r.w_ + r.n_, 0);
    for (int i = 0; i < a.n_; ++i) {
      unsigned __int128 carry = 0;
      for (int j = 0; j < b.n_; ++j) {
        carry += static_cast<unsigned __int128>(a.w_[i]) * b.w_[j] + r.w_[i + j];
        r.w_[i + j] = static_cast<std::uint64_t>(carry);
        carry >>= 64;
      }
      r.w_[i + b.n_] = static_cast<std::uint64_t>(carry);
    }
    r.trim();
    r.neg_ = a.neg_ != b.neg_;
    return r;
  }

 private:
  void trim() {
    while (n_ > 0 && w_[n_ - 1] == 0) --n_;
    if (n_ == 0) neg_ = false;
  }

  static int compare_magnitude(const BigInt& a, const BigInt& b) {
    if (a.n_ != b.n_) return a.n_ < b.n_ ? -1 : 1;
    for (int i = a.n_ - 1; i >= 0; --i)
      if (a.w_[i] != b.w_[i]) return a.w_[i] < b.w_[i] ? -1 : 1;
    return 0;
  }

  // a + (b with sign b_neg)
  static BigInt add(const BigInt& a, const BigInt& b, bool b_neg) {
    BigInt r;
    if (a.neg_ == b_neg) {
      const BigInt& big = a.n_ >= b.n_ ? a : b;
      const BigInt& small = a.n_ >= b.n_ ? b : a;
      std::uint64_t carry = 0;
      for (int i = 0; i < big.n_; ++i) {
        const std::uint64_t s = big.w_[i] + carry;
        carry = s < carry;
        const std::uint64_t t = i < small.n_ ? s + small.w_[i] : s;
        carry += t < s;
        r.w_[i] = t;
      }
      r.n_ = big.n_;
      if (carry) r.w_[r.n_++] = carry;
      r.neg_ = a.neg_;
      return r;
    }
    const int cmp = compare_magnitude(a, b);
    if (cmp == 0) return r;
    const BigInt& big = cmp > 0 ? a : b;
    const BigInt& small = cmp > 0 ? b : a;
    std::uint64_t borrow = 0;
    for (int i = 0; i < big.n_; ++i) {
      const std::uint64_t sub = (i < small.n_ ? small.w_[i] : 0);
      const std::uint64_t t = big.w_[i] - sub - borrow;
      borrow = (big.w_[i] < sub) || (big.w_[i] - sub < borrow);
      r.w_[i] = t;
    }
    r.n_ = big.n_;
    r.neg_ = cmp > 0 ? a.neg_ : b_neg;
    r.trim();
    return r;
  }

  std::uint64_t w_[kCap];
  int n_ = 0;
  bool neg_ = false;
};

// Exponent of the unit in the last place of x (x != 0): x is an integer multiple of 2^result.
inline int ulp_exponent(double x) {
  int e = 0;
  std::frexp(x, &e);
  return e - 53;
}

inline int min_ulp_exponent(std::initializer_list<double> values) {
  int emin = 1 << 20;
  for (double v : values)
    if (v != 0) emin = std::min(emin, ulp_exponent(v));
  return emin;
}

}  // namespace ridt::detail::exact
