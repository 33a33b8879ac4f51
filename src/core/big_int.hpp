// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact signed integers of any size (private to src/; core's one integer engine, beside the
// floating-point expansions of expansion.hpp, which cannot span the double exponent range).
//
// Two layers. `limbs::` holds the arithmetic, written once, on magnitudes stored as spans of
// 32-bit limbs, least significant first: compare, add, sub, mul, mul_small, shift_left,
// shift_right, divmod_small, divmod (Knuth's algorithm D). Results are trimmed (no leading zero
// limb; 0 has length 0); each routine states the output capacity it needs and which outputs may
// alias an input. Over it, BasicBigInt<Store> is a sign-magnitude value type with the usual
// operators, divmod (truncating, like C++ `/` and `%`), divide_exact, gcd and a correctly
// rounded to_double, with two owners of its limbs:
//   BigInt<L>    L limbs inline, never allocates, noexcept. Every operation needs the limbs of
//                its schoolbook result (a + b: max(|a|, |b|) + 1 limbs, a * b: |a| + |b|); the
//                caller proves its bound, and exceeding it is a programming error reported by
//                locus::detail::assert_failed (checked in every build, never an overflow).
//   DynBigInt    limbs in a std::vector, unbounded; operations may throw std::bad_alloc.
// Doubles enter exactly: from_double(x, shift) is x * 2^shift, which must be an integer;
// low_exponent(x) is an e with x = m 2^e, m an integer below 2^53, so that
// from_double(x, -e_min) is exact for every x of a set whose least low_exponent is e_min.
// Cost: schoolbook, O(n m) limb operations for products and divisions; no global state.

#include <locus/config.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace locus::detail {

using Limb = std::uint32_t;
inline constexpr int limb_bits = 32;

namespace limbs {

using Wide = std::uint64_t;
using In = std::span<const Limb>;
using Out = std::span<Limb>;

/// The length of a without its leading zero limbs.
[[nodiscard]] inline std::size_t trimmed(In a) noexcept {
  std::size_t n = a.size();
  while (n > 0 && a[n - 1] == 0) --n;
  return n;
}

/// Number of significant bits of a (0 for 0).
[[nodiscard]] inline std::size_t bit_length(In a) noexcept {
  const std::size_t n = trimmed(a);
  if (n == 0) return 0;
  return n * limb_bits - static_cast<std::size_t>(std::countl_zero(a[n - 1]));
}

/// Sign of a - b: -1, 0 or +1.
[[nodiscard]] inline int compare(In a, In b) noexcept {
  const std::size_t an = trimmed(a), bn = trimmed(b);
  if (an != bn) return an < bn ? -1 : 1;
  for (std::size_t i = an; i-- > 0;)
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  return 0;
}

/// r = a + b. Capacity: max(|a|, |b|) + 1 limbs. r may be a or b (same first limb).
inline std::size_t add(In a, In b, Out r) noexcept {
  if (a.size() < b.size()) std::swap(a, b);
  LOCUS_ASSERT(r.size() > a.size(), "limbs::add: output capacity");
  Wide carry = 0;
  std::size_t i = 0;
  for (; i < b.size(); ++i) {
    const Wide s = Wide{a[i]} + b[i] + carry;
    r[i] = static_cast<Limb>(s);
    carry = s >> limb_bits;
  }
  for (; i < a.size(); ++i) {
    const Wide s = Wide{a[i]} + carry;
    r[i] = static_cast<Limb>(s);
    carry = s >> limb_bits;
  }
  r[i] = static_cast<Limb>(carry);
  return trimmed(r.first(i + 1));
}

/// r = a - b, requires a >= b. Capacity: |a| limbs. r may be a or b.
inline std::size_t sub(In a, In b, Out r) noexcept {
  const std::size_t bn = trimmed(b);
  LOCUS_ASSERT(compare(a, b) >= 0 && r.size() >= a.size(), "limbs::sub: a < b or capacity");
  Wide borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Wide d = Wide{a[i]} - (i < bn ? b[i] : 0u) - borrow;
    r[i] = static_cast<Limb>(d);
    borrow = (d >> limb_bits) != 0 ? 1 : 0;
  }
  return trimmed(r.first(a.size()));
}

