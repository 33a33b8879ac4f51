// SPDX-License-Identifier: BSL-1.0
// Minimum-volume box: hull, candidate directions, calipers on projections, local refinement
// (bounding/min_box3.hpp; row cg.minbox).

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/core/basis.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace locus {
namespace {

using V3 = Vec3<double>;
using V2 = Vec2<double>;

struct Frame {
  V3 axis[3];
  V3 center;  // relative to the reference point
  double extent[3];
  double volume;
};

class Evaluator {
 public:
  explicit Evaluator(const std::vector<V3>& verts) : verts_(verts) {}

  // The best box with one axis along the unit vector n (calipers on the projection).
  bool candidate(const V3& n, Frame& out) {
    const OrthonormalBasis<double, 3> b = complete_basis(n);
    if (b.status != Status::ok) return false;
    const V3 u = b.axis[1], v = b.axis[2], w = b.axis[0];
    proj_.resize(verts_.size());
    double hmin = std::numeric_limits<double>::infinity(), hmax = -hmin;
    for (std::size_t i = 0; i < verts_.size(); ++i) {
      proj_[i] = {dot(u, verts_[i]), dot(v, verts_[i])};
      const double h = dot(w, verts_[i]);
      hmin = std::min(hmin, h);
      hmax = std::max(hmax, h);
    }
    hull2_.compute(proj_, Hull2Options{}, h2_);
    if (h2_.status != Status::ok || h2_.dimension != 2) return false;
    poly_.resize(h2_.indices.size());
    for (std::size_t i = 0; i < poly_.size(); ++i) poly_[i] = proj_[h2_.indices[i]];
    const detail::PolygonRect r = detail::min_rect_of_convex_polygon(poly_, RectCriterion::area);
    const V2 a1 = perp(r.axis0);
    out.axis[0] = r.axis0.x * u + r.axis0.y * v;
    out.axis[1] = a1.x * u + a1.y * v;
    out.axis[2] = w;
    out.extent[0] = r.extent[0];
    out.extent[1] = r.extent[1];
    out.extent[2] = 0.5 * (hmax - hmin);
    out.center = r.center.x * u + r.center.y * v + (0.5 * (hmin + hmax)) * w;
    out.volume = 8.0 * out.extent[0] * out.extent[1] * out.extent[2];
    return true;
  }

  // The axis-aligned box of the vertices in the frame `axes` (extents, centre, volume).
  void fit(const V3 axes[3], Frame& out) const {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::numeric_limits<double>::infinity();
      hi[k] = -lo[k];
    }
    for (const V3& p : verts_)
      for (int k = 0; k < 3; ++k) {
        const double s = dot(axes[k], p);
        lo[k] = std::min(lo[k], s);
        hi[k] = std::max(hi[k], s);
      }
    out.center = V3{};
    for (int k = 0; k < 3; ++k) {
      out.axis[k] = axes[k];
      out.extent[k] = 0.5 * (hi[k] - lo[k]);
      out.center += (0.5 * (hi[k] + lo[k])) * axes[k];
    }
    out.volume = 8.0 * out.extent[0] * out.extent[1] * out.extent[2];
  }

 private:
  const std::vector<V3>& verts_;
  std::vector<V2> proj_, poly_;
  ConvexHull2<double> hull2_;
  Hull2Result h2_;
};

// Rotate the frame by angle t about its axis k (the other two turn in their plane).
void rotate(const V3 in[3], int k, double t, V3 out[3]) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const double c = std::cos(t), s = std::sin(t);
  out[k] = in[k];
  out[i] = normalize(c * in[i] + s * in[j]);
  out[j] = normalize(cross(in[k], out[i]));
  if (dot(out[j], c * in[j] - s * in[i]) < 0.0) out[j] = -out[j];
}

// Coordinate descent over the three rotation angles, halving the step.
void refine(const Evaluator& ev, Frame& best, std::uint64_t& work, std::uint64_t budget,
            std::size_t h) {
  double step = 0.02;
  int evaluations = 0;
  while (step > 1e-9 && evaluations < 3000) {
    bool improved = false;
    for (int k = 0; k < 3; ++k)
      for (double sgn : {1.0, -1.0}) {
        if (work + h > budget) return;
        work += h;
        ++evaluations;
        V3 axes[3];
        rotate(best.axis, k, sgn * step, axes);
        Frame f;
        ev.fit(axes, f);
        if (f.volume < best.volume) {
          best = f;
          improved = true;
        }
      }
    if (!improved) step *= 0.5;
  }
}

