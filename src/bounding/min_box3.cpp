// SPDX-License-Identifier: BSL-1.0
// Minimum-volume box: exact hull, facet normals, then a certified branch and bound over every
// hull edge's arc of supporting normals (bounding/min_box3.hpp; row cg.minbox).

#include <locus/bounding/min_box3.hpp>
#include <locus/bounding/min_rect2.hpp>
#include <locus/core/basis.hpp>
#include <locus/hull/hull2.hpp>
#include <locus/hull/hull3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <vector>

namespace locus {
namespace {

using V3 = Vec3<double>;
using V2 = Vec2<double>;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double eps = std::numeric_limits<double>::epsilon();

struct Frame {
  V3 axis[3];  // axis[2] is the evaluated normal for candidates
  V3 center;   // relative to the reference point
  double extent[3];
  double volume;
};

// The hull as a mesh over local vertex indices, with rounded facet normals and a bound on
// each normal's angular error.
struct Mesh {
  struct Edge {
    std::uint32_t a, b;  // end vertices
    std::uint32_t f, g;  // the two triangles
  };
  std::vector<V3> verts;
  std::vector<std::array<std::uint32_t, 3>> tris;
  std::vector<V3> normal;
  // Angle between normal[f] and the exact normal of the (rounded) triangle: the rounded cross
  // product of two edge vectors errs by about 8 eps / sin(angle between them); infinite for a
  // sliver (sine < 1e-8) whose normal is not trusted.
  std::vector<double> normal_err;
  std::vector<Edge> edges;
  std::vector<std::uint32_t> first, neighbours;  // vertex adjacency (CSR over edges)
  // Edges grouped by the direction of their facet normals (a cube-map grid on the Gauss
  // sphere): every normal of a cell's edges, widened by its error, lies within the angle
  // asin(sine) of `centre` (sine = 2 when that angle reaches pi / 2).
  struct Cell {
    V3 centre;
    double sine;
    std::uint32_t begin, end;  // range in `edges`
  };
  std::vector<Cell> cells;

  // A vertex of maximum x . v, by ascent over the vertex graph from `start` (a local maximum
  // of a linear function over a convex polytope's vertex graph is global).
  std::uint32_t climb(const V3& x, std::uint32_t v, std::uint64_t& visits) const {
    double top = dot(x, verts[v]);
    for (;;) {
      std::uint32_t next = v;
      for (std::uint32_t k = first[v]; k < first[v + 1]; ++k) {
        const double s = dot(x, verts[neighbours[k]]);
        if (s > top) {
          top = s;
          next = neighbours[k];
        }
      }
      visits += first[v + 1] - first[v];
      if (next == v) return v;
      v = next;
    }
  }
};

// f(n) = (width of the hull along n) * (minimum-area rectangle of its projection along n),
// the volume of the best box with one axis n. The projection's hull vertices are silhouette
// vertices: a vertex is on the projected hull only if it has an incident facet facing n
// (n . N >= 0) and one facing away (n . N <= 0); facets whose sign the rounding of their normal
// leaves open count as both, so no projected hull vertex is missed.
class Evaluator {
 public:
  explicit Evaluator(const Mesh& m) : m_(m), stamp_(m.verts.size(), 0) {}

  // Work of the last candidate() (cells, edges and vertices visited).
  std::uint64_t last_work() const { return work_; }

