// SPDX-License-Identifier: BSL-1.0
// Booleans of polyhedra through BSP trees (bsp/bsp3_boolean.hpp). Oracles: exact GMP volumes
// (divergence theorem on the output) against the known volumes of booleans of dyadic boxes
// (whose cuts are representable, so the equality is exact); inclusion-exclusion of volumes for
// rotated solids; a sampling oracle: a random point is inside the output (exact ray-parity
// point-in-polyhedron of containment/) exactly when op(inside A, inside B). Degenerate cases:
// shared faces, identical, disjoint and empty operands, NaN; 2^k scaling.

#include <locus/bsp/bsp3.hpp>
#include <locus/bsp/bsp3_boolean.hpp>
#include <locus/containment/point_in_polyhedron.hpp>

#include "bsp/solids3.hpp"
#include "support/typed.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <span>

namespace {

using locus::MeshBoolean;
using locus::MeshBooleanOp;
using locus::Side;
using locus::Status;
using locus::Vec3;
using locus_test::Solid3;

template <class T>
class Bsp3BooleanTest : public ::testing::Test {};
TYPED_TEST_SUITE(Bsp3BooleanTest, locus_test::RealTypes);

constexpr MeshBooleanOp ops[] = {MeshBooleanOp::union_, MeshBooleanOp::intersection,
                                 MeshBooleanOp::difference, MeshBooleanOp::symmetric_difference};

template <class T>
MeshBoolean<T> run(MeshBooleanOp op, const Solid3<T>& a, const Solid3<T>& b) {
  return locus::mesh_boolean(
      op, std::span<const Vec3<T>>(a.v), std::span<const std::array<std::uint32_t, 3>>(a.f),
      std::span<const Vec3<T>>(b.v), std::span<const std::array<std::uint32_t, 3>>(b.f));
}

template <class T>
Side side(const std::vector<Vec3<T>>& v, const std::vector<std::array<std::uint32_t, 3>>& f,
          const Vec3<T>& p) {
  return locus::classify(p, std::span<const Vec3<T>>(v),
                         std::span<const std::array<std::uint32_t, 3>>(f));
}

bool apply(MeshBooleanOp op, bool a, bool b) {
  switch (op) {
    case MeshBooleanOp::union_:
      return a || b;
    case MeshBooleanOp::intersection:
      return a && b;
    case MeshBooleanOp::difference:
      return a && !b;
    case MeshBooleanOp::symmetric_difference:
      return a != b;
  }
  return false;
}

/// Random points away from both surfaces are inside the result exactly when op(A, B) holds.
template <class T>
void check_sampling(MeshBooleanOp op, const Solid3<T>& a, const Solid3<T>& b,
                    const MeshBoolean<T>& r, locus_test::Rng& rng, T lo, T hi, int count) {
  for (int i = 0; i < count; ++i) {
    const Vec3<T> p = rng.vec<T, 3>(lo, hi);
    const Side sa = side(a.v, a.f, p), sb = side(b.v, b.f, p);
    if (sa == Side::boundary || sb == Side::boundary) continue;
    const Side got = side(r.vertices, r.triangles, p);
    ASSERT_NE(got, Side::boundary);
    ASSERT_EQ(got == Side::inside, apply(op, sa == Side::inside, sb == Side::inside))
        << "op " << int(op) << " p " << p.x << ' ' << p.y << ' ' << p.z;
  }
}

template <class T>
double total_area(const MeshBoolean<T>& r) {
  double s = 0;
  for (const auto& t : r.triangles) {
    const Vec3<double> a = locus::vec_cast<double>(r.vertices[t[0]]),
                       b = locus::vec_cast<double>(r.vertices[t[1]]),
                       c = locus::vec_cast<double>(r.vertices[t[2]]);
    const Vec3<double> n = locus::cross(b - a, c - a);
    s += 0.5 * std::sqrt(locus::dot(n, n));
  }
  return s;
}

/// Directed edges (i, j) used a different number of times than (j, i): 0 for a closed,
/// consistently oriented triangle mesh (T-junctions count).
template <class T>
std::size_t unpaired_edges(const MeshBoolean<T>& r) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const auto& t : r.triangles)
    for (int e = 0; e < 3; ++e) ++count[{t[e], t[(e + 1) % 3]}];
  std::size_t bad = 0;
  for (const auto& [edge, n] : count) {
    const auto it = count.find({edge.second, edge.first});
    if (it == count.end() || it->second != n) ++bad;
  }
  return bad;
}

