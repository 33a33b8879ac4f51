// SPDX-License-Identifier: BSL-1.0
// Scale covariance of measure/ (issue 17 item 6; the distance harness's check 8,
// tests/support/scale_covariance.hpp): area_volume.hpp, formulas.hpp and inertia.hpp on input
// scaled by 2^k give lengths times 2^k, areas 2^(2k), volumes 2^(3k), second moments of area
// 2^(4k) and of volume 2^(5k). Exponents: check 8's where the results stay in range, and the
// largest |k| that keeps them normal (covariant_exponents). Every routine is scale-exact.

#include <locus/measure/area_volume.hpp>
#include <locus/measure/formulas.hpp>
#include <locus/measure/inertia.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

namespace {

using locus::Vec;
using locus::Vec2;
using locus::Vec3;
using locus_test::add;
using locus_test::Covariant;
using locus_test::covariant_exponents;
using locus_test::Rng;
using locus_test::scaled;
using Tri = std::array<std::uint32_t, 3>;

template <class T>
class MeasureScale : public ::testing::Test {};
TYPED_TEST_SUITE(MeasureScale, locus_test::RealTypes);

// Coordinates on the grid 2^-10 Z in [lo, hi]: exact when scaled by 2^k.
template <class T>
T grid(Rng& rng, double lo, double hi) {
  return T(std::ldexp(std::round(std::ldexp(rng.uniform<double>(lo, hi), 10)), -10));
}
template <class T, int N>
Vec<T, N> grid_vec(Rng& rng, double lo, double hi) {
  Vec<T, N> v{};
  for (int i = 0; i < N; ++i) v[i] = grid<T>(rng, lo, hi);
  return v;
}

// A closed, outward octahedron with jittered vertices (a valid closed mesh for every jitter).
template <class T>
std::vector<Vec3<T>> octahedron(Rng& rng) {
  std::vector<Vec3<T>> v;
  const double c[6][3] = {{2, 0, 0}, {-2, 0, 0}, {0, 2, 0}, {0, -2, 0}, {0, 0, 2}, {0, 0, -2}};
  for (const auto& p : c)
    v.push_back({T(p[0]) + grid<T>(rng, -0.5, 0.5) + T(1), T(p[1]) + grid<T>(rng, -0.5, 0.5),
                 T(p[2]) + grid<T>(rng, -0.5, 0.5) - T(0.5)});
  return v;
}
const std::vector<Tri> octahedron_tris{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                       {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

TYPED_TEST(MeasureScale, AreaVolume) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Vec3<T>> poly;
    for (int i = 0; i < 7; ++i) {
      const double a = 2 * locus::pi_v<double> * i / 7;
      Vec3<T> p{T(2 * std::cos(a)), T(std::sin(a)), T(0)};
      p.z = T(0.5) * p.x - T(0.25) * p.y + T(1);
      poly.push_back(scaled(scaled(p, 10), -10));  // exact, on the grid as far as it matters
    }
    const auto mesh = octahedron<T>(rng);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto q = scaled(poly, k);
          std::vector<Covariant> out{{"polygon_area", double(locus::polygon_area<T>(q)), 2}};
          add(out, "polygon_vector_area", locus::polygon_vector_area<T>(q), 2);
          add(out, "polygon_centroid", locus::polygon_centroid<T>(q), 1);
          return out;
        },
        covariant_exponents<T>(2));
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto v = scaled(mesh, k);
          return std::vector<Covariant>{
              {"mesh_signed_volume", double(locus::mesh_signed_volume<T>(v, octahedron_tris)), 3},
              {"mesh_volume", double(locus::mesh_volume<T>(v, octahedron_tris)), 3}};
        },
        covariant_exponents<T>(3));
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto v = scaled(mesh, k);
          return std::vector<Covariant>{
              {"mesh_surface_area", double(locus::mesh_surface_area<T>(v, octahedron_tris)), 2}};
        },
        covariant_exponents<T>(2));
  }
}

TYPED_TEST(MeasureScale, Inertia) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 10; ++trial) {
    const auto mesh = octahedron<T>(rng);
    locus_test::expect_scale_covariant(
        [&](int k) {
          const auto m = locus::mass_properties<T>(scaled(mesh, k), octahedron_tris, T(3));
          std::vector<Covariant> out{{"status", double(m.status), 0},
                                     {"volume", double(m.volume), 3},
                                     {"mass", double(m.mass), 3}};
          add(out, "centroid", m.centroid, 1);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) out.push_back({"inertia", double(m.inertia(i, j)), 5});
          return out;
        },
        covariant_exponents<T>(5));
    locus::Polygon2<T> poly;
    for (int i = 0; i < 6; ++i) {
      const double a = 2 * locus::pi_v<double> * i / 6 + 0.1 * trial;
      poly.vertices.push_back({T(1) + grid<T>(rng, -0.2, 0.2) + T(2 * std::cos(a)),
                               grid<T>(rng, -0.2, 0.2) + T(std::sin(a))});
      poly.vertices.back() = scaled(scaled(poly.vertices.back(), 12), -12);
    }
    locus_test::expect_scale_covariant(
        [&](int k) {
          locus::Polygon2<T> q{scaled(poly.vertices, k)};
          const auto m = locus::mass_properties<T>(q, T(2));
          std::vector<Covariant> out{{"status", double(m.status), 0},
                                     {"area", double(m.area), 2},
                                     {"mass", double(m.mass), 2},
                                     {"polar_moment", double(m.polar_moment), 4}};
          add(out, "centroid", m.centroid, 1);
          for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
              out.push_back({"second_moment", double(m.second_moment(i, j)), 4});
          return out;
        },
        covariant_exponents<T>(4));
  }
}

