// SPDX-License-Identifier: BSL-1.0
// Exact crossings of segments with planes (include/locus/core/plane_crossing.hpp): each
// coordinate of a crossing is num / den * 2^E with integers num, den on core's big integer and one
// power of two E shared by every point of the call.

#include <locus/core/plane_crossing.hpp>

#include "big_int.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <numeric>

namespace locus {

namespace {

using detail::DynBigInt;

/// The least low_exponent over the nonzero values (INT_MAX when all are zero).
struct LowExponent {
  int e = INT_MAX;
  void add(double x) noexcept {
    if (x != 0.0) e = std::min(e, detail::low_exponent(x));
  }
  void add(const Vec3<double>& p) noexcept {
    add(p.x);
    add(p.y);
    add(p.z);
  }
  [[nodiscard]] int value() const noexcept { return e == INT_MAX ? 0 : e; }
};

using BigVec = std::array<DynBigInt, 3>;

[[nodiscard]] BigVec to_big(const Vec3<double>& p, int e) {
  return {DynBigInt::from_double(p.x, -e), DynBigInt::from_double(p.y, -e),
          DynBigInt::from_double(p.z, -e)};
}

[[nodiscard]] DynBigInt dot(const BigVec& a, const BigVec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

[[nodiscard]] BigVec sub(const BigVec& a, const BigVec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

[[nodiscard]] BigVec cross(const BigVec& a, const BigVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The plane's value, times one positive power of two fixed per plane, at integer points
/// P = X 2^-e (so the power of two cancels in every crossing of that plane).
class PlaneFunction {
 public:
  PlaneFunction(const ExactPlane3& plane, int e) : through_points_(plane.through_points) {
    if (through_points_) {
      p0_ = to_big(plane.p0, e);
      normal_ = cross(sub(to_big(plane.p1, e), p0_), sub(to_big(plane.p2, e), p0_));
      return;
    }
    // dot(n, X) - c = 2^(en + e) dot(N, P) - 2^ec C with N = n 2^-en, C = c 2^-ec; both terms
    // are brought to the smaller of the two exponents.
    LowExponent en;
    en.add(plane.normal);
    const int n_exp = en.value();
    LowExponent ec;
    ec.add(plane.constant);
    const int c_exp = ec.value();
    const int low = std::min(n_exp + e, c_exp);
    normal_ = to_big(plane.normal, n_exp);
    normal_shift_ = static_cast<std::size_t>(n_exp + e - low);
    constant_ = DynBigInt::from_double(plane.constant, -c_exp)
                << static_cast<std::size_t>(c_exp - low);
  }

  [[nodiscard]] DynBigInt operator()(const BigVec& p) const {
    if (through_points_) return dot(normal_, sub(p, p0_));
    return (dot(normal_, p) << normal_shift_) - constant_;
  }

 private:
  bool through_points_;
  BigVec normal_{};
  BigVec p0_{};
  std::size_t normal_shift_ = 0;
  DynBigInt constant_{};
};

struct ExactPoint {
  BigVec num;
  DynBigInt den;  // > 0
};

/// num / den * 2^e, within one unit in the last place.
[[nodiscard]] double rounded(const DynBigInt& num, const DynBigInt& den, int e) {
  if (num.is_zero()) return 0.0;
  // Enough quotient bits (at least 66) that truncating it costs far less than the final rounding.
  const auto nb = static_cast<long>(num.bit_length()), db = static_cast<long>(den.bit_length());
  const long shift = std::max(0L, db - nb + 66);
  const DynBigInt q = (num << static_cast<std::size_t>(shift)) / den;
  return std::ldexp(q.to_double(), e - static_cast<int>(shift));
}

}  // namespace

void rank_plane_crossings(std::span<PlaneCrossing3> crossings, int axis) {
  if (crossings.empty()) return;
  LowExponent low;
  for (const PlaneCrossing3& c : crossings) {
    low.add(c.a);
    if (c.plane != nullptr) {
      low.add(c.b);
      if (c.plane->through_points) {
        low.add(c.plane->p0);
        low.add(c.plane->p1);
        low.add(c.plane->p2);
      }
    }
  }
  const int e = low.value();

  // One PlaneFunction per distinct plane (callers pass a handful).
  std::vector<std::pair<const ExactPlane3*, PlaneFunction>> functions;
  const auto function_of = [&](const ExactPlane3* plane) -> const PlaneFunction& {
    for (const auto& [p, f] : functions) {
      if (p == plane) return f;
    }
    functions.emplace_back(plane, PlaneFunction(*plane, e));
    return functions.back().second;
  };

  std::vector<ExactPoint> points;
  points.reserve(crossings.size());
  for (const PlaneCrossing3& c : crossings) {
    const BigVec a = to_big(c.a, e);
    if (c.plane == nullptr) {
      points.push_back({a, DynBigInt(1)});
      continue;
    }
    const BigVec b = to_big(c.b, e);
    const PlaneFunction& f = function_of(c.plane);
    DynBigInt fa = f(a), fb = f(b);
    DynBigInt den = fa - fb;
    if (den.is_zero() || fa.sign() * fb.sign() > 0) {
      points.push_back({a, DynBigInt(1)});  // precondition broken: the point a (documented)
      continue;
    }
    BigVec num{fa * b[0] - fb * a[0], fa * b[1] - fb * a[1], fa * b[2] - fb * a[2]};
    if (den.is_negative()) {
      den = -den;
      for (DynBigInt& v : num) v = -v;
    }
    points.push_back({std::move(num), std::move(den)});
  }

  const auto k = static_cast<std::size_t>(std::clamp(axis, 0, 2));
  const auto compare_points = [&](std::size_t i, std::size_t j) {
    return compare(points[i].num[k] * points[j].den, points[j].num[k] * points[i].den);
  };
  std::vector<std::size_t> order(crossings.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return compare_points(i, j) < 0; });
  std::size_t rank = 0;
  for (std::size_t r = 0; r < order.size(); ++r) {
    if (r > 0 && compare_points(order[r - 1], order[r]) != 0) ++rank;
    crossings[order[r]].rank = rank;
  }
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const ExactPoint& p = points[i];
    crossings[i].point = {rounded(p.num[0], p.den, e), rounded(p.num[1], p.den, e),
                          rounded(p.num[2], p.den, e)};
  }
}

}  // namespace locus