/// Edges violating the 2-manifold rule: every directed edge (i, j) used exactly once and its
/// reverse exactly once, no triangle with a repeated vertex. 0 for a watertight manifold mesh.
template <class T>
std::size_t non_manifold_edges(const MeshBoolean<T>& r) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  std::size_t bad = 0;
  for (const auto& t : r.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) ++bad;
    for (int e = 0; e < 3; ++e) ++count[{t[e], t[(e + 1) % 3]}];
  }
  for (const auto& [edge, n] : count) {
    const auto it = count.find({edge.second, edge.first});
    if (n != 1 || it == count.end() || it->second != 1) ++bad;
  }
  return bad;
}

/// V - E + F of a closed triangle mesh (E = 3F / 2).
template <class T>
long long euler_characteristic(const MeshBoolean<T>& r) {
  return static_cast<long long>(r.vertices.size()) -
         static_cast<long long>(3 * r.triangles.size() / 2) +
         static_cast<long long>(r.triangles.size());
}

TYPED_TEST(Bsp3BooleanTest, DyadicBoxesExactVolumes) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 41);
  SCOPED_TRACE(rng.trace());
  const T sizes[] = {T(0.5), T(1), T(2)};
  for (int trial = 0; trial < 16; ++trial) {
    Vec3<T> lo[2], hi[2];
    for (int s = 0; s < 2; ++s)
      for (int k = 0; k < 3; ++k) {
        lo[s][k] = T(rng.uniform_int(0, 8)) / T(4);
        hi[s][k] = lo[s][k] + sizes[rng.uniform_int(0, 2)];
      }
    const Solid3<T> a = locus_test::box3<T>(lo[0], hi[0]), b = locus_test::box3<T>(lo[1], hi[1]);
    mpq_class va = 1, vb = 1, vi = 1;
    for (int k = 0; k < 3; ++k) {
      va *= mpq_class(double(hi[0][k] - lo[0][k]));
      vb *= mpq_class(double(hi[1][k] - lo[1][k]));
      const T overlap = std::min(hi[0][k], hi[1][k]) - std::max(lo[0][k], lo[1][k]);
      vi *= mpq_class(double(std::max(overlap, T(0))));
    }
    const mpq_class want[4] = {va + vb - vi, vi, va - vi, va + vb - 2 * vi};
    for (int o = 0; o < 4; ++o) {
      const MeshBoolean<T> r = run(ops[o], a, b);
      ASSERT_EQ(r.status, Status::ok);
      EXPECT_EQ(locus_test::exact_volume(r.vertices, r.triangles), want[o])
          << "trial " << trial << " op " << o;
      // Exact cuts: every T-junction is found and repaired, the surface closes.
      EXPECT_EQ(unpaired_edges(r), 0u) << "trial " << trial << " op " << o;
      check_sampling(ops[o], a, b, r, rng, T(-0.5), T(5), 24);
    }
  }
}

