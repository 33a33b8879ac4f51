// SPDX-License-Identifier: BSL-1.0
// Tests for distance/point_mesh.hpp, point_polyhedron.hpp and point_tetrahedron.hpp (row
// dist3.pt-polyhedron; book figure 10.20).
#include <locus/containment/point_in_polyhedron.hpp>
#include <locus/distance/point_mesh.hpp>
#include <locus/distance/point_polyhedron.hpp>
#include <locus/distance/point_tetrahedron.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/hull/hull3.hpp>

#include "distance/harness.hpp"
#include "distance/side_boxes_meshes.hpp"
#include "support/sanitizer.hpp"
#include "support/typed.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

using namespace locus;
using locus_test::Rng;
namespace dist = locus_test::dist;
using Tri = std::array<std::uint32_t, 3>;

template <class T>
class PointMeshTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointMeshTest, locus_test::RealTypes);

namespace {

#if LOCUS_TEST_SANITIZED
constexpr int kScale = 4;  // fewer cases under the sanitizers
#else
constexpr int kScale = 1;
#endif

template <class T>
struct Mesh {
  std::vector<Vec3<T>> v;
  std::vector<Tri> t;
};

// Icosphere: an icosahedron subdivided `levels` times, projected on the sphere (closed, convex
// up to rounding, outward).
template <class T>
Mesh<T> icosphere(int levels, T radius, Vec3<T> centre) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3<double>> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                 {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                 {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<Tri> t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]) * 0.5);
      return mid[key] = static_cast<std::uint32_t>(v.size() - 1);
    };
    std::vector<Tri> next;
    for (const Tri& f : t) {
      const std::uint32_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]),
                          c = midpoint(f[2], f[0]);
      next.push_back({f[0], a, c});
      next.push_back({f[1], b, a});
      next.push_back({f[2], c, b});
      next.push_back({a, b, c});
    }
    t = std::move(next);
  }
  Mesh<T> m;
  for (const auto& p : v) m.v.push_back(centre + vec_cast<T>(normalize(p) * double(radius)));
  m.t = t;
  return m;
}

// A torus grid (closed, non-convex, genus 1).
template <class T>
Mesh<T> torus(int nu, int nv, T big, T small) {
  Mesh<T> m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double a = 6.283185307179586 * i / nu, b = 6.283185307179586 * j / nv;
      const double r = double(big) + double(small) * std::cos(b);
      m.v.push_back(
          Vec3<T>{T(r * std::cos(a)), T(r * std::sin(a)), T(double(small) * std::sin(b))});
    }
  auto id = [&](int i, int j) {
    return static_cast<std::uint32_t>(((i + nu) % nu) * nv + (j + nv) % nv);
  };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// An integer-coordinate closed mesh: the surface of a 3x3x3 block of unit cubes with one cube
// removed at a corner (non-convex), every face split into 2 triangles. Integer query points hit
// vertices, edges and face planes exactly (the degenerate rays of figures 13.18 and 13.19).
template <class T>
Mesh<T> notched_block() {
  auto solid = [](int x, int y, int z) {
    if (x < 0 || y < 0 || z < 0 || x > 2 || y > 2 || z > 2) return false;
    return !(x == 2 && y == 2 && z == 2);
  };
  Mesh<T> m;
  std::map<std::array<int, 3>, std::uint32_t> index;
  auto vid = [&](int x, int y, int z) {
    const std::array<int, 3> k{x, y, z};
    const auto it = index.find(k);
    if (it != index.end()) return it->second;
    m.v.push_back(Vec3<T>{T(x), T(y), T(z)});
    return index[k] = static_cast<std::uint32_t>(m.v.size() - 1);
  };
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) {
        if (!solid(x, y, z)) continue;
        for (int axis = 0; axis < 3; ++axis)
          for (int s = -1; s <= 1; s += 2) {
            int n[3] = {x, y, z};
            n[axis] += s;
            if (solid(n[0], n[1], n[2])) continue;
            // The face at coordinate c along `axis`, outward normal s e_axis.
            const int c = s > 0 ? (axis == 0   ? x
                                   : axis == 1 ? y
                                               : z) +
                                      1
                                : (axis == 0   ? x
                                   : axis == 1 ? y
                                               : z);
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            int base[3] = {x, y, z};
            base[axis] = c;
            auto corner = [&](int du, int dw) {
              int q[3] = {base[0], base[1], base[2]};
              q[u] += du;
              q[w] += dw;
              return vid(q[0], q[1], q[2]);
            };
            const std::uint32_t a = corner(0, 0), b = corner(1, 0), cc = corner(1, 1),
                                d = corner(0, 1);
            if (s > 0) {  // (e_u x e_w) = e_axis: counter-clockwise in (u, w) is outward
              m.t.push_back({a, b, cc});
              m.t.push_back({a, cc, d});
            } else {
              m.t.push_back({a, cc, b});
              m.t.push_back({a, d, cc});
            }
          }
      }
  return m;
}

