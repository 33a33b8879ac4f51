// SPDX-License-Identifier: BSL-1.0
// GJK distance and EPA penetration depth between random convex polyhedra of 32 vertices (rows
// dist3.gjk; distance/gjk.hpp). Items per second = queries per second over 256 pairs cycled.
//
// Inputs: each polyhedron is 32 random points on an ellipsoid (so all 32 are vertices),
// randomly rotated; "separated" pairs have centres 3-4 units apart (distance > 0), "intersecting"
// pairs 0.5-1.5 apart. Every library gets the same vertices; shapes are built outside the timed
// loops. Accuracy (counter max_err, and printed once to stderr): the largest absolute error over
// the pairs against the exact answer: for distances the minimum over all vertex-triangle and
// edge-edge pairs (locus point_triangle / segment_segment), for depths the smallest face-plane
// distance of the hull of the 32 x 32 vertex differences (the Minkowski difference). Three
// classes of distance queries, each with its own counter (and a line on stderr):
//   max_err           generic separated pairs (distance about 0.5 .. 3);
//   near_contact_err  the same pairs moved together along their separating direction to a gap
//                     of 1e-9 .. 1e-6 (relative to the unit-size shapes), where termination
//                     tolerances show;
//   parallel_err      face-face pairs: a large face of b turned to face a large face of a,
//                     tilted by 0 or 1e-12 .. 1e-7 radians, at a gap of 1e-4 .. 1e-1 (every point
//                     of the two faces is almost equally close: the closest features are
//                     degenerate and the final GJK simplex is nearly flat).
//
// Peers (LOCUS_HAVE_CCD, LOCUS_HAVE_FCL): libccd 2.1 has no distance query (ccdGJKDist exists
// only in FCL's fork of it), so its GJK distance is measured through FCL's GJKSolver_libccd;
// libccd itself is measured for penetration (ccdGJKPenetration = GJK + EPA, ccdMPRPenetration)
// with a linear-scan support function over the same vertex array. FCL: GJKSolver_libccd and
// GJKSolver_indep, shapeDistance and shapeIntersect (with contacts) on fcl::Convex (32 vertices:
// FCL's Convex scans linearly up to 32 vertices, like ConvexPoints). Default tolerances
// everywhere (locus: 64 eps relative; libccd/FCL: 1e-6 distance, 1e-4 EPA).
//
// Run: locus_bench_distance --benchmark_filter=Gjk --benchmark_min_time=0.5
#include <locus/core/rotation.hpp>
#include <locus/distance/gjk.hpp>
#include <locus/distance/point_triangle.hpp>
#include <locus/distance/segment_segment.hpp>
#include <locus/hull/hull3.hpp>

#include <benchmark/benchmark.h>

#if defined(LOCUS_HAVE_CCD)
#include <ccd/ccd.h>
#endif
#if defined(LOCUS_HAVE_FCL)
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr std::size_t kPairs = 256;
constexpr int kVerts = 32;

struct Poly {
  std::vector<locus::Vec3d> v;
  std::vector<std::array<std::uint32_t, 3>> tris;
};

Poly random_poly(std::mt19937_64& rng, const locus::Vec3d& center) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.5, 1.0);
  const locus::Vec3d axes{u(rng), u(rng), u(rng)};
  const locus::Vec3d axis = locus::normalize(locus::Vec3d{g(rng), g(rng), g(rng)});
  const locus::Mat3d rot = locus::to_matrix(locus::AxisAngle<double>{axis, 6.0 * u(rng)});
  Poly p;
  for (int i = 0; i < kVerts; ++i) {
    const locus::Vec3d s = locus::normalize(locus::Vec3d{g(rng), g(rng), g(rng)});
    p.v.push_back(center + rot * locus::cwise_mul(s, axes));
  }
  const locus::Hull3Result h = locus::convex_hull(p.v);
  p.tris = h.triangles;
  return p;
}

struct PairSet {
  std::vector<Poly> a, b;
  std::vector<double> exact;  // distance (separated set) or depth (intersecting set)
};

