// SPDX-License-Identifier: BSL-1.0
// The BSP tree of a polyhedron (bsp/bsp3.hpp). Oracles: point classification against the exact
// ray-parity point-in-polyhedron of containment/point_in_polyhedron.hpp (seeded random points,
// grid points on the planes of dyadic solids, vertices and edge midpoints) for a box,
// tetrahedron, octahedron, icosahedron, the non-convex L-shaped prism and rotated copies, in
// all three construction orders; polygon partition: the pieces' areas sum to the polygon's,
// inside / outside pieces have their centroids on the stated side, coplanar squares on a face
// give the exact coincident areas; bad input; 2^k scaling.

#include <locus/bsp/bsp3.hpp>
#include <locus/containment/point_in_polyhedron.hpp>

#include "bsp/solids3.hpp"
#include "support/typed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>

namespace {

using locus::Bsp3;
using locus::Bsp3Location;
using locus::Bsp3Options;
using locus::Bsp3Split;
using locus::Side;
using locus::Status;
using locus::Vec3;
using locus_test::Solid3;

template <class T>
class Bsp3Test : public ::testing::Test {};
TYPED_TEST_SUITE(Bsp3Test, locus_test::RealTypes);

template <class T>
Side oracle(const Solid3<T>& s, const Vec3<T>& p) {
  return locus::classify(p, std::span<const Vec3<T>>(s.v),
                         std::span<const std::array<std::uint32_t, 3>>(s.f));
}

template <class T>
Bsp3<T> tree_of(const Solid3<T>& s, Bsp3Split split, std::uint64_t seed = 7) {
  Bsp3Options o;
  o.split = split;
  o.seed = seed;
  return Bsp3<T>(s.v, s.f, o);
}

template <class T>
std::vector<Solid3<T>> solids() {
  std::vector<Solid3<T>> r;
  r.push_back(locus_test::box3<T>({0, 0, 0}, {2, 1, 4}));
  r.push_back(locus_test::from_mesh(locus::tetrahedron_mesh<T>()));
  r.push_back(locus_test::from_mesh(locus::octahedron_mesh<T>()));
  r.push_back(locus_test::from_mesh(locus::icosahedron_mesh<T>()));
  r.push_back(locus_test::l_prism3<T>());
  // A U-shaped prism: two notches, so planes cut other faces.
  r.push_back(locus_test::u_prism3<T>());
  const double k = 1 / std::sqrt(3.0);
  r.push_back(locus_test::moved(locus_test::l_prism3<T>(), {k, k, k}, 0.7, {0.1, -0.2, 0.3}));
  return r;
}

template <class T>
T area(std::span<const Vec3<T>> poly) {
  Vec3<double> s{0, 0, 0};
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
    s = s + locus::cross(locus::vec_cast<double>(poly[i]) - locus::vec_cast<double>(poly[0]),
                         locus::vec_cast<double>(poly[i + 1]) - locus::vec_cast<double>(poly[0]));
  return static_cast<T>(0.5 * std::sqrt(locus::dot(s, s)));
}

TYPED_TEST(Bsp3Test, ClassifyMatchesPointInPolyhedron) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 31);
  SCOPED_TRACE(rng.trace());
  const auto all = solids<T>();
  for (std::size_t si = 0; si < all.size(); ++si) {
    const Solid3<T>& s = all[si];
    std::vector<Vec3<T>> pts;
    Vec3<T> lo = s.v[0], hi = s.v[0];
    for (const auto& v : s.v)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], v[k]);
        hi[k] = std::max(hi[k], v[k]);
      }
    for (int i = 0; i < 60; ++i) {
      Vec3<T> p;
      for (int k = 0; k < 3; ++k) p[k] = rng.uniform<T>(lo[k] - T(0.3), hi[k] + T(0.3));
      pts.push_back(p);
      // Grid points (quarters): on the planes of the dyadic solids.
      for (int k = 0; k < 3; ++k) p[k] = T(rng.uniform_int(-2, 16)) / T(4);
      pts.push_back(p);
    }
    for (const auto& v : s.v) pts.push_back(v);
    for (const auto& f : s.f) pts.push_back((s.v[f[0]] + s.v[f[1]]) * T(0.5));
    for (const Bsp3Split split :
         {Bsp3Split::first_face, Bsp3Split::balanced, Bsp3Split::random_order}) {
      const Bsp3<T> tree = tree_of(s, split);
      ASSERT_EQ(tree.status(), Status::ok);
      for (const auto& p : pts)
        ASSERT_EQ(tree.classify(p), oracle(s, p)) << "solid " << si << " split " << int(split)
                                                  << " p " << p.x << ' ' << p.y << ' ' << p.z;
    }
  }
}

