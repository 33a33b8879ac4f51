// SPDX-License-Identifier: BSL-1.0
// Oriented box against an orthogonal frustum by 26 separating axes
// (include/locus/intersection/oriented_box_frustum.hpp; docs/notes/sat3.md).

#include <locus/intersection/oriented_box_frustum.hpp>

#include <cmath>

namespace locus::detail::box_frustum {

namespace {
using V = Vec3<double>;
}  // namespace

template <Real T>
bool test(const OrientedBox3<T>& box_in, const Frustum3<T>& fr) noexcept {
  if (!is_valid(fr) || !is_finite(fr.origin) || !is_finite(fr.direction) || !is_finite(fr.up) ||
      !is_finite(fr.right) || !is_finite(box_in.center))
    return false;
  for (int i = 0; i < 3; ++i)
    if (!is_finite(box_in.axis[i]) || !(box_in.extent[i] >= T(0)) || !is_finite(box_in.extent[i]))
      return false;
  // Everything in the frustum's frame: x along R, y along U, z along D.
  const V R = vec_cast<double>(fr.right), U = vec_cast<double>(fr.up),
          D = vec_cast<double>(fr.direction);
  const V d = vec_cast<double>(box_in.center) - vec_cast<double>(fr.origin);
  const V c{dot(d, R), dot(d, U), dot(d, D)};
  V a[3];
  double e[3];
  for (int i = 0; i < 3; ++i) {
    const V ai = vec_cast<double>(box_in.axis[i]);
    a[i] = V{dot(ai, R), dot(ai, U), dot(ai, D)};
    e[i] = double(box_in.extent[i]);
  }
  const double n = fr.d_min, f = fr.d_max, r = fr.r_bound, u = fr.u_bound;
  // Separated along L when the box interval and the frustum interval are disjoint.
  const auto separated = [&](const V& L) {
    const double center = dot(L, c);
    const double radius = e[0] * std::abs(dot(L, a[0])) + e[1] * std::abs(dot(L, a[1])) +
                          e[2] * std::abs(dot(L, a[2]));
    const double p = L.z, q = (r * std::abs(L.x) + u * std::abs(L.y)) / n;
    const double lo = p - q >= 0 ? n * (p - q) : f * (p - q);
    const double hi = p + q >= 0 ? f * (p + q) : n * (p + q);
    return center - radius > hi || center + radius < lo;
  };
  // Book order: the frustum's faces, the box's faces, then the edge-edge cross products.
  if (separated(V{0, 0, 1})) return false;
  const V sides[4] = {{n, 0, -r}, {-n, 0, -r}, {0, n, -u}, {0, -n, -u}};
  for (const V& s : sides)
    if (separated(s)) return false;
  for (int i = 0; i < 3; ++i)
    if (separated(a[i])) return false;
  const V edges[6] = {{1, 0, 0}, {0, 1, 0}, {r, u, n}, {-r, u, n}, {r, -u, n}, {-r, -u, n}};
  for (const V& g : edges)
    for (int i = 0; i < 3; ++i) {
      const V L = cross(g, a[i]);
      // Nearly parallel edges (sin < 2^-20): the cross product is rounding noise that could
      // claim a separation; the face axes decide then (complete for exactly parallel edges).
      if (dot(L, L) <= 0x1p-40 * dot(g, g) * dot(a[i], a[i])) continue;
      if (separated(L)) return false;
    }
  return true;
}

template bool test<float>(const OrientedBox3<float>&, const Frustum3<float>&) noexcept;
template bool test<double>(const OrientedBox3<double>&, const Frustum3<double>&) noexcept;

}  // namespace locus::detail::box_frustum
