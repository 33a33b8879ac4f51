// SPDX-License-Identifier: BSL-1.0
#pragma once
// Small closed triangle meshes (outward normals) for the 3D BSP tests, rigid motions and the
// exact GMP volume of a triangle soup (divergence theorem: sum of det[a; b; c] / 6).

#include <locus/core/vec.hpp>
#include <locus/mesh/platonic.hpp>

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace locus_test {

template <class T>
struct Solid3 {
  std::vector<locus::Vec3<T>> v;
  std::vector<std::array<std::uint32_t, 3>> f;
};

/// The box [lo, hi], 12 triangles.
template <class T>
Solid3<T> box3(const locus::Vec3<T>& lo, const locus::Vec3<T>& hi) {
  Solid3<T> s;
  for (int i = 0; i < 8; ++i)
    s.v.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  // Quads counter-clockwise seen from outside.
  const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& r : q) {
    s.f.push_back({r[0], r[1], r[2]});
    s.f.push_back({r[0], r[2], r[3]});
  }
  return s;
}

/// A prism over a simple polygon (counter-clockwise) from z = z0 to z = z1; `caps` triangulates
/// the polygon (counter-clockwise triangles of polygon indices).
template <class T>
Solid3<T> prism3(const std::vector<std::array<T, 2>>& poly,
                 const std::vector<std::array<std::uint32_t, 3>>& caps, T z0, T z1) {
  Solid3<T> s;
  const auto n = static_cast<std::uint32_t>(poly.size());
  for (const auto& p : poly) s.v.push_back({p[0], p[1], z0});
  for (const auto& p : poly) s.v.push_back({p[0], p[1], z1});
  for (const auto& t : caps) {
    s.f.push_back({t[0], t[2], t[1]});              // bottom, seen from below
    s.f.push_back({t[0] + n, t[1] + n, t[2] + n});  // top
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    s.f.push_back({i, j, j + n});
    s.f.push_back({i, j + n, i + n});
  }
  return s;
}

/// The L-shaped prism: [0,2]x[0,2] minus [1,2]x[1,2], z in [0,1] (non-convex).
template <class T>
Solid3<T> l_prism3() {
  return prism3<T>({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},
                   {{3, 4, 5}, {3, 5, 0}, {3, 0, 1}, {3, 1, 2}}, T(0), T(1));
}

/// The U-shaped prism: [0,3]x[0,2] minus the notch [1,2]x[1,2], z in [-1,1].
template <class T>
Solid3<T> u_prism3() {
  return prism3<T>({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},
                   {{0, 1, 5}, {1, 4, 5}, {1, 2, 4}, {2, 3, 4}, {0, 5, 6}, {0, 6, 7}}, T(-1), T(1));
}

template <class T>
Solid3<T> from_mesh(const locus::PolygonMesh<T>& m) {
  Solid3<T> s;
  s.v = m.vertices;
  for (std::size_t f = 0; f + 1 < m.face_offsets.size(); ++f)
    for (std::uint32_t k = m.face_offsets[f] + 1; k + 1 < m.face_offsets[f + 1]; ++k)
      s.f.push_back({m.face_indices[m.face_offsets[f]], m.face_indices[k], m.face_indices[k + 1]});
  return s;
}

/// Rotation about a unit axis by angle, then translation (computed in double, rounded to T).
template <class T>
Solid3<T> moved(const Solid3<T>& s, const locus::Vec3<double>& axis, double angle,
                const locus::Vec3<double>& shift) {
  Solid3<T> r = s;
  const double c = std::cos(angle), sn = std::sin(angle);
  for (auto& p : r.v) {
    const locus::Vec3<double> x = locus::vec_cast<double>(p);
    const locus::Vec3<double> y =
        x * c + locus::cross(axis, x) * sn + axis * (locus::dot(axis, x) * (1 - c)) + shift;
    p = locus::vec_cast<T>(y);
  }
  return r;
}

/// Exact volume of a closed, outward triangle soup (GMP).
template <class T>
mpq_class exact_volume(const std::vector<locus::Vec3<T>>& v,
                       const std::vector<std::array<std::uint32_t, 3>>& f) {
  mpq_class sum = 0;
  for (const auto& t : f) {
    mpq_class a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) a[i][k] = double(v[t[i]][k]);
    sum += a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  }
  return sum / 6;
}

template <class T>
double volume(const std::vector<locus::Vec3<T>>& v,
              const std::vector<std::array<std::uint32_t, 3>>& f) {
  long double sum = 0;
  for (const auto& t : f) {
    const locus::Vec3<double> a = locus::vec_cast<double>(v[t[0]]),
                              b = locus::vec_cast<double>(v[t[1]]),
                              c = locus::vec_cast<double>(v[t[2]]);
    sum += static_cast<long double>(locus::dot(a, locus::cross(b, c)));
  }
  return static_cast<double>(sum / 6);
}

}  // namespace locus_test