double brute_distance(const Poly& a, const Poly& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : b.tris)
    for (const auto& p : a.v)
      best = std::min(
          best, locus::distance(p, locus::Triangle3d{b.v[t[0]], b.v[t[1]], b.v[t[2]]}).distance);
  for (const auto& t : a.tris)
    for (const auto& p : b.v)
      best = std::min(
          best, locus::distance(p, locus::Triangle3d{a.v[t[0]], a.v[t[1]], a.v[t[2]]}).distance);
  for (const auto& ta : a.tris)
    for (int i = 0; i < 3; ++i)
      for (const auto& tb : b.tris)
        for (int j = 0; j < 3; ++j)
          best = std::min(best, locus::distance(locus::Segment3d{a.v[ta[i]], a.v[ta[(i + 1) % 3]]},
                                                locus::Segment3d{b.v[tb[j]], b.v[tb[(j + 1) % 3]]})
                                    .distance);
  return best;
}

double brute_depth(const Poly& a, const Poly& b) {
  std::vector<locus::Vec3d> d;
  for (const auto& p : a.v)
    for (const auto& q : b.v) d.push_back(p - q);
  const locus::Hull3Result h = locus::convex_hull(d);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : h.triangles) {
    const locus::Vec3d n =
        locus::normalize(locus::normal(locus::Triangle3d{d[t[0]], d[t[1]], d[t[2]]}));
    best = std::min(best, locus::dot(n, d[t[0]]));
  }
  return best;  // < 0 would mean the origin is outside (not an intersecting pair)
}

const PairSet& pairs(bool separated) {
  static PairSet sep, inter;
  static bool built = false;
  if (!built) {
    for (int k = 0; k < 2; ++k) {
      PairSet& s = k == 0 ? sep : inter;
      std::mt19937_64 rng(k == 0 ? 101 : 202);
      std::normal_distribution<double> g;
      std::uniform_real_distribution<double> u(0, 1);
      while (s.a.size() < kPairs) {
        const locus::Vec3d dir = locus::normalize(locus::Vec3d{g(rng), g(rng), g(rng)});
        const double d = k == 0 ? 3.0 + u(rng) : 0.5 + u(rng);
        Poly a = random_poly(rng, {0, 0, 0}), b = random_poly(rng, d * dir);
        const double e = k == 0 ? brute_distance(a, b) : brute_depth(a, b);
        if (!(e > 1e-6)) continue;
        s.a.push_back(std::move(a));
        s.b.push_back(std::move(b));
        s.exact.push_back(e);
      }
    }
    built = true;
  }
  return separated ? sep : inter;
}

/// The separated pairs moved together along their separating direction so that the distance
/// is 1e-9 .. 1e-6 (near contact, where termination tolerances show); exact by brute force.
const PairSet& close_pairs() {
  static const PairSet close = [] {
    const PairSet& s = pairs(true);
    PairSet c;
    std::mt19937_64 rng(303);
    std::uniform_real_distribution<double> u(6, 9);
    for (std::size_t i = 0; i < kPairs; ++i) {
      const auto r = locus::gjk_distance(locus::ConvexPoints<double, 3>{s.a[i].v},
                                         locus::ConvexPoints<double, 3>{s.b[i].v});
      const double target = std::pow(10.0, -u(rng));
      Poly b = s.b[i];
      for (auto& q : b.v) q -= (s.exact[i] - target) * r.normal;
      const double e = brute_distance(s.a[i], b);
      if (!(e > 0)) continue;
      c.a.push_back(s.a[i]);
      c.b.push_back(std::move(b));
      c.exact.push_back(e);
    }
    return c;
  }();
  return close;
}

/// The hull triangle of largest area: its unit outward normal and centroid.
std::pair<locus::Vec3d, locus::Vec3d> largest_face(const Poly& p) {
  double best = -1;
  locus::Vec3d n{}, c{};
  for (const auto& t : p.tris) {
    const locus::Triangle3d tri{p.v[t[0]], p.v[t[1]], p.v[t[2]]};
    const locus::Vec3d m = locus::normal(tri);
    if (locus::length(m) > best) {
      best = locus::length(m);
      n = locus::normalize(m);
      c = (tri.v0 + tri.v1 + tri.v2) / 3.0;
    }
  }
  return {n, c};
}