// O'Rourke's family for one hull edge: the unit normals n(t) = cos(t) a + sin(t) b, t in
// [0, phi], of the planes that support the hull along the edge (the edge's arc on the Gauss
// sphere between the normals a and a' of its two facets). f(t) = the best box with one axis n(t)
// (calipers). search(): the arc is sampled every <= max_step rad and every sampled local minimum
// (ends included) is refined by golden-section search on its bracket down to 1e-9 rad.
// certify(): branch and bound with the Lipschitz bound below proves that no t on the arc has
// f(t) < (1 - tol) * best.
//
// Bound: all hull vertices lie within R of a centre, so every width is <= 2R, and turning a
// unit vector by an angle d changes the width along it by <= 2 R d. The rotation about the edge
// by d = |t - t'| maps the best frame at t' to a frame with first axis n(t), hence
// f(t) <= prod (w'_i + 2 R d) and symmetrically f(t) >= f(t') - g(d) with
// g(d) = (2R + 2Rd)^3 - (2R)^3 (the product's growth is largest when every width is 2R).
struct ArcSearch {
  ArcSearch(Evaluator& evaluator, Frame& best_frame, std::uint64_t& work_done,
            std::uint64_t work_budget, std::size_t hull_vertices, double hull_radius)
      : ev(evaluator),
        best(best_frame),
        work(work_done),
        budget(work_budget),
        h(hull_vertices),
        radius(hull_radius) {}

  Evaluator& ev;
  Frame& best;
  std::uint64_t& work;
  std::uint64_t budget;
  std::size_t h;
  double radius;
  std::size_t evaluations = 0;
  std::vector<double> values;  // f at every arc's samples, arcs in search order

  static constexpr double max_step = 0.05;

  // f at angle t on the arc; false when the budget is exhausted.
  bool eval(const V3& a, const V3& b, double t, double& value) {
    if (work + h > budget) return false;
    work += h;
    ++evaluations;
    Frame f;
    value = std::numeric_limits<double>::infinity();
    if (!ev.candidate(normalize(std::cos(t) * a + std::sin(t) * b), f)) return true;
    value = f.volume;
    if (f.volume < best.volume) best = f;
    return true;
  }

  static std::size_t intervals(double phi) {
    return std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(phi / max_step)));
  }

  // Samples f on the arc (appended to values) and refines every sampled local minimum.
  bool search(const V3& a, const V3& b, double phi) {
    const std::size_t m = intervals(phi), first = values.size();
    const double step = phi / static_cast<double>(m);
    values.resize(first + m + 1);
    double* f = values.data() + first;
    for (std::size_t i = 0; i <= m; ++i)
      if (!eval(a, b, static_cast<double>(i) * step, f[i])) return false;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (std::size_t i = 0; i <= m; ++i) {
      if ((i > 0 && f[i] > f[i - 1]) || (i < m && f[i] > f[i + 1])) continue;
      double lo = static_cast<double>(i == 0 ? 0 : i - 1) * step;
      double hi = static_cast<double>(std::min(i + 1, m)) * step;
      double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = 0.0, f2 = 0.0;
      if (!eval(a, b, x1, f1) || !eval(a, b, x2, f2)) return false;
      while (hi - lo > 1e-9) {
        if (f1 <= f2) {
          hi = x2;
          x2 = x1;
          f2 = f1;
          x1 = hi - g * (hi - lo);
          if (!eval(a, b, x1, f1)) return false;
        } else {
          lo = x1;
          x1 = x2;
          f1 = f2;
          x2 = lo + g * (hi - lo);
          if (!eval(a, b, x2, f2)) return false;
        }
      }
    }
    return true;
  }

  double growth(double d) const {
    const double w = 2.0 * radius;
    return (w + w * d) * (w + w * d) * (w + w * d) - w * w * w;
  }

  // Branch and bound over the arc's sample intervals (values from search(), starting at
  // `first`). Sets `proved` false when an interval shrinks to 1e-12 rad unresolved; returns
  // false when the budget is exhausted.
  bool certify(const V3& a, const V3& b, double phi, std::size_t first, double tol, bool& proved) {
    const std::size_t m = intervals(phi);
    const double step = phi / static_cast<double>(m);
    stack_.clear();
    for (std::size_t i = 0; i < m; ++i)
      stack_.push_back({static_cast<double>(i) * step, static_cast<double>(i + 1) * step,
                        values[first + i], values[first + i + 1]});
    while (!stack_.empty()) {
      const Piece p = stack_.back();
      stack_.pop_back();
      const double bound = (1.0 - tol) * best.volume;
      // Every t in the piece is within half its width of an end (an end whose calipers
      // failed, value infinite, bounds nothing: the piece is split).
      if (std::isfinite(p.flo) && std::isfinite(p.fhi) &&
          std::min(p.flo, p.fhi) - growth(0.5 * (p.hi - p.lo)) >= bound)
        continue;
      if (p.hi - p.lo < 1e-12) {
        proved = false;
        continue;
      }
      const double mid = 0.5 * (p.lo + p.hi);
      double fm = 0.0;
      if (!eval(a, b, mid, fm)) return false;
      stack_.push_back({p.lo, mid, p.flo, fm});
      stack_.push_back({mid, p.hi, fm, p.fhi});
    }
    return true;
  }

 private:
  struct Piece {
    double lo, hi, flo, fhi;  // an angle interval and f at its ends
  };
  std::vector<Piece> stack_;
};