template <class T>
double brute_mesh(const Vec3<T>& p, const Mesh<T>& m) {
  double best = std::numeric_limits<double>::infinity();
  for (const Tri& t : m.t) {
    const Triangle3<double> tri{vec_cast<double>(m.v[t[0]]), vec_cast<double>(m.v[t[1]]),
                                vec_cast<double>(m.v[t[2]])};
    best = std::min(best, distance(vec_cast<double>(p), tri).distance);
  }
  return best;
}

template <class T>
void check_tree_against_brute(const Mesh<T>& m, Rng& rng, int queries, T spread) {
  const MeshDistanceTree<T> tree(std::span<const Vec3<T>>(m.v), std::span<const Tri>(m.t));
  ASSERT_EQ(tree.status(), Status::ok);
  const double tl = std::is_same_v<T, float> ? 2e-5 : 1e-12;
  for (int n = 0; n < queries; ++n) {
    const Vec3<T> p = n % 3 == 0
                          ? m.v[static_cast<std::size_t>(rng.uniform_int(0, int(m.v.size()) - 1))] +
                                rng.vec<T, 3>(-spread / 20, spread / 20)
                          : rng.vec<T, 3>(-spread, spread);
    const auto r = distance(p, tree);
    const double b = brute_mesh(p, m);
    ASSERT_LT(r.param_b.triangle, m.t.size());
    EXPECT_NEAR(double(r.distance), b, tl * double(spread)) << n;
    // The result's parameter reproduces its point, and the one-call brute force agrees.
    EXPECT_TRUE(locus_test::vec_near(point_at(tree, r.param_b), r.closest[1], T(tl) * spread * 4));
    const auto q = distance_to_mesh(p, std::span<const Vec3<T>>(m.v), std::span<const Tri>(m.t));
    EXPECT_NEAR(q.distance, r.distance, T(tl) * spread);
    const auto s = distance(tree, p);
    EXPECT_EQ(s.sqr_distance, r.sqr_distance);
    EXPECT_EQ(s.param_a, r.param_b);
  }
}

}  // namespace

TYPED_TEST(PointMeshTest, TreeMatchesBruteForce) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 81);
  SCOPED_TRACE(rng.trace());
  check_tree_against_brute(icosphere<T>(3, T(4), Vec3<T>{T(1), T(-2), T(0.5)}), rng, 600 / kScale,
                           T(8));
  check_tree_against_brute(torus<T>(48, 24, T(5), T(1.5)), rng, 600 / kScale, T(9));
  check_tree_against_brute(notched_block<T>(), rng, 300 / kScale, T(4));
  // Triangle soup (open, intersecting, some degenerate triangles).
  Mesh<T> soup;
  for (int i = 0; i < 400; ++i) {
    const auto c = rng.vec<T, 3>(-10, 10);
    soup.v.push_back(c);
    soup.v.push_back(i % 17 == 0 ? c : c + rng.vec<T, 3>(-2, 2));  // zero-length edge sometimes
    soup.v.push_back(i % 13 == 0 ? c + (soup.v.back() - c) * T(2) : c + rng.vec<T, 3>(-2, 2));
    const auto k = static_cast<std::uint32_t>(3 * i);
    soup.t.push_back({k, k + 1, k + 2});
  }
  check_tree_against_brute(soup, rng, 400 / kScale, T(12));
}

