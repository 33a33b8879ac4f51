// SPDX-License-Identifier: BSL-1.0
// Tests of measure/area_volume.hpp, measure/inertia.hpp, measure/formulas.hpp (rows cg.measure,
// formulas). Oracles: exact GMP volumes of meshes with rational vertices (a different reference
// point from the library's), closed forms for boxes and tetrahedra, Monte Carlo integration of
// the centroid and inertia, 2D polygon functions of primitives/polygon.hpp for embedded
// polygons, meshes built independently for the Platonic solids, and identities between the
// appendix C formulas.
#include <locus/measure/area_volume.hpp>
#include <locus/measure/formulas.hpp>
#include <locus/measure/inertia.hpp>

#include <locus/core/rotation.hpp>
#include <locus/primitives/plane.hpp>
#include <locus/primitives/tetrahedron.hpp>
#include <locus/primitives/triangle.hpp>

#include "support/typed.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <vector>

namespace {

using locus::Mat3;
using locus::Status;
using locus::Vec2;
using locus::Vec3;
using locus_test::Rng;
using locus_test::tol;
using Tri = std::array<std::uint32_t, 3>;

template <class T>
class Measure : public ::testing::Test {};
TYPED_TEST_SUITE(Measure, locus_test::RealTypes);

template <class T>
struct Mesh {
  std::vector<Vec3<T>> v;
  std::vector<Tri> t;
  std::span<const Vec3<T>> vs() const { return v; }
  std::span<const Tri> ts() const { return t; }
};

// Box [0, a] x [0, b] x [0, c], outward.
template <class T>
Mesh<T> box_mesh(T a, T b, T c) {
  Mesh<T> m;
  for (int i = 0; i < 8; ++i)
    m.v.push_back({(i & 1) ? a : T(0), ((i >> 1) & 1) ? b : T(0), (i >> 2) ? c : T(0)});
  m.t = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
         {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

// Tetrahedron mesh from four points with outward faces.
template <class T>
Mesh<T> tet_mesh(const std::array<Vec3<T>, 4>& p) {
  Mesh<T> m{{p[0], p[1], p[2], p[3]}, {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
  if (locus::orient3d(p[0], p[1], p[2], p[3]) == locus::Sign::negative)
    for (auto& t : m.t) std::swap(t[1], t[2]);
  return m;
}

// A closed star-shaped mesh: the octahedron's faces subdivided once, vertices pushed radially by
// random integer factors (rational vertices).
template <class T>
Mesh<T> random_star_mesh(Rng& rng) {
  Mesh<T> m;
  m.v = {{T(1), T(0), T(0)},  {T(-1), T(0), T(0)}, {T(0), T(1), T(0)},
         {T(0), T(-1), T(0)}, {T(0), T(0), T(1)},  {T(0), T(0), T(-1)}};
  const std::vector<Tri> base{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                              {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
  auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
    const auto key = std::make_pair(std::min(i, j), std::max(i, j));
    auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    m.v.push_back(m.v[i] + m.v[j]);
    return mid[key] = std::uint32_t(m.v.size() - 1);
  };
  for (const Tri& t : base) {
    const std::uint32_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]),
                        c = midpoint(t[2], t[0]);
    m.t.push_back({t[0], a, c});
    m.t.push_back({a, t[1], b});
    m.t.push_back({c, b, t[2]});
    m.t.push_back({a, b, c});
  }
  for (auto& v : m.v) v = T(rng.uniform_int(2, 9)) * v;
  const Vec3<T> shift{T(rng.uniform_int(-20, 20)), T(rng.uniform_int(-20, 20)),
                      T(rng.uniform_int(-20, 20))};
  for (auto& v : m.v) v += shift;
  return m;
}

template <class T>
Mat3<T> random_rotation(Rng& rng) {
  return locus::to_matrix(locus::AxisAngle<T>{rng.unit<T, 3>(), rng.uniform(T(0), T(3))});
}

template <class T>
::testing::AssertionResult mat_near(const Mat3<T>& a, const Mat3<T>& b, T abs_tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!(std::abs(a(i, j) - b(i, j)) <= abs_tol))
        return ::testing::AssertionFailure()
               << "entry " << i << j << ": " << a(i, j) << " vs " << b(i, j);
  return ::testing::AssertionSuccess();
}

// ---- 3D polygons ---------------------------------------------------------------------------

TYPED_TEST(Measure, Polygon3AreaMatchesEmbedded2D) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200; ++it) {
    // A star polygon in the plane, embedded by a rotation and translation.
    const int n = rng.uniform_int(3, 12);
    std::vector<Vec2<T>> p2;
    for (int i = 0; i < n; ++i) {
      const T a = T(2) * locus::pi_v<T> * (T(i) + rng.uniform(T(0), T(0.9))) / T(n);
      const T r = rng.uniform(T(0.5), T(3));
      p2.push_back({r * std::cos(a), r * std::sin(a)});
    }
    const Mat3<T> rot = random_rotation<T>(rng);
    const Vec3<T> shift = rng.vec<T, 3>(T(-50), T(50));
    std::vector<Vec3<T>> p3;
    for (const auto& q : p2) p3.push_back(rot * Vec3<T>{q.x, q.y, T(0)} + shift);
    const T a2 = locus::polygon_area(std::span<const Vec2<T>>(p2));
    const T a3 = locus::polygon_area(std::span<const Vec3<T>>(p3));
    // The embedding rounds each vertex by about eps * 50; areas of order 10.
    EXPECT_NEAR(a3, a2, tol<T>(400, T(10)));
    // Direction: the rotated +z times the signed 2D area. The vertices go round the origin by
    // increasing angle, but for n = 3 an angular gap can exceed pi, the origin falls outside
    // and the triangle may be clockwise (seeds 2, 4, 5), so the sign is not always +.
    const T s2 = locus::polygon_signed_area(std::span<const Vec2<T>>(p2));
    const Vec3<T> va = locus::polygon_vector_area(std::span<const Vec3<T>>(p3));
    EXPECT_TRUE(
        locus_test::vec_near(va, s2 * (rot * Vec3<T>{T(0), T(0), T(1)}), tol<T>(400, T(10))));
    // Newell's normal of plane.hpp is twice the vector area.
    EXPECT_TRUE(locus_test::vec_near(T(0.5) * locus::newell_normal(std::span<const Vec3<T>>(p3)),
                                     va, tol<T>(4000, T(10))));
    const Vec2<T> c2 = locus::polygon_centroid(std::span<const Vec2<T>>(p2));
    const Vec3<T> c3 = locus::polygon_centroid(std::span<const Vec3<T>>(p3));
    EXPECT_TRUE(
        locus_test::vec_near(c3, rot * Vec3<T>{c2.x, c2.y, T(0)} + shift, tol<T>(400, T(50))));
  }
  EXPECT_EQ(locus::polygon_area(std::span<const Vec3<T>>()), T(0));
  EXPECT_EQ(locus::polygon_centroid(std::span<const Vec3<T>>()), (Vec3<T>{}));
}

// ---- polyhedra -------------------------------------------------------------------------------

TYPED_TEST(Measure, MeshVolumeVsExactRational) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 100; ++it) {
    const Mesh<T> m = random_star_mesh<T>(rng);
    // Exact: sum of det[a, b, c] / 6 about the coordinate origin (the library uses the box
    // centre); the absolute sum bounds the rounding.
    mpq_class exact = 0;
    double magnitude = 0;
    for (const Tri& t : m.t) {
      const Vec3<T>&a = m.v[t[0]], &b = m.v[t[1]], &c = m.v[t[2]];
      const mpq_class ax(double(a.x)), ay(double(a.y)), az(double(a.z));
      const mpq_class bx(double(b.x)), by(double(b.y)), bz(double(b.z));
      const mpq_class cx(double(c.x)), cy(double(c.y)), cz(double(c.z));
      exact += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
      magnitude += std::abs(double(locus::dot(a - m.v[0], locus::cross(b - m.v[0], c - m.v[0]))));
    }
    exact /= 6;
    const T vol = locus::mesh_signed_volume(m.vs(), m.ts());
    EXPECT_NEAR(double(vol), exact.get_d(), double(tol<T>(8, T(magnitude))) + 1e-12 * magnitude);
    const auto mp = locus::mass_properties(m.vs(), m.ts());
    EXPECT_EQ(mp.status, Status::ok);
    EXPECT_NEAR(double(mp.volume), exact.get_d(),
                double(tol<T>(8, T(magnitude))) + 1e-12 * magnitude);
  }
}

