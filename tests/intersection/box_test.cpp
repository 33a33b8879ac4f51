// SPDX-License-Identifier: BSL-1.0
// Row int3.boxes: linear components against aligned and oriented boxes (slabs), plane-box
// sides, aligned box pairs, oriented box pairs (15 separating axes) and box-sphere, float and
// double. Oracles are independent and exact (GMP rationals): the slab interval of a component
// in rationals (for an oriented box: the slabs |dot(axis_k, x - center)| <= extent_k of the
// data as given); the plane function at all eight corners; box-box by "some edge of one meets
// the other" with the rational slab oracle; Arvo's squared distance in rationals. Aligned-box
// decisions must match exactly on random data and on integer grids (axis-parallel directions,
// rays starting on faces, grazing edges, tangent spheres, planes through corners); oriented-box
// decisions, which go through a rounded frame transform, must match wherever the exact answer
// is stable under a relative perturbation of 1e-9 (and exactly for boxes whose axes are signed
// coordinate axes). Also: points on both objects, swap symmetry, power-of-two scaling, NaN/Inf.

#include <locus/intersection/aligned_box_aligned_box.hpp>
#include <locus/intersection/aligned_box_plane.hpp>
#include <locus/intersection/aligned_box_sphere.hpp>
#include <locus/intersection/line_aligned_box.hpp>
#include <locus/intersection/line_oriented_box.hpp>
#include <locus/intersection/oriented_box_oriented_box.hpp>
#include <locus/intersection/oriented_box_plane.hpp>
#include <locus/intersection/oriented_box_sphere.hpp>
#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_oriented_box.hpp>
#include <locus/intersection/segment_aligned_box.hpp>
#include <locus/intersection/segment_oriented_box.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "intersection/linear3_oracle.hpp"
#include "support/scale_covariance.hpp"
#include "support/typed.hpp"

namespace {

using namespace locus;
using locus_test::Rng;
namespace ex = locus_test::exact3;

template <class T>
class IntersectionBoxes : public ::testing::Test {};
TYPED_TEST_SUITE(IntersectionBoxes, locus_test::RealTypes);

template <class P>
struct Make;
template <class T>
struct Make<Line3<T>> {
  static Line3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
  static constexpr const char* name = "line";
};
template <class T>
struct Make<Ray3<T>> {
  static Ray3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q - p}; }
  static constexpr const char* name = "ray";
};
template <class T>
struct Make<Segment3<T>> {
  static Segment3<T> from(const Vec3<T>& p, const Vec3<T>& q) { return {p, q}; }
  static constexpr const char* name = "segment";
};
template <class T, class F>
void for_each_linear(F&& f) {
  f.template operator()<Line3<T>>();
  f.template operator()<Ray3<T>>();
  f.template operator()<Segment3<T>>();
}

// A box as exact slabs: |dot(axis_k, x - center)| <= extent_k (aligned: axis_k = e_k).
struct QBox {
  ex::Q3 c, a[3];
  mpq_class e[3];
};
template <class T>
QBox qbox(const AlignedBox3<T>& b) {
  const ex::Q3 lo = ex::q(b.min), hi = ex::q(b.max);
  QBox q;
  q.c = mpq_class(1, 2) * (lo + hi);
  const ex::Q3 half = mpq_class(1, 2) * (hi - lo);
  q.a[0] = {1, 0, 0}, q.a[1] = {0, 1, 0}, q.a[2] = {0, 0, 1};
  q.e[0] = half.x, q.e[1] = half.y, q.e[2] = half.z;
  return q;
}
template <class T>
QBox qbox(const OrientedBox3<T>& b) {
  QBox q;
  q.c = ex::q(b.center);
  for (int k = 0; k < 3; ++k) q.a[k] = ex::q(b.axis[k]), q.e[k] = mpq_class(double(b.extent[k]));
  return q;
}

