// SPDX-License-Identifier: BSL-1.0
// Row mesh.platonic: the generators of mesh/platonic.hpp, float and double. Counts of vertices,
// edges and faces (from the face lists, not the generator); regularity (unit circumradius, one
// edge length, one face size, one vertex degree); outward orientation (exact orient3d of each
// face against the centre for the convex solids; positive divergence-theorem volume for all,
// compared with the closed-form volume of the tessellated solid); segment minimums.

#include <locus/core/predicates.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>

#include "support/typed.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <vector>

namespace {

using namespace locus;

template <class T>
class Platonic : public ::testing::Test {};
TYPED_TEST_SUITE(Platonic, locus_test::RealTypes);

template <class T>
std::set<std::pair<std::uint32_t, std::uint32_t>> edges_of(const PolygonMesh<T>& m) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> e;
  for (std::size_t f = 0; f < face_count(m); ++f) {
    const auto c = face(m, f);
    for (std::size_t i = 0; i < c.size(); ++i) {
      e.insert({std::min(c[i], c[(i + 1) % c.size()]), std::max(c[i], c[(i + 1) % c.size()])});
    }
  }
  return e;
}

// Divergence theorem over the fan triangles, in double.
template <class T>
double volume(const PolygonMesh<T>& m) {
  double v = 0;
  for (const auto& t : fan_triangles(m)) {
    const Vec3<double> a = vec_cast<double>(m.vertices[t[0]]);
    const Vec3<double> b = vec_cast<double>(m.vertices[t[1]]);
    const Vec3<double> c = vec_cast<double>(m.vertices[t[2]]);
    v += dot(a, cross(b, c)) / 6;
  }
  return v;
}

struct Expect {
  std::size_t v, e, f, face_size, degree;
};

TYPED_TEST(Platonic, FiveSolidsAreRegularAndOutward) {
  using T = TypeParam;
  const double phi = std::numbers::phi;
  // Volumes of the solids of unit circumradius (edge a: tetra a = sqrt(8/3), cube 2/sqrt(3),
  // octa sqrt(2), dodeca 4 / (sqrt(3)(1 + sqrt(5))), icosa 1 / sin(2 pi / 5)).
  const double at = std::sqrt(8.0 / 3), ac = 2 / std::sqrt(3.0), ao = std::sqrt(2.0);
  const double ad = 4 / (std::sqrt(3.0) * (1 + std::sqrt(5.0)));
  const double ai = 1 / std::sin(2 * std::numbers::pi / 5);
  const std::vector<std::tuple<PolygonMesh<T>, Expect, double>> solids = {
      {tetrahedron_mesh<T>(), {4, 6, 4, 3, 3}, at * at * at / (6 * std::sqrt(2.0))},
      {hexahedron_mesh<T>(), {8, 12, 6, 4, 3}, ac * ac * ac},
      {octahedron_mesh<T>(), {6, 12, 8, 3, 4}, std::sqrt(2.0) / 3 * ao * ao * ao},
      {dodecahedron_mesh<T>(), {20, 30, 12, 5, 3}, (15 + 7 * std::sqrt(5.0)) / 4 * ad * ad * ad},
      {icosahedron_mesh<T>(), {12, 30, 20, 3, 5}, 5 * phi * phi / 6 * ai * ai * ai}};
  for (const auto& [m, x, vol] : solids) {
    SCOPED_TRACE(x.f);
    ASSERT_EQ(check_polygon_mesh(m), Status::ok);
    EXPECT_EQ(m.vertices.size(), x.v);
    EXPECT_EQ(face_count(m), x.f);
    const auto edges = edges_of(m);
    EXPECT_EQ(edges.size(), x.e);
    std::map<std::uint32_t, std::size_t> degree;
    const double len = std::sqrt(
        double(sqr_length(m.vertices[edges.begin()->first] - m.vertices[edges.begin()->second])));
    for (const auto& [a, b] : edges) {
      ++degree[a];
      ++degree[b];
      EXPECT_NEAR(std::sqrt(double(sqr_length(m.vertices[a] - m.vertices[b]))), len,
                  double(locus_test::tol<T>(8)));
    }
    for (const auto& [v, d] : degree) EXPECT_EQ(d, x.degree);
    for (const Vec3<T>& p : m.vertices) {
      EXPECT_NEAR(std::sqrt(double(sqr_length(p))), 1.0, double(locus_test::tol<T>(4)));
    }
    for (std::size_t f = 0; f < face_count(m); ++f) {
      const auto c = face(m, f);
      EXPECT_EQ(c.size(), x.face_size);
      EXPECT_EQ(orient3d(m.vertices[c[0]], m.vertices[c[1]], m.vertices[c[2]], Vec3<T>{}),
                Sign::negative);
    }
    EXPECT_NEAR(volume(m), vol, 1e-5);
  }
  const PolygonMesh<T> d3 = dodecahedron_triangle_mesh<T>();
  EXPECT_EQ(face_count(d3), 36u);
  EXPECT_EQ(d3.vertices, dodecahedron_mesh<T>().vertices);
}