TYPED_TEST(Measure, BoxClosedForms) {
  using T = TypeParam;
  const T a = T(2), b = T(3), c = T(5);
  Mesh<T> m = box_mesh(a, b, c);
  for (auto& v : m.v) v += Vec3<T>{T(10), T(-4), T(7)};
  const auto mp = locus::mass_properties(m.vs(), m.ts(), T(2));
  ASSERT_EQ(mp.status, Status::ok);
  EXPECT_NEAR(mp.volume, a * b * c, tol<T>(16, T(30)));
  EXPECT_NEAR(mp.mass, T(2) * a * b * c, tol<T>(16, T(60)));
  EXPECT_TRUE(
      locus_test::vec_near(mp.centroid, Vec3<T>{T(11), T(-2.5), T(9.5)}, tol<T>(16, T(10))));
  const T mass = T(2) * a * b * c;
  const Mat3<T> expect =
      Mat3<T>::diagonal(Vec3<T>{mass * (b * b + c * c) / T(12), mass * (a * a + c * c) / T(12),
                                mass * (a * a + b * b) / T(12)});
  EXPECT_TRUE(mat_near(mp.inertia, expect, tol<T>(64, T(300))));
  EXPECT_NEAR(locus::mesh_surface_area(m.vs(), m.ts()), T(2) * (a * b + b * c + c * a),
              tol<T>(16, T(62)));
  // Reversed triangles (inward normals): negative signed volume, the same solid properties.
  Mesh<T> inward = m;
  for (auto& t : inward.t) std::swap(t[1], t[2]);
  EXPECT_NEAR(locus::mesh_signed_volume(inward.vs(), inward.ts()), -a * b * c, tol<T>(16, T(30)));
  const auto mi = locus::mass_properties(inward.vs(), inward.ts(), T(2));
  EXPECT_NEAR(mi.volume, a * b * c, tol<T>(16, T(30)));
  EXPECT_TRUE(mat_near(mi.inertia, expect, tol<T>(64, T(300))));
}