// The exact parameter interval of the component inside the slabs (with a relative margin
// `grow` added to every extent): kind 0 empty, 1 point, 2 segment, and the end parameters.
struct QClip {
  int kind = 0;
  mpq_class t0, t1;
};
inline QClip clip(const ex::QLin& l, const QBox& b, const mpq_class& grow = 0) {
  bool lo_inf = !l.lo, hi_inf = !l.hi;
  mpq_class lo = 0, hi = 1;
  for (int k = 0; k < 3; ++k) {
    // -e <= dot(a, o - c) + t dot(a, d) <= e
    const mpq_class e = b.e[k] * (1 + grow);
    const mpq_class w = ex::qdot(b.a[k], l.o - b.c), s = ex::qdot(b.a[k], l.d);
    if (s == 0) {
      if (w < -e || w > e) return {};
      continue;
    }
    mpq_class ta = (-e - w) / s, tb = (e - w) / s;
    if (ta > tb) std::swap(ta, tb);
    if (lo_inf || ta > lo) lo = ta, lo_inf = false;
    if (hi_inf || tb < hi) hi = tb, hi_inf = false;
  }
  if (lo_inf) {  // zero direction: a point
    return {1, 0, 0};
  }
  if (lo > hi) return {};
  return {lo == hi ? 1 : 2, lo, hi};
}

template <class T>
std::string str(const Vec3<T>& v) {
  char b[160];
  std::snprintf(b, sizeof b, "(%.17g, %.17g, %.17g)", double(v.x), double(v.y), double(v.z));
  return b;
}

template <class T>
double err(const Vec3<T>& p, const ex::Q3& e) {
  return std::max({std::abs(mpq_class(mpq_class(double(p.x)) - e.x).get_d()),
                   std::abs(mpq_class(mpq_class(double(p.y)) - e.y).get_d()),
                   std::abs(mpq_class(mpq_class(double(p.z)) - e.z).get_d())});
}

template <class P>
std::string describe(const P& p) {
  if constexpr (requires { p.p0; })
    return "segment " + str(p.p0) + " " + str(p.p1);
  else
    return "origin " + str(p.origin) + " direction " + str(p.direction);
}

// Checks the linear-box result against the oracle; for oriented boxes only where the exact
// answer is stable (returns false when skipped).
template <class T, class A, class Box>
bool check_linear_box(const A& a, const Box& box, bool exact_expected) {
  SCOPED_TRACE(std::string(Make<A>::name));
  const ex::QLin ql = ex::ql(a);
  const QBox qb = qbox(box);
  const QClip e = clip(ql, qb);
  if (!exact_expected) {
    const mpq_class g("1/1000000000");
    const QClip e_in = clip(ql, qb, -g), e_out = clip(ql, qb, g);
    if ((e_in.kind != 0) != (e_out.kind != 0) || e.kind == 1) return false;
  }
  const LinearBoxIntersection<T> r = intersection(a, box);
  EXPECT_EQ(r.kind == Kind::empty ? 0 : (r.kind == Kind::point ? 1 : 2), e.kind);
  EXPECT_EQ(intersects(a, box), e.kind != 0);
  EXPECT_EQ(intersects(box, a), e.kind != 0);
  const auto s = intersection(box, a);
  EXPECT_EQ(s.kind, r.kind);
  if (e.kind == 0 || r.kind == Kind::empty) return true;
  // End points: near the exact ones, on the component through param_a, and inside the box.
  const double eps = double(eps_v<T>);
  double m = ex::qmax_abs(ql.o) + ex::qmax_abs(ql.d);
  for (int k = 0; k < 3; ++k) m += std::abs(qb.e[k].get_d());
  m += ex::qmax_abs(qb.c);
  for (int i = 0; i < r.count; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const mpq_class t = i == 0 ? e.t0 : e.t1;
    const ex::Q3 x = ql.o + t * ql.d;
    const double bound = 16 * eps * std::max(ex::qmax_abs(x), m);
    EXPECT_LE(err(r.point[k], x), bound) << "entry " << i;
    EXPECT_LE(std::abs(mpq_class(mpq_class(double(r.param_a[k])) - t).get_d()) * ex::qmax_abs(ql.d),
              bound);
    EXPECT_EQ(s.point[k], r.point[k]);
    EXPECT_EQ(s.param_b[k], r.param_a[k]);
  }
  if (r.count == 2) {
    EXPECT_LE(r.param_a[0], r.param_a[1]);
  }
  return true;
}