  // `all`: project every vertex (no silhouette culling).
  bool candidate(const V3& n, Frame& out, bool all = false) {
    const OrthonormalBasis<double, 3> b = complete_basis(n);
    if (b.status != Status::ok) return false;
    const V3 w = b.axis[0], u = b.axis[1], v = b.axis[2];
    if (++tick_ == 0) {  // wrapped: restart the stamps
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      tick_ = 1;
    }
    proj_.clear();
    const auto take = [&](std::uint32_t i) {
      if (stamp_[i] == tick_) return;
      stamp_[i] = tick_;
      proj_.push_back({dot(u, m_.verts[i]), dot(v, m_.verts[i])});
    };
    // Bit 1: the facet may face n (n . N >= 0); bit 2: it may face away.
    const auto side = [&](std::uint32_t f) {
      const double d = dot(w, m_.normal[f]), e = m_.normal_err[f] + 4.0 * eps;
      return (d >= -e ? 1 : 0) | (d <= e ? 2 : 0);
    };
    work_ = m_.cells.size();
    for (const Mesh::Cell& c : all ? std::span<const Mesh::Cell>() : std::span(m_.cells)) {
      // A cell whose normals all lie strictly on one side of the plane n^perp has no
      // silhouette edge.
      if (std::abs(dot(w, c.centre)) > c.sine + 4.0 * eps) continue;
      work_ += c.end - c.begin;
      for (std::uint32_t k = c.begin; k < c.end; ++k) {
        const Mesh::Edge& e = m_.edges[k];
        if ((side(e.f) | side(e.g)) == 3) {
          take(e.a);
          take(e.b);
        }
      }
    }
    if (all || proj_.size() < 3)
      for (std::uint32_t i = 0; i < m_.verts.size(); ++i) take(i);
    work_ += proj_.size();
    double hmin = inf, hmax = -inf;
    if (m_.neighbours.empty()) {
      for (const V3& p : m_.verts) {
        const double h = dot(w, p);
        hmin = std::min(hmin, h);
        hmax = std::max(hmax, h);
      }
      work_ += m_.verts.size();
    } else {
      top_ = m_.climb(w, top_, work_);
      bottom_ = m_.climb(-w, bottom_, work_);
      hmax = dot(w, m_.verts[top_]);
      hmin = dot(w, m_.verts[bottom_]);
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

  // The box of the frame `axes` by six support ascents from (and updating) `start`; work in
  // vertex visits. Equal to fit() up to rounding ties.
  void fit_climb(const V3 axes[3], Frame& out, std::uint32_t start[6], std::uint64_t& work) const {
    out.center = V3{};
    for (int k = 0; k < 3; ++k) {
      start[2 * k] = m_.climb(axes[k], start[2 * k], work);
      start[2 * k + 1] = m_.climb(-axes[k], start[2 * k + 1], work);
      const double hi = dot(axes[k], m_.verts[start[2 * k]]);
      const double lo = dot(axes[k], m_.verts[start[2 * k + 1]]);
      out.axis[k] = axes[k];
      out.extent[k] = 0.5 * (hi - lo);
      out.center += (0.5 * (hi + lo)) * axes[k];
    }
    out.volume = 8.0 * out.extent[0] * out.extent[1] * out.extent[2];
  }

  // The box of all hull vertices in the frame `axes` (extents, centre, volume).
  void fit(const V3 axes[3], Frame& out) const {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = inf;
      hi[k] = -inf;
    }
    for (const V3& p : m_.verts)
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
  const Mesh& m_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t tick_ = 0;
  std::uint32_t top_ = 0, bottom_ = 0;  // warm starts of the support ascents
  std::uint64_t work_ = 0;
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

// Coordinate descent over the three rotation angles, halving the step; the frames are fitted by
// support ascents, the final one over every vertex (so `best` stays an enclosing box).
void refine(const Evaluator& ev, const Mesh& m, Frame& best, std::uint64_t& work,
            std::uint64_t budget) {
  const bool climb = !m.neighbours.empty();
  std::uint32_t start[6] = {0, 0, 0, 0, 0, 0};
  int evaluations = 0;
  Frame current = best;
  double step = 0.02;
  while (step > 1e-9 && evaluations < 3000) {
    bool improved = false;
    for (int k = 0; k < 3; ++k)
      for (double sgn : {1.0, -1.0}) {
        if (work + m.verts.size() > budget) break;
        ++evaluations;
        V3 axes[3];
        rotate(current.axis, k, sgn * step, axes);
        Frame f;
        if (climb) {
          ev.fit_climb(axes, f, start, work);
        } else {
          work += m.verts.size();
          ev.fit(axes, f);
        }
        if (f.volume < current.volume) {
          current = f;
          improved = true;
        }
      }
    if (work + m.verts.size() > budget) break;
    if (!improved) step *= 0.5;
  }
  Frame f;
  ev.fit(current.axis, f);
  work += m.verts.size();
  if (f.volume < best.volume) best = f;
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
  Mesh m;
  m.verts.resize(hull.vertices.size());
  for (std::size_t i = 0; i < m.verts.size(); ++i)
    m.verts[i] = vec_cast<double>(points[hull.vertices[i]]) - ref;

  if (hull.dimension == 0) {
    r.box.center = points[hull.vertices[0]];
    for (int k = 0; k < 3; ++k) r.box.axis[k] = unit_vec<T, 3>(k);
    r.box.extent = Vec3<T>{};
    r.certified = true;
    return r;
  }
  if (hull.dimension < 3) {
    Evaluator ev(m);  // no facets: candidates project every vertex
    Frame f;
    if (hull.dimension == 1) {
      const V3 d =
          vec_cast<double>(points[hull.polygon[1]]) - vec_cast<double>(points[hull.polygon[0]]);
      ev.fit(complete_basis(d).axis.data(), f);
    } else {
      const V3 a = vec_cast<double>(points[hull.polygon[0]]),
               b = vec_cast<double>(points[hull.polygon[1]]),
               c = vec_cast<double>(points[hull.polygon[2]]);
      // The flat direction is axis[2].
      if (!ev.candidate(normalize(cross(b - a, c - a)), f)) {
        r.status = Status::degenerate_input;
        return r;
      }
    }
    r.box = to_box<T>(f, ref);
    r.volume = T(0);
    r.candidates = 1;
    r.certified = true;  // a flat box is a minimum
    return r;
  }

  // The mesh over local indices (hull.vertices is sorted).
  const auto local = [&](std::uint32_t i) {
    return static_cast<std::uint32_t>(
        std::lower_bound(hull.vertices.begin(), hull.vertices.end(), i) - hull.vertices.begin());
  };
  const std::size_t nt = hull.triangles.size();
  m.tris.resize(nt);
  m.normal.resize(nt);
  m.normal_err.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    for (std::size_t k = 0; k < 3; ++k) m.tris[t][k] = local(hull.triangles[t][k]);
    const V3 e1 = m.verts[m.tris[t][1]] - m.verts[m.tris[t][0]],
             e2 = m.verts[m.tris[t][2]] - m.verts[m.tris[t][0]];
    const V3 n = cross(e1, e2);
    const double sine = length(n) / (length(e1) * length(e2));
    m.normal[t] = normalize(n);
    m.normal_err[t] = sine > 1e-8 ? 16.0 * eps / sine : inf;
  }
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t u = hull.adjacency[t][e];
      if (u < t) continue;  // each edge once
      m.edges.push_back({m.tris[t][e], m.tris[t][(e + 1) % 3], static_cast<std::uint32_t>(t), u});
    }

  {
    // Cube-map cells of about 16 edges, keyed by the mean normal of each edge's facets.
    const std::size_t grid = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::sqrt(static_cast<double>(m.edges.size()) / 96.0)));
    const auto key = [&](const Mesh::Edge& e) {
      const V3 c = m.normal[e.f] + m.normal[e.g];
      const V3 a = cwise_abs(c);
      const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
      const double s = a[k] > 0.0 ? 1.0 / a[k] : 0.0;
      const auto cell = [&](double x) {
        return std::min(grid - 1,
                        static_cast<std::size_t>((x * s + 1.0) * 0.5 * static_cast<double>(grid)));
      };
      const std::size_t face = static_cast<std::size_t>(2 * k + (c[k] < 0.0 ? 1 : 0));
      return (face * grid + cell(c[(k + 1) % 3])) * grid + cell(c[(k + 2) % 3]);
    };
    std::vector<std::pair<std::size_t, Mesh::Edge>> keyed;
    keyed.reserve(m.edges.size());
    for (const Mesh::Edge& e : m.edges) keyed.push_back({key(e), e});
    std::sort(keyed.begin(), keyed.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < keyed.size(); ++i) m.edges[i] = keyed[i].second;
    for (std::size_t i = 0; i < keyed.size();) {
      std::size_t j = i;
      V3 c{};
      while (j < keyed.size() && keyed[j].first == keyed[i].first) {
        c += m.normal[m.edges[j].f] + m.normal[m.edges[j].g];
        ++j;
      }
      // Widest angle from the centre (rounded up), as a sine; 2 = not bounded below pi / 2.
      double sine = 2.0;
      if (sqr_length(c) > 0.0) {
        c = normalize(c);
        // (atan2 of sine and cosine: accurate for the tiny angles of near-coplanar facets.)
        double angle = 0.0;
        for (std::size_t k = i; k < j; ++k)
          for (std::uint32_t f : {m.edges[k].f, m.edges[k].g})
            angle = std::max(angle, std::atan2(length(cross(c, m.normal[f])), dot(c, m.normal[f])) +
                                        m.normal_err[f]);
        angle += 1e-12;
        if (angle < 1.5) sine = std::sin(angle);
      }
      m.cells.push_back({c, sine, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
      i = j;
    }
  }
  m.first.assign(m.verts.size() + 1, 0);
  for (const Mesh::Edge& e : m.edges) {
    ++m.first[e.a + 1];
    ++m.first[e.b + 1];
  }
  for (std::size_t i = 0; i < m.verts.size(); ++i) m.first[i + 1] += m.first[i];
  m.neighbours.resize(m.first.back());
  {
    std::vector<std::uint32_t> fill(m.first.begin(), m.first.end() - 1);
    for (const Mesh::Edge& e : m.edges) {
      m.neighbours[fill[e.a]++] = e.b;
      m.neighbours[fill[e.b]++] = e.a;
    }
  }

  Evaluator ev(m);
  const std::size_t h = m.verts.size();
  std::uint64_t work = 0;
  bool exhausted = false;
  Frame best{};
  best.volume = inf;
  // A candidate's volume is trusted only after the box of all vertices in its frame confirms it.
  const auto consider = [&](const Frame& f) {
    if (!(f.volume < best.volume)) return;
    Frame g;
    ev.fit(f.axis, g);
    if (g.volume < best.volume) best = g;
  };
  const auto evaluate = [&](const V3& n, double& value, double& width) {
    if (work > options.max_work) {
      exhausted = true;
      return false;
    }
    ++r.candidates;
    Frame f;
    value = inf;
    width = 0.0;
    bool ok = ev.candidate(n, f);
    work += ev.last_work();
    if (!ok) return true;
    if (f.volume < best.volume) {
      // A new best must be confirmed by the box of all vertices in its frame; if that box is
      // larger, the silhouette culling missed a vertex (rounding): evaluate again without it.
      Frame g;
      ev.fit(f.axis, g);
      work += h;
      if (g.volume > f.volume * (1.0 + 1e-9)) {
        ok = ev.candidate(n, f, true);
        work += ev.last_work();
        if (!ok) return true;
      }
    }
    value = f.volume;
    width = 2.0 * f.extent[2];
    consider(f);
    return true;
  };

  // Every facet normal (the ends of the arcs; the facet-flush boxes). When the first ones
  // show that the whole pass cannot fit the budget (a hull with very many vertices, e.g.
  // points on a sphere), the facets are visited in a stride order that spreads the ones the
  // budget reaches over the hull, and the arcs are not searched.
  std::vector<double> fvalue(nt, inf), fwidth(nt, 0.0);
  const std::size_t head = std::min<std::size_t>(64, nt);
  for (std::size_t t = 0; t < head && !exhausted; ++t)
    if (std::isfinite(m.normal_err[t])) evaluate(m.normal[t], fvalue[t], fwidth[t]);
  std::size_t stride = 1;
  if (static_cast<double>(work) / static_cast<double>(head) * static_cast<double>(nt) >
      static_cast<double>(options.max_work)) {
    stride = 7919;  // a prime, made coprime with nt: j -> j * stride mod nt is a permutation
    while (std::gcd(stride, nt) != 1) stride += 2;
  }
  for (std::size_t j = 0; j < nt && !exhausted; ++j) {
    const std::size_t t = (j * stride) % nt;
    if (t >= head && std::isfinite(m.normal_err[t])) evaluate(m.normal[t], fvalue[t], fwidth[t]);
  }
  // The cross products of edge pairs of small hulls.
  if (m.edges.size() <= options.max_pair_edges)
    for (std::size_t i = 0; i < m.edges.size() && !exhausted; ++i)
      for (std::size_t j = i + 1; j < m.edges.size() && !exhausted; ++j) {
        const V3 n = cross(m.verts[m.edges[i].b] - m.verts[m.edges[i].a],
                           m.verts[m.edges[j].b] - m.verts[m.edges[j].a]);
        double value = 0.0, width = 0.0;
        if (sqr_length(n) > 0.0) evaluate(normalize(n), value, width);
      }
  if (!(best.volume < inf)) {
    // Budget too small for a single candidate: the box of the coordinate axes.
    const V3 axes[3] = {V3{1, 0, 0}, V3{0, 1, 0}, V3{0, 0, 1}};
    ev.fit(axes, best);
  }
  if (options.refine) refine(ev, m, best, work, options.max_work + options.max_work / 16);

  if (options.edge_arcs && !exhausted) {
    // Branch and bound over the arcs (see the header comment for the bound). The centre of the
    // vertices is inside the hull; D bounds its diameter and L every width of it.
    V3 centre{};
    for (const V3& p : m.verts) centre += p;
    centre = (1.0 / static_cast<double>(h)) * centre;
    double radius = 0.0;
    for (const V3& p : m.verts) radius = std::max(radius, length(p - centre));
    const double diam = 2.0 * radius * (1.0 + 1e-12);
    double inradius = inf;
    bool all_trusted = true;
    for (std::size_t t = 0; t < nt; ++t) {
      if (!std::isfinite(m.normal_err[t])) {
        all_trusted = false;
        continue;
      }
      const double dist = dot(m.normal[t], m.verts[m.tris[t][0]] - centre);
      inradius = std::min(inradius, dist - (m.normal_err[t] + 8.0 * eps) * diam);
    }
    const double min_width = 2.0 * inradius;
    const double tol = options.certify_tol > 0.0 ? options.certify_tol : 1e-3;

    struct Arc {
      V3 a, b;        // n(t) = cos(t) a + sin(t) b
      double margin;  // angular error of the arc's ends
      double diam;    // diameter bound of the hull's projection along the arc's pole a x b
    };
    struct Piece {
      double bound;
      std::uint32_t arc;
      double lo, hi, flo, fhi, wlo, whi;  // angle interval; f and width along n at its ends
      bool operator<(const Piece& o) const { return bound > o.bound; }  // min-heap
    };
    std::vector<Arc> arcs;
    std::priority_queue<Piece> heap;
    // Lower bound of f over the piece (and within the arc's margin of it): the width along n is
    // concave on the arc, the rectangle area changes by the factor of the header comment.
    const auto lower_bound = [&](const Piece& p) {
      if (!(std::isfinite(p.flo) && std::isfinite(p.fhi) && min_width > 0.0)) return 0.0;
      if (!(p.wlo > 0.0 && p.whi > 0.0)) return 0.0;
      const Arc& arc = arcs[p.arc];
      const double w = std::min(p.wlo, p.whi) - 4.0 * arc.margin * diam;
      if (!(w > 0.0)) return 0.0;
      const double rect = std::min(p.flo / p.wlo, p.fhi / p.whi);
      const double g =
          1.0 +
          (0.7071067811865476 * 0.5 * (p.hi - p.lo) * arc.diam + arc.margin * diam) / min_width;
      return w * rect / (g * g);
    };
    // Projection diameters per arc cost O(h) each; above this the global one is used.
    const bool per_arc_diam = m.edges.size() * h <= 50000000u;
    bool proved = all_trusted && min_width > 0.0;
    // (A hull flat to rounding has no usable width bound: its arcs are left unsearched.)
    for (const Mesh::Edge& e :
         (min_width > 0.0 ? std::span<const Mesh::Edge>(m.edges) : std::span<const Mesh::Edge>())) {
      if (!std::isfinite(m.normal_err[e.f]) || !std::isfinite(m.normal_err[e.g])) continue;
      const V3 a = m.normal[e.f];
      const double c = dot(a, m.normal[e.g]);
      const V3 s = m.normal[e.g] - c * a;
      const double sn = length(s);
      const V3 b = sn > 0.0 ? (1.0 / sn) * s : complete_basis(a).axis[1];
      double arc_diam = diam;
      if (per_arc_diam) {
        const V3 pole = normalize(cross(a, b));
        double r2 = 0.0;
        for (const V3& q : m.verts) {
          const V3 d = q - centre;
          const double z = dot(d, pole);
          r2 = std::max(r2, sqr_length(d) - z * z);
        }
        arc_diam = std::min(diam, 2.0 * std::sqrt(r2) * (1.0 + 1e-12) + 8.0 * eps * diam);
      }
      arcs.push_back({a, b, m.normal_err[e.f] + m.normal_err[e.g] + 8.0 * eps, arc_diam});
      Piece p{0.0,         static_cast<std::uint32_t>(arcs.size() - 1),
              0.0,         std::atan2(sn, c),
              fvalue[e.f], fvalue[e.g],
              fwidth[e.f], fwidth[e.g]};
      p.bound = lower_bound(p);
      if (p.bound < (1.0 - tol) * best.volume) heap.push(p);
    }
    r.arcs = arcs.size();
    const double best_before = best.volume;
    while (!heap.empty()) {
      const double threshold = (1.0 - tol) * best.volume;
      if (heap.top().bound >= threshold) break;  // every piece left is proved
      const Piece p = heap.top();
      heap.pop();
      // Splitting cannot help a piece below 1e-12 rad, nor one with an end whose own bound
      // at zero distance fails (the arc ends' normal errors alone exceed the tolerance).
      Piece at_lo = p, at_hi = p;
      at_lo.hi = at_lo.lo;
      at_lo.fhi = at_lo.flo;
      at_lo.whi = at_lo.wlo;
      at_hi.lo = at_hi.hi;
      at_hi.flo = at_hi.fhi;
      at_hi.wlo = at_hi.whi;
      if (p.hi - p.lo < 1e-12 || lower_bound(at_lo) < threshold || lower_bound(at_hi) < threshold) {
        proved = false;
        continue;
      }
      const Arc& arc = arcs[p.arc];
      const double mid = 0.5 * (p.lo + p.hi);
      double fm = 0.0, wm = 0.0;
      if (!evaluate(normalize(std::cos(mid) * arc.a + std::sin(mid) * arc.b), fm, wm)) break;
      Piece left{0.0, p.arc, p.lo, mid, p.flo, fm, p.wlo, wm};
      Piece right{0.0, p.arc, mid, p.hi, fm, p.fhi, wm, p.whi};
      left.bound = lower_bound(left);
      right.bound = lower_bound(right);
      const double t2 = (1.0 - tol) * best.volume;
      if (left.bound < t2) heap.push(left);
      if (right.bound < t2) heap.push(right);
    }
    r.certified = proved && !exhausted && options.certify_tol > 0.0;
    if (best.volume < best_before && options.refine && !exhausted)
      refine(ev, m, best, work, options.max_work);
  }
  r.box = to_box<T>(best, ref);
  r.volume = static_cast<T>(best.volume);
  if (exhausted) r.status = Status::limit_exceeded;
  return r;
}

template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>, const MinBoxOptions&);
template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>, const MinBoxOptions&);

}  // namespace locus