TYPED_TEST(Measure, TetrahedronClosedForm) {
  using T = TypeParam;
  // The corner tetrahedron (0, e1, e2, e3): V = 1/6, centroid 1/4, inertia about the centroid
  // I_xx = 1/30 - V (1/16 + 1/16) = 1/80, I_xy = -1/120 + V / 16 = 1/480.
  const Mesh<T> m = tet_mesh<T>(
      {Vec3<T>{}, Vec3<T>{T(1), T(0), T(0)}, Vec3<T>{T(0), T(1), T(0)}, Vec3<T>{T(0), T(0), T(1)}});
  const auto mp = locus::mass_properties(m.vs(), m.ts());
  ASSERT_EQ(mp.status, Status::ok);
  EXPECT_NEAR(mp.volume, T(1) / T(6), tol<T>(8));
  EXPECT_TRUE(locus_test::vec_near(mp.centroid, Vec3<T>{T(0.25), T(0.25), T(0.25)}, tol<T>(8)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(mp.inertia(i, j), i == j ? T(1) / T(80) : T(1) / T(480), tol<T>(8)) << i << j;
  // Its volume equals Tetrahedron3's.
  const locus::Tetrahedron3<T> tet{{m.v[0], m.v[1], m.v[2], m.v[3]}};
  EXPECT_NEAR(locus::mesh_volume(m.vs(), m.ts()), locus::volume(tet), tol<T>(8));
}

TYPED_TEST(Measure, CentroidAndInertiaVsMonteCarlo) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  std::exponential_distribution<double> expo(1.0);
  int checked = 0;
  for (int it = 0; it < 6; ++it) {
    std::array<Vec3<T>, 4> p;
    for (auto& x : p) x = rng.vec<T, 3>(T(-2), T(2));
    if (std::abs(locus::orient3d_value(p[0], p[1], p[2], p[3])) < 1.0) continue;
    const auto mp = locus::mass_properties(tet_mesh(p).vs(), tet_mesh(p).ts());
    ASSERT_EQ(mp.status, Status::ok);
    ++checked;
    // Uniform samples (Dirichlet(1,1,1,1) barycentric weights).
    const int n = 40000;
    Vec3<double> mean{};
    double s[3][3] = {};
    std::vector<Vec3<double>> pts;
    for (int k = 0; k < n; ++k) {
      double w[4], sum = 0;
      for (double& x : w) sum += (x = expo(rng.engine()));
      Vec3<double> x{};
      for (int i = 0; i < 4; ++i) x += (w[i] / sum) * locus::vec_cast<double>(p[std::size_t(i)]);
      pts.push_back(x);
      mean += x;
    }
    mean = mean / double(n);
    for (const auto& x : pts)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s[i][j] += (x[i] - mean[i]) * (x[j] - mean[j]);
    const double vol = double(mp.volume);
    // Standard error of a coordinate mean is about 1/sqrt(n) times the spread (< 2): 5 sigma.
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(double(mp.centroid[i]), mean[i], 5 * 2.0 / std::sqrt(n));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double cov = s[i][j] / n;
        const double trace = (s[0][0] + s[1][1] + s[2][2]) / n;
        const double expect = vol * ((i == j ? trace : 0.0) - cov);
        EXPECT_NEAR(double(mp.inertia(i, j)), expect, 5 * vol * 8.0 / std::sqrt(n)) << i << j;
      }
  }
  EXPECT_GE(checked, 3);
}