TYPED_TEST(IntersectionBoxes, LinearAlignedBoxAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int kinds[3] = {0, 0, 0};
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 6000; ++i) {
      const bool grid = i % 2 == 1;
      const auto g = [&](int r) {
        return grid ? Vec3<T>{T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r)),
                              T(rng.uniform_int(-r, r))}
                    : rng.vec<T, 3>(T(-r), T(r));
      };
      const Vec3<T> p = g(2), q = g(2);
      const AlignedBox3<T> box{cwise_min(p, q), cwise_max(p, q)};
      const A a = Make<A>::from(g(3), g(3));
      SCOPED_TRACE(describe(a) + " box " + str(box.min) + " " + str(box.max));
      check_linear_box<T>(a, box, true);
      ++kinds[clip(ex::ql(a), qbox(box)).kind];
      if (::testing::Test::HasFailure()) return;
    }
  });
  EXPECT_GT(kinds[1], 300);  // touching: corners, edges, faces, rays starting on faces
  EXPECT_GT(kinds[2], 1500);
}

}  // namespace

namespace {

// A rotation from a random unit quaternion (rounded: the axes are unit and orthogonal to a few
// eps, the data as given).
template <class T>
std::array<Vec3<T>, 3> random_axes(Rng& rng) {
  const Vec<double, 4> q = rng.unit<double, 4>();
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {Vec3<T>{T(1 - 2 * (y * y + z * z)), T(2 * (x * y + w * z)), T(2 * (x * z - w * y))},
          Vec3<T>{T(2 * (x * y - w * z)), T(1 - 2 * (x * x + z * z)), T(2 * (y * z + w * x))},
          Vec3<T>{T(2 * (x * z + w * y)), T(2 * (y * z - w * x)), T(1 - 2 * (x * x + y * y))}};
}

// Signed permutations of the coordinate axes: exact frames.
template <class T>
std::array<Vec3<T>, 3> signed_permutation(Rng& rng) {
  static constexpr int P[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  const int p = rng.uniform_int(0, 5);
  std::array<Vec3<T>, 3> a{};
  for (int k = 0; k < 3; ++k)
    a[static_cast<std::size_t>(k)][P[p][k]] = rng.uniform_int(0, 1) ? T(1) : T(-1);
  return a;
}

template <class T>
OrientedBox3<T> make_obb(const Vec3<T>& c, const std::array<Vec3<T>, 3>& a, const Vec3<T>& e) {
  return {c, {a[0], a[1], a[2]}, e};
}

TYPED_TEST(IntersectionBoxes, LinearOrientedBoxAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int checked = 0, hits = 0;
  for_each_linear<T>([&]<class A>() {
    for (int i = 0; i < 4000; ++i) {
      const bool exact = i % 2 == 1;  // signed-permutation frames on an integer grid
      const auto g = [&](int r) {
        return exact ? Vec3<T>{T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r)),
                               T(rng.uniform_int(-r, r))}
                     : rng.vec<T, 3>(T(-r), T(r));
      };
      const auto axes = exact ? signed_permutation<T>(rng) : random_axes<T>(rng);
      Vec3<T> e = g(2);
      for (int k = 0; k < 3; ++k) e[k] = std::abs(e[k]);
      const OrientedBox3<T> box = make_obb(g(1), axes, e);
      const A a = Make<A>::from(g(3), g(3));
      SCOPED_TRACE(describe(a) + " box centre " + str(box.center) + " extent " + str(e));
      if (check_linear_box<T>(a, box, exact)) ++checked;
      hits += intersects(a, box) ? 1 : 0;
      if (::testing::Test::HasFailure()) return;
    }
  });
  EXPECT_GT(checked, 11000);
  EXPECT_GT(hits, 3000);
}

