// SPDX-License-Identifier: BSL-1.0
// Row int3.linear-triangle, watertightness of watertight_hit(): rays and lines aimed EXACTLY at
// vertices and edge points of closed triangle meshes (an octahedron, an icosahedron, random
// convex polyhedra from hull3, and star-shaped non-convex spheres with random radii) must hit
// exactly as the parity of crossings demands: from a point inside a convex mesh every ray hits
// exactly once (0 is a leak, 2 or more a double hit); a ray from the centre of a star-shaped mesh
// hits exactly once; a line through any mesh hits an even number of triangles, and a line
// through a convex one 0 or 2; a ray from outside hits an even number. All coordinates lie on a
// dyadic grid (multiples of 2^-12 below 2^8) so targets, directions and edge midpoints are
// exact in float and double: the rays pass exactly through the vertices and edges. The number of
// rays is about 2.6 * 10^5 per type when optimised (LOCUS_WATERTIGHT_RAYS overrides; the
// unoptimised sanitizer build runs 6000).

#include <locus/hull/hull3.hpp>
#include <locus/intersection/line_triangle.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/segment_triangle.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "support/sanitizer.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;

#if LOCUS_TEST_SANITIZED
[[maybe_unused]] constexpr bool sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
[[maybe_unused]] constexpr bool sanitized = true;
#else
[[maybe_unused]] constexpr bool sanitized = false;
#endif
#else
[[maybe_unused]] constexpr bool sanitized = false;
#endif

long ray_budget() {
  if (const char* s = std::getenv("LOCUS_WATERTIGHT_RAYS")) return std::max(1L, std::atol(s));
#ifdef NDEBUG
  return sanitized ? 6000 : 200000;
#else
  return 6000;  // unoptimised (the sanitizer build): about 8 * 10^3 casts per type
#endif
}

template <class T>
class Watertight : public ::testing::Test {};
TYPED_TEST_SUITE(Watertight, locus_test::RealTypes);

template <class T>
struct Mesh {
  std::string name;
  std::vector<Vec3<T>> v;
  std::vector<std::array<int, 3>> f;  // counter-clockwise seen from outside
  bool convex;
};

template <class T>
T grid(double x) {
  return T(std::round(x * 4096.0) / 4096.0);
}

template <class T>
Mesh<T> octahedron() {
  Mesh<T> m{"octahedron",
            {{3, 0, 0}, {-3, 0, 0}, {0, 3, 0}, {0, -3, 0}, {0, 0, 3}, {0, 0, -3}},
            {},
            true};
  m.f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

template <class T>
Mesh<T> icosahedron(int subdivisions, Rng* radii) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3<double>> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                 {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                 {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& p : v) p = p / std::sqrt(sqr_length(p));
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    const auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (const auto it = mid.find(key); it != mid.end()) return it->second;
      Vec3<double> p = v[static_cast<std::size_t>(a)] + v[static_cast<std::size_t>(b)];
      v.push_back(p / std::sqrt(sqr_length(p)));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> g2;
    for (const auto& t : f) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      g2.push_back({t[0], a, c});
      g2.push_back({t[1], b, a});
      g2.push_back({t[2], c, b});
      g2.push_back({a, b, c});
    }
    f = g2;
  }
  Mesh<T> m{radii ? "star-shaped sphere" : "icosahedron", {}, f, radii == nullptr};
  for (const auto& p : v) {
    const double r = radii ? radii->uniform<double>(1.5, 4.0) : 3.0;
    m.v.push_back({grid<T>(r * p.x), grid<T>(r * p.y), grid<T>(r * p.z)});
  }
  return m;
}

template <class T>
Mesh<T> random_hull(Rng& rng, int n) {
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < n; ++i) {
    const Vec3<T> u = rng.unit<T, 3>();
    const double r = rng.uniform<double>(2.0, 4.0);
    pts.push_back({grid<T>(r * double(u.x)), grid<T>(r * double(u.y)), grid<T>(r * double(u.z))});
  }
  const Hull3Result h = convex_hull(std::span<const Vec3<T>>(pts));
  Mesh<T> m{"random hull", pts, {}, true};
  for (const auto& t : h.triangles)
    m.f.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  return m;
}

template <class T>
Triangle3<T> tri(const Mesh<T>& m, const std::array<int, 3>& f) {
  return {m.v[static_cast<std::size_t>(f[0])], m.v[static_cast<std::size_t>(f[1])],
          m.v[static_cast<std::size_t>(f[2])]};
}

// Exact targets: vertices, edge midpoints and edge points at 1/4, face points at (1, 1, 2)/4.
template <class T>
std::vector<Vec3<T>> targets(const Mesh<T>& m) {
  std::vector<Vec3<T>> out = m.v;
  for (const auto& f : m.f)
    for (int e = 0; e < 3; ++e) {
      const Vec3<T> a = m.v[static_cast<std::size_t>(f[static_cast<std::size_t>(e)])],
                    b = m.v[static_cast<std::size_t>(f[static_cast<std::size_t>((e + 1) % 3)])];
      if (lexicographic_compare(a, b) == Sign::negative) {
        out.push_back((a + b) * T(0.5));
        out.push_back(a + (b - a) * T(0.25));
      }
    }
  for (const auto& f : m.f) {
    const Triangle3<T> t = tri(m, f);
    out.push_back((t.v0 + t.v1 + T(2) * t.v2) * T(0.25));
  }
  return out;
}