TYPED_TEST(Bsp3BooleanTest, RotatedSolidsVolumesAndSampling) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 42);
  SCOPED_TRACE(rng.trace());
  const Solid3<T> sphere = locus_test::from_mesh(locus::icosphere_mesh<T>(T(1.2), 1));
  const Solid3<T> l = locus_test::l_prism3<T>();
  for (int trial = 0; trial < 1; ++trial) {
    const Solid3<T> box =
        locus_test::moved(locus_test::box3<T>({0, 0, 0}, {1.5, 1, 2}), rng.unit<double, 3>(),
                          rng.uniform<double>(0.2, 3), rng.vec<double, 3>(-0.5, 0.5));
    for (const Solid3<T>* a : {&sphere, &l}) {
      const double va = locus_test::volume(a->v, a->f), vb = locus_test::volume(box.v, box.f);
      double got[4];
      for (int o = 0; o < 4; ++o) {
        const MeshBoolean<T> r = run(ops[o], *a, box);
        ASSERT_EQ(r.status, Status::ok);
        got[o] = locus_test::volume(r.vertices, r.triangles);
        check_sampling(ops[o], *a, box, r, rng, T(-2), T(2.5), 30);
      }
      const double tol = 64 * double(std::numeric_limits<T>::epsilon()) * (va + vb + 1);
      EXPECT_NEAR(got[0] + got[1], va + vb, tol) << "trial " << trial;
      EXPECT_NEAR(got[2], va - got[1], tol) << "trial " << trial;
      EXPECT_NEAR(got[3], got[0] - got[1], tol) << "trial " << trial;
      EXPECT_GE(got[1], -tol);
    }
  }
}

TYPED_TEST(Bsp3BooleanTest, CubesSharingAFace) {
  using T = TypeParam;
  const Solid3<T> a = locus_test::box3<T>({0, 0, 0}, {1, 1, 1}),
                  b = locus_test::box3<T>({1, 0, 0}, {2, 1, 1});
  const MeshBoolean<T> u = run(MeshBooleanOp::union_, a, b);
  ASSERT_EQ(u.status, Status::ok);
  EXPECT_EQ(locus_test::exact_volume(u.vertices, u.triangles), 2);
  EXPECT_EQ(total_area(u), 10.0);  // the shared face is gone
  EXPECT_EQ(unpaired_edges(u), 0u);
  for (const auto& t : u.triangles)
    EXPECT_FALSE(u.vertices[t[0]].x == 1 && u.vertices[t[1]].x == 1 && u.vertices[t[2]].x == 1);
  const MeshBoolean<T> i = run(MeshBooleanOp::intersection, a, b);
  EXPECT_EQ(i.status, Status::ok);
  EXPECT_TRUE(i.triangles.empty());  // touching solids: no volume in common
  const MeshBoolean<T> d = run(MeshBooleanOp::difference, a, b);
  EXPECT_EQ(locus_test::exact_volume(d.vertices, d.triangles), 1);
  EXPECT_EQ(total_area(d), 6.0);
}

// A square hole drilled through the non-convex L prism: a genus-1 result, exact volumes and a
// closed mesh (every cut is dyadic).
TYPED_TEST(Bsp3BooleanTest, HoleThroughLPrism) {
  using T = TypeParam;
  const Solid3<T> l = locus_test::l_prism3<T>();
  const Solid3<T> drill = locus_test::box3<T>({0.25, 0.25, -1}, {0.75, 0.75, 2});
  const MeshBoolean<T> d = run(MeshBooleanOp::difference, l, drill);
  ASSERT_EQ(d.status, Status::ok);
  EXPECT_EQ(locus_test::exact_volume(d.vertices, d.triangles), mpq_class(11, 4));
  EXPECT_EQ(unpaired_edges(d), 0u);
  // Euler characteristic V - E + F = 0 for a closed surface of genus 1.
  const long long e = static_cast<long long>(3 * d.triangles.size() / 2);
  EXPECT_EQ(
      static_cast<long long>(d.vertices.size()) - e + static_cast<long long>(d.triangles.size()),
      0);
  const MeshBoolean<T> i = run(MeshBooleanOp::intersection, l, drill);
  EXPECT_EQ(locus_test::exact_volume(i.vertices, i.triangles), mpq_class(1, 4));
  EXPECT_EQ(unpaired_edges(i), 0u);
  const MeshBoolean<T> u = run(MeshBooleanOp::union_, l, drill);
  EXPECT_EQ(locus_test::exact_volume(u.vertices, u.triangles), mpq_class(7, 2));
  EXPECT_EQ(unpaired_edges(u), 0u);
  locus_test::Rng rng(locus_test::test_seed() + 44);
  SCOPED_TRACE(rng.trace());
  check_sampling(MeshBooleanOp::difference, l, drill, d, rng, T(-0.5), T(2.5), 60);
}