// Rounded rigid motions make quads slightly non-planar (tiny reflex edges): the cut points
// near a vertex must still be routed to the vertex's side (docs/notes/bsp3.md).
TYPED_TEST(Bsp3Test, RotatedSolidsMatchPointInPolyhedron) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 34);
  SCOPED_TRACE(rng.trace());
  std::vector<Solid3<T>> base;
  base.push_back(locus_test::box3<T>({0, 0, 0}, {2, 1, 4}));
  base.push_back(locus_test::l_prism3<T>());
  base.push_back(locus_test::u_prism3<T>());
  base.push_back(locus_test::from_mesh(locus::icosphere_mesh<T>(T(1.5), 1)));
  for (int motion = 0; motion < 2; ++motion) {
    const Vec3<double> axis = rng.unit<double, 3>();
    const double angle = rng.uniform<double>(0.1, 3.0);
    const Vec3<double> shift = rng.vec<double, 3>(-1, 1);
    for (std::size_t si = 0; si < base.size(); ++si) {
      const Solid3<T> s = locus_test::moved(base[si], axis, angle, shift);
      for (const Bsp3Split split : {Bsp3Split::first_face, Bsp3Split::balanced}) {
        const Bsp3<T> tree = tree_of(s, split);
        for (int i = 0; i < 60; ++i) {
          const Vec3<T> p = rng.vec<T, 3>(T(-4), T(4));
          ASSERT_EQ(tree.classify(p), oracle(s, p))
              << "motion " << motion << " solid " << si << " split " << int(split);
        }
        for (const auto& v : s.v) ASSERT_EQ(tree.classify(v), Side::boundary);
      }
    }
  }
}

TYPED_TEST(Bsp3Test, ConvexSolidsNeedNoSplits) {
  using T = TypeParam;
  for (const auto& m : {locus::tetrahedron_mesh<T>(), locus::icosahedron_mesh<T>()}) {
    const Solid3<T> s = locus_test::from_mesh(m);
    const Bsp3<T> tree = tree_of(s, Bsp3Split::first_face);
    EXPECT_EQ(tree.fragments().size(), s.f.size());
    EXPECT_EQ(tree.depth(), s.f.size());  // every other face is behind each face's plane
  }
  // The L prism's reflex planes cut faces: some splits, every fragment a convex polygon.
  const Bsp3<T> l = tree_of(locus_test::l_prism3<T>(), Bsp3Split::first_face);
  EXPECT_GT(l.fragments().size(), l.faces().size());
}

TYPED_TEST(Bsp3Test, CutPointsStayNearTheirFacePlane) {
  using T = TypeParam;
  const auto all = solids<T>();
  for (const auto& s : all) {
    const Bsp3<T> tree = tree_of(s, Bsp3Split::random_order, 3);
    double m = 0;
    for (const auto& v : s.v)
      for (int k = 0; k < 3; ++k) m = std::max(m, std::abs(double(v[k])));
    const double u = std::numeric_limits<T>::epsilon() / 2;
    for (const auto& fr : tree.fragments()) {
      const auto& t = tree.faces()[fr.face];
      const Vec3<double> a = locus::vec_cast<double>(tree.vertices()[t[0]]),
                         b = locus::vec_cast<double>(tree.vertices()[t[1]]),
                         c = locus::vec_cast<double>(tree.vertices()[t[2]]);
      const Vec3<double> n = locus::cross(b - a, c - a);
      for (std::uint32_t i = fr.first; i < fr.first + fr.count; ++i) {
        const Vec3<double> p = locus::vec_cast<double>(tree.points()[i]);
        const double dist = std::abs(locus::dot(n, p - a)) / std::sqrt(locus::dot(n, n));
        EXPECT_LE(dist, 16 * u * m + 1e-14 * m);
      }
    }
  }
}