TYPED_TEST(Measure, TransformInvariance) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 40; ++it) {
    const Mesh<T> m = random_star_mesh<T>(rng);
    const auto base = locus::mass_properties(m.vs(), m.ts());
    ASSERT_EQ(base.status, Status::ok);
    const Mat3<T> r = random_rotation<T>(rng);
    const Vec3<T> shift = rng.vec<T, 3>(T(-100), T(100));
    Mesh<T> moved = m;
    for (auto& v : moved.v) v = r * v + shift;
    const auto mp = locus::mass_properties(moved.vs(), moved.ts());
    ASSERT_EQ(mp.status, Status::ok);
    // Scales: coordinates up to ~150, volumes ~1e3..1e4, inertia ~ V * 100.
    const T vs = std::abs(base.volume);
    EXPECT_NEAR(mp.volume, base.volume, tol<T>(2000, vs));
    EXPECT_TRUE(locus_test::vec_near(mp.centroid, r * base.centroid + shift, tol<T>(2000, T(150))));
    const Mat3<T> expect = locus::rotate_inertia(base.inertia, r);
    T scale = T(0);
    for (int i = 0; i < 3; ++i) scale = std::max(scale, std::abs(base.inertia(i, i)));
    EXPECT_TRUE(mat_near(mp.inertia, expect, tol<T>(20000, scale)));
    // Triangle order and vertex rotation within triangles change nothing.
    Mesh<T> shuffled = m;
    std::reverse(shuffled.t.begin(), shuffled.t.end());
    for (auto& t : shuffled.t) std::rotate(t.begin(), t.begin() + 1, t.end());
    const auto ms = locus::mass_properties(shuffled.vs(), shuffled.ts());
    EXPECT_NEAR(ms.volume, base.volume, tol<T>(200, vs));
    EXPECT_TRUE(mat_near(ms.inertia, base.inertia, tol<T>(2000, scale)));
  }
  // Parallel axis: the tensor about a point vs a mesh translated so that point is the origin.
  const Mesh<T> b = box_mesh(T(1), T(2), T(3));
  const auto mp = locus::mass_properties(b.vs(), b.ts());
  const Mat3<T> about0 = locus::inertia_about(mp.inertia, mp.mass, mp.centroid, Vec3<T>{});
  // About the corner of the box: I_xx = m (b^2 + c^2) / 3 = 6 * 13 / 3 = 26, I_xy = -m a b / 4.
  EXPECT_NEAR(about0(0, 0), T(26), tol<T>(64, T(26)));
  EXPECT_NEAR(about0(0, 1), -T(6) * T(1) * T(2) / T(4), tol<T>(64, T(26)));
}

TYPED_TEST(Measure, MeshBadInput) {
  using T = TypeParam;
  const Mesh<T> b = box_mesh(T(1), T(1), T(1));
  EXPECT_EQ(locus::mass_properties(b.vs(), std::span<const Tri>()).status, Status::empty_input);
  EXPECT_EQ(locus::mesh_signed_volume(b.vs(), std::span<const Tri>()), T(0));
  Mesh<T> bad = b;
  bad.t.push_back({0, 1, 42});
  EXPECT_EQ(locus::mass_properties(bad.vs(), bad.ts()).status, Status::invalid_input);
  EXPECT_NEAR(locus::mesh_signed_volume(bad.vs(), bad.ts()), T(1), tol<T>(16));  // skipped
  Mesh<T> nan = b;
  nan.v[3].x = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::mass_properties(nan.vs(), nan.ts()).status, Status::non_finite_input);
  EXPECT_EQ(locus::mass_properties(b.vs(), b.ts(), std::numeric_limits<T>::infinity()).status,
            Status::non_finite_input);
  // A flat "solid": both faces of a square.
  Mesh<T> flat{{{T(0), T(0), T(0)}, {T(1), T(0), T(0)}, {T(1), T(1), T(0)}, {T(0), T(1), T(0)}},
               {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}, {0, 3, 2}}};
  const auto mf = locus::mass_properties(flat.vs(), flat.ts());
  EXPECT_EQ(mf.status, Status::degenerate_input);
  EXPECT_EQ(mf.mass, T(0));
  EXPECT_TRUE(locus_test::vec_near(mf.centroid, Vec3<T>{T(0.5), T(0.5), T(0)}, tol<T>(4)));
}