TYPED_TEST(Bsp3BooleanTest, IdenticalAndDisjointOperands) {
  using T = TypeParam;
  const Solid3<T> a = locus_test::l_prism3<T>();
  const double area_a = 2 * 3 + 8;  // caps 3 each, walls 8
  const MeshBoolean<T> u = run(MeshBooleanOp::union_, a, a);
  EXPECT_EQ(locus_test::exact_volume(u.vertices, u.triangles), 3);
  EXPECT_EQ(total_area(u), area_a);  // coincident faces kept once
  EXPECT_EQ(unpaired_edges(u), 0u);
  const MeshBoolean<T> i = run(MeshBooleanOp::intersection, a, a);
  EXPECT_EQ(locus_test::exact_volume(i.vertices, i.triangles), 3);
  EXPECT_EQ(total_area(i), area_a);
  const MeshBoolean<T> d = run(MeshBooleanOp::difference, a, a);
  EXPECT_TRUE(d.triangles.empty());

  Solid3<T> far = a;
  for (auto& v : far.v) v.x += 10;
  const MeshBoolean<T> du = run(MeshBooleanOp::union_, a, far);
  EXPECT_EQ(locus_test::exact_volume(du.vertices, du.triangles), 6);
  EXPECT_TRUE(run(MeshBooleanOp::intersection, a, far).triangles.empty());
  const MeshBoolean<T> dd = run(MeshBooleanOp::difference, a, far);
  EXPECT_EQ(locus_test::exact_volume(dd.vertices, dd.triangles), 3);
  // B's planes still cut A's faces (a BSP plane is unbounded): same surface, more triangles.
  EXPECT_NEAR(total_area(dd), area_a, 1e-9 * area_a);
  EXPECT_EQ(unpaired_edges(dd), 0u);  // the extra cut points were stitched in
}

TYPED_TEST(Bsp3BooleanTest, BadInput) {
  using T = TypeParam;
  const Solid3<T> a = locus_test::box3<T>({0, 0, 0}, {1, 1, 1});
  const Solid3<T> empty;
  const MeshBoolean<T> u = run(MeshBooleanOp::union_, a, empty);
  EXPECT_EQ(u.status, Status::empty_input);
  EXPECT_EQ(locus_test::exact_volume(u.vertices, u.triangles), 1);  // A u {} = A
  const MeshBoolean<T> i = run(MeshBooleanOp::intersection, empty, a);
  EXPECT_EQ(i.status, Status::empty_input);
  EXPECT_TRUE(i.triangles.empty());
  const MeshBoolean<T> d = run(MeshBooleanOp::difference, a, empty);
  EXPECT_EQ(locus_test::exact_volume(d.vertices, d.triangles), 1);

  Solid3<T> nan = a;
  nan.v[5].z = std::numeric_limits<T>::quiet_NaN();
  for (const MeshBooleanOp op : ops) {
    const MeshBoolean<T> r = run(op, a, nan);
    EXPECT_EQ(r.status, Status::non_finite_input);
    EXPECT_TRUE(r.triangles.empty());
  }
  Solid3<T> bad = a;
  bad.f[0][0] = 100;
  EXPECT_EQ(run(MeshBooleanOp::union_, bad, a).status, Status::invalid_input);
}