TYPED_TEST(Bsp3Test, PartitionAreasAndSides) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 32);
  SCOPED_TRACE(rng.trace());
  const auto all = solids<T>();
  for (std::size_t si = 0; si < all.size(); ++si) {
    const Solid3<T>& s = all[si];
    const Bsp3<T> tree = tree_of(s, Bsp3Split::balanced);
    for (int trial = 0; trial < 12; ++trial) {
      // A random convex quadrilateral: a parallelogram.
      const Vec3<T> o = rng.vec<T, 3>(T(-1), T(2)), e1 = rng.vec<T, 3>(T(-1), T(1)),
                    e2 = rng.vec<T, 3>(T(-1), T(1));
      const std::vector<Vec3<T>> poly = {o, o + e1, o + e1 + e2, o + e2};
      const auto part = tree.partition(poly);
      if (area<T>(poly) < T(1e-3)) continue;
      ASSERT_EQ(part.status, Status::ok);
      double sum = 0;
      for (const auto& piece : part.pieces) {
        const auto pts = std::span<const Vec3<T>>(part.points).subspan(piece.first, piece.count);
        sum += double(area<T>(pts));
        Vec3<T> c{0, 0, 0};
        for (const auto& p : pts) c = c + p;
        c = c / T(pts.size());
        if (area<T>(pts) < T(1e-4)) continue;  // a sliver's centroid is too near its edges
        const Side want = oracle(s, c);
        if (piece.location == Bsp3Location::inside) {
          EXPECT_NE(want, Side::outside) << "solid " << si;
        } else if (piece.location == Bsp3Location::outside) {
          EXPECT_NE(want, Side::inside) << "solid " << si;
        }
      }
      EXPECT_NEAR(sum, double(area<T>(poly)),
                  1e-4 * double(area<T>(poly)) + 64 * double(locus::eps_v<T>))
          << "solid " << si;
    }
  }
}

TYPED_TEST(Bsp3Test, CoincidentSquaresOnAFace) {
  using T = TypeParam;
  // Box [0,2]^3; the square [1,3]x[1,3] at z = 2 half overlaps the top face.
  const Solid3<T> box = locus_test::box3<T>({0, 0, 0}, {2, 2, 2});
  for (const Bsp3Split split :
       {Bsp3Split::first_face, Bsp3Split::balanced, Bsp3Split::random_order}) {
    const Bsp3<T> tree = tree_of(box, split);
    for (const bool up : {true, false}) {
      std::vector<Vec3<T>> sq = {{1, 1, 2}, {3, 1, 2}, {3, 3, 2}, {1, 3, 2}};
      if (!up) std::reverse(sq.begin(), sq.end());
      const auto part = tree.partition(sq);
      ASSERT_EQ(part.status, Status::ok);
      double same = 0, opposite = 0, out = 0, in = 0;
      for (const auto& piece : part.pieces) {
        const double a = double(
            area<T>(std::span<const Vec3<T>>(part.points).subspan(piece.first, piece.count)));
        switch (piece.location) {
          case Bsp3Location::coincident_same:
            same += a;
            break;
          case Bsp3Location::coincident_opposite:
            opposite += a;
            break;
          case Bsp3Location::outside:
            out += a;
            break;
          case Bsp3Location::inside:
            in += a;
            break;
        }
      }
      EXPECT_EQ(up ? same : opposite, 1.0);
      EXPECT_EQ(up ? opposite : same, 0.0);
      EXPECT_EQ(out, 3.0);
      EXPECT_EQ(in, 0.0);
    }
    // A horizontal square through the middle: exactly 4 of its 16 inside.
    const std::vector<Vec3<T>> mid = {{-1, -1, 1}, {3, -1, 1}, {3, 3, 1}, {-1, 3, 1}};
    const auto part = tree.partition(mid);
    double in = 0, total = 0;
    for (const auto& piece : part.pieces) {
      const double a =
          double(area<T>(std::span<const Vec3<T>>(part.points).subspan(piece.first, piece.count)));
      total += a;
      if (piece.location == Bsp3Location::inside) in += a;
    }
    EXPECT_EQ(in, 4.0);
    EXPECT_EQ(total, 16.0);
  }
}

