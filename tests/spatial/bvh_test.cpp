// SPDX-License-Identifier: BSL-1.0
// spatial/bvh.hpp: every ray query against the brute force over all triangles with the same
// watertight_hit() (exactly the same triangle, t, barycentrics), on seeded random meshes (a
// noisy icosphere plus a soup of random triangles) and rays, some aimed exactly at vertices;
// watertightness on closed meshes (rays aimed exactly at vertices and edge points: 0 leaks, one
// hit); bad input; power-of-two scaling; boxes of user objects against brute force; the
// point-mesh distance against distance_to_mesh; every compiled instruction-set version.

#include <locus/distance/batch.hpp>
#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/spatial/bvh.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
using Tris = std::vector<std::array<std::uint32_t, 3>>;
template <class T>
constexpr T inf_v = std::numeric_limits<T>::infinity();

template <class T>
class BvhTest : public ::testing::Test {};
TYPED_TEST_SUITE(BvhTest, locus_test::RealTypes);

template <class T>
struct Soup {
  std::vector<Vec3<T>> v;
  Tris f;
};

template <class T>
T grid(double x) {
  return T(std::round(x * 4096.0) / 4096.0);
}

/// A closed icosphere of radius r with coordinates on the 2^-12 grid (so edge midpoints are
/// exact), optionally with radial noise (still star-shaped about the origin).
template <class T>
Soup<T> icosphere(double r, int levels, Rng* noise) {
  const PolygonMesh<double> m = icosphere_mesh<double>(1.0, levels);
  Soup<T> s;
  for (const auto& p : m.vertices) {
    const double k = r * (noise ? noise->uniform<double>(0.8, 1.2) : 1.0);
    s.v.push_back({grid<T>(k * p.x), grid<T>(k * p.y), grid<T>(k * p.z)});
  }
  s.f = fan_triangles(m);
  return s;
}

/// A noisy icosphere plus random triangles (some tiny, some degenerate) in [-3, 3]^3.
template <class T>
Soup<T> random_scene(Rng& rng) {
  Soup<T> s = icosphere<T>(2.0, 2, &rng);
  for (int i = 0; i < 150; ++i) {
    const Vec3<T> c = rng.vec<T, 3>(T(-3), T(3));
    const T size = rng.uniform<T>(T(0.05), T(1));
    const auto base = static_cast<std::uint32_t>(s.v.size());
    for (int k = 0; k < 3; ++k) s.v.push_back(c + size * rng.vec<T, 3>(T(-1), T(1)));
    if (i % 25 == 0) s.v.back() = s.v[base];  // degenerate: two equal vertices
    s.f.push_back({base, base + 1, base + 2});
  }
  return s;
}

template <class T>
Triangle3<T> tri_of(const Soup<T>& s, std::size_t i) {
  return {s.v[s.f[i][0]], s.v[s.f[i][1]], s.v[s.f[i][2]]};
}

template <class T>
MeshHit<T> brute_closest(const Soup<T>& s, const Ray3<T>& r, T tmax) {
  MeshHit<T> best;
  for (std::size_t i = 0; i < s.f.size(); ++i) {
    const auto h = watertight_hit(r, tri_of(s, i));
    if (!h.hit || !(h.t <= tmax)) continue;
    if (!best || h.t < best.t) best = {static_cast<std::uint32_t>(i), h.t, h.barycentric, h.front};
  }
  return best;
}

template <class T>
std::vector<MeshHit<T>> brute_all(const Soup<T>& s, const Ray3<T>& r, T tmax) {
  std::vector<MeshHit<T>> out;
  for (std::size_t i = 0; i < s.f.size(); ++i) {
    const auto h = watertight_hit(r, tri_of(s, i));
    if (h.hit && h.t <= tmax)
      out.push_back({static_cast<std::uint32_t>(i), h.t, h.barycentric, h.front});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const MeshHit<T>& a, const MeshHit<T>& b) { return a.t < b.t; });
  return out;
}

template <class T>
std::vector<Ray3<T>> random_rays(Rng& rng, const Soup<T>& s, int n) {
  std::vector<Ray3<T>> rays;
  for (int i = 0; i < n; ++i) {
    const Vec3<T> o = rng.vec<T, 3>(T(-4), T(4));
    Vec3<T> d = rng.unit<T, 3>();
    if (i % 3 == 0) d = s.v[static_cast<std::size_t>(rng.uniform_int(0, int(s.v.size()) - 1))] - o;
    if (i % 7 == 0) d = d * T(1e-3);  // a short direction: larger t
    rays.push_back({o, d});
  }
  return rays;
}