// Exact classification: the tree's parity query against the brute-force exact classification
// of containment/point_in_polyhedron.hpp, including integer points on vertices, edges and face
// planes of the notched block (the degenerate rays).
TYPED_TEST(PointMeshTest, ClassifyMatchesContainment) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 83);
  SCOPED_TRACE(rng.trace());
  const Mesh<T> meshes[] = {notched_block<T>(), torus<T>(24, 12, T(4), T(1.5)),
                            icosphere<T>(2, T(3), Vec3<T>{})};
  for (const auto& m : meshes) {
    const MeshDistanceTree<T> tree(std::span<const Vec3<T>>(m.v), std::span<const Tri>(m.t));
    ASSERT_TRUE(tree.closed());
    const auto check = [&](const Vec3<T>& p) {
      const Side want = classify(p, std::span<const Vec3<T>>(m.v), std::span<const Tri>(m.t));
      EXPECT_EQ(classify(p, tree), want) << p.x << " " << p.y << " " << p.z;
      const T sd = signed_distance(p, tree);
      if (want == Side::inside) {
        EXPECT_LE(sd, T(0));
      } else if (want == Side::outside) {
        EXPECT_GT(sd, T(0));
      } else {
        EXPECT_EQ(sd, T(0));
      }
    };
    for (int n = 0; n < 1500 / kScale; ++n) check(rng.vec<T, 3>(-6, 6));
    for (const auto& v : m.v) check(v);
  }
  // Every half-integer point of the notched block's surroundings.
  const auto block = notched_block<T>();
  const MeshDistanceTree<T> tree(std::span<const Vec3<T>>(block.v), std::span<const Tri>(block.t));
  int inside = 0, boundary = 0;
  for (int x = -1; x <= 7; ++x)
    for (int y = -1; y <= 7; ++y)
      for (int z = -1; z <= 7; ++z) {
        const Vec3<T> p{T(x) / 2, T(y) / 2, T(z) / 2};
        const Side want =
            classify(p, std::span<const Vec3<T>>(block.v), std::span<const Tri>(block.t));
        EXPECT_EQ(classify(p, tree), want) << x << " " << y << " " << z;
        inside += want == Side::inside;
        boundary += want == Side::boundary;
      }
  EXPECT_GT(inside, 100);  // the test is not vacuous
  EXPECT_GT(boundary, 100);
}

TYPED_TEST(PointMeshTest, ConvexPolyhedronAndTetrahedron) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 85);
  SCOPED_TRACE(rng.trace());
  const double tl = std::is_same_v<T, float> ? 2e-5 : 1e-12;
  // Convex polyhedra from the hulls of random points.
  for (int h = 0; h < 20; ++h) {
    std::vector<Vec3<T>> pts;
    for (int i = 0; i < 30; ++i) pts.push_back(rng.vec<T, 3>(-5, 5));
    const auto hull = convex_hull(pts);
    ASSERT_EQ(hull.dimension, 3);
    const std::span<const Vec3<T>> v(pts);
    const std::span<const Tri> t(hull.triangles);
    for (int n = 0; n < 200 / kScale; ++n) {
      const Vec3<T> p = n % 10 == 0 ? pts[hull.vertices[0]] : rng.vec<T, 3>(-8, 8);
      const auto r = distance_to_convex_polyhedron(p, v, t);
      const Side s = classify_convex(p, v, t);
      double want = 0;
      if (s == Side::outside) {
        Mesh<T> m{pts, hull.triangles};
        want = brute_mesh(p, m);
      }
      EXPECT_NEAR(double(r.distance), want, tl * 8);
      if (s != Side::outside) {
        EXPECT_EQ(r.distance, T(0));
      }
    }
  }
  // Tetrahedra: the harness (never worse than its oracle search, swap, rigid motions; its
  // agreement check stalls on the kinks of the cube-to-simplex map and is replaced by the
  // brute-force oracle below).
  dist::Options<T> opt;
  opt.check_agreement = false;
  dist::check_pairs<T, 3, Vec3<T>, Tetrahedron3<T>>(
      [&](Rng& g) {
        Tetrahedron3<T> tet{
            {g.vec<T, 3>(-5, 5), g.vec<T, 3>(-5, 5), g.vec<T, 3>(-5, 5), g.vec<T, 3>(-5, 5)}};
        if (g.uniform_int(0, 9) == 0) tet.v[3] = (tet.v[0] + tet.v[1]) * T(0.5);  // flat (nearly)
        return std::pair{g.vec<T, 3>(-8, 8), tet};
      },
      opt);
  for (int n = 0; n < 2000 / kScale; ++n) {
    Tetrahedron3<T> tet{
        {rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5), rng.vec<T, 3>(-5, 5)}};
    const Vec3<T> p = rng.vec<T, 3>(-6, 6);
    const auto r = distance(p, tet);
    double want = 0;
    if (classify(p, tet) == Side::outside) {
      want = std::numeric_limits<double>::infinity();
      for (int i = 0; i < 4; ++i) {
        const auto f = face(tet, i);
        want = std::min(
            want, double(distance(vec_cast<double>(p),
                                  Triangle3<double>{vec_cast<double>(f.v0), vec_cast<double>(f.v1),
                                                    vec_cast<double>(f.v2)})
                             .distance));
      }
    }
    EXPECT_NEAR(double(r.distance), want, tl * 8);
    EXPECT_NEAR(double(r.param_b.x + r.param_b.y + r.param_b.z + r.param_b.w), 1.0, tl);
  }
  // Figure 10.20 regions of the unit corner tetrahedron: vertex, edge, face, inside.
  const Tetrahedron3<T> unit{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const T tt = std::is_same_v<T, float> ? T(1e-6) : T(1e-14);
  EXPECT_NEAR(distance(Vec3<T>{-1, -1, -1}, unit).distance, std::sqrt(T(3)), tt);      // vertex 0
  EXPECT_NEAR(distance(Vec3<T>{0.5, -1, -1}, unit).distance, std::sqrt(T(2)), tt);     // edge 01
  EXPECT_NEAR(distance(Vec3<T>{0.25, 0.25, -2}, unit).distance, T(2), tt);             // face z = 0
  EXPECT_NEAR(distance(Vec3<T>{1, 1, 1}, unit).distance, T(2) / std::sqrt(T(3)), tt);  // face 123
  const auto in = distance(Vec3<T>{T(0.1), T(0.2), T(0.3)}, unit);
  EXPECT_EQ(in.distance, T(0));
  EXPECT_NEAR(in.param_b.x, T(0.4), tt);
  EXPECT_NEAR(in.param_b.w, T(0.3), tt);
}