TYPED_TEST(Bsp3BooleanTest, PowerOfTwoScalingAndTreeOverload) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 43);
  SCOPED_TRACE(rng.trace());
  const Solid3<T> a = locus_test::from_mesh(locus::icosahedron_mesh<T>());
  const Solid3<T> b =
      locus_test::moved(locus_test::l_prism3<T>(), rng.unit<double, 3>(), 1.0, {-0.5, -0.5, -0.5});
  for (const int e : {-30}) {
    const T s = std::ldexp(T(1), e);
    Solid3<T> as = a, bs = b;
    for (auto& v : as.v) v = v * s;
    for (auto& v : bs.v) v = v * s;
    for (const MeshBooleanOp op : ops) {
      const MeshBoolean<T> r = run(op, a, b), rs = run(op, as, bs);
      ASSERT_EQ(r.triangles, rs.triangles);
      ASSERT_EQ(r.vertices.size(), rs.vertices.size());
      for (std::size_t k = 0; k < r.vertices.size(); ++k)
        ASSERT_EQ(r.vertices[k] * s, rs.vertices[k]);
    }
  }
  const locus::Bsp3<T> ta(a.v, a.f), tb(b.v, b.f);
  const MeshBoolean<T> via_trees = locus::mesh_boolean(MeshBooleanOp::difference, ta, tb);
  const MeshBoolean<T> via_meshes = run(MeshBooleanOp::difference, a, b);
  EXPECT_EQ(via_trees.triangles, via_meshes.triangles);
  // Any point range, without spelling the scalar type.
  const MeshBoolean<T> via_ranges =
      locus::mesh_boolean(MeshBooleanOp::difference, a.v, a.f, b.v, b.f);
  EXPECT_EQ(via_ranges.triangles, via_meshes.triangles);
}

/// Randomly rotated and shifted pairs of solids: the output is a watertight 2-manifold mesh
/// (every edge used once in each direction) for union, intersection and difference, and a closed
/// (balanced) one for xor, whose two parts touch along the intersection curve; the volumes agree
/// with inclusion-exclusion, Euler characteristics with the known topology, and random points
/// with the exact point-in-polyhedron of the operands.
TYPED_TEST(Bsp3BooleanTest, RotatedSolidsAreWatertight) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 45);
  SCOPED_TRACE(rng.trace());
  const Solid3<T> shapes[] = {
      locus_test::box3<T>({-0.5, -0.375, -0.625}, {0.5, 0.375, 0.625}),
      locus_test::from_mesh(locus::tetrahedron_mesh<T>()),
      locus_test::from_mesh(locus::icosphere_mesh<T>(T(0.8), 0)),
      locus_test::moved(locus_test::l_prism3<T>(), {0, 0, 1}, 0, {-1, -1, -0.5}),
  };
  const bool convex[] = {true, true, true, false};
  for (int trial = 0; trial < 8; ++trial) {
    const int ia = trial % 4, ib = (trial / 2) % 4;  // every shape against another
    const auto place = [&rng](const Solid3<T>& s) {
      return locus_test::moved(s, rng.unit<double, 3>(), rng.uniform<double>(0.1, 3),
                               rng.vec<double, 3>(-0.3, 0.3));
    };
    const Solid3<T> a = place(shapes[ia]);
    const Solid3<T> b = place(shapes[ib]);
    const double va = locus_test::volume(a.v, a.f), vb = locus_test::volume(b.v, b.f);
    const locus::Bsp3<T> ta(a.v, a.f), tb(b.v, b.f);  // built once for the four operations
    double got[4];
    for (int o = 0; o < 4; ++o) {
      const MeshBoolean<T> r = locus::mesh_boolean(ops[o], ta, tb);
      ASSERT_EQ(r.status, Status::ok);
      got[o] = locus_test::volume(r.vertices, r.triangles);
      if (ops[o] == MeshBooleanOp::symmetric_difference)
        EXPECT_EQ(unpaired_edges(r), 0u) << "trial " << trial;
      else
        EXPECT_EQ(non_manifold_edges(r), 0u) << "trial " << trial << " op " << o;
      // Two overlapping convex solids: union and intersection are balls (sphere surfaces).
      if (convex[ia] && convex[ib] && o < 2 && !r.triangles.empty()) {
        EXPECT_EQ(euler_characteristic(r), 2) << "trial " << trial << " op " << o;
      }
      check_sampling(ops[o], a, b, r, rng, T(-1.5), T(1.5), 8);
    }
    const double tol = 64 * double(std::numeric_limits<T>::epsilon()) * (va + vb + 1);
    EXPECT_NEAR(got[0] + got[1], va + vb, tol) << "trial " << trial;
    EXPECT_NEAR(got[2], va - got[1], tol) << "trial " << trial;
    EXPECT_NEAR(got[3], got[0] - got[1], tol) << "trial " << trial;
  }
}