/// Rotation taking unit u to unit v (about u x v; a half turn about any axis orthogonal to u
/// when v = -u).
locus::Mat3d rotation_between(const locus::Vec3d& u, const locus::Vec3d& v) {
  const locus::Vec3d axis = locus::cross(u, v);
  const double s = locus::length(axis), c = locus::dot(u, v);
  if (s < 1e-12) {
    if (c > 0) return locus::Mat3d::identity();
    const locus::Vec3d o = std::fabs(u.x) < 0.9 ? locus::Vec3d{1, 0, 0} : locus::Vec3d{0, 1, 0};
    return locus::to_matrix(
        locus::AxisAngle<double>{locus::normalize(locus::cross(u, o)), std::acos(-1.0)});
  }
  return locus::to_matrix(locus::AxisAngle<double>{axis / s, std::atan2(s, c)});
}

/// Face-face pairs (see the header comment): b's largest face turned against a's largest face,
/// spun about the common normal, tilted by a tiny angle, its centroid at gap g over a's.
const PairSet& parallel_pairs() {
  static const PairSet par = [] {
    PairSet c;
    std::mt19937_64 rng(404);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(0, 1);
    while (c.a.size() < kPairs) {
      Poly a = random_poly(rng, {0, 0, 0}), b = random_poly(rng, {0, 0, 0});
      const auto [na, ca] = largest_face(a);
      const auto [nb, cb] = largest_face(b);
      const double tilt = u(rng) < 0.25 ? 0.0 : std::pow(10.0, -7.0 - 5.0 * u(rng));
      const double gap = std::pow(10.0, -1.0 - 3.0 * u(rng));
      const locus::Vec3d side =
          locus::normalize(locus::cross(na, locus::Vec3d{g(rng), g(rng), g(rng)}));
      const locus::Mat3d rot = locus::to_matrix(locus::AxisAngle<double>{side, tilt}) *
                               locus::to_matrix(locus::AxisAngle<double>{na, 6.3 * u(rng)}) *
                               rotation_between(nb, -na);
      const locus::Vec3d t = ca + gap * na - rot * cb;
      for (auto& q : b.v) q = rot * q + t;
      const double e = brute_distance(a, b);
      if (!(e > 0)) continue;
      c.a.push_back(std::move(a));
      c.b.push_back(std::move(b));
      c.exact.push_back(e);
    }
    return c;
  }();
  return par;
}

/// Largest error of a distance function over a set of pairs (accuracy only, not timed).
template <class F>
double set_error(const PairSet& c, F&& distance_of) {
  double max_err = 0;
  for (std::size_t i = 0; i < c.a.size(); ++i) {
    const double e = std::fabs(distance_of(c, i) - c.exact[i]);
    max_err = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::max(max_err, e);
  }
  return max_err;
}

/// The three accuracy classes of a distance function, as counters and one stderr line.
template <class F>
void distance_accuracy(benchmark::State& state, const char* name, F&& distance_of) {
  state.counters["max_err"] = set_error(pairs(true), distance_of);
  state.counters["near_contact_err"] = set_error(close_pairs(), distance_of);
  state.counters["parallel_err"] = set_error(parallel_pairs(), distance_of);
  static std::set<std::string> printed;
  if (printed.insert(name).second)
    std::fprintf(stderr, "%-34s max abs error: generic %.3g  near contact %.3g  face-face %.3g\n",
                 name, state.counters["max_err"].value, state.counters["near_contact_err"].value,
                 state.counters["parallel_err"].value);
}

void report_time(benchmark::State& state) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void report(benchmark::State& state, const char* name, double max_err) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["max_err"] = max_err;
  static std::set<std::string> printed;  // once per benchmark, not once per timing run
  if (printed.insert(name).second)
    std::fprintf(stderr, "%-34s max abs error vs exact: %.3g\n", name, max_err);
}

// ---- locus ------------------------------------------------------------------------------------