// ---- 2D mass properties -------------------------------------------------------------------

TYPED_TEST(Measure, Polygon2MassProperties) {
  using T = TypeParam;
  // Rectangle w x h: second moments w^3 h / 12 and w h^3 / 12 about the centroid.
  const locus::Polygon2<T> rect{{{T(1), T(1)}, {T(5), T(1)}, {T(5), T(3)}, {T(1), T(3)}}};
  const auto mp = locus::mass_properties(rect, T(3));
  ASSERT_EQ(mp.status, Status::ok);
  EXPECT_NEAR(mp.area, T(8), tol<T>(8, T(8)));
  EXPECT_NEAR(mp.mass, T(24), tol<T>(8, T(24)));
  EXPECT_TRUE(locus_test::vec_near(mp.centroid, Vec2<T>{T(3), T(2)}, tol<T>(8, T(3))));
  EXPECT_NEAR(mp.second_moment(0, 0), T(3) * T(64) * T(2) / T(12), tol<T>(32, T(32)));
  EXPECT_NEAR(mp.second_moment(1, 1), T(3) * T(4) * T(8) / T(12), tol<T>(32, T(32)));
  EXPECT_NEAR(mp.second_moment(0, 1), T(0), tol<T>(32, T(32)));
  EXPECT_NEAR(mp.polar_moment, T(40), tol<T>(32, T(40)));
  // Random polygons: area and centroid as polygon.hpp; clockwise gives the same values; the
  // rotated polygon's tensor is R M R^T.
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 100; ++it) {
    locus::Polygon2<T> p;
    const int n = rng.uniform_int(3, 10);
    for (int i = 0; i < n; ++i) {
      const T a = T(2) * locus::pi_v<T> * (T(i) + rng.uniform(T(0), T(0.9))) / T(n);
      const T r = rng.uniform(T(0.5), T(3));
      p.vertices.push_back({r * std::cos(a) + T(7), r * std::sin(a) - T(3)});
    }
    const auto m0 = locus::mass_properties(p);
    EXPECT_NEAR(m0.area, locus::area(p), tol<T>(64, T(30)));
    EXPECT_TRUE(locus_test::vec_near(m0.centroid, locus::centroid(p), tol<T>(64, T(10))));
    locus::Polygon2<T> cw{{p.vertices.rbegin(), p.vertices.rend()}};
    const auto m1 = locus::mass_properties(cw);
    EXPECT_NEAR(m1.polar_moment, m0.polar_moment, tol<T>(256, T(100)));
    const T t = rng.uniform(T(0), T(6));
    const T c = std::cos(t), s = std::sin(t);
    locus::Polygon2<T> rot;
    for (const auto& v : p.vertices) rot.vertices.push_back({c * v.x - s * v.y, s * v.x + c * v.y});
    const auto m2 = locus::mass_properties(rot);
    const auto& a = m0.second_moment;
    const T rxx = c * c * a(0, 0) - T(2) * c * s * a(0, 1) + s * s * a(1, 1);
    const T rxy = c * s * (a(0, 0) - a(1, 1)) + (c * c - s * s) * a(0, 1);
    EXPECT_NEAR(m2.second_moment(0, 0), rxx, tol<T>(1024, T(100)));
    EXPECT_NEAR(m2.second_moment(0, 1), rxy, tol<T>(1024, T(100)));
    EXPECT_NEAR(m2.polar_moment, m0.polar_moment, tol<T>(1024, T(100)));
  }
  EXPECT_EQ(locus::mass_properties(locus::Polygon2<T>{}).status, Status::empty_input);
  const locus::Polygon2<T> line{{{T(0), T(0)}, {T(1), T(1)}, {T(2), T(2)}}};
  EXPECT_EQ(locus::mass_properties(line).status, Status::degenerate_input);
  const locus::Polygon2<T> nanp{
      {{T(0), T(0)}, {std::numeric_limits<T>::quiet_NaN(), T(1)}, {T(2), T(0)}}};
  EXPECT_EQ(locus::mass_properties(nanp).status, Status::non_finite_input);
}