struct Tally {
  long rays = 0, leaks = 0, doubles = 0, parity = 0;
};

template <class T, class P>
int count_hits(const Mesh<T>& m, const P& p) {
  int hits = 0;
  for (const auto& f : m.f) hits += watertight_hit(p, tri(m, f)).hit ? 1 : 0;
  return hits;
}

template <class T>
void run_mesh(const Mesh<T>& m, Rng& rng, long budget, Tally& tally) {
  const std::vector<Vec3<T>> tg = targets(m);
  // Every face counter-clockwise from outside, seen from the centre (star-shaped meshes).
  for (const auto& f : m.f) {
    const Triangle3<T> t = tri(m, f);
    ASSERT_EQ(orient3d(t.v0, t.v1, t.v2, Vec3<T>{}), Sign::negative) << m.name;
  }
  const long per_target = std::max(1L, budget / static_cast<long>(tg.size()) / 3);
  for (const Vec3<T>& target : tg) {
    for (long k = 0; k < per_target; ++k) {
      // Inside: the centre (star-shaped) or a random point of the inner half (convex).
      Vec3<T> in{};
      if (m.convex) {
        const Vec3<T> u = rng.unit<T, 3>();
        in = {grid<T>(0.5 * double(u.x)), grid<T>(0.5 * double(u.y)), grid<T>(0.5 * double(u.z))};
      }
      const Vec3<T> out_u = rng.unit<T, 3>();
      const Vec3<T> out{grid<T>(8 * double(out_u.x)), grid<T>(8 * double(out_u.y)),
                        grid<T>(8 * double(out_u.z))};
      const int from_inside = count_hits(m, Ray3<T>{in, target - in});
      const int seg_inside = count_hits(m, Segment3<T>{in, in + T(4) * (target - in)});
      const int line = count_hits(m, Line3<T>{out, target - out});
      const int from_outside = count_hits(m, Ray3<T>{out, target - out});
      tally.rays += 4;
      tally.leaks += (from_inside == 0) + (seg_inside == 0);
      tally.doubles += (from_inside > 1) + (seg_inside > 1);
      tally.parity += (line % 2 != 0) + (from_outside % 2 != 0);
      if (m.convex) tally.doubles += (line > 2) + (from_outside > 2);
      if (from_inside != 1 || seg_inside != 1 || line % 2 || from_outside % 2 ||
          (m.convex && line > 2)) {
        ADD_FAILURE() << m.name << ": target (" << target.x << ", " << target.y << ", " << target.z
                      << "), inside " << in.x << " " << in.y << " " << in.z << ", outside " << out.x
                      << " " << out.y << " " << out.z << ": hits " << from_inside << " "
                      << seg_inside << " " << line << " " << from_outside;
        return;
      }
    }
  }
}

TYPED_TEST(Watertight, RaysThroughVerticesAndEdgesOfClosedMeshes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const long budget = ray_budget();
  Tally tally;
  std::vector<Mesh<T>> meshes = {octahedron<T>(), icosahedron<T>(0, nullptr),
                                 icosahedron<T>(1, nullptr), random_hull<T>(rng, 60),
                                 icosahedron<T>(2, &rng)};
  for (const Mesh<T>& m : meshes) {
    SCOPED_TRACE(m.name);
    ASSERT_GE(m.f.size(), 8u);
    run_mesh(m, rng, budget / static_cast<long>(meshes.size()), tally);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("[ measured ] %ld rays and lines: %ld leaks, %ld double hits, %ld parity errors\n",
              tally.rays, tally.leaks, tally.doubles, tally.parity);
  EXPECT_EQ(tally.leaks, 0);
  EXPECT_EQ(tally.doubles, 0);
  EXPECT_EQ(tally.parity, 0);
  EXPECT_GE(tally.rays, budget / 2);
}

// The closed-set intersects() is NOT watertight-exclusive: at a shared edge both triangles
// report the point (a design check of the two semantics, on the octahedron).
TYPED_TEST(Watertight, ClosedSetCountsSharedEdgesTwice) {
  using T = TypeParam;
  const Mesh<T> m = octahedron<T>();
  const Ray3<T> r{{0, 0, 0}, {1, 1, 0}};  // through the midpoint of the edge (3,0,0)-(0,3,0)
  int closed = 0;
  for (const auto& f : m.f) closed += intersects(r, tri(m, f)) ? 1 : 0;
  EXPECT_EQ(closed, 2);
  EXPECT_EQ(count_hits(m, r), 1);
  // Through the vertex (0, 0, 3): four triangles share it; exactly one is hit.
  const Ray3<T> up{{0, 0, 0}, {0, 0, 1}};
  closed = 0;
  for (const auto& f : m.f) closed += intersects(up, tri(m, f)) ? 1 : 0;
  EXPECT_EQ(closed, 4);
  EXPECT_EQ(count_hits(m, up), 1);
}

}  // namespace
