// SPDX-License-Identifier: BSL-1.0
#pragma once
// Mesh generators (row mesh.platonic, book section 9.3.3, figures 9.14, 9.17): the five
// Platonic solids and tessellations of the sphere, torus, cylinder and cone, as PolygonMesh.
// Conventions: every face is counter-clockwise seen from outside (its normal, (v1 - v0) x
// (v2 - v0) for a triangle, points out of the solid); every mesh is closed and manifold
// (mesh_checks.hpp verifies it in the tests). Platonic solids have unit circumradius and their
// centre at the origin: tetrahedron_mesh (4 triangles), hexahedron_mesh (6 squares),
// octahedron_mesh (8 triangles), dodecahedron_mesh (12 pentagons; dodecahedron_triangle_mesh
// fans each into 3), icosahedron_mesh (20 triangles). The convex solids' faces are oriented with
// the exact orient3d against the centre, so rounding in the coordinates cannot flip one.
// uv_sphere_mesh(radius, slices, stacks): poles on z, triangles; icosphere_mesh(radius, levels):
// the icosahedron with each triangle split in four `levels` times, new vertices pushed onto the
// sphere (20 * 4^levels faces). torus_mesh(R, r, major, minor): about the z axis, radius R to the
// tube centre, tube radius r (R > r > 0 for a ring torus), triangles, genus 1.
// cylinder_mesh(radius, height, slices) and cone_mesh(radius, height, slices): axis z from
// -height/2 to height/2 (the cone's apex on top), side triangles, each cap one `slices`-gon face.
// Segment counts below the minimum (3 around, 2 stacks, 0 levels) are raised to it. Coordinates are
// computed in double and rounded to T. Cost: linear in the output.

#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/vec.hpp>
#include <locus/mesh/polygon_mesh.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace locus {

namespace detail::platonic {

/// Reverses every face whose plane does not have `centre` strictly behind it (convex solids).
template <Real T>
inline void orient_outward(PolygonMesh<T>& m, const Vec3<T>& centre) {
  for (std::size_t f = 0; f + 1 < m.face_offsets.size(); ++f) {
    const auto b = m.face_indices.begin() + m.face_offsets[f];
    const auto e = m.face_indices.begin() + m.face_offsets[f + 1];
    if (orient3d(m.vertices[b[0]], m.vertices[b[1]], m.vertices[b[2]], centre) == Sign::positive) {
      std::reverse(b, e);
    }
  }
}

template <Real T>
inline PolygonMesh<T> from_points(const std::vector<Vec3<double>>& pts) {
  PolygonMesh<T> m;
  for (const Vec3<double>& p : pts) {
    m.vertices.push_back({static_cast<T>(p.x), static_cast<T>(p.y), static_cast<T>(p.z)});
  }
  return m;
}

/// Triangles i < j < k of mutually nearest points (edge = the smallest distance): the faces of
/// the tetrahedron, octahedron and icosahedron, whose next distance is far larger.
inline std::vector<std::array<std::uint32_t, 3>> nearest_triangles(
    const std::vector<Vec3<double>>& p) {
  double dmin = 1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) dmin = std::min(dmin, sqr_length(p[i] - p[j]));
  }
  const auto near = [&](std::size_t i, std::size_t j) {
    return sqr_length(p[i] - p[j]) < 1.2 * dmin;
  };
  std::vector<std::array<std::uint32_t, 3>> t;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    for (std::uint32_t j = i + 1; j < p.size(); ++j) {
      for (std::uint32_t k = j + 1; k < p.size(); ++k) {
        if (near(i, j) && near(j, k) && near(i, k)) t.push_back({i, j, k});
      }
    }
  }
  return t;
}

inline std::vector<Vec3<double>> icosahedron_points() {
  const double phi = std::numbers::phi, s = 1 / std::sqrt(1 + phi * phi);
  std::vector<Vec3<double>> p;
  for (const double a : {-1.0, 1.0}) {
    for (const double b : {-phi, phi}) {
      p.push_back(Vec3<double>{0, a, b} * s);
      p.push_back(Vec3<double>{a, b, 0} * s);
      p.push_back(Vec3<double>{b, 0, a} * s);
    }
  }
  return p;
}

template <Real T>
inline PolygonMesh<T> triangles_of(const std::vector<Vec3<double>>& pts) {
  PolygonMesh<T> m = from_points<T>(pts);
  for (const auto& t : nearest_triangles(pts)) add_face(m, std::span<const std::uint32_t>(t));
  orient_outward(m, Vec3<T>{});
  return m;
}

/// The vertex at the given spherical angles (z up).
inline Vec3<double> spherical(double radius, double azimuth, double polar) {
  return {radius * std::sin(polar) * std::cos(azimuth),
          radius * std::sin(polar) * std::sin(azimuth), radius * std::cos(polar)};
}

template <Real T>
inline void add_tri(PolygonMesh<T>& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const std::array<std::uint32_t, 3> t{a, b, c};
  add_face(m, std::span<const std::uint32_t>(t));
}

}  // namespace detail::platonic