// ---- appendix C formulas --------------------------------------------------------------------

TYPED_TEST(Measure, TriangleAndQuadrilateralFormulas) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int it = 0; it < 200; ++it) {
    const locus::Triangle2<T> tri{rng.vec<T, 2>(T(-5), T(5)), rng.vec<T, 2>(T(-5), T(5)),
                                  rng.vec<T, 2>(T(-5), T(5))};
    const T a = locus::length(tri.v1 - tri.v2), b = locus::length(tri.v2 - tri.v0),
            c = locus::length(tri.v0 - tri.v1);
    const T k = locus::area(tri);
    // Heron from rounded sides: error ~ eps * (longest side)^2 / (shortest altitude) at worst;
    // compare on well-shaped triangles only.
    if (k < T(1)) continue;
    EXPECT_NEAR(locus::triangle_area_from_sides(a, b, c), k, tol<T>(64, T(50)));
    EXPECT_NEAR(locus::triangle_inradius(a, b, c) * (a + b + c) / T(2), k, tol<T>(64, T(50)));
    EXPECT_NEAR(locus::triangle_circumradius(a, b, c),
                a / (T(2) * std::sin(std::acos((b * b + c * c - a * a) / (T(2) * b * c)))),
                tol<T>(4096, T(50)));
    // A convex quadrilateral: diagonal formula, shoelace, Bretschneider, centroid.
    const Vec2<T> d = tri.v0 + tri.v2 - tri.v1;  // parallelogram completion: convex
    const std::vector<Vec2<T>> quad{tri.v0, tri.v1, tri.v2, d};
    const T shoelace = locus::polygon_area(std::span<const Vec2<T>>(quad));
    EXPECT_NEAR(locus::quadrilateral_area(tri.v0, tri.v1, tri.v2, d), shoelace, tol<T>(64, T(100)));
    EXPECT_NEAR(locus::parallelogram_area(tri.v1 - tri.v0, tri.v2 - tri.v1), shoelace,
                tol<T>(64, T(100)));
    EXPECT_TRUE(locus_test::vec_near(locus::quadrilateral_centroid(tri.v0, tri.v1, tri.v2, d),
                                     T(0.5) * (tri.v0 + tri.v2), tol<T>(64, T(10))));
    EXPECT_NEAR(locus::quadrilateral_perimeter(tri.v0, tri.v1, tri.v2, d), T(2) * (a + c),
                tol<T>(16, T(40)));
    auto angle = [](Vec2<T> u, Vec2<T> w) {
      return std::atan2(std::abs(locus::perp_dot(u, w)), locus::dot(u, w));
    };
    const T alpha = angle(tri.v1 - tri.v0, d - tri.v0), gamma = angle(tri.v1 - tri.v2, d - tri.v2);
    const T side[4] = {locus::length(tri.v1 - tri.v0), locus::length(tri.v2 - tri.v1),
                       locus::length(d - tri.v2), locus::length(tri.v0 - d)};
    EXPECT_NEAR(
        locus::quadrilateral_area_bretschneider(side[0], side[1], side[2], side[3], alpha, gamma),
        shoelace, std::sqrt(locus::eps_v<T>) * T(100));
    // 3D quadrilateral: the same area after embedding in z = 0 and rotating.
    const Vec3<T> q0{tri.v0.x, tri.v0.y, T(0)}, q1{tri.v1.x, tri.v1.y, T(0)},
        q2{tri.v2.x, tri.v2.y, T(0)}, q3{d.x, d.y, T(0)};
    EXPECT_NEAR(locus::quadrilateral_area(q0, q1, q2, q3), shoelace, tol<T>(64, T(100)));
  }
  EXPECT_NEAR(locus::trapezoid_area(T(2), T(4), T(3)), T(9), tol<T>(4, T(9)));
  EXPECT_TRUE(std::isnan(locus::triangle_area_from_sides(T(1), T(1), T(3))));
  EXPECT_TRUE(
      std::isnan(locus::triangle_area_from_sides(std::numeric_limits<T>::quiet_NaN(), T(1), T(1))));
  EXPECT_EQ(locus::triangle_area_from_sides(T(1), T(2), T(3)), T(0));  // degenerate: exact 0
}