// Axis-parallel directions and origins on faces: no NaN (0 * inf) arises, the answer is exact.
TYPED_TEST(IntersectionBoxes, AxisParallelRaysOnFaces) {
  using T = TypeParam;
  const AlignedBox3<T> box{{0, 0, 0}, {2, 2, 2}};
  // Along x in the plane of the face y = 0: touches the face along a segment.
  const auto r = intersection(Ray3<T>{{-1, 0, 1}, {1, 0, 0}}, box);
  ASSERT_EQ(r.kind, Kind::segment);
  EXPECT_EQ(r.point[0], (Vec3<T>{0, 0, 1}));
  EXPECT_EQ(r.point[1], (Vec3<T>{2, 0, 1}));
  EXPECT_EQ(r.param_a[0], T(1));
  EXPECT_EQ(r.param_a[1], T(3));
  // Starting on a face, pointing out: only the origin.
  const auto o = intersection(Ray3<T>{{2, 1, 1}, {1, 0, 0}}, box);
  ASSERT_EQ(o.kind, Kind::point);
  EXPECT_EQ(o.point[0], (Vec3<T>{2, 1, 1}));
  // Starting on a face, pointing in: through the box.
  const auto in = intersection(Ray3<T>{{2, 1, 1}, {-1, 0, 0}}, box);
  ASSERT_EQ(in.kind, Kind::segment);
  EXPECT_EQ(in.param_a[1], T(2));
  // Just outside a face, parallel: misses.
  EXPECT_FALSE(intersects(Line3<T>{{std::nextafter(T(2), T(3)), 1, 1}, {0, 1, 0}}, box));
  // Through an edge exactly (grazing): a point.
  EXPECT_EQ(intersection(Line3<T>{{-1, 1, 1}, {1, -1, 0}}, box).kind, Kind::point);
  // Zero direction: a point inside or on the boundary, else empty.
  EXPECT_EQ(intersection(Ray3<T>{{2, 2, 2}, {0, 0, 0}}, box).kind, Kind::point);
  EXPECT_EQ(intersection(Ray3<T>{{3, 2, 2}, {0, 0, 0}}, box).kind, Kind::empty);
}

TYPED_TEST(IntersectionBoxes, PlaneBoxSidesAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int sides[3] = {0, 0, 0}, touching = 0;
  for (int i = 0; i < 8000; ++i) {
    const bool grid = i % 2 == 1;
    const auto g = [&](int r) {
      return grid ? Vec3<T>{T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r)),
                            T(rng.uniform_int(-r, r))}
                  : rng.vec<T, 3>(T(-r), T(r));
    };
    const Vec3<T> p = g(2), q = g(2);
    const AlignedBox3<T> box{cwise_min(p, q), cwise_max(p, q)};
    Vec3<T> n = g(2);
    if (n == Vec3<T>{}) n.x = 1;
    const Plane3<T> pl{n, grid ? T(rng.uniform_int(-4, 4)) : rng.uniform<T>(-3, 3)};
    // The exact plane function at the eight corners.
    int lo = 2, hi = -2;
    for (int k = 0; k < 8; ++k) {
      const Vec3<T> c{(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                      (k & 4) ? box.max.z : box.min.z};
      const mpq_class v = ex::qdot(ex::q(n), ex::q(c)) - mpq_class(double(pl.constant));
      const int s = v > 0 ? 1 : (v < 0 ? -1 : 0);
      lo = std::min(lo, s), hi = std::max(hi, s);
    }
    const int expected = lo > 0 ? 1 : (hi < 0 ? -1 : 0);
    ASSERT_EQ(to_int(side_of_plane(box, pl)), expected) << i;
    EXPECT_EQ(intersects(box, pl), expected == 0);
    EXPECT_EQ(intersects(pl, box), expected == 0);
    ++sides[expected + 1];
    touching += (expected == 0 && (lo == 0 || hi == 0)) ? 1 : 0;
    // The same box as an oriented box with the coordinate axes: the same answer (exact frame).
    const OrientedBox3<T> ob{(box.min + box.max) * T(0.5),
                             {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                             (box.max - box.min) * T(0.5)};
    if (grid && ob.center * T(2) == box.min + box.max) {
      EXPECT_EQ(side_of_plane(ob, pl), side_of_plane(box, pl)) << i;
    }
  }
  EXPECT_GT(sides[0], 1000);
  EXPECT_GT(sides[1], 1000);
  EXPECT_GT(sides[2], 1000);
  EXPECT_GT(touching, 200);
}