void BM_Gjk_Distance_locus(benchmark::State& state) {
  const PairSet& s = pairs(true);
  distance_accuracy(state, "distance locus", [](const PairSet& c, std::size_t k) {
    return locus::gjk_distance(locus::ConvexPoints<double, 3>{c.a[k].v},
                               locus::ConvexPoints<double, 3>{c.b[k].v})
        .distance;
  });
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = locus::gjk_distance(locus::ConvexPoints<double, 3>{s.a[i].v},
                                       locus::ConvexPoints<double, 3>{s.b[i].v});
    benchmark::DoNotOptimize(r.distance);
    i = (i + 1) % kPairs;
  }
  report_time(state);
}
BENCHMARK(BM_Gjk_Distance_locus);

void BM_Gjk_Penetration_locus(benchmark::State& state) {
  const PairSet& s = pairs(false);
  double max_err = 0;
  for (std::size_t i = 0; i < kPairs; ++i) {
    const auto r = locus::penetration(locus::ConvexPoints<double, 3>{s.a[i].v},
                                      locus::ConvexPoints<double, 3>{s.b[i].v});
    max_err = std::max(max_err, std::fabs(r.depth - s.exact[i]));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = locus::penetration(locus::ConvexPoints<double, 3>{s.a[i].v},
                                      locus::ConvexPoints<double, 3>{s.b[i].v});
    benchmark::DoNotOptimize(r.depth);
    i = (i + 1) % kPairs;
  }
  report(state, "penetration locus", max_err);
}
BENCHMARK(BM_Gjk_Penetration_locus);

// ---- libccd -----------------------------------------------------------------------------------
#if defined(LOCUS_HAVE_CCD)

void ccd_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const Poly& p = *static_cast<const Poly*>(obj);
  std::size_t best = 0;
  double hbest = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < p.v.size(); ++k) {
    const double h = p.v[k].x * dir->v[0] + p.v[k].y * dir->v[1] + p.v[k].z * dir->v[2];
    if (h > hbest) {
      hbest = h;
      best = k;
    }
  }
  ccdVec3Set(out, p.v[best].x, p.v[best].y, p.v[best].z);
}

void ccd_center(const void* obj, ccd_vec3_t* out) {
  const Poly& p = *static_cast<const Poly*>(obj);
  locus::Vec3d c{};
  for (const auto& q : p.v) c += q;
  c = c / double(p.v.size());
  ccdVec3Set(out, c.x, c.y, c.z);
}

ccd_t ccd_setup() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd_support;
  ccd.support2 = ccd_support;
  ccd.center1 = ccd_center;
  ccd.center2 = ccd_center;
  ccd.max_iterations = 128;
  return ccd;
}

template <bool Mpr>
void BM_Gjk_Penetration_libccd(benchmark::State& state) {
  const PairSet& s = pairs(false);
  const ccd_t ccd = ccd_setup();
  const auto run = [&](std::size_t i) {
    ccd_real_t depth = 0;
    ccd_vec3_t dir, pos;
    const int rc = Mpr ? ccdMPRPenetration(&s.a[i], &s.b[i], &ccd, &depth, &dir, &pos)
                       : ccdGJKPenetration(&s.a[i], &s.b[i], &ccd, &depth, &dir, &pos);
    return rc == 0 ? double(depth) : std::numeric_limits<double>::quiet_NaN();
  };
  double max_err = 0;
  for (std::size_t i = 0; i < kPairs; ++i) {
    const double e = std::fabs(run(i) - s.exact[i]);
    max_err = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::max(max_err, e);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(run(i));
    i = (i + 1) % kPairs;
  }
  report(state, Mpr ? "penetration libccd MPR" : "penetration libccd GJK+EPA", max_err);
}
void BM_Gjk_Penetration_libccd_GJK_EPA(benchmark::State& state) {
  BM_Gjk_Penetration_libccd<false>(state);
}
void BM_Gjk_Penetration_libccd_MPR(benchmark::State& state) {
  BM_Gjk_Penetration_libccd<true>(state);
}
BENCHMARK(BM_Gjk_Penetration_libccd_GJK_EPA);
BENCHMARK(BM_Gjk_Penetration_libccd_MPR);
#endif

// ---- FCL --------------------------------------------------------------------------------------
#if defined(LOCUS_HAVE_FCL)