/// r = a * m for one limb m. Capacity: |a| + 1 limbs. r may be a.
inline std::size_t mul_small(In a, Limb m, Out r) noexcept {
  LOCUS_ASSERT(r.size() > a.size(), "limbs::mul_small: output capacity");
  Wide carry = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Wide t = Wide{a[i]} * m + carry;
    r[i] = static_cast<Limb>(t);
    carry = t >> limb_bits;
  }
  r[a.size()] = static_cast<Limb>(carry);
  return trimmed(r.first(a.size() + 1));
}

/// r = a * b (schoolbook). Capacity: |a| + |b| limbs. r must not overlap a or b.
inline std::size_t mul(In a, In b, Out r) noexcept {
  const std::size_t an = trimmed(a), bn = trimmed(b);
  if (an == 0 || bn == 0) return 0;
  LOCUS_ASSERT(r.size() >= an + bn, "limbs::mul: output capacity");
  std::fill_n(r.begin(), an + bn, Limb{0});
  for (std::size_t i = 0; i < an; ++i) {
    const Wide ai = a[i];
    Wide carry = 0;
    for (std::size_t j = 0; j < bn; ++j) {
      const Wide t = ai * b[j] + r[i + j] + carry;  // < 2^64: (2^32-1)^2 + 2 (2^32-1)
      r[i + j] = static_cast<Limb>(t);
      carry = t >> limb_bits;
    }
    r[i + bn] = static_cast<Limb>(carry);
  }
  return trimmed(r.first(an + bn));
}

/// r = a * 2^bits. Capacity: |a| + bits / 32 + 1 limbs. r may be a.
inline std::size_t shift_left(In a, std::size_t bits, Out r) noexcept {
  const std::size_t an = trimmed(a);
  if (an == 0) return 0;
  const std::size_t w = bits / limb_bits;
  const int s = static_cast<int>(bits % limb_bits);
  LOCUS_ASSERT(r.size() > an + w, "limbs::shift_left: output capacity");
  // Top down, so that in place every limb is read before it is overwritten.
  if (s == 0) {
    r[an + w] = 0;
    for (std::size_t i = an; i-- > 0;) r[i + w] = a[i];
  } else {
    r[an + w] = a[an - 1] >> (limb_bits - s);
    for (std::size_t i = an - 1; i > 0; --i)
      r[i + w] = static_cast<Limb>((a[i] << s) | (a[i - 1] >> (limb_bits - s)));
    r[w] = static_cast<Limb>(a[0] << s);
  }
  std::fill_n(r.begin(), w, Limb{0});
  return trimmed(r.first(an + w + 1));
}

/// r = floor(a / 2^bits). Capacity: |a| - bits / 32 limbs (none if that is <= 0). r may be a.
inline std::size_t shift_right(In a, std::size_t bits, Out r) noexcept {
  const std::size_t an = trimmed(a);
  const std::size_t w = bits / limb_bits;
  if (w >= an) return 0;
  const int s = static_cast<int>(bits % limb_bits);
  const std::size_t n = an - w;
  LOCUS_ASSERT(r.size() >= n, "limbs::shift_right: output capacity");
  for (std::size_t i = 0; i < n; ++i) {
    const Limb lo = a[i + w] >> s;
    const Limb hi =
        (s == 0 || i + 1 == n) ? 0u : static_cast<Limb>(a[i + w + 1] << (limb_bits - s));
    r[i] = lo | hi;
  }
  return trimmed(r.first(n));
}

/// q = floor(a / d) and returns a mod d, for one nonzero limb d. Capacity of q: |a| limbs
/// (written in full, untrimmed). q may be a.
inline Limb divmod_small(In a, Limb d, Out q) noexcept {
  LOCUS_ASSERT(d != 0 && q.size() >= a.size(), "limbs::divmod_small: d == 0 or capacity");
  Wide rem = 0;
  for (std::size_t i = a.size(); i-- > 0;) {
    const Wide cur = (rem << limb_bits) | a[i];
    q[i] = static_cast<Limb>(cur / d);
    rem = cur % d;
  }
  return static_cast<Limb>(rem);
}