TYPED_TEST(Platonic, TessellationsHaveTheirCountsAndVolumes) {
  using T = TypeParam;
  const double pi = std::numbers::pi;
  // UV sphere: slices (stacks - 1) + 2 vertices, 2 slices (stacks - 1) triangles.
  const PolygonMesh<T> uv = uv_sphere_mesh<T>(T(2), 10, 6);
  EXPECT_EQ(uv.vertices.size(), 52u);
  EXPECT_EQ(face_count(uv), 100u);
  for (const Vec3<T>& p : uv.vertices) {
    EXPECT_NEAR(std::sqrt(double(sqr_length(p))), 2.0, double(locus_test::tol<T>(8)));
  }
  EXPECT_GT(volume(uv), 0.75 * 4 / 3.0 * pi * 8);
  EXPECT_LT(volume(uv), 4 / 3.0 * pi * 8);
  // Icosphere: 10 4^L + 2 vertices, 20 4^L faces, on the sphere, volume tending to the ball's.
  double previous = 0;
  for (int level = 0; level < 4; ++level) {
    const PolygonMesh<T> s = icosphere_mesh<T>(T(1), level);
    const std::size_t p4 = std::size_t{1} << (2 * level);
    EXPECT_EQ(s.vertices.size(), 10 * p4 + 2);
    EXPECT_EQ(face_count(s), 20 * p4);
    EXPECT_EQ(edges_of(s).size(), 30 * p4);
    for (const Vec3<T>& p : s.vertices) {
      EXPECT_NEAR(std::sqrt(double(sqr_length(p))), 1.0, double(locus_test::tol<T>(8)));
    }
    // Inscribed: below the ball's volume, growing with the level, within 1% at level 3.
    EXPECT_GT(volume(s), previous);
    EXPECT_LT(volume(s), 4 / 3.0 * pi);
    previous = volume(s);
  }
  EXPECT_GT(previous, 0.99 * 4 / 3.0 * pi);
  // Cylinder and cone: the prism and pyramid over the regular n-gon.
  const int n = 11;
  const double base = n / 2.0 * std::sin(2 * pi / n) * 1.5 * 1.5;
  const PolygonMesh<T> cyl = cylinder_mesh<T>(T(1.5), T(2), n);
  EXPECT_EQ(cyl.vertices.size(), 2u * n);
  EXPECT_EQ(face_count(cyl), 2u * n + 2);
  EXPECT_NEAR(volume(cyl), base * 2, double(locus_test::tol<T>(64)) * 10);
  const PolygonMesh<T> con = cone_mesh<T>(T(1.5), T(2), n);
  EXPECT_EQ(con.vertices.size(), n + 1u);
  EXPECT_EQ(face_count(con), n + 1u);
  EXPECT_NEAR(volume(con), base * 2 / 3, double(locus_test::tol<T>(64)) * 10);
  // Torus: nu nv vertices, 2 nu nv triangles, volume tending to 2 pi^2 R r^2 from below.
  const PolygonMesh<T> tor = torus_mesh<T>(T(3), T(1), 48, 24);
  EXPECT_EQ(tor.vertices.size(), 48u * 24);
  EXPECT_EQ(face_count(tor), 2u * 48 * 24);
  EXPECT_GT(volume(tor), 0.97 * 2 * pi * pi * 3);
  EXPECT_LT(volume(tor), 2 * pi * pi * 3);
  // Segment minimums.
  EXPECT_EQ(face_count(cylinder_mesh<T>(T(1), T(1), 1)), 8u);
  EXPECT_EQ(face_count(uv_sphere_mesh<T>(T(1), 0, 0)), 6u);
  EXPECT_EQ(face_count(torus_mesh<T>(T(2), T(1), 2, 2)), 18u);
  EXPECT_EQ(face_count(icosphere_mesh<T>(T(1), -1)), 20u);
}

}  // namespace