TYPED_TEST(BvhTest, RandomScenesMatchBruteForce) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int scene = 0; scene < 2; ++scene) {
    const Soup<T> s = random_scene<T>(rng);
    const Bvh<T> bvh(s.v, s.f, BvhOptions{16, scene == 0 ? 4 : 1});
    ASSERT_EQ(bvh.status(), Status::ok);
    ASSERT_EQ(bvh.primitive_count(), s.f.size());
    const auto rays = random_rays<T>(rng, s, 120);
    int hits = 0;
    for (const auto& r : rays) {
      const T tmax = rng.uniform_int(0, 3) == 0 ? rng.uniform<T>(T(0), T(4)) : inf_v<T>;
      const MeshHit<T> want = brute_closest(s, r, tmax);
      const MeshHit<T> got = bvh.closest_hit(r, tmax);
      ASSERT_EQ(got, want) << "ray " << r.origin.x << " " << r.direction.x;
      hits += want ? 1 : 0;
      EXPECT_EQ(bvh.any_hit(r, tmax), bool(want));
      const auto all = bvh.all_hits(r, tmax);
      const auto all_want = brute_all(s, r, tmax);
      ASSERT_EQ(all.size(), all_want.size());
      for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], all_want[i]);
    }
    EXPECT_GT(hits, 30);  // the comparison is not vacuous
  }
}

TYPED_TEST(BvhTest, BatchesAndEveryInstructionSetAgree) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 1);
  SCOPED_TRACE(rng.trace());
  const Soup<T> s = random_scene<T>(rng);
  const Bvh<T> bvh(s.v, s.f);
  const auto rays = random_rays<T>(rng, s, 100);
  std::vector<MeshHit<T>> want(rays.size());
  std::vector<std::uint8_t> any_want(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    want[i] = brute_closest(s, rays[i], inf_v<T>);
    any_want[i] = want[i] ? 1 : 0;
  }
  const detail::BatchIsa saved = detail::batch_isa();
  for (const auto isa :
       {detail::BatchIsa::baseline, detail::BatchIsa::avx2, detail::BatchIsa::x86_64_v4}) {
    (void)detail::set_batch_isa(isa);
    for (unsigned threads : {1u, 3u}) {
      std::vector<MeshHit<T>> got(rays.size());
      std::vector<std::uint8_t> any(rays.size());
      bvh.closest_hits(rays, got, inf_v<T>, threads);
      bvh.any_hits(rays, any, inf_v<T>, threads);
      EXPECT_EQ(got, want);
      EXPECT_EQ(any, any_want);
    }
  }
  (void)detail::set_batch_isa(saved);
}

/// Rays from the centre aimed exactly at every vertex and edge midpoint (and at random points of
/// edges on the grid) of a closed star-shaped mesh: each must hit exactly once.
template <class T>
void expect_watertight(const Soup<T>& s, Rng& rng, const char* name) {
  SCOPED_TRACE(name);
  const Bvh<T> bvh(s.v, s.f);
  ASSERT_EQ(bvh.status(), Status::ok);
  std::vector<Vec3<T>> targets = s.v;
  for (const auto& f : s.f)
    for (int k = 0; k < 3; ++k) {
      const Vec3<T> a = s.v[f[static_cast<std::size_t>(k)]], b = s.v[f[(k + 1) % 3]];
      targets.push_back(T(0.5) * (a + b));
      // a quarter point: exact on the grid as well
      targets.push_back(T(0.75) * a + T(0.25) * b);
    }
  int leaks = 0, doubles = 0, outside_odd = 0;
  for (const auto& x : targets) {
    const Ray3<T> r{Vec3<T>{}, x};
    const MeshHit<T> h = bvh.closest_hit(r);
    if (!h) ++leaks;
    if (bvh.all_hits(r).size() != 1) ++doubles;
    if (!bvh.any_hit(r)) ++leaks;
    // From outside, through the same target: an even number of crossings.
    Vec3<T> o = rng.vec<T, 3>(T(-8), T(8));
    while (max_abs(o) < T(5)) o = rng.vec<T, 3>(T(-8), T(8));  // outside the mesh
    const Ray3<T> ro{o, x - o};
    if (bvh.all_hits(ro).size() % 2 != 0) ++outside_odd;
  }
  EXPECT_EQ(leaks, 0);
  EXPECT_EQ(doubles, 0);
  EXPECT_EQ(outside_odd, 0);
}

