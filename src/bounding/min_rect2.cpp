// SPDX-License-Identifier: BSL-1.0
// Minimum enclosing rectangle by rotating calipers (bounding/min_rect2.hpp; row cg.minbox).

#include <locus/bounding/detail/ball_predicates.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/distance/detail/rescale.hpp>
#include <locus/hull/hull2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace locus {
namespace detail {

PolygonRect min_rect_of_convex_polygon(std::span<const Vec2<double>> poly,
                                       RectCriterion criterion) noexcept {
  const std::size_t h = poly.size();
  auto at = [&](std::size_t i) -> const Vec2<double>& { return poly[i % h]; };
  // (x, y) -> (y, -x): exact, and det[u, v] = u . rot(v).
  auto rot = [](const Vec2<double>& v) { return Vec2<double>{v.y, -v.x}; };
  PolygonRect best{std::numeric_limits<double>::infinity(), {}, {1.0, 0.0}, {0.0, 0.0}, 0};
  std::size_t right = 1, top = 1, left = 1;
  // Each caliper advances at most 2h steps in total over all edges; the budget enforces it.
  std::size_t budget = 8 * h + 16;
  for (std::size_t i = 0; i < h; ++i) {
    const Vec2<double>& a = at(i);
    const Vec2<double>& b = at(i + 1);
    if (right < i + 1) right = i + 1;
    // Max projection on u: advance while (b - a) . (p[right+1] - p[right]) > 0.
    while (budget > 0 && dot_differences<2>(a, b, at(right), at(right + 1)) == Sign::positive) {
      ++right;
      --budget;
    }
    if (top < right) top = right;
    // Max height: advance while det[b - a, p[top+1] - p[top]] > 0.
    while (budget > 0 &&
           dot_differences<2>(a, b, rot(at(top)), rot(at(top + 1))) == Sign::positive) {
      ++top;
      --budget;
    }
    if (left < top) left = top;
    // Min projection on u: advance while (b - a) . (p[left+1] - p[left]) < 0.
    while (budget > 0 && dot_differences<2>(a, b, at(left), at(left + 1)) == Sign::negative) {
      ++left;
      --budget;
    }
    const Vec2<double> u = b - a;
    const double uu = sqr_length(u);
    const double smax = dot(u, at(right) - a), smin = dot(u, at(left) - a);
    const double tmax = perp_dot(u, at(top) - a);
    const double width = (smax - smin) / std::sqrt(uu), height = tmax / std::sqrt(uu);
    const double m =
        criterion == RectCriterion::area ? (smax - smin) * tmax / uu : 2.0 * (width + height);
    if (m < best.measure) {
      const Vec2<double> axis0 = u / std::sqrt(uu);
      const Vec2<double> axis1 = perp(axis0);
      best.measure = m;
      best.axis0 = axis0;
      best.extent[0] = 0.5 * width;
      best.extent[1] = 0.5 * height;
      best.center = a + (0.5 * (smax + smin) / uu) * u + (0.5 * height) * axis1;
      best.edge = static_cast<std::uint32_t>(i);
    }
  }
  return best;
}

}  // namespace detail

template <Real T>
MinRectResult<T> min_rect(std::span<const Vec2<T>> points, RectCriterion criterion) {
  MinRectResult<T> r;
  const Hull2Result hull = convex_hull(points);
  r.status = hull.status;
  if (hull.status != Status::ok) return r;
  const auto p = [&](std::size_t k) { return vec_cast<double>(points[hull.indices[k]]); };
  if (hull.dimension == 0) {
    r.rectangle = {points[hull.indices[0]], {{T(1), T(0)}, {T(0), T(1)}}, {T(0), T(0)}};
    r.edge = {hull.indices[0], hull.indices[0]};
    return r;
  }
  // The calipers' areas are products of four coordinates: they run on the hull scaled by a
  // power of two f when those could leave the range (distance/detail/rescale.hpp), and the
  // rectangle is scaled back by 1/f (exact), so it scales exactly with the input.
  double m = 0.0;
  for (std::size_t k = 0; k < hull.indices.size(); ++k) m = std::max(m, max_abs(p(k)));
  const double f = detail::outside_product_range<double, 4>(m) ? normalising_scale(m) : 1.0;
  if (hull.dimension == 1) {
    const Vec2<double> a = p(0), b = p(1);
    const Normalized<double, 2> d = normalize_with_length(f * (b - a));
    r.rectangle = {vec_cast<T>(0.5 * a + 0.5 * b),
                   {vec_cast<T>(d.dir), vec_cast<T>(perp(d.dir))},
                   {static_cast<T>(0.5 * d.length / f), T(0)}};
    r.perimeter = static_cast<T>(2.0 * d.length / f);
    r.edge = {hull.indices[0], hull.indices[1]};
    return r;
  }
  std::vector<Vec2<double>> poly(hull.indices.size());
  for (std::size_t k = 0; k < poly.size(); ++k) poly[k] = f * p(k);
  detail::PolygonRect best = detail::min_rect_of_convex_polygon(poly, criterion);
  best.center = best.center / f;
  best.extent[0] /= f;
  best.extent[1] /= f;
  r.rectangle = {vec_cast<T>(best.center),
                 {vec_cast<T>(best.axis0), vec_cast<T>(perp(best.axis0))},
                 {static_cast<T>(best.extent[0]), static_cast<T>(best.extent[1])}};
  r.area = static_cast<T>(4.0 * best.extent[0] * best.extent[1]);
  r.perimeter = static_cast<T>(4.0 * (best.extent[0] + best.extent[1]));
  r.edge = {hull.indices[best.edge], hull.indices[(best.edge + 1) % poly.size()]};
  return r;
}

template MinRectResult<float> min_rect<float>(std::span<const Vec2<float>>, RectCriterion);
template MinRectResult<double> min_rect<double>(std::span<const Vec2<double>>, RectCriterion);

}  // namespace locus