template <class T>
OrientedBox<T, 3> to_box(const Frame& f, const V3& ref) {
  OrientedBox<T, 3> b;
  b.center = vec_cast<T>(ref + f.center);
  for (int k = 0; k < 3; ++k) b.axis[k] = vec_cast<T>(f.axis[k]);
  b.extent = {static_cast<T>(f.extent[0]), static_cast<T>(f.extent[1]),
              static_cast<T>(f.extent[2])};
  return b;
}

}  // namespace

template <Real T>
MinBoxResult<T> min_box(std::span<const Vec3<T>> points, const MinBoxOptions& options) {
  MinBoxResult<T> r;
  const Hull3Result hull = convex_hull(points);
  r.status = hull.status;
  if (hull.status != Status::ok) return r;
  // Hull vertices relative to the first one (keeps far-from-origin sets precise).
  const V3 ref = vec_cast<double>(points[hull.vertices[0]]);
  std::vector<V3> verts(hull.vertices.size());
  for (std::size_t i = 0; i < verts.size(); ++i)
    verts[i] = vec_cast<double>(points[hull.vertices[i]]) - ref;

  if (hull.dimension == 0) {
    r.box.center = points[hull.vertices[0]];
    for (int k = 0; k < 3; ++k) r.box.axis[k] = unit_vec<T, 3>(k);
    r.box.extent = Vec3<T>{};
    r.certified = true;
    return r;
  }
  Evaluator ev(verts);
  if (hull.dimension == 1) {
    const V3 d =
        vec_cast<double>(points[hull.polygon[1]]) - vec_cast<double>(points[hull.polygon[0]]);
    const OrthonormalBasis<double, 3> b = complete_basis(d);
    Frame f;
    ev.fit(b.axis.data(), f);
    r.box = to_box<T>(f, ref);
    r.volume = T(0);
    r.candidates = 1;
    r.certified = true;  // a flat box is a minimum
    return r;
  }
  if (hull.dimension == 2) {
    const V3 a = vec_cast<double>(points[hull.polygon[0]]),
             b = vec_cast<double>(points[hull.polygon[1]]),
             c = vec_cast<double>(points[hull.polygon[2]]);
    Frame f;
    if (!ev.candidate(normalize(cross(b - a, c - a)), f)) {
      r.status = Status::degenerate_input;
      return r;
    }
    // Reorder so the flat direction is axis[2] (it already is) and report volume 0 exactly.
    r.box = to_box<T>(f, ref);
    r.volume = T(0);
    r.candidates = 1;
    r.certified = true;  // a flat box is a minimum
    return r;
  }

  // Candidate directions: facet normals (deduplicated up to sign), then edge pairs.
  std::vector<V3> dirs;
  auto canonical = [](V3 n) {
    const V3 a = cwise_abs(n);
    const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return n[k] < 0.0 ? -n : n;
  };
  const auto vtx = [&](std::uint32_t i) { return vec_cast<double>(points[i]) - ref; };
  for (const auto& t : hull.triangles) {
    const V3 n = cross(vtx(t[1]) - vtx(t[0]), vtx(t[2]) - vtx(t[0]));
    if (sqr_length(n) > 0.0) dirs.push_back(canonical(normalize(n)));
  }
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (const auto& t : hull.triangles)
    for (std::size_t e = 0; e < 3; ++e)
      if (t[e] < t[(e + 1) % 3]) edges.push_back({t[e], t[(e + 1) % 3]});
  if (edges.size() <= options.max_pair_edges)
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const V3 n =
            cross(vtx(edges[i][1]) - vtx(edges[i][0]), vtx(edges[j][1]) - vtx(edges[j][0]));
        if (sqr_length(n) > 0.0) dirs.push_back(canonical(normalize(n)));
      }
  std::sort(dirs.begin(), dirs.end(), [](const V3& a, const V3& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  });
  dirs.erase(std::unique(dirs.begin(), dirs.end(),
                         [](const V3& a, const V3& b) { return max_abs(a - b) <= 1e-13; }),
             dirs.end());

  const std::size_t h = verts.size();
  std::uint64_t work = 0;
  Frame best{};
  best.volume = std::numeric_limits<double>::infinity();
  bool exhausted = false;
  for (const V3& n : dirs) {
    if (work + h > options.max_work) {
      exhausted = true;
      break;
    }
    work += h;
    Frame f;
    if (!ev.candidate(n, f)) continue;
    ++r.candidates;
    if (f.volume < best.volume) best = f;
  }
  if (!(best.volume < std::numeric_limits<double>::infinity())) {
    // Budget too small for a single candidate: the box of the coordinate axes.
    const V3 axes[3] = {V3{1, 0, 0}, V3{0, 1, 0}, V3{0, 0, 1}};
    ev.fit(axes, best);
  }
  // The previous candidate search's answer (refined) is kept as a floor for the arc search.
  if (options.refine && !exhausted) refine(ev, best, work, options.max_work, h);
  if (options.edge_arcs && !exhausted) {
    // Facet normals. The hull is exact but a rounded cross product of a sliver triangle (say
    // through a point that rounding moved a hair off a hull edge) can point anywhere: a normal
    // whose sine of the triangle's angle is below 1e-8 (error over 1e-8 rad) is not trusted, its
    // arcs are skipped and the result is not certified. Trusted arcs are widened by
    // arc_margin at both ends to cover their endpoints' rounding.
    constexpr double arc_margin = 1e-7;
    std::vector<V3> normal(hull.triangles.size());
    std::vector<char> trusted(hull.triangles.size());
    bool all_trusted = true;
    for (std::size_t t = 0; t < normal.size(); ++t) {
      const auto& tri = hull.triangles[t];
      const V3 e1 = vtx(tri[1]) - vtx(tri[0]), e2 = vtx(tri[2]) - vtx(tri[0]);
      const V3 n = cross(e1, e2);
      trusted[t] = length(n) > 1e-8 * length(e1) * length(e2) ? 1 : 0;
      normal[t] = normalize(n);
    }
    // Radius about the centre of the vertices' bounding box (rounded up a little).
    V3 lo = verts[0], hi = verts[0];
    for (const V3& p : verts) {
      lo = cwise_min(lo, p);
      hi = cwise_max(hi, p);
    }
    const V3 mid = 0.5 * (lo + hi);
    double radius = 0.0;
    for (const V3& p : verts) radius = std::max(radius, length(p - mid));
    radius *= 1.0 + 1e-12;
    struct Arc {
      V3 a, b;
      double phi;
      std::size_t first;  // index of its first sample in ArcSearch::values
    };
    std::vector<Arc> arc_list;
    Frame arc_best = best;
    ArcSearch arcs(ev, arc_best, work, options.max_work, h, radius);
    for (std::size_t t = 0; t < normal.size() && !exhausted; ++t)
      for (std::size_t e = 0; e < 3; ++e) {
        const std::size_t u = hull.adjacency[t][e];
        if (u < t) continue;  // each edge once
        const V3 a = normal[t];
        const double c = dot(a, normal[u]);
        const V3 s = normal[u] - c * a;
        const double sn = length(s);
        if (!trusted[t] || !trusted[u]) {
          all_trusted = false;
          continue;
        }
        // Coplanar neighbours (an edge inside a triangulated facet): the arc is a point, the
        // facet normal, already a candidate.
        if (!(sn > 1e-12)) continue;
        const V3 b = (1.0 / sn) * s;
        const double cm = std::cos(arc_margin), sm = std::sin(arc_margin);
        const Arc arc{cm * a - sm * b, sm * a + cm * b, std::atan2(sn, c) + 2.0 * arc_margin,
                      arcs.values.size()};
        ++r.arcs;
        if (!arcs.search(arc.a, arc.b, arc.phi)) {
          exhausted = true;
          break;
        }
        arc_list.push_back(arc);
      }
    // Certification against the final best (pruning only gets easier as best decreases).
    bool proved = !exhausted && all_trusted && options.certify_tol > 0.0;
    for (std::size_t i = 0; i < arc_list.size() && proved; ++i)
      if (!arcs.certify(arc_list[i].a, arc_list[i].b, arc_list[i].phi, arc_list[i].first,
                        options.certify_tol, proved)) {
        exhausted = true;
        proved = false;
      }
    r.certified = proved;
    r.candidates += arcs.evaluations;
    if (arc_best.volume < best.volume) {
      best = arc_best;
      if (options.refine && !exhausted) refine(ev, best, work, options.max_work, h);
    }
  }
  r.box = to_box<T>(best, ref);
  r.volume = static_cast<T>(best.volume);
  if (exhausted) r.status = Status::limit_exceeded;
  return r;
}

template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>, const MinBoxOptions&);
template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>, const MinBoxOptions&);

}  // namespace locus