TYPED_TEST(BvhTest, WatertightOnClosedMeshes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  expect_watertight(icosphere<T>(3.0, 1, nullptr), rng, "icosphere");
  expect_watertight(icosphere<T>(3.0, 1, &rng), rng, "noisy icosphere");
  const PolygonMesh<double> cube = hexahedron_mesh<double>();
  Soup<T> c;
  for (const auto& p : cube.vertices)
    c.v.push_back({grid<T>(2 * p.x), grid<T>(2 * p.y), grid<T>(2 * p.z)});
  c.f = fan_triangles(cube);
  expect_watertight(c, rng, "cube");
}

TYPED_TEST(BvhTest, BadInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const Ray3<T> r{{0, 0, -5}, {0, 0, 1}};
  {
    const Bvh<T> empty(std::vector<Vec3<T>>{}, Tris{});
    EXPECT_EQ(empty.status(), Status::empty_input);
    EXPECT_FALSE(empty.closest_hit(r));
    EXPECT_FALSE(empty.any_hit(r));
    EXPECT_TRUE(empty.all_hits(r).empty());
    EXPECT_TRUE(std::isnan(empty.nearest({0, 0, 0}).distance));
    const Bvh<T> none;
    EXPECT_FALSE(none.closest_hit(r));
  }
  const std::vector<Vec3<T>> v = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {2, 2, 2}};
  EXPECT_EQ(Bvh<T>(v, Tris{{0, 1, 7}}).status(), Status::invalid_input);
  std::vector<Vec3<T>> vn = v;
  vn[3].x = nan;
  EXPECT_EQ(Bvh<T>(vn, Tris{{0, 1, 3}}).status(), Status::non_finite_input);
  EXPECT_FALSE(Bvh<T>(vn, Tris{{0, 1, 3}}).closest_hit(r));
  // An unused non-finite vertex is fine.
  const Bvh<T> one(vn, Tris{{0, 1, 2}});
  ASSERT_EQ(one.status(), Status::ok);
  EXPECT_TRUE(one.closest_hit(r));
  for (const Ray3<T>& bad :
       {Ray3<T>{{nan, 0, -5}, {0, 0, 1}}, Ray3<T>{{0, 0, -5}, {0, nan, 1}},
        Ray3<T>{{0, 0, -5}, {0, 0, inf_v<T>}}, Ray3<T>{{0, 0, -5}, {0, 0, 0}}}) {
    EXPECT_FALSE(one.closest_hit(bad));
    EXPECT_FALSE(one.any_hit(bad));
    EXPECT_TRUE(one.all_hits(bad).empty());
  }
  EXPECT_FALSE(one.closest_hit(r, nan));
  EXPECT_FALSE(one.closest_hit(r, T(-1)));
  EXPECT_FALSE(one.closest_hit(r, T(4.5)));  // the hit is at t = 5
  EXPECT_TRUE(one.closest_hit(r, T(5)));     // closed: t == tmax counts
  // Degenerate triangles only: never hit (as watertight_hit), nearest still measures them.
  const std::vector<Vec3<T>> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  const Bvh<T> flat(line, Tris{{0, 1, 2}, {0, 0, 0}});
  ASSERT_EQ(flat.status(), Status::ok);
  EXPECT_FALSE(flat.closest_hit(Ray3<T>{{1, 1, -3}, {0, 0, 1}}));
  EXPECT_FALSE(flat.closest_hit(Ray3<T>{{-1, -1, -1}, {1, 1, 1}}));
  EXPECT_EQ(flat.nearest({1, 1, 1}).distance, T(0));
  // Rays along zero axes on the box planes (infinite reciprocals in the slab test), through a
  // vertex, along an edge, in the triangle's plane: as watertight_hit.
  const Triangle3<T> t0{v[0], v[1], v[2]};
  for (const Ray3<T>& x : {Ray3<T>{{-1, -1, -5}, {0, 0, 1}}, Ray3<T>{{0, -1, -5}, {0, 0, 1}},
                           Ray3<T>{{-3, -1, 0}, {1, 0, 0}}, Ray3<T>{{-3, 0, 0}, {1, 0, 0}},
                           Ray3<T>{{0, 0, 5}, {0, 0, -1}}}) {
    EXPECT_EQ(bool(one.closest_hit(x)), watertight_hit(x, t0).hit);
  }
}