TYPED_TEST(IntersectionBoxes, OrientedBoxPlaneStableCases) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto axes = random_axes<T>(rng);
    Vec3<T> e = rng.vec<T, 3>(0, 2);
    const OrientedBox3<T> box = make_obb(rng.vec<T, 3>(-1, 1), axes, e);
    const Vec3<T> n = rng.unit<T, 3>();
    const Plane3<T> pl{n, rng.uniform<T>(-3, 3)};
    // Exact: the projected radius of the slab box against the centre's value, with margin.
    const ex::Q3 qn = ex::q(n);
    mpq_class r = 0;
    for (int k = 0; k < 3; ++k)
      r += abs(ex::qdot(qn, ex::q(axes[static_cast<std::size_t>(k)]))) * mpq_class(double(e[k]));
    const mpq_class v = ex::qdot(qn, ex::q(box.center)) - mpq_class(double(pl.constant));
    const mpq_class margin = abs(abs(v) - r);
    if (margin < mpq_class(1e-9)) continue;
    const int expected = v > r ? 1 : (v < -r ? -1 : 0);
    EXPECT_EQ(to_int(side_of_plane(box, pl)), expected) << i;
    EXPECT_EQ(intersects(box, pl), expected == 0);
    ++checked;
  }
  EXPECT_GT(checked, 3900);
}

TYPED_TEST(IntersectionBoxes, AlignedBoxPairsExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int meet = 0;
  for (int i = 0; i < 5000; ++i) {
    const auto g = [&] {
      return Vec3<T>{T(rng.uniform_int(-3, 3)), T(rng.uniform_int(-3, 3)),
                     T(rng.uniform_int(-3, 3))};
    };
    const Vec3<T> p = g(), q = g(), r = g(), s = g();
    const AlignedBox3<T> a{cwise_min(p, q), cwise_max(p, q)}, b{cwise_min(r, s), cwise_max(r, s)};
    // Brute force on the half-integer lattice: closed boxes with integer corners meet iff they
    // share a lattice point of spacing 1/2.
    bool found = false;
    for (int x = -6; x <= 6 && !found; ++x)
      for (int y = -6; y <= 6 && !found; ++y)
        for (int z = -6; z <= 6 && !found; ++z) {
          const Vec3<T> c{T(x) / 2, T(y) / 2, T(z) / 2};
          found = c.x >= a.min.x && c.x <= a.max.x && c.y >= a.min.y && c.y <= a.max.y &&
                  c.z >= a.min.z && c.z <= a.max.z && c.x >= b.min.x && c.x <= b.max.x &&
                  c.y >= b.min.y && c.y <= b.max.y && c.z >= b.min.z && c.z <= b.max.z;
        }
    ASSERT_EQ(intersects(a, b), found) << i;
    EXPECT_EQ(intersects(b, a), found);
    const auto box = intersection(a, b);
    ASSERT_EQ(box.has_value(), found);
    if (found) {
      EXPECT_FALSE(is_empty(*box));
      EXPECT_EQ(box->min, intersection(b, a)->min);
      EXPECT_EQ(box->max, intersection(b, a)->max);
    }
    meet += found ? 1 : 0;
  }
  EXPECT_GT(meet, 1000);
  EXPECT_FALSE(intersects(AlignedBox3<T>{{0, 0, 0}, {1, 1, 1}}, empty_box<T, 3>()));
}

