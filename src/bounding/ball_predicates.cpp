// SPDX-License-Identifier: BSL-1.0
// Exact fallbacks of the side-of-ball tests (include/locus/bounding/detail/ball_predicates.hpp).
//
// Every finite double is an integer times 2^e with e >= -1074; shifting all inputs of one test
// to their smallest exponent makes them integers, and the test polynomial is then evaluated in
// fixed-capacity signed big integers, exactly. The capacity covers degree 6 in values spanning
// the whole double range (6 * (2098 + 53) bits plus carries). These paths run only when the
// floating-point filter cannot decide, so they favour simplicity over speed.

#include <locus/bounding/detail/ball_predicates.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace locus::detail {
namespace {

constexpr int kLimbs = 420;  // 32-bit limbs: 13440 bits

struct Big {
  int size = 0;  // limbs in use (no leading zero limbs)
  bool negative = false;
  std::uint32_t limb[kLimbs];
};

void trim(Big& a) noexcept {
  while (a.size > 0 && a.limb[a.size - 1] == 0) --a.size;
  if (a.size == 0) a.negative = false;
}

int compare_magnitude(const Big& a, const Big& b) noexcept {
  if (a.size != b.size) return a.size < b.size ? -1 : 1;
  for (int i = a.size - 1; i >= 0; --i)
    if (a.limb[i] != b.limb[i]) return a.limb[i] < b.limb[i] ? -1 : 1;
  return 0;
}

// r = |a| + |b| (r may alias neither).
void add_magnitude(const Big& a, const Big& b, Big& r) noexcept {
  const int n = std::max(a.size, b.size);
  std::uint64_t carry = 0;
  for (int i = 0; i < n; ++i) {
    const std::uint64_t s = carry + (i < a.size ? a.limb[i] : 0u) + (i < b.size ? b.limb[i] : 0u);
    r.limb[i] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
  r.size = n;
  if (carry != 0 && n < kLimbs) r.limb[r.size++] = static_cast<std::uint32_t>(carry);
}

// r = |a| - |b| with |a| >= |b|.
void sub_magnitude(const Big& a, const Big& b, Big& r) noexcept {
  std::int64_t borrow = 0;
  for (int i = 0; i < a.size; ++i) {
    std::int64_t d = static_cast<std::int64_t>(a.limb[i]) - borrow -
                     static_cast<std::int64_t>(i < b.size ? b.limb[i] : 0u);
    borrow = d < 0 ? 1 : 0;
    if (d < 0) d += (std::int64_t{1} << 32);
    r.limb[i] = static_cast<std::uint32_t>(d);
  }
  r.size = a.size;
  trim(r);
}

// r = a + s * b, s = +1 or -1 (r may alias neither).
void add(const Big& a, const Big& b, bool subtract, Big& r) noexcept {
  const bool bneg = subtract ? !b.negative : b.negative;
  if (a.negative == bneg) {
    add_magnitude(a, b, r);
    r.negative = a.negative;
  } else if (compare_magnitude(a, b) >= 0) {
    sub_magnitude(a, b, r);
    r.negative = a.negative;
  } else {
    sub_magnitude(b, a, r);
    r.negative = bneg;
  }
  trim(r);
}

void mul(const Big& a, const Big& b, Big& r) noexcept {
  if (a.size == 0 || b.size == 0) {
    r.size = 0;
    r.negative = false;
    return;
  }
  const int n = std::min(a.size + b.size, kLimbs);
  std::memset(r.limb, 0, sizeof(std::uint32_t) * static_cast<std::size_t>(n));
  for (int i = 0; i < a.size; ++i) {
    std::uint64_t carry = 0;
    const std::uint64_t ai = a.limb[i];
    int j = 0;
    for (; j < b.size && i + j < n; ++j) {
      const std::uint64_t t = ai * b.limb[j] + r.limb[i + j] + carry;
      r.limb[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    if (i + j < n) r.limb[i + j] = static_cast<std::uint32_t>(carry);
  }
  r.size = n;
  r.negative = a.negative != b.negative;
  trim(r);
}

// The exponent e with x = m 2^e, m an odd-or-53-bit integer (frexp based); x != 0, finite.
int low_exponent(double x) noexcept {
  int k = 0;
  (void)std::frexp(x, &k);
  return k - 53;
}

// x = m 2^(e) -> the integer m 2^(e - emin).
void from_double(double x, int emin, Big& r) noexcept {
  r.size = 0;
  r.negative = false;
  if (x == 0.0) return;
  int k = 0;
  const double f = std::frexp(std::abs(x), &k);
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));  // exact: 53-bit integer
  const int shift = (k - 53) - emin;                             // >= 0
  const int word = shift / 32, bit = shift % 32;
  std::memset(r.limb, 0, sizeof(std::uint32_t) * static_cast<std::size_t>(word + 4));
  const std::uint64_t lo = m << bit, hi = bit == 0 ? 0 : m >> (64 - bit);  // m 2^bit < 2^85
  r.limb[word] = static_cast<std::uint32_t>(lo);
  r.limb[word + 1] = static_cast<std::uint32_t>(lo >> 32);
  r.limb[word + 2] = static_cast<std::uint32_t>(hi);
  r.limb[word + 3] = static_cast<std::uint32_t>(hi >> 32);
  r.size = word + 4;
  r.negative = x < 0.0;
  trim(r);
}

int common_exponent(const double* v, int n) noexcept {
  int emin = 0;
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (v[i] == 0.0) continue;
    const int e = low_exponent(v[i]);
    if (!any || e < emin) emin = e;
    any = true;
  }
  return emin;
}

bool all_finite(const double* v, int n) noexcept {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

Sign sign_of_big(const Big& a) noexcept {
  if (a.size == 0) return Sign::zero;
  return a.negative ? Sign::negative : Sign::positive;
}

// Scratch for one evaluation: a few dozen big integers, too large for comfortable stack use
// under sanitizers, so they live in a per-thread buffer.
struct Scratch {
  Big v[48];
};
Scratch& scratch() noexcept {
  thread_local Scratch s;
  return s;
}

}  // namespace

Sign diametral_side_exact(const double* p, const double* a, const double* b, int n) noexcept {
  double all[9];
  for (int i = 0; i < n; ++i) {
    all[i] = p[i];
    all[n + i] = a[i];
    all[2 * n + i] = b[i];
  }
  if (!all_finite(all, 3 * n)) return Sign::zero;
  const int emin = common_exponent(all, 3 * n);
  Big* v = scratch().v;
  Big& sum = v[0];
  Big& tmp = v[1];
  sum.size = 0;
  sum.negative = false;
  for (int i = 0; i < n; ++i) {
    from_double(p[i], emin, v[2]);
    from_double(a[i], emin, v[3]);
    from_double(b[i], emin, v[4]);
    add(v[2], v[3], true, v[5]);  // p - a
    add(v[2], v[4], true, v[6]);  // p - b
    mul(v[5], v[6], v[7]);
    add(sum, v[7], false, tmp);
    std::swap(sum, tmp);
  }
  return sign_of_big(sum);
}

Sign dot_differences_exact(const double* a, const double* b, const double* c, const double* d,
                           int n) noexcept {
  double all[12];
  for (int i = 0; i < n; ++i) {
    all[i] = a[i];
    all[n + i] = b[i];
    all[2 * n + i] = c[i];
    all[3 * n + i] = d[i];
  }
  if (!all_finite(all, 4 * n)) return Sign::zero;
  const int emin = common_exponent(all, 4 * n);
  Big* v = scratch().v;
  Big& sum = v[0];
  Big& tmp = v[1];
  sum.size = 0;
  sum.negative = false;
  for (int i = 0; i < n; ++i) {
    from_double(a[i], emin, v[2]);
    from_double(b[i], emin, v[3]);
    from_double(c[i], emin, v[4]);
    from_double(d[i], emin, v[8]);
    add(v[3], v[2], true, v[5]);  // b - a
    add(v[8], v[4], true, v[6]);  // d - c
    mul(v[5], v[6], v[7]);
    add(sum, v[7], false, tmp);
    std::swap(sum, tmp);
  }
  return sign_of_big(sum);
}

Sign circumcircle_sphere_side_exact(const double* a, const double* b, const double* c,
                                    const double* p) noexcept {
  double all[12];
  for (int i = 0; i < 3; ++i) {
    all[i] = a[i];
    all[3 + i] = b[i];
    all[6 + i] = c[i];
    all[9 + i] = p[i];
  }
  if (!all_finite(all, 12)) return Sign::zero;
  const int emin = common_exponent(all, 12);
  Big* v = scratch().v;
  // v[0..2] u, v[3..5] vv, v[6..8] q, v[9..11] w; temporaries from 12 on.
  for (int i = 0; i < 3; ++i) {
    from_double(a[i], emin, v[12]);
    from_double(b[i], emin, v[13]);
    from_double(c[i], emin, v[14]);
    from_double(p[i], emin, v[15]);
    add(v[13], v[12], true, v[i]);
    add(v[14], v[12], true, v[3 + i]);
    add(v[15], v[12], true, v[6 + i]);
  }
  auto cross3 = [&](int x, int y, int out) {  // out[0..2] = x[0..2] x y[0..2]
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      mul(v[x + j], v[y + k], v[40]);
      mul(v[x + k], v[y + j], v[41]);
      add(v[40], v[41], true, v[out + i]);
    }
  };
  auto dot3 = [&](int x, int y, int out) {
    mul(v[x], v[y], v[out]);
    for (int i = 1; i < 3; ++i) {
      mul(v[x + i], v[y + i], v[40]);
      add(v[out], v[40], false, v[41]);
      std::swap(v[out], v[41]);
    }
  };
  cross3(0, 3, 9);               // w = u x v
  cross3(3, 9, 16);              // v x w        -> 16..18
  cross3(9, 0, 19);              // w x u        -> 19..21
  dot3(0, 0, 22);                // |u|^2
  dot3(3, 3, 23);                // |v|^2
  dot3(6, 6, 24);                // |q|^2
  dot3(9, 9, 25);                // |w|^2
  for (int i = 0; i < 3; ++i) {  // X -> 26..28
    mul(v[22], v[16 + i], v[40]);
    mul(v[23], v[19 + i], v[41]);
    add(v[40], v[41], false, v[26 + i]);
  }
  dot3(6, 26, 29);           // q . X
  mul(v[25], v[24], v[30]);  // |w|^2 |q|^2
  add(v[30], v[29], true, v[31]);
  return sign_of_big(v[31]);
}

}  // namespace locus::detail