std::vector<fcl::Convex<double>> fcl_shapes(const std::vector<Poly>& polys) {
  std::vector<fcl::Convex<double>> out;
  for (const Poly& p : polys) {
    auto verts = std::make_shared<std::vector<fcl::Vector3d>>();
    for (const auto& q : p.v) verts->emplace_back(q.x, q.y, q.z);
    auto faces = std::make_shared<std::vector<int>>();
    for (const auto& t : p.tris) {
      faces->push_back(3);
      for (std::uint32_t k : t) faces->push_back(static_cast<int>(k));
    }
    out.emplace_back(verts, static_cast<int>(p.tris.size()), faces);
  }
  return out;
}

template <class Solver>
void BM_Gjk_Distance_fcl(benchmark::State& state, const char* name) {
  const PairSet& s = pairs(true);
  const auto a = fcl_shapes(s.a), b = fcl_shapes(s.b);
  const Solver solver;
  const fcl::Transform3d id = fcl::Transform3d::Identity();
  const auto run = [&](std::size_t i) {
    double d = 0;
    fcl::Vector3d p1, p2;
    solver.shapeDistance(a[i], id, b[i], id, &d, &p1, &p2);
    return d;
  };
  {
    // FCL shapes for every accuracy set (built once per benchmark, outside the timing).
    const PairSet* sets[3] = {&pairs(true), &close_pairs(), &parallel_pairs()};
    std::vector<fcl::Convex<double>> fa[3], fb[3];
    for (int k = 0; k < 3; ++k) {
      fa[k] = fcl_shapes(sets[k]->a);
      fb[k] = fcl_shapes(sets[k]->b);
    }
    distance_accuracy(state, name, [&](const PairSet& c, std::size_t k) {
      const int set = &c == sets[0] ? 0 : &c == sets[1] ? 1 : 2;
      double d = 0;
      fcl::Vector3d p1, p2;
      solver.shapeDistance(fa[set][k], id, fb[set][k], id, &d, &p1, &p2);
      return d;
    });
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(run(i));
    i = (i + 1) % kPairs;
  }
  report_time(state);
}
void BM_Gjk_Distance_fcl_libccd(benchmark::State& state) {
  BM_Gjk_Distance_fcl<fcl::detail::GJKSolver_libccd<double>>(state,
                                                             "distance FCL GJKSolver_libccd");
}
void BM_Gjk_Distance_fcl_indep(benchmark::State& state) {
  BM_Gjk_Distance_fcl<fcl::detail::GJKSolver_indep<double>>(state, "distance FCL GJKSolver_indep");
}
BENCHMARK(BM_Gjk_Distance_fcl_libccd);
BENCHMARK(BM_Gjk_Distance_fcl_indep);

template <class Solver>
void BM_Gjk_Penetration_fcl(benchmark::State& state, const char* name) {
  const PairSet& s = pairs(false);
  const auto a = fcl_shapes(s.a), b = fcl_shapes(s.b);
  const Solver solver;
  const fcl::Transform3d id = fcl::Transform3d::Identity();
  std::vector<fcl::ContactPoint<double>> contacts;
  const auto run = [&](std::size_t i) {
    contacts.clear();
    const bool hit = solver.shapeIntersect(a[i], id, b[i], id, &contacts);
    return hit && !contacts.empty() ? contacts[0].penetration_depth
                                    : std::numeric_limits<double>::quiet_NaN();
  };
  double max_err = 0;
  for (std::size_t i = 0; i < kPairs; ++i) {
    const double e = std::fabs(run(i) - s.exact[i]);
    max_err = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::max(max_err, e);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(run(i));
    i = (i + 1) % kPairs;
  }
  report(state, name, max_err);
}
void BM_Gjk_Penetration_fcl_libccd(benchmark::State& state) {
  BM_Gjk_Penetration_fcl<fcl::detail::GJKSolver_libccd<double>>(state,
                                                                "penetration FCL GJKSolver_libccd");
}
void BM_Gjk_Penetration_fcl_indep(benchmark::State& state) {
  BM_Gjk_Penetration_fcl<fcl::detail::GJKSolver_indep<double>>(state,
                                                               "penetration FCL GJKSolver_indep");
}
BENCHMARK(BM_Gjk_Penetration_fcl_libccd);
BENCHMARK(BM_Gjk_Penetration_fcl_indep);
#endif

}  // namespace