/// Trimmed lengths of divmod's quotient and remainder.
struct DivSizes {
  std::size_t quotient;
  std::size_t remainder;
};

/// q = floor(a / b), r = a - q b for b != 0 (Knuth, TAOCP vol. 2, 4.3.1, algorithm D).
/// Capacities: q |a| - |b| + 1 limbs (at least 1), r |b| limbs, scratch |a| + |b| + 2 limbs.
/// q, r and scratch must not overlap each other, a or b.
inline DivSizes divmod(In a, In b, Out q, Out r, Out scratch) noexcept {
  const std::size_t an = trimmed(a), bn = trimmed(b);
  LOCUS_ASSERT(bn > 0, "limbs::divmod: division by zero");
  LOCUS_ASSERT(r.size() >= bn, "limbs::divmod: remainder capacity");
  if (an < bn) {
    std::copy_n(a.begin(), an, r.begin());
    return {0, an};
  }
  LOCUS_ASSERT(q.size() >= an - bn + 1, "limbs::divmod: quotient capacity");
  if (bn == 1) {
    const Limb rem = divmod_small(a.first(an), b[0], q);
    r[0] = rem;
    return {trimmed(q.first(an)), rem != 0 ? 1u : 0u};
  }
  LOCUS_ASSERT(scratch.size() >= an + bn + 2, "limbs::divmod: scratch capacity");
  // Normalise: shift both so that the divisor's top limb has its top bit set; then the
  // estimate qhat from the top two limbs of the remainder is at most 2 too large.
  const int s = std::countl_zero(b[bn - 1]);
  const Out u = scratch.first(an + 1);
  const Out v = scratch.subspan(an + 1, bn);
  std::fill(u.begin(), u.end(), Limb{0});
  (void)shift_left(a.first(an), static_cast<std::size_t>(s), u);
  (void)shift_left(b.first(bn), static_cast<std::size_t>(s), scratch.subspan(an + 1, bn + 1));
  const Wide base = Wide{1} << limb_bits;
  const Wide vtop = v[bn - 1], vnext = v[bn - 2];
  for (std::size_t j = an - bn + 1; j-- > 0;) {
    const Wide num = (Wide{u[j + bn]} << limb_bits) | u[j + bn - 1];
    Wide qhat = num / vtop, rhat = num % vtop;
    while (qhat >= base || qhat * vnext > ((rhat << limb_bits) | u[j + bn - 2])) {
      --qhat;
      rhat += vtop;
      if (rhat >= base) break;
    }
    // u[j .. j + bn] -= qhat * v, in signed 64-bit steps.
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < bn; ++i) {
      const Wide p = qhat * v[i];
      const std::int64_t t =
          static_cast<std::int64_t>(u[i + j]) - borrow - static_cast<std::int64_t>(p & 0xffffffffu);
      u[i + j] = static_cast<Limb>(t);
      borrow = static_cast<std::int64_t>(p >> limb_bits) - (t >> limb_bits);
    }
    const std::int64_t t = static_cast<std::int64_t>(u[j + bn]) - borrow;
    u[j + bn] = static_cast<Limb>(t);
    if (t < 0) {  // qhat was one too large (probability about 2 / 2^32): add v back.
      --qhat;
      Wide carry = 0;
      for (std::size_t i = 0; i < bn; ++i) {
        const Wide sum = Wide{u[i + j]} + v[i] + carry;
        u[i + j] = static_cast<Limb>(sum);
        carry = sum >> limb_bits;
      }
      u[j + bn] = static_cast<Limb>(u[j + bn] + carry);
    }
    q[j] = static_cast<Limb>(qhat);
  }
  const std::size_t rn = shift_right(u.first(bn), static_cast<std::size_t>(s), r);
  return {trimmed(q.first(an - bn + 1)), rn};
}

}  // namespace limbs