/// Regular tetrahedron: 4 vertices, 4 triangles.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> tetrahedron_mesh() {
  const double s = 1 / std::sqrt(3.0);
  return detail::platonic::triangles_of<T>({{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}});
}

/// Regular hexahedron (cube): 8 vertices, 6 squares.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> hexahedron_mesh() {
  const double s = 1 / std::sqrt(3.0);
  std::vector<Vec3<double>> p;
  for (int i = 0; i < 8; ++i) p.push_back({i & 1 ? s : -s, i & 2 ? s : -s, i & 4 ? s : -s});
  PolygonMesh<T> m = detail::platonic::from_points<T>(p);
  // Face with coordinate `axis` fixed: the cycle of its four corners.
  for (int axis = 0; axis < 3; ++axis) {
    const int b1 = 1 << ((axis + 1) % 3), b2 = 1 << ((axis + 2) % 3);
    for (const int side : {0, 1 << axis}) {
      const std::array<std::uint32_t, 4> q{
          static_cast<std::uint32_t>(side), static_cast<std::uint32_t>(side | b1),
          static_cast<std::uint32_t>(side | b1 | b2), static_cast<std::uint32_t>(side | b2)};
      add_face(m, std::span<const std::uint32_t>(q));
    }
  }
  detail::platonic::orient_outward(m, Vec3<T>{});
  return m;
}

/// Regular octahedron: 6 vertices, 8 triangles.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> octahedron_mesh() {
  return detail::platonic::triangles_of<T>(
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}});
}

/// Regular icosahedron: 12 vertices, 20 triangles.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> icosahedron_mesh() {
  return detail::platonic::triangles_of<T>(detail::platonic::icosahedron_points());
}

/// Regular dodecahedron: 20 vertices, 12 pentagons (figure 9.14).
template <Real T = double>
[[nodiscard]] PolygonMesh<T> dodecahedron_mesh() {
  const double phi = std::numbers::phi, s = 1 / std::sqrt(3.0);
  std::vector<Vec3<double>> p;
  for (int i = 0; i < 8; ++i)
    p.push_back(Vec3<double>{i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0} * s);
  for (const double a : {-1 / phi, 1 / phi}) {
    for (const double b : {-phi, phi}) {
      p.push_back(Vec3<double>{0, a, b} * s);
      p.push_back(Vec3<double>{a, b, 0} * s);
      p.push_back(Vec3<double>{b, 0, a} * s);
    }
  }
  PolygonMesh<T> m = detail::platonic::from_points<T>(p);
  // The faces are dual to the vertices of the icosahedron (1, 0, phi) and its cyclic and sign
  // variants: the five nearest points to each such direction u, in angular order about u.
  std::vector<Vec3<double>> dual;
  for (const double a : {-1.0, 1.0}) {
    for (const double b : {-phi, phi}) {
      dual.push_back({0, b, a});
      dual.push_back({b, a, 0});
      dual.push_back({a, 0, b});
    }
  }
  for (const Vec3<double>& d : dual) {
    const Vec3<double> u = normalize(d);
    std::vector<std::pair<double, std::uint32_t>> by_dot;
    for (std::uint32_t i = 0; i < p.size(); ++i) by_dot.push_back({-dot(u, p[i]), i});
    std::sort(by_dot.begin(), by_dot.end());
    const Vec3<double> e1 = normalize(p[by_dot[0].second] - u * dot(u, p[by_dot[0].second]));
    const Vec3<double> e2 = cross(u, e1);
    std::vector<std::pair<double, std::uint32_t>> ring;
    for (int k = 0; k < 5; ++k) {
      const Vec3<double>& q = p[by_dot[static_cast<std::size_t>(k)].second];
      ring.push_back(
          {std::atan2(dot(q, e2), dot(q, e1)), by_dot[static_cast<std::size_t>(k)].second});
    }
    std::sort(ring.begin(), ring.end());
    std::array<std::uint32_t, 5> face{};
    for (std::size_t k = 0; k < 5; ++k) face[k] = ring[k].second;
    add_face(m, std::span<const std::uint32_t>(face));
  }
  detail::platonic::orient_outward(m, Vec3<T>{});
  return m;
}

/// The dodecahedron with each pentagon split into a fan of 3 triangles (36 triangles).
template <Real T = double>
[[nodiscard]] PolygonMesh<T> dodecahedron_triangle_mesh() {
  const PolygonMesh<T> d = dodecahedron_mesh<T>();
  const auto tris = fan_triangles(d);
  return from_triangles(std::span<const Vec3<T>>(d.vertices),
                        std::span<const std::array<std::uint32_t, 3>>(tris));
}