TYPED_TEST(Bsp3Test, BadInput) {
  using T = TypeParam;
  const Solid3<T> box = locus_test::box3<T>({0, 0, 0}, {1, 1, 1});
  Bsp3<T> empty(std::span<const Vec3<T>>{}, {});
  EXPECT_EQ(empty.status(), Status::empty_input);
  EXPECT_EQ(empty.classify({0, 0, 0}), Side::outside);
  const std::vector<Vec3<T>> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const auto p0 = empty.partition(tri);
  EXPECT_EQ(p0.status, Status::ok);
  ASSERT_EQ(p0.pieces.size(), 1u);
  EXPECT_EQ(p0.pieces[0].location, Bsp3Location::outside);

  Solid3<T> nan = box;
  nan.v[3].y = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(Bsp3<T>(nan.v, nan.f).status(), Status::non_finite_input);
  Solid3<T> bad = box;
  bad.f[2][1] = 99;
  EXPECT_EQ(Bsp3<T>(bad.v, bad.f).status(), Status::invalid_input);
  // Only degenerate (collinear) triangles.
  const std::vector<Vec3<T>> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  const std::vector<std::array<std::uint32_t, 3>> flat = {{0, 1, 2}, {0, 0, 1}};
  const Bsp3<T> degenerate(line, flat);
  EXPECT_EQ(degenerate.status(), Status::degenerate_input);
  EXPECT_EQ(degenerate.classify({1, 1, 1}), Side::outside);

  const Bsp3<T> tree(box.v, box.f);
  EXPECT_EQ(tree.classify({std::numeric_limits<T>::quiet_NaN(), 0, 0}), Side::outside);
  EXPECT_EQ(tree.classify({std::numeric_limits<T>::infinity(), 0, 0}), Side::outside);
  EXPECT_EQ(tree.partition(std::span<const Vec3<T>>(tri.data(), 2)).status,
            Status::degenerate_input);
  EXPECT_EQ(tree.partition(line).status, Status::degenerate_input);
  std::vector<Vec3<T>> nan_poly = tri;
  nan_poly[1].z = std::numeric_limits<T>::infinity();
  EXPECT_EQ(tree.partition(nan_poly).status, Status::non_finite_input);
}

TYPED_TEST(Bsp3Test, PowerOfTwoScaling) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 33);
  SCOPED_TRACE(rng.trace());
  const auto all = solids<T>();
  for (const int e : {-20, 12}) {
    const T scale = std::ldexp(T(1), e);
    for (const auto& s : all) {
      Solid3<T> big = s;
      for (auto& v : big.v) v = v * scale;
      const Bsp3<T> a = tree_of(s, Bsp3Split::balanced), b = tree_of(big, Bsp3Split::balanced);
      ASSERT_EQ(a.points().size(), b.points().size());
      for (std::size_t i = 0; i < a.points().size(); ++i)
        ASSERT_EQ(a.points()[i] * scale, b.points()[i]);
      for (int i = 0; i < 40; ++i) {
        const Vec3<T> p = rng.vec<T, 3>(T(-1), T(3));
        ASSERT_EQ(a.classify(p), b.classify(p * scale));
      }
    }
  }
}

// Huge coordinates: the plane values overflow double, the tree must still answer exactly.
TEST(Bsp3HugeTest, OverflowingCutsStayFinite) {
  const double s = 0x1p300;
  Solid3<double> l = locus_test::l_prism3<double>();
  for (auto& v : l.v) v = v * s;
  const Bsp3<double> tree(l.v, l.f, {Bsp3Split::first_face});
  ASSERT_EQ(tree.status(), Status::ok);
  for (const auto& p : tree.points())
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  locus_test::Rng rng(locus_test::test_seed() + 35);
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 100; ++i) {
    const Vec3<double> p = rng.vec<double, 3>(-0.5, 2.5) * s;
    ASSERT_EQ(tree.classify(p), oracle(l, p));
  }
}

TYPED_TEST(Bsp3Test, AnyPointRange) {
  using T = TypeParam;
  const Solid3<T> box = locus_test::box3<T>({0, 0, 0}, {1, 1, 1});
  const auto tree = locus::make_bsp3(box.v, box.f);
  static_assert(std::is_same_v<std::decay_t<decltype(tree)>, Bsp3<T>>);
  EXPECT_EQ(classify(Vec3<T>{T(0.5), T(0.5), T(0.5)}, tree), Side::inside);
  EXPECT_EQ(classify(Vec3<T>{T(0.5), T(0.5), T(1)}, tree), Side::boundary);
}

}  // namespace