/// Limbs held inline: L of them, no allocation.
template <std::size_t L>
struct FixedLimbs {
  static_assert(L >= 2, "an int64 takes two limbs");
  static constexpr bool fixed = true;
  using Scratch = FixedLimbs<2 * L + 2>;  // divmod's working space for operands of L limbs
  Limb limb[L];  // deliberately uninitialised: only the first size() limbs are ever read

  std::span<Limb> reserve(std::size_t n) noexcept {
    if (n > L) assert_failed("n <= L", "BigInt<L>: capacity exceeded", __FILE__, __LINE__);
    return {limb, L};
  }
  [[nodiscard]] const Limb* data() const noexcept { return limb; }
  [[nodiscard]] Limb* data() noexcept { return limb; }
  void take(FixedLimbs& o, std::size_t n) noexcept { std::copy_n(o.limb, n, limb); }
};

/// Limbs in a vector, unbounded.
struct VectorLimbs {
  static constexpr bool fixed = false;
  using Scratch = VectorLimbs;
  std::vector<Limb> limb;

  std::span<Limb> reserve(std::size_t n) {
    if (limb.size() < n) limb.resize(std::max(n, 2 * limb.size()));
    return {limb.data(), limb.size()};
  }
  [[nodiscard]] const Limb* data() const noexcept { return limb.data(); }
  [[nodiscard]] Limb* data() noexcept { return limb.data(); }
  void take(VectorLimbs& o, std::size_t) noexcept { limb.swap(o.limb); }
};

/// |x| = mantissa 2^exponent exactly, mantissa an integer below 2^53 (x finite; read from the
/// bits: exponent in [-1074, 971], -1074 for subnormals and zero).
struct DoubleParts {
  std::uint64_t mantissa;
  int exponent;
};
[[nodiscard]] constexpr DoubleParts decompose(double x) noexcept {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ffu);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0) return {fraction, -1074};
  return {fraction | (std::uint64_t{1} << 52), biased - 1075};
}

/// An e with x = m 2^e, m an integer, |m| < 2^53 (decompose(x).exponent); x finite.
[[nodiscard]] constexpr int low_exponent(double x) noexcept { return decompose(x).exponent; }

/// A signed integer in sign-magnitude form over the limb routines; see the header comment.
template <class Store>
class BasicBigInt {
 public:
  static constexpr bool fixed = Store::fixed;

  BasicBigInt() noexcept {}
  /// The integer v.
  BasicBigInt(std::int64_t v) noexcept(fixed) {  // NOLINT: implicit, like the built-in types
    const std::uint64_t m =
        v < 0 ? 0u - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    const std::span<Limb> r = s_.reserve(2);
    r[0] = static_cast<Limb>(m);
    r[1] = static_cast<Limb>(m >> limb_bits);
    n_ = limbs::trimmed(r.first(2));
    neg_ = v < 0;
  }
  BasicBigInt(const BasicBigInt& o) noexcept(fixed) : n_(o.n_), neg_(o.neg_) {
    std::copy_n(o.s_.data(), n_, s_.reserve(n_).begin());
  }
  BasicBigInt(BasicBigInt&& o) noexcept : n_(o.n_), neg_(o.neg_) { s_.take(o.s_, n_); }
  BasicBigInt& operator=(const BasicBigInt& o) noexcept(fixed) {
    if (this != &o) {
      std::copy_n(o.s_.data(), o.n_, s_.reserve(o.n_).begin());
      n_ = o.n_;
      neg_ = o.neg_;
    }
    return *this;
  }
  BasicBigInt& operator=(BasicBigInt&& o) noexcept {
    if (this != &o) {
      s_.take(o.s_, o.n_);
      n_ = o.n_;
      neg_ = o.neg_;
    }
    return *this;
  }
  ~BasicBigInt() = default;

