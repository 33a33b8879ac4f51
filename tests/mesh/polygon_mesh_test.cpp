// SPDX-License-Identifier: BSL-1.0
// Tests of mesh/polygon_mesh.hpp: the compressed face layout, the well-formedness check and the
// fan triangulation, checked against a direct construction and, for areas, exact rationals.

#include <locus/mesh/polygon_mesh.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

using locus::PolygonMesh;
using locus::Status;

template <class T>
class PolygonMeshTest : public ::testing::Test {};
TYPED_TEST_SUITE(PolygonMeshTest, locus_test::RealTypes);

TYPED_TEST(PolygonMeshTest, EmptyMeshIsWellFormed) {
  using T = TypeParam;
  const PolygonMesh<T> m;
  EXPECT_EQ(locus::face_count(m), 0u);
  EXPECT_EQ(locus::check_polygon_mesh(m), Status::ok);
  EXPECT_TRUE(locus::fan_triangles(m).empty());
}

TYPED_TEST(PolygonMeshTest, FacesAndFansOfRandomPolygons) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 50; ++trial) {
    PolygonMesh<T> m;
    const int nv = rng.uniform_int(3, 40);
    for (int i = 0; i < nv; ++i) m.vertices.push_back(rng.template vec<T, 3>(T(-1), T(1)));
    std::vector<std::vector<std::uint32_t>> faces;
    const int nf = rng.uniform_int(0, 20);
    for (int f = 0; f < nf; ++f) {
      std::vector<std::uint32_t> fv(static_cast<std::size_t>(rng.uniform_int(3, 9)));
      for (auto& i : fv) i = static_cast<std::uint32_t>(rng.uniform_int(0, nv - 1));
      faces.push_back(fv);
      locus::add_face(m, std::span<const std::uint32_t>(fv));
    }
    ASSERT_EQ(locus::check_polygon_mesh(m), Status::ok);
    ASSERT_EQ(locus::face_count(m), faces.size());
    std::vector<std::array<std::uint32_t, 3>> expect;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto got = locus::face(m, f);
      ASSERT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()), faces[f]);
      for (std::size_t i = 1; i + 1 < faces[f].size(); ++i) {
        expect.push_back({faces[f][0], faces[f][i], faces[f][i + 1]});
      }
    }
    EXPECT_EQ(locus::fan_triangles(m), expect);
    EXPECT_EQ(locus::fan_triangle_count(m), expect.size());
    // from_triangles is the inverse on a triangle mesh (deduced from a std::vector).
    const PolygonMesh<T> t = locus::from_triangles(m.vertices, expect);
    EXPECT_EQ(locus::fan_triangles(t), expect);
    EXPECT_EQ(t.face_offsets.size(), expect.size() + 1);
  }
}

// The fan of a convex polygon covers it exactly: the triangle areas (exact rationals) add up to
// the shoelace area of the polygon (exact rationals), and every triangle is counter-clockwise.
TYPED_TEST(PolygonMeshTest, FanOfConvexPolygonHasThePolygonsArea) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const int n = rng.uniform_int(3, 12);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(rng.uniform(0.0, 6.283185307179586));
    std::sort(angles.begin(), angles.end());
    PolygonMesh<T> m;
    std::vector<std::uint32_t> ring;
    for (int i = 0; i < n; ++i) {
      m.vertices.push_back(
          {T(std::cos(angles[std::size_t(i)])), T(std::sin(angles[std::size_t(i)])), T(0)});
      ring.push_back(static_cast<std::uint32_t>(i));
    }
    locus::add_face(m, std::span<const std::uint32_t>(ring));
    const auto q = [&](std::uint32_t i, int c) { return mpq_class(double(m.vertices[i][c])); };
    mpq_class shoelace = 0;
    for (int i = 0; i < n; ++i) {
      const auto a = std::uint32_t(i), b = std::uint32_t((i + 1) % n);
      shoelace += q(a, 0) * q(b, 1) - q(b, 0) * q(a, 1);
    }
    mpq_class fan = 0;
    for (const auto& t : locus::fan_triangles(m)) {
      const mpq_class twice = (q(t[1], 0) - q(t[0], 0)) * (q(t[2], 1) - q(t[0], 1)) -
                              (q(t[2], 0) - q(t[0], 0)) * (q(t[1], 1) - q(t[0], 1));
      EXPECT_GE(sgn(twice), 0);
      fan += twice;
    }
    EXPECT_EQ(fan, shoelace);
  }
}

TYPED_TEST(PolygonMeshTest, CheckReportsMalformedMeshes) {
  using T = TypeParam;
  PolygonMesh<T> good;
  good.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  good.face_offsets = {0, 3, 7};
  good.face_indices = {0, 1, 2, 1, 3, 2, 0};
  ASSERT_EQ(locus::check_polygon_mesh(good), Status::ok);
  auto bad = good;
  bad.face_indices[4] = 4;  // index == vertex count
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::invalid_input);
  bad = good;
  bad.face_offsets = {0, 2, 7};  // a face of 2 vertices
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::invalid_input);
  bad = good;
  bad.face_offsets = {0, 3, 6};  // does not end at face_indices.size()
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::invalid_input);
  bad = good;
  bad.face_offsets = {1, 3, 7};
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::invalid_input);
  bad = good;
  bad.face_offsets.clear();
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::invalid_input);
  bad = good;
  bad.vertices[3].y = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::non_finite_input);
  bad.vertices[3].y = std::numeric_limits<T>::infinity();
  EXPECT_EQ(locus::check_polygon_mesh(bad), Status::non_finite_input);
}

}  // namespace