// Oriented box pairs against "an edge of one meets the other" with the exact slab oracle, where
// the exact answer is stable under a 1e-9 relative change of the extents.
TYPED_TEST(IntersectionBoxes, OrientedBoxPairsAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto meet_exact = [](const OrientedBox3<T>& a, const OrientedBox3<T>& b,
                             const mpq_class& grow) {
    const QBox qa = qbox(a), qb = qbox(b);
    const auto corners_of = [&](const QBox& q) {
      std::vector<ex::Q3> c;
      for (int k = 0; k < 8; ++k) {
        ex::Q3 p = q.c;
        for (int j = 0; j < 3; ++j)
          p = p + (((k >> j) & 1) ? mpq_class(1) : mpq_class(-1)) * (q.e[j] * (1 + grow)) * q.a[j];
        c.push_back(p);
      }
      return c;
    };
    for (int pass = 0; pass < 2; ++pass) {
      const QBox& x = pass ? qb : qa;
      const QBox& y = pass ? qa : qb;
      const std::vector<ex::Q3> c = corners_of(x);
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 3; ++j) {
          const int k = i ^ (1 << j);
          if (k < i) continue;
          const ex::QLin edge{c[static_cast<std::size_t>(i)],
                              c[static_cast<std::size_t>(k)] - c[static_cast<std::size_t>(i)], true,
                              true};
          if (clip(edge, y, grow).kind != 0) return true;
        }
    }
    return false;
  };
  int checked = 0, meets = 0, parallel = 0;
  for (int i = 0; i < 1200; ++i) {
    const auto aa = random_axes<T>(rng);
    // A third of the pairs share the axes (parallel case) or are rotated by a tiny angle.
    std::array<Vec3<T>, 3> ba = random_axes<T>(rng);
    if (i % 3 == 1) ba = aa, ++parallel;
    const Vec3<T> ea = rng.vec<T, 3>(T(0.1), T(1)), eb = rng.vec<T, 3>(T(0.1), T(1));
    const OrientedBox3<T> a = make_obb(rng.vec<T, 3>(-1, 1), aa, ea);
    const OrientedBox3<T> b = make_obb(rng.vec<T, 3>(-1, 1) * T(1.5), ba, eb);
    const mpq_class g("1/1000000000");
    const bool in = meet_exact(a, b, -g), out = meet_exact(a, b, g);
    if (in != out) continue;
    ASSERT_EQ(intersects(a, b), in) << i;
    EXPECT_EQ(intersects(b, a), in);
    ++checked;
    meets += in ? 1 : 0;
  }
  EXPECT_GT(checked, 1150);
  EXPECT_GT(meets, 240);
  EXPECT_LT(meets, checked - 240);
  EXPECT_EQ(parallel, 400);
}