  /// x * 2^shift exactly; x finite and x * 2^shift an integer (asserted).
  [[nodiscard]] static BasicBigInt from_double(double x, int shift = 0) noexcept(fixed) {
    BasicBigInt r;
    LOCUS_ASSERT(std::isfinite(x), "BigInt::from_double: non-finite input");
    if (x == 0.0 || !std::isfinite(x)) return r;
    const DoubleParts parts = decompose(x);
    const std::uint64_t m = parts.mantissa;
    const int e = parts.exponent + shift;
    if (e >= 0) {
      const Limb ml[2] = {static_cast<Limb>(m), static_cast<Limb>(m >> limb_bits)};
      const auto ue = static_cast<std::size_t>(e);
      r.n_ = limbs::shift_left(ml, ue, r.s_.reserve(2 + ue / limb_bits + 1));
    } else {
      LOCUS_ASSERT(-e < 64 && (m & ((std::uint64_t{1} << -e) - 1)) == 0,
                   "BigInt::from_double: x * 2^shift is not an integer");
      const std::uint64_t v = -e < 64 ? m >> -e : 0u;
      const std::span<Limb> out = r.s_.reserve(2);
      out[0] = static_cast<Limb>(v);
      out[1] = static_cast<Limb>(v >> limb_bits);
      r.n_ = limbs::trimmed(out.first(2));
    }
    r.neg_ = x < 0.0 && r.n_ != 0;
    return r;
  }
  /// The integer with magnitude m (least significant limb first) and the given sign.
  [[nodiscard]] static BasicBigInt from_limbs(std::span<const Limb> m,
                                              bool negative) noexcept(fixed) {
    BasicBigInt r;
    const std::size_t n = limbs::trimmed(m);
    std::copy_n(m.begin(), n, r.s_.reserve(n).begin());
    r.n_ = n;
    r.neg_ = negative && n != 0;
    return r;
  }

  /// -1, 0 or +1.
  [[nodiscard]] int sign() const noexcept { return n_ == 0 ? 0 : (neg_ ? -1 : 1); }
  [[nodiscard]] bool is_zero() const noexcept { return n_ == 0; }
  [[nodiscard]] bool is_negative() const noexcept { return neg_; }
  /// The magnitude, least significant limb first, trimmed.
  [[nodiscard]] std::span<const Limb> magnitude() const noexcept { return {s_.data(), n_}; }
  /// Significant bits of the magnitude (0 for 0).
  [[nodiscard]] std::size_t bit_length() const noexcept { return limbs::bit_length(magnitude()); }
  /// The nearest double (ties to even); +-infinity beyond the double range.
  [[nodiscard]] double to_double() const noexcept {
    const std::size_t bits = bit_length();
    if (bits == 0) return 0.0;
    std::uint64_t top = 0;
    int scale = 0;
    if (bits <= 64) {
      for (std::size_t i = n_; i-- > 0;) top = (top << limb_bits) | s_.data()[i];
    } else {
      // The top 64 bits, with any nonzero bit below them folded into the last one (a sticky
      // bit): converting those 64 bits rounds exactly as the full value would.
      const std::size_t drop = bits - 64;
      const std::size_t w = drop / limb_bits;
      const int s = static_cast<int>(drop % limb_bits);
      Limb window[3] = {0, 0, 0};
      for (std::size_t i = 0; i < 3 && w + i < n_; ++i) window[i] = s_.data()[w + i];
      const std::uint64_t lo = (std::uint64_t{window[1]} << limb_bits) | window[0];
      top = s == 0 ? lo : (lo >> s) | (std::uint64_t{window[2]} << (64 - s));
      bool sticky = s != 0 && (window[0] & ((Limb{1} << s) - 1)) != 0;
      for (std::size_t i = 0; i < w && !sticky; ++i) sticky = s_.data()[i] != 0;
      top |= sticky ? 1u : 0u;
      scale = static_cast<int>(std::min<std::size_t>(drop, std::size_t{1} << 20));  // inf beyond
    }
    const double d = std::ldexp(static_cast<double>(top), scale);
    return neg_ ? -d : d;
  }

  [[nodiscard]] BasicBigInt operator-() const noexcept(fixed) {
    BasicBigInt r(*this);
    r.neg_ = !r.neg_ && r.n_ != 0;
    return r;
  }
  [[nodiscard]] friend BasicBigInt abs(BasicBigInt a) noexcept(fixed) {
    a.neg_ = false;
    return a;
  }