TYPED_TEST(MeasureScale, Formulas) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    // Lengths (a triangle's sides: a, b and c < a + b), heights, angles; points.
    const T a = grid<T>(rng, 1, 4), b = grid<T>(rng, 1, 4);
    const T c = grid<T>(rng, std::abs(double(a - b)) + 0.01, double(a + b) - 0.01);
    const T d = grid<T>(rng, 1, 4), h = grid<T>(rng, 0.5, 3);
    const T alpha = T(rng.uniform<double>(0.5, 2.5)), gamma = T(rng.uniform<double>(0.5, 2.5));
    const T theta = T(rng.uniform<double>(0.1, 6));
    const Vec2<T> q2[4] = {grid_vec<T, 2>(rng, -1, 0), grid_vec<T, 2>(rng, 1, 2),
                           grid_vec<T, 2>(rng, 2, 3), grid_vec<T, 2>(rng, -2, -1)};
    Vec3<T> q3[4];
    for (int i = 0; i < 4; ++i) q3[i] = {q2[i].x, q2[i].y, grid<T>(rng, -1, 1)};
    const int n = 3 + trial % 7;
    auto lengths = [&](int k) {
      auto s = [k](T x) { return std::ldexp(x, k); };
      auto p2 = [&](int i) { return scaled(q2[i], k); };
      auto p3 = [&](int i) { return scaled(q3[i], k); };
      std::vector<Covariant> out{
          {"triangle_inradius", double(locus::triangle_inradius(s(a), s(b), s(c))), 1},
          {"triangle_circumradius", double(locus::triangle_circumradius(s(a), s(b), s(c))), 1},
          {"quadrilateral_perimeter 2D",
           double(locus::quadrilateral_perimeter(p2(0), p2(1), p2(2), p2(3))), 1},
          {"quadrilateral_perimeter 3D",
           double(locus::quadrilateral_perimeter(p3(0), p3(1), p3(2), p3(3))), 1},
          {"regular_polygon_perimeter", double(locus::regular_polygon_perimeter(n, s(a))), 1},
          {"regular_polygon_inradius", double(locus::regular_polygon_inradius(n, s(a))), 1},
          {"regular_polygon_circumradius", double(locus::regular_polygon_circumradius(n, s(a))), 1},
          {"arc_length", double(locus::arc_length(s(a), theta)), 1},
          {"chord_length", double(locus::chord_length(s(a), theta)), 1}};
      add(out, "quadrilateral_centroid", locus::quadrilateral_centroid(p2(0), p2(1), p2(2), p2(3)),
          1);
      return out;
    };
    auto areas = [&](int k) {
      auto s = [k](T x) { return std::ldexp(x, k); };
      auto p2 = [&](int i) { return scaled(q2[i], k); };
      auto p3 = [&](int i) { return scaled(q3[i], k); };
      return std::vector<Covariant>{
          {"triangle_area_from_sides", double(locus::triangle_area_from_sides(s(a), s(b), s(c))),
           2},
          {"quadrilateral_signed_area",
           double(locus::quadrilateral_signed_area(p2(0), p2(1), p2(2), p2(3))), 2},
          {"quadrilateral_area 2D", double(locus::quadrilateral_area(p2(0), p2(1), p2(2), p2(3))),
           2},
          {"quadrilateral_area 3D", double(locus::quadrilateral_area(p3(0), p3(1), p3(2), p3(3))),
           2},
          {"trapezoid_area", double(locus::trapezoid_area(s(a), s(b), s(h))), 2},
          {"parallelogram_area 2D", double(locus::parallelogram_area(p2(1), p2(3))), 2},
          {"parallelogram_area 3D", double(locus::parallelogram_area(p3(1), p3(3))), 2},
          {"quadrilateral_area_bretschneider",
           double(locus::quadrilateral_area_bretschneider(s(a), s(b), s(c), s(d), alpha, gamma)),
           2},
          {"regular_polygon_area", double(locus::regular_polygon_area(n, s(a))), 2},
          {"circular_sector_area", double(locus::circular_sector_area(s(a), theta)), 2},
          {"circular_segment_area", double(locus::circular_segment_area(s(a), theta)), 2},
          {"annulus_area", double(locus::annulus_area(s(a + b), s(a))), 2},
          {"spherical_zone_area", double(locus::spherical_zone_area(s(a), s(h))), 2},
          {"platonic_surface_area",
           double(locus::platonic_surface_area(locus::PlatonicSolid(trial % 5), s(a))), 2}};
    };
    auto volumes = [&](int k) {
      auto s = [k](T x) { return std::ldexp(x, k); };
      auto s2 = [k](T x) { return std::ldexp(x, 2 * k); };
      return std::vector<Covariant>{
          {"spherical_cap_volume", double(locus::spherical_cap_volume(s(a + h), s(h))), 3},
          {"spherical_sector_volume", double(locus::spherical_sector_volume(s(a + h), s(h))), 3},
          {"spherical_segment_volume", double(locus::spherical_segment_volume(s(a), s(b), s(h))),
           3},
          {"prism_volume", double(locus::prism_volume(s2(a), s(h))), 3},
          {"pyramid_volume", double(locus::pyramid_volume(s2(a), s(h))), 3},
          {"pyramid_frustum_volume", double(locus::pyramid_frustum_volume(s2(a), s2(b), s(h))), 3},
          {"platonic_volume", double(locus::platonic_volume(locus::PlatonicSolid(trial % 5), s(a))),
           3}};
    };
    locus_test::expect_scale_covariant(lengths, covariant_exponents<T>(1));
    locus_test::expect_scale_covariant(areas, covariant_exponents<T>(2));
    locus_test::expect_scale_covariant(volumes, covariant_exponents<T>(3));
  }
}

}  // namespace