// Touching oriented boxes with exact frames: face to face, edge to edge, corner to corner meet.
TYPED_TEST(IntersectionBoxes, OrientedBoxPairsTouching) {
  using T = TypeParam;
  const std::array<Vec3<T>, 3> I = {Vec3<T>{1, 0, 0}, Vec3<T>{0, 1, 0}, Vec3<T>{0, 0, 1}};
  const OrientedBox3<T> a = make_obb(Vec3<T>{0, 0, 0}, I, Vec3<T>{1, 1, 1});
  EXPECT_TRUE(intersects(a, make_obb(Vec3<T>{2, 0, 0}, I, Vec3<T>{1, 1, 1})));
  EXPECT_TRUE(intersects(a, make_obb(Vec3<T>{2, 2, 0}, I, Vec3<T>{1, 1, 1})));
  EXPECT_TRUE(intersects(a, make_obb(Vec3<T>{2, 2, 2}, I, Vec3<T>{1, 1, 1})));
  EXPECT_FALSE(intersects(a, make_obb(Vec3<T>{T(2.25), 0, 0}, I, Vec3<T>{1, 1, 1})));
  // Separated only by an edge-edge axis (figure 11.69): p is the cube turned 45 degrees about z
  // (its +x extreme an edge along z at x = sqrt 2), q the cube turned about y (its -x extreme an
  // edge along y); along x = z cross y they are 2 sqrt 2 apart at most, while every face axis
  // shows an overlap.
  const T h = std::sqrt(T(0.5));
  const std::array<Vec3<T>, 3> rz = {Vec3<T>{h, h, 0}, Vec3<T>{-h, h, 0}, Vec3<T>{0, 0, 1}};
  const std::array<Vec3<T>, 3> ry = {Vec3<T>{h, 0, -h}, Vec3<T>{0, 1, 0}, Vec3<T>{h, 0, h}};
  const OrientedBox3<T> p = make_obb(Vec3<T>{0, 0, 0}, rz, Vec3<T>{1, 1, 1});
  const T gap = 2 * std::sqrt(T(2));
  EXPECT_FALSE(intersects(p, make_obb(Vec3<T>{gap + T(0.01), 0, 0}, ry, Vec3<T>{1, 1, 1})));
  EXPECT_TRUE(intersects(p, make_obb(Vec3<T>{gap - T(0.01), 0, 0}, ry, Vec3<T>{1, 1, 1})));
  // With the cross-product axes ignored (parallel_tolerance 1: every pair counts as parallel)
  // the same separated pair is reported as meeting: the edge axis is what separates it.
  EXPECT_TRUE(intersects(p, make_obb(Vec3<T>{gap + T(0.01), 0, 0}, ry, Vec3<T>{1, 1, 1}), T(1)));
  OrientedBox3<T> bad = a;
  bad.extent.x = -1;
  EXPECT_FALSE(intersects(bad, a));
  bad = a;
  bad.center.y = std::numeric_limits<T>::quiet_NaN();
  EXPECT_FALSE(intersects(a, bad));
}

TYPED_TEST(IntersectionBoxes, BoxSphereAgainstExact) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  int meets = 0, tangent = 0, checked = 0;
  for (int i = 0; i < 8000; ++i) {
    const bool grid = i % 2 == 1;
    const auto g = [&](int r) {
      return grid ? Vec3<T>{T(rng.uniform_int(-r, r)), T(rng.uniform_int(-r, r)),
                            T(rng.uniform_int(-r, r))}
                  : rng.vec<T, 3>(T(-r), T(r));
    };
    const Vec3<T> p = g(2), q = g(2);
    const AlignedBox3<T> box{cwise_min(p, q), cwise_max(p, q)};
    const Sphere3<T> s{g(4), grid ? T(rng.uniform_int(0, 3)) : rng.uniform<T>(0, 3)};
    mpq_class d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const mpq_class c(double(s.center[k])), lo(double(box.min[k])), hi(double(box.max[k]));
      if (c < lo) d2 += (lo - c) * (lo - c);
      if (c > hi) d2 += (c - hi) * (c - hi);
    }
    const mpq_class r2 = mpq_class(double(s.radius)) * mpq_class(double(s.radius));
    const bool expected = d2 <= r2;
    ASSERT_EQ(intersects(box, s), expected) << i;
    EXPECT_EQ(intersects(s, box), expected);
    meets += expected, tangent += d2 == r2 && r2 > 0;
    // As an oriented box with a signed-permutation frame and the same centre: exact too.
    if (grid) {
      const auto axes = signed_permutation<T>(rng);
      const Vec3<T> c = (box.min + box.max) * T(0.5), e = (box.max - box.min) * T(0.5);
      Vec3<T> ee{};
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          if (axes[static_cast<std::size_t>(k)][j] != T(0)) ee[k] = e[j];
      EXPECT_EQ(intersects(make_obb(c, axes, ee), s), expected) << i;
      ++checked;
    }
  }
  EXPECT_GT(meets, 1000);
  EXPECT_GT(tangent, 100);
  EXPECT_GT(checked, 3000);
  EXPECT_FALSE(intersects(AlignedBox3<T>{{0, 0, 0}, {1, 1, 1}}, Sphere3<T>{{0, 0, 0}, T(-1)}));
  EXPECT_FALSE(intersects(AlignedBox3<T>{{0, 0, 0}, {1, 1, 1}},
                          Sphere3<T>{{std::numeric_limits<T>::quiet_NaN(), 0, 0}, T(1)}));
}