/// Two overlapping icospheres (80 faces each): watertight union and
/// intersection with the volumes of inclusion-exclusion, sphere topology.
TYPED_TEST(Bsp3BooleanTest, IcospherePairIsWatertight) {
  using T = TypeParam;
  const Solid3<T> s = locus_test::from_mesh(locus::icosphere_mesh<T>(T(1), 1));
  const Solid3<T> a = locus_test::moved(s, {0.6, 0.0, 0.8}, 0.7, {0, 0, 0});
  const Solid3<T> b = locus_test::moved(s, {0.0, 0.6, 0.8}, 1.9, {0.7, 0.3, 0.2});
  const MeshBoolean<T> u = run(MeshBooleanOp::union_, a, b),
                       i = run(MeshBooleanOp::intersection, a, b);
  EXPECT_EQ(non_manifold_edges(u), 0u);
  EXPECT_EQ(non_manifold_edges(i), 0u);
  EXPECT_EQ(euler_characteristic(u), 2);
  EXPECT_EQ(euler_characteristic(i), 2);
  const double va = locus_test::volume(a.v, a.f), vb = locus_test::volume(b.v, b.f);
  EXPECT_NEAR(
      locus_test::volume(u.vertices, u.triangles) + locus_test::volume(i.vertices, i.triangles),
      va + vb, 64 * double(std::numeric_limits<T>::epsilon()) * (va + vb));
}