/// Latitude-longitude sphere of the given radius about the origin.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> uv_sphere_mesh(T radius, int slices, int stacks) {
  slices = std::max(slices, 3);
  stacks = std::max(stacks, 2);
  const double pi = std::numbers::pi, r = static_cast<double>(radius);
  std::vector<Vec3<double>> p{{0, 0, r}};
  for (int i = 1; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      p.push_back(detail::platonic::spherical(r, 2 * pi * j / slices, pi * i / stacks));
    }
  }
  p.push_back({0, 0, -r});
  PolygonMesh<T> m = detail::platonic::from_points<T>(p);
  const auto at = [&](int i, int j) {  // ring i in 1..stacks-1
    return static_cast<std::uint32_t>(1 + (i - 1) * slices + (j % slices));
  };
  const auto south = static_cast<std::uint32_t>(p.size() - 1);
  for (int j = 0; j < slices; ++j) {
    detail::platonic::add_tri(m, 0u, at(1, j), at(1, j + 1));
    for (int i = 1; i + 1 < stacks; ++i) {
      detail::platonic::add_tri(m, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      detail::platonic::add_tri(m, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
    detail::platonic::add_tri(m, at(stacks - 1, j), south, at(stacks - 1, j + 1));
  }
  return m;
}

/// Subdivided icosahedron on the sphere of the given radius about the origin.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> icosphere_mesh(T radius, int levels) {
  std::vector<Vec3<double>> p = detail::platonic::icosahedron_points();
  const PolygonMesh<double> ico = icosahedron_mesh<double>();
  std::vector<std::array<std::uint32_t, 3>> tris = fan_triangles(ico);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = mid.try_emplace({key.first, key.second}, 0u);
      if (fresh) {
        it->second = static_cast<std::uint32_t>(p.size());
        p.push_back(normalize(p[a] + p[b]));
      }
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    next.reserve(4 * tris.size());
    for (const auto& t : tris) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]);
      const std::uint32_t ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    tris = std::move(next);
  }
  for (Vec3<double>& q : p) q = q * static_cast<double>(radius);
  PolygonMesh<T> m = detail::platonic::from_points<T>(p);
  for (const auto& t : tris) add_face(m, std::span<const std::uint32_t>(t));
  return m;
}

/// Ring torus about the z axis (see the top of the header).
template <Real T = double>
[[nodiscard]] PolygonMesh<T> torus_mesh(T major_radius, T minor_radius, int major_segments,
                                        int minor_segments) {
  const int nu = std::max(major_segments, 3), nv = std::max(minor_segments, 3);
  const double pi = std::numbers::pi, R = static_cast<double>(major_radius);
  const double r = static_cast<double>(minor_radius);
  std::vector<Vec3<double>> p;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      p.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                   r * std::sin(v)});
    }
  }
  PolygonMesh<T> m = detail::platonic::from_points<T>(p);
  const auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>((i % nu) * nv + (j % nv));
  };
  // (u, v) increasing is counter-clockwise seen from outside: d/du x d/dv points out.
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      detail::platonic::add_tri(m, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      detail::platonic::add_tri(m, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return m;
}

/// Capped cylinder, or a cone when the top radius is 0 (shared by cylinder() and cone()).
namespace detail::platonic {
template <Real T>
inline PolygonMesh<T> frustum_mesh(double r0, double r1, double height, int slices) {
  slices = std::max(slices, 3);
  const double pi = std::numbers::pi, h = height / 2;
  std::vector<Vec3<double>> p;
  for (int j = 0; j < slices; ++j) {
    p.push_back({r0 * std::cos(2 * pi * j / slices), r0 * std::sin(2 * pi * j / slices), -h});
  }
  if (r1 > 0) {
    for (int j = 0; j < slices; ++j) {
      p.push_back({r1 * std::cos(2 * pi * j / slices), r1 * std::sin(2 * pi * j / slices), h});
    }
  } else {
    p.push_back({0, 0, h});
  }
  PolygonMesh<T> m = from_points<T>(p);
  const auto n = static_cast<std::uint32_t>(slices);
  std::vector<std::uint32_t> bottom;
  for (std::uint32_t j = 0; j < n; ++j) bottom.push_back(n - 1 - j);  // seen from below: CCW
  add_face(m, std::span<const std::uint32_t>(bottom));
  if (r1 > 0) {
    std::vector<std::uint32_t> top;
    for (std::uint32_t j = 0; j < n; ++j) top.push_back(n + j);
    add_face(m, std::span<const std::uint32_t>(top));
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t k = (j + 1) % n;
      add_tri(m, j, k, n + k);
      add_tri(m, j, n + k, n + j);
    }
  } else {
    for (std::uint32_t j = 0; j < n; ++j) add_tri(m, j, (j + 1) % n, n);
  }
  return m;
}
}  // namespace detail::platonic

/// Capped cylinder of the given radius and height about the z axis, centred at the origin.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> cylinder_mesh(T radius, T height, int slices) {
  return detail::platonic::frustum_mesh<T>(static_cast<double>(radius), static_cast<double>(radius),
                                           static_cast<double>(height), slices);
}

/// Cone of the given base radius and height about the z axis, apex at z = height / 2.
template <Real T = double>
[[nodiscard]] PolygonMesh<T> cone_mesh(T radius, T height, int slices) {
  return detail::platonic::frustum_mesh<T>(static_cast<double>(radius), 0.0,
                                           static_cast<double>(height), slices);
}

}  // namespace locus
