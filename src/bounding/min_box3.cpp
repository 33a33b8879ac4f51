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
  if (options.refine && !exhausted) refine(ev, best, work, options.max_work, h);
  r.box = to_box<T>(best, ref);
  r.volume = static_cast<T>(best.volume);
  if (exhausted) r.status = Status::limit_exceeded;
  return r;
}

template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>, const MinBoxOptions&);
template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>, const MinBoxOptions&);

}  // namespace locus