/// Coincident faces of rotated boxes (the shared face has the same rounded corners in both; its
/// quads are folded by rounding): closed (balanced) output with the right volume, though folds
/// may remain (not asserted 2-manifold, see the header); exactly coplanar partial contact:
/// watertight 2-manifold with the exact volume; boxes touching along an edge or at a corner
/// (non-manifold results): balanced, right volumes; xor of identical operands: no volume.
TYPED_TEST(Bsp3BooleanTest, DegenerateContacts) {
  using T = TypeParam;
  const Vec3<double> axis{0.48, 0.6, 0.64};
  const auto rot = [&axis](const Solid3<T>& s) {
    return locus_test::moved(s, axis, 0.9, {0, 0, 0});
  };
  const double tol = 64 * double(std::numeric_limits<T>::epsilon());
  const Solid3<T> a = rot(locus_test::box3<T>({0, 0, 0}, {1, 1, 1}));
  const Solid3<T> shared = rot(locus_test::box3<T>({1, 0, 0}, {2, 1, 1}));
  const double want_shared[4] = {2, 0, 1, 2}, want_same[4] = {1, 1, 0, 0};
  for (int o = 0; o < 4; ++o) {
    const MeshBoolean<T> r = run(ops[o], a, shared), s = run(ops[o], a, a);
    EXPECT_EQ(unpaired_edges(r), 0u) << "op " << o;
    EXPECT_EQ(unpaired_edges(s), 0u) << "op " << o;
    EXPECT_NEAR(locus_test::volume(r.vertices, r.triangles), want_shared[o], tol) << "op " << o;
    EXPECT_NEAR(locus_test::volume(s.vertices, s.triangles), want_same[o], tol) << "op " << o;
  }
  EXPECT_TRUE(run(MeshBooleanOp::intersection, a, shared).triangles.empty());
  // A smaller box glued on part of a face (exactly coplanar): the face is cut around it.
  const Solid3<T> flat = locus_test::box3<T>({0, 0, 0}, {1, 1, 1});
  const Solid3<T> half = locus_test::box3<T>({1, 0.25, 0.25}, {2, 0.75, 0.75});
  const MeshBoolean<T> uh = run(MeshBooleanOp::union_, flat, half);
  EXPECT_EQ(non_manifold_edges(uh), 0u);
  EXPECT_EQ(euler_characteristic(uh), 2);
  EXPECT_EQ(locus_test::exact_volume(uh.vertices, uh.triangles), mpq_class(5, 4));
  const MeshBoolean<T> xh = run(MeshBooleanOp::symmetric_difference, flat, half);
  EXPECT_EQ(locus_test::exact_volume(xh.vertices, xh.triangles), mpq_class(5, 4));
  // Touching along an edge and at a corner: non-manifold results, still balanced.
  const Solid3<T> edge = rot(locus_test::box3<T>({1, 1, 0}, {2, 2, 1}));
  const Solid3<T> corner = rot(locus_test::box3<T>({1, 1, 1}, {2, 2, 2}));
  for (const Solid3<T>* b : {&edge, &corner}) {
    const MeshBoolean<T> r = run(MeshBooleanOp::union_, a, *b);
    EXPECT_EQ(unpaired_edges(r), 0u);
    EXPECT_NEAR(locus_test::volume(r.vertices, r.triangles), 2, tol);
    const MeshBoolean<T> d = run(MeshBooleanOp::difference, a, *b);
    EXPECT_EQ(unpaired_edges(d), 0u);
    EXPECT_NEAR(locus_test::volume(d.vertices, d.triangles), 1, tol);
  }
}

TYPED_TEST(Bsp3BooleanTest, ComplementIsReversedAndUnbounded) {
  using T = TypeParam;
  locus_test::Rng rng(locus_test::test_seed() + 46);
  SCOPED_TRACE(rng.trace());
  const Solid3<T> a = locus_test::from_mesh(locus::icosphere_mesh<T>(T(1), 1));
  const Solid3<T> b = locus_test::moved(locus_test::box3<T>({0, 0, 0}, {1, 1, 1}),
                                        rng.unit<double, 3>(), 0.8, {-0.2, -0.1, 0});
  const MeshBoolean<T> nb = locus::mesh_complement<T>(b.v, b.f);
  ASSERT_EQ(nb.status, Status::ok);
  ASSERT_EQ(nb.triangles.size(), b.f.size());
  EXPECT_NEAR(locus_test::volume(nb.vertices, nb.triangles), -locus_test::volume(b.v, b.f), 1e-12);
  // A n complement(B) = A - B; its points away from the surfaces agree.
  const locus::Bsp3<T> tnb(nb.vertices, nb.triangles);
  EXPECT_EQ(tnb.classify(Vec3<T>{50, 0, 0}), Side::inside);  // the complement is unbounded
  const MeshBoolean<T> via =
      run(MeshBooleanOp::intersection, a, Solid3<T>{nb.vertices, nb.triangles});
  const MeshBoolean<T> d = run(MeshBooleanOp::difference, a, b);
  EXPECT_EQ(non_manifold_edges(via), 0u);
  EXPECT_NEAR(locus_test::volume(via.vertices, via.triangles),
              locus_test::volume(d.vertices, d.triangles), 1e-5);
  Solid3<T> nan = b;
  nan.v[0].x = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::mesh_complement<T>(nan.v, nan.f).status, Status::non_finite_input);
  EXPECT_EQ(locus::mesh_complement<T>(std::span<const Vec3<T>>(), {}).status, Status::empty_input);
}

}  // namespace