// Power-of-two scaling leaves every decision unchanged and scales the points exactly for
// aligned boxes.
TYPED_TEST(IntersectionBoxes, PowerOfTwoScaling) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int i = 0; i < 500; ++i) {
    std::vector<Vec3<T>> v(6);
    for (auto& p : v) p = rng.vec<T, 3>(-2, 2);
    const T radius = rng.uniform<T>(0, 2);
    const auto run = [&](int k) {
      const auto s = locus_test::scaled(v, k);
      const AlignedBox3<T> box{cwise_min(s[0], s[1]), cwise_max(s[0], s[1])};
      const Ray3<T> ray{s[2], s[3] - s[2]};
      const auto r = intersection(ray, box);
      std::vector<locus_test::Covariant> out{
          {"kind", double(static_cast<int>(r.kind)), 0},
          {"box-sphere", intersects(box, Sphere3<T>{s[4], std::ldexp(radius, k)}) ? 1.0 : 0.0, 0},
          {"plane side", double(to_int(side_of_plane(box, Plane3<T>{s[5], dot(s[5], s[4])}))), 0}};
      for (std::size_t j = 0; j < static_cast<std::size_t>(r.count); ++j) {
        locus_test::add(out, "point", r.point[j], 1);
        out.push_back({"t", double(r.param_a[j]), 0});
      }
      return out;
    };
    locus_test::expect_scale_covariant(run, locus_test::scale_exponents<T>());
    if (::testing::Test::HasFailure()) return;
  }
}

TYPED_TEST(IntersectionBoxes, NonFiniteInput) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  const AlignedBox3<T> box{{0, 0, 0}, {1, 1, 1}};
  for (const T bad : {nan, inf, -inf}) {
    EXPECT_EQ(intersection(Ray3<T>{{bad, 0, 0}, {1, 0, 0}}, box).kind, Kind::empty);
    EXPECT_EQ(intersection(Ray3<T>{{-1, 0.5, 0.5}, {bad, 0, 0}}, box).kind, Kind::empty);
    EXPECT_EQ(intersection(Segment3<T>{{-1, 0.5, 0.5}, {2, bad, 0.5}}, box).kind, Kind::empty);
    EXPECT_EQ(
        intersection(Line3<T>{{-1, 0.5, 0.5}, {1, 0, 0}}, AlignedBox3<T>{{bad, 0, 0}, {1, 1, 1}})
            .kind,
        Kind::empty);
    EXPECT_EQ(side_of_plane(box, Plane3<T>{{bad, 0, 1}, 0}), Sign::zero);
    EXPECT_FALSE(intersects(box, Plane3<T>{{0, 0, 1}, bad}));
  }
  EXPECT_EQ(intersection(Ray3<T>{{-1, 0.5, 0.5}, {1, 0, 0}}, empty_box<T, 3>()).kind, Kind::empty);
}

}  // namespace