  BasicBigInt& operator+=(const BasicBigInt& o) noexcept(fixed) { return add_signed(o, o.neg_); }
  BasicBigInt& operator-=(const BasicBigInt& o) noexcept(fixed) {
    return add_signed(o, !o.neg_ && o.n_ != 0);
  }
  BasicBigInt& operator*=(const BasicBigInt& o) noexcept(fixed) {
    const bool neg = neg_ != o.neg_;
    if (n_ == 0 || o.n_ == 0) {
      n_ = 0;
      neg_ = false;
    } else if (o.n_ == 1 && this != &o) {
      const std::span<Limb> r = s_.reserve(n_ + 1);  // before reading: a vector may move
      n_ = limbs::mul_small(std::span<const Limb>(r.data(), n_), o.s_.data()[0], r);
      neg_ = neg;
    } else {
      BasicBigInt r;
      r.n_ = limbs::mul(magnitude(), o.magnitude(), r.s_.reserve(n_ + o.n_));
      r.neg_ = neg;
      *this = std::move(r);
    }
    return *this;
  }
  /// Multiplication by 2^bits.
  BasicBigInt& operator<<=(std::size_t bits) noexcept(fixed) {
    if (n_ != 0) {
      const std::span<Limb> r = s_.reserve(n_ + bits / limb_bits + 1);
      n_ = limbs::shift_left(std::span<const Limb>(r.data(), n_), bits, r);
    }
    return *this;
  }
  /// Division by 2^bits, truncated toward zero.
  BasicBigInt& operator>>=(std::size_t bits) noexcept {
    n_ = limbs::shift_right(magnitude(), bits, std::span<Limb>(s_.data(), n_));
    neg_ = neg_ && n_ != 0;
    return *this;
  }

  [[nodiscard]] friend BasicBigInt operator+(BasicBigInt a, const BasicBigInt& b) noexcept(fixed) {
    return std::move(a += b);
  }
  [[nodiscard]] friend BasicBigInt operator-(BasicBigInt a, const BasicBigInt& b) noexcept(fixed) {
    return std::move(a -= b);
  }
  [[nodiscard]] friend BasicBigInt operator*(const BasicBigInt& a,
                                             const BasicBigInt& b) noexcept(fixed) {
    BasicBigInt r;
    if (a.n_ == 0 || b.n_ == 0) return r;
    r.n_ = limbs::mul(a.magnitude(), b.magnitude(), r.s_.reserve(a.n_ + b.n_));
    r.neg_ = a.neg_ != b.neg_;
    return r;
  }
  [[nodiscard]] friend BasicBigInt operator<<(BasicBigInt a, std::size_t bits) noexcept(fixed) {
    return std::move(a <<= bits);
  }
  [[nodiscard]] friend BasicBigInt operator>>(BasicBigInt a, std::size_t bits) noexcept(fixed) {
    return std::move(a >>= bits);
  }

  /// Sign of a - b.
  [[nodiscard]] friend int compare(const BasicBigInt& a, const BasicBigInt& b) noexcept {
    if (a.sign() != b.sign()) return a.sign() < b.sign() ? -1 : 1;
    const int m = limbs::compare(a.magnitude(), b.magnitude());
    return a.neg_ ? -m : m;
  }
  [[nodiscard]] friend std::strong_ordering operator<=>(const BasicBigInt& a,
                                                        const BasicBigInt& b) noexcept {
    return compare(a, b) <=> 0;
  }
  [[nodiscard]] friend bool operator==(const BasicBigInt& a, const BasicBigInt& b) noexcept {
    return compare(a, b) == 0;
  }