TYPED_TEST(BvhTest, PowerOfTwoScaling) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 2);
  SCOPED_TRACE(rng.trace());
  const Soup<T> s = random_scene<T>(rng);
  const Bvh<T> bvh(s.v, s.f);
  const auto rays = random_rays<T>(rng, s, 60);
  for (const int k : {-40, -3, 5, 30}) {
    const T f = std::ldexp(T(1), k);
    Soup<T> ss = s;
    for (auto& p : ss.v) p = f * p;
    const Bvh<T> scaled(ss.v, ss.f);
    for (const auto& r : rays) {
      const MeshHit<T> a = bvh.closest_hit(r);
      // origin and direction scaled: same t; direction alone scaled by 2: t halves.
      const MeshHit<T> b = scaled.closest_hit(Ray3<T>{f * r.origin, f * r.direction});
      const MeshHit<T> c = bvh.closest_hit(Ray3<T>{r.origin, T(2) * r.direction});
      EXPECT_EQ(a.triangle, b.triangle) << k;
      EXPECT_EQ(a.triangle, c.triangle);
      if (a) {
        EXPECT_EQ(b, brute_closest(ss, Ray3<T>{f * r.origin, f * r.direction}, inf_v<T>));
        EXPECT_EQ(c.t, a.t / 2);
      }
    }
  }
}

TYPED_TEST(BvhTest, NearestMatchesDistanceToMesh) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 3);
  SCOPED_TRACE(rng.trace());
  const Soup<T> s = random_scene<T>(rng);
  const Bvh<T> bvh(s.v, s.f);
  for (int i = 0; i < 150; ++i) {
    Vec3<T> p = rng.vec<T, 3>(T(-5), T(5));
    if (i % 10 == 0) p = s.v[static_cast<std::size_t>(rng.uniform_int(0, int(s.v.size()) - 1))];
    const auto want = distance_to_mesh(p, std::span<const Vec3<T>>(s.v), s.f);
    const auto got = distance(p, bvh);
    EXPECT_EQ(got.param_b.triangle, want.param_b.triangle);
    EXPECT_EQ(got.sqr_distance, want.sqr_distance);
    EXPECT_EQ(got.closest[1], want.closest[1]);
  }
  EXPECT_TRUE(std::isnan(bvh.nearest({inf_v<T>, 0, 0}).distance));
}

TYPED_TEST(BvhTest, BoxesOfUserObjects) {
  using T = TypeParam;
  Rng rng(locus_test::test_seed() + 4);
  SCOPED_TRACE(rng.trace());
  std::vector<AlignedBox3<T>> boxes;
  for (int i = 0; i < 300; ++i) {
    const Vec3<T> c = rng.vec<T, 3>(T(-10), T(10));
    const Vec3<T> h = rng.vec<T, 3>(T(0), T(i % 10 == 0 ? 0 : 1));  // some flat or point boxes
    boxes.push_back({c - h, c + h});
  }
  const Bvh<T> bvh = Bvh<T>::from_boxes(boxes);
  ASSERT_EQ(bvh.status(), Status::ok);
  EXPECT_FALSE(bvh.has_triangles());
  int met = 0;
  for (int q = 0; q < 60; ++q) {
    const Vec3<T> c = rng.vec<T, 3>(T(-10), T(10));
    const Vec3<T> h = rng.vec<T, 3>(T(0), T(3));
    const AlignedBox3<T> qb{c - h, c + h};
    std::vector<std::uint32_t> got, want;
    bvh.visit_overlaps(qb, [&](std::uint32_t id) {
      got.push_back(id);
      return true;
    });
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      bool m = true;
      for (int a = 0; a < 3; ++a)
        m = m && boxes[i].min[a] <= qb.max[a] && qb.min[a] <= boxes[i].max[a];
      if (m) want.push_back(i);
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
    // Rays: every box the ray meets is visited (the visit may include more).
    const Vec3<T> o = rng.vec<T, 3>(T(-12), T(12));
    const Vec3<T> aim = boxes[static_cast<std::size_t>(rng.uniform_int(0, 299))].min;
    const Ray3<T> r{o, q % 2 ? rng.unit<T, 3>() : aim - o};
    std::vector<char> seen(boxes.size(), 0);
    bvh.visit_ray(r, inf_v<T>, [&](std::uint32_t id, T tmax) {
      seen[id] = 1;
      return tmax;
    });
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (intersects(r, boxes[i])) {
        ++met;
        EXPECT_TRUE(seen[i]) << i;
      }
  }
  EXPECT_GT(met, 20);
  EXPECT_EQ(Bvh<T>::from_boxes(std::vector<AlignedBox3<T>>{}).status(), Status::empty_input);
}

}  // namespace