TYPED_TEST(PointMeshTest, BadInput) {
  using T = TypeParam;
  using V = Vec3<T>;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const std::vector<V> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Tri> t = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto sv = std::span<const V>(v);
  // Empty mesh.
  const MeshDistanceTree<T> empty(sv, std::span<const Tri>());
  EXPECT_EQ(empty.status(), Status::empty_input);
  EXPECT_TRUE(dist::is_nan_result(distance(V{0, 0, 0}, empty)));
  EXPECT_EQ(distance(V{0, 0, 0}, empty).param_b.triangle, MeshPoint<T>::none);
  EXPECT_EQ(classify(V{0, 0, 0}, empty), Side::outside);
  EXPECT_TRUE(std::isnan(signed_distance(V{0, 0, 0}, empty)));
  EXPECT_TRUE(dist::is_nan_result(distance_to_mesh(V{0, 0, 0}, sv, std::span<const Tri>())));
  EXPECT_TRUE(
      dist::is_nan_result(distance_to_convex_polyhedron(V{0, 0, 0}, sv, std::span<const Tri>())));
  const MeshDistanceTree<T> def;
  EXPECT_TRUE(dist::is_nan_result(distance(V{0, 0, 0}, def)));
  // Index out of range and non-finite vertices.
  const std::vector<Tri> bad_t = {{0, 2, 7}};
  EXPECT_EQ(MeshDistanceTree<T>(sv, std::span<const Tri>(bad_t)).status(), Status::invalid_input);
  EXPECT_TRUE(dist::is_nan_result(distance_to_mesh(V{0, 0, 0}, sv, std::span<const Tri>(bad_t))));
  EXPECT_TRUE(dist::is_nan_result(
      distance_to_convex_polyhedron(V{0, 0, 0}, sv, std::span<const Tri>(bad_t))));
  std::vector<V> nv = v;
  nv[3].z = nan;
  const MeshDistanceTree<T> nt{std::span<const V>(nv), std::span<const Tri>(t)};
  EXPECT_EQ(nt.status(), Status::non_finite_input);
  EXPECT_TRUE(dist::is_nan_result(distance(V{0, 0, 0}, nt)));
  EXPECT_TRUE(dist::is_nan_result(
      distance_to_mesh(V{0, 0, 0}, std::span<const V>(nv), std::span<const Tri>(t))));
  // Non-finite query point on a good tree.
  const MeshDistanceTree<T> good(sv, std::span<const Tri>(t));
  EXPECT_EQ(good.status(), Status::ok);
  EXPECT_TRUE(good.closed());
  EXPECT_TRUE(dist::is_nan_result(distance(V{nan, 0, 0}, good)));
  EXPECT_EQ(classify(V{nan, 0, 0}, good), Side::outside);
  EXPECT_TRUE(
      dist::is_nan_result(distance(V{nan, 0, 0}, Tetrahedron3<T>{{v[0], v[1], v[2], v[3]}})));
  // An open mesh is reported as not closed; the distance still works.
  const std::vector<Tri> open = {{0, 1, 2}};
  const MeshDistanceTree<T> ot(sv, std::span<const Tri>(open));
  EXPECT_FALSE(ot.closed());
  EXPECT_NEAR(distance(V{0.25, 0.25, 2}, ot).distance, T(2), T(1e-6));
  // One triangle, tetrahedron closed mesh: signed distance inside is negative.
  EXPECT_NEAR(signed_distance(V{T(0.1), T(0.1), T(0.1)}, good), T(-0.1), T(1e-6));
  EXPECT_NEAR(signed_distance(V{2, 0, 0}, good), T(1), T(1e-6));
}