  struct DivMod;
  /// Quotient truncated toward zero and remainder with the sign of a (C++'s / and %); b != 0.
  [[nodiscard]] friend DivMod divmod(const BasicBigInt& a, const BasicBigInt& b) noexcept(fixed) {
    DivMod out;
    const std::size_t qcap = a.n_ >= b.n_ ? a.n_ - b.n_ + 1 : 1;
    typename Store::Scratch scratch;
    const limbs::DivSizes n = limbs::divmod(
        a.magnitude(), b.magnitude(), out.quotient.s_.reserve(qcap),
        out.remainder.s_.reserve(std::max<std::size_t>(b.n_, 1)), scratch.reserve(a.n_ + b.n_ + 2));
    out.quotient.n_ = n.quotient;
    out.quotient.neg_ = (a.neg_ != b.neg_) && n.quotient != 0;
    out.remainder.n_ = n.remainder;
    out.remainder.neg_ = a.neg_ && n.remainder != 0;
    return out;
  }
  [[nodiscard]] friend BasicBigInt operator/(const BasicBigInt& a,
                                             const BasicBigInt& b) noexcept(fixed) {
    return divmod(a, b).quotient;
  }
  [[nodiscard]] friend BasicBigInt operator%(const BasicBigInt& a,
                                             const BasicBigInt& b) noexcept(fixed) {
    return divmod(a, b).remainder;
  }
  /// a / b where b divides a (asserted).
  [[nodiscard]] friend BasicBigInt divide_exact(const BasicBigInt& a,
                                                const BasicBigInt& b) noexcept(fixed) {
    DivMod d = divmod(a, b);
    LOCUS_ASSERT(d.remainder.is_zero(), "divide_exact: b does not divide a");
    return std::move(d.quotient);
  }
  /// The greatest common divisor, >= 0 (gcd(0, 0) = 0). Euclid's algorithm.
  [[nodiscard]] friend BasicBigInt gcd(BasicBigInt a, BasicBigInt b) noexcept(fixed) {
    a.neg_ = false;
    b.neg_ = false;
    while (!b.is_zero()) {
      BasicBigInt r = divmod(a, b).remainder;
      a = std::move(b);
      b = std::move(r);
    }
    return a;
  }

  /// Decimal digits, with a leading '-' when negative.
  [[nodiscard]] std::string to_string() const {
    if (n_ == 0) return "0";
    std::vector<Limb> m(s_.data(), s_.data() + n_);
    std::string digits;
    std::size_t n = n_;
    while (n > 0) {
      Limb rem = limbs::divmod_small(std::span<const Limb>(m.data(), n), 1000000000u,
                                     std::span<Limb>(m.data(), n));
      n = limbs::trimmed(std::span<const Limb>(m.data(), n));
      for (int i = 0; i < 9 && (n > 0 || rem != 0); ++i) {
        digits.push_back(static_cast<char>('0' + rem % 10));
        rem /= 10;
      }
    }
    if (neg_) digits.push_back('-');
    std::reverse(digits.begin(), digits.end());
    return digits;
  }

 private:
  // this += (negate_o ? -|o| : |o|), sign carried by negate_o.
  BasicBigInt& add_signed(const BasicBigInt& o, bool o_negative) noexcept(fixed) {
    if (o.n_ == 0) return *this;
    if (n_ == 0 || neg_ == o_negative) {
      const bool neg = n_ == 0 ? o_negative : neg_;
      const std::span<Limb> r = s_.reserve(std::max(n_, o.n_) + 1);
      n_ = limbs::add(std::span<const Limb>(r.data(), n_), o.magnitude(), r);
      neg_ = neg;
      return *this;
    }
    const int c = limbs::compare(magnitude(), o.magnitude());
    if (c == 0) {
      n_ = 0;
      neg_ = false;
    } else if (c > 0) {
      n_ = limbs::sub(magnitude(), o.magnitude(), std::span<Limb>(s_.data(), n_));
    } else {
      const std::span<Limb> r = s_.reserve(o.n_);
      n_ = limbs::sub(o.magnitude(), std::span<const Limb>(r.data(), n_), r);
      neg_ = o_negative;
    }
    return *this;
  }

  std::size_t n_ = 0;  // limbs in use, trimmed
  bool neg_ = false;   // never true for 0
  Store s_;
};

template <class Store>
struct BasicBigInt<Store>::DivMod {
  BasicBigInt quotient;
  BasicBigInt remainder;
};

/// Fixed-capacity integer of L 32-bit limbs (no allocation).
template <std::size_t L>
using BigInt = BasicBigInt<FixedLimbs<L>>;
/// Unbounded integer (vector-backed).
using DynBigInt = BasicBigInt<VectorLimbs>;

}  // namespace locus::detail