TYPED_TEST(Measure, RegularPolygonAndCircleFormulas) {
  using T = TypeParam;
  for (int n = 3; n <= 12; ++n) {
    // The regular n-gon with circumradius R, built from its vertices.
    const T rr = T(2);
    std::vector<Vec2<T>> v;
    for (int i = 0; i < n; ++i) {
      const T a = T(2) * locus::pi_v<T> * T(i) / T(n);
      v.push_back({rr * std::cos(a), rr * std::sin(a)});
    }
    const T s = locus::length(v[1] - v[0]);
    EXPECT_NEAR(locus::regular_polygon_area(n, s), locus::polygon_area(std::span<const Vec2<T>>(v)),
                tol<T>(64, T(13)));
    EXPECT_NEAR(locus::regular_polygon_perimeter(n, s),
                locus::polygon_perimeter(std::span<const Vec2<T>>(v)), tol<T>(64, T(13)));
    EXPECT_NEAR(locus::regular_polygon_circumradius(n, s), rr, tol<T>(64, T(2)));
    EXPECT_NEAR(locus::regular_polygon_inradius(n, s), locus::length(T(0.5) * (v[0] + v[1])),
                tol<T>(64, T(2)));
  }
  EXPECT_TRUE(std::isnan(locus::regular_polygon_area(2, T(1))));
  // Circle pieces: segment = sector - triangle; small angles agree with the series limit.
  const T r = T(3);
  for (T th : {T(0.01), T(0.3), T(0.7), T(2), T(3.5), T(6)}) {
    const T tri = T(0.5) * r * r * std::sin(th);
    EXPECT_NEAR(locus::circular_segment_area(r, th), locus::circular_sector_area(r, th) - tri,
                tol<T>(64, T(30)));
    EXPECT_NEAR(locus::chord_length(r, th), T(2) * r * std::sin(th / T(2)), tol<T>(4, T(6)));
    EXPECT_NEAR(locus::arc_length(r, th), r * th, tol<T>(4, T(20)));
  }
  // theta - sin theta ~ theta^3 / 6 with full relative accuracy where direct evaluation fails.
  const T small = T(1e-3);
  EXPECT_NEAR(locus::circular_segment_area(T(1), small) / (small * small * small / T(12)), T(1),
              T(1e-5));
  EXPECT_NEAR(locus::annulus_area(T(3), T(2)), T(5) * locus::pi_v<T>, tol<T>(8, T(16)));
}

TYPED_TEST(Measure, SphereAndPyramidFormulas) {
  using T = TypeParam;
  const T r = T(2), pi = locus::pi_v<T>;
  for (T h : {T(0.1), T(1), T(2), T(3.5), T(4)}) {
    // Cap = segment with one base radius sqrt(h (2r - h)) and the other zero.
    const T a2 = h * (T(2) * r - h);
    EXPECT_NEAR(locus::spherical_cap_volume(r, h),
                locus::spherical_segment_volume(std::sqrt(a2), T(0), h), tol<T>(64, T(40)));
    // Sector = cap + cone from the centre (height r - h, base radius^2 a2).
    EXPECT_NEAR(locus::spherical_sector_volume(r, h),
                locus::spherical_cap_volume(r, h) + pi * a2 * (r - h) / T(3), tol<T>(64, T(40)));
  }
  EXPECT_NEAR(locus::spherical_cap_volume(r, T(2) * r), T(4) / T(3) * pi * r * r * r,
              tol<T>(16, T(40)));
  EXPECT_NEAR(locus::spherical_zone_area(r, T(2) * r), T(4) * pi * r * r, tol<T>(16, T(60)));
  // Pyramid frustum = big pyramid - small pyramid (square bases 4 and 1, heights 2h and h).
  const T h = T(3);
  EXPECT_NEAR(locus::pyramid_frustum_volume(T(16), T(4), h),
              locus::pyramid_volume(T(16), T(2) * h) - locus::pyramid_volume(T(4), h),
              tol<T>(16, T(40)));
  EXPECT_NEAR(locus::prism_volume(T(4), h), T(12), tol<T>(4, T(12)));
}

TYPED_TEST(Measure, PlatonicSolidsVsMeshes) {
  using T = TypeParam;
  using locus::PlatonicSolid;
  // Cube of edge 2, octahedron |x|+|y|+|z| <= 1 (edge sqrt 2), tetrahedron from alternate cube
  // corners (edge 2 sqrt 2), icosahedron (0, +-1, +-phi) cyclic (edge 2) with faces found as
  // the triples at mutual distance 2.
  const Mesh<T> cube = box_mesh(T(2), T(2), T(2));
  EXPECT_NEAR(locus::mesh_volume(cube.vs(), cube.ts()),
              locus::platonic_volume(PlatonicSolid::cube, T(2)), tol<T>(16, T(8)));
  EXPECT_NEAR(locus::mesh_surface_area(cube.vs(), cube.ts()),
              locus::platonic_surface_area(PlatonicSolid::cube, T(2)), tol<T>(16, T(24)));
  const Mesh<T> tet = tet_mesh<T>({Vec3<T>{T(0), T(0), T(0)}, Vec3<T>{T(2), T(2), T(0)},
                                   Vec3<T>{T(2), T(0), T(2)}, Vec3<T>{T(0), T(2), T(2)}});
  const T et = T(2) * std::sqrt(T(2));
  EXPECT_NEAR(locus::mesh_volume(tet.vs(), tet.ts()),
              locus::platonic_volume(PlatonicSolid::tetrahedron, et), tol<T>(16, T(8)));
  EXPECT_NEAR(locus::mesh_surface_area(tet.vs(), tet.ts()),
              locus::platonic_surface_area(PlatonicSolid::tetrahedron, et), tol<T>(32, T(14)));
  Mesh<T> oct;
  oct.v = {{T(1), T(0), T(0)},  {T(-1), T(0), T(0)}, {T(0), T(1), T(0)},
           {T(0), T(-1), T(0)}, {T(0), T(0), T(1)},  {T(0), T(0), T(-1)}};
  oct.t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  EXPECT_NEAR(locus::mesh_volume(oct.vs(), oct.ts()),
              locus::platonic_volume(PlatonicSolid::octahedron, std::sqrt(T(2))), tol<T>(16, T(2)));
  EXPECT_NEAR(locus::mesh_surface_area(oct.vs(), oct.ts()),
              locus::platonic_surface_area(PlatonicSolid::octahedron, std::sqrt(T(2))),
              tol<T>(32, T(4)));
  Mesh<T> ico;
  const T phi = (T(1) + std::sqrt(T(5))) / T(2);
  for (int k = 0; k < 3; ++k)
    for (int s1 = -1; s1 <= 1; s1 += 2)
      for (int s2 = -1; s2 <= 1; s2 += 2) {
        Vec3<T> v{};
        v[(k + 1) % 3] = T(s1);
        v[(k + 2) % 3] = T(s2) * phi;
        ico.v.push_back(v);
      }
  auto edge = [&](std::uint32_t i, std::uint32_t j) {
    return std::abs(locus::length(ico.v[i] - ico.v[j]) - T(2)) < T(1e-3);
  };
  for (std::uint32_t i = 0; i < 12; ++i)
    for (std::uint32_t j = i + 1; j < 12; ++j)
      for (std::uint32_t k = j + 1; k < 12; ++k)
        if (edge(i, j) && edge(j, k) && edge(i, k)) {
          Tri t{i, j, k};
          const Vec3<T> n = locus::cross(ico.v[j] - ico.v[i], ico.v[k] - ico.v[i]);
          if (locus::dot(n, ico.v[i]) < T(0)) std::swap(t[1], t[2]);
          ico.t.push_back(t);
        }
  ASSERT_EQ(ico.t.size(), 20u);
  EXPECT_NEAR(locus::mesh_volume(ico.vs(), ico.ts()),
              locus::platonic_volume(PlatonicSolid::icosahedron, T(2)), tol<T>(64, T(20)));
  EXPECT_NEAR(locus::mesh_surface_area(ico.vs(), ico.ts()),
              locus::platonic_surface_area(PlatonicSolid::icosahedron, T(2)), tol<T>(64, T(40)));
  // Dodecahedron: published constants V = 7.6631189606 a^3, A = 20.6457288071 a^2.
  EXPECT_NEAR(locus::platonic_volume(PlatonicSolid::dodecahedron, T(1)), T(7.6631189606), T(1e-5));
  EXPECT_NEAR(locus::platonic_surface_area(PlatonicSolid::dodecahedron, T(1)), T(20.6457288071),
              T(1e-5));
}

}  // namespace
