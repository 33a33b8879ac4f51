// SPDX-License-Identifier: BSL-1.0
// Minimum-volume box: exact hull, facet normals, then a certified branch and bound over every
// hull edge's arc of supporting normals (bounding/min_box3.hpp; row cg.minbox).

#include <locus/bounding/min_box3.hpp>
#include <locus/core/basis.hpp>
#include <locus/distance/detail/rescale.hpp>
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
  // Chord ratios of a candidate (see chord_factor; inf: unknown). For a direction x, the chord
  // of x is q - p for vertices p of minimum and q of maximum x . v, so width(x) = x . (q - p).
  // sec: |q - p| / width(x); tan: the part of q - p off x that a rotation about an axis
  // perpendicular to the normal n can turn into x, over width(x): for x = n, the part
  // perpendicular to n; for x perpendicular to n, the part along n (its part along n cross x
  // stays perpendicular to x under such rotations). *_width: x = the normal axis[2]; *_rect:
  // the largest over every x perpendicular to it.
  double sec_width = inf, tan_width = inf, sec_rect = inf, tan_rect = inf;
};

// The minimum-area rectangle of a strictly convex counter-clockwise polygon (k >= 3) by
// rotating calipers (a side flush with an edge), and the largest chord ratios (see Frame) over
// all directions given the vertices' heights z along the projection direction. Over the
// directions between two consecutive edge normals the chord's vertices are fixed and the
// width is a cosine of the direction, so the ratios are largest at an edge normal: there the
// chords are from the edge's two ends to the antipodal vertex (to both vertices of an
// antipodal edge parallel to it up to rounding). Caliper steps are rounded: a step missed by
// rounding (a near tie) changes the extents by rounding only.
struct PolygonRect {
  double area;
  V2 axis0;  // along the flush edge
  double extent[2];
  V2 center;
  double sec, tan;
};

PolygonRect rect_of_polygon(const std::vector<V2>& p, const std::vector<double>& z) {
  const std::size_t k = p.size();
  // (Indices stay below 3k + 1.)
  const auto wrap = [k](std::size_t i) { return i < k ? i : (i < 2 * k ? i - k : i - 2 * k); };
  const auto at = [&](std::size_t i) -> const V2& { return p[wrap(i)]; };
  PolygonRect best{inf, V2{1.0, 0.0}, {0.0, 0.0}, V2{}, 1.0, 0.0};
  // Largest squared chord ratios, times the squared width.
  double sec2 = 1.0, tan2 = 0.0;
  // The chord from vertex i to j at the normal of an edge u, width2 = (x . chord)^2 * |u|^2.
  const auto chord = [&](std::size_t i, std::size_t j, double width2) {
    const V2 d = at(j) - at(i);
    const double dz = z[wrap(j)] - z[wrap(i)];
    sec2 = std::max(sec2, (sqr_length(d) + dz * dz) / width2);
    tan2 = std::max(tan2, dz * dz / width2);
  };
  std::size_t right = 1, top = 1, left = 1;
  for (std::size_t i = 0; i < k; ++i) {
    const V2& a = at(i);
    const V2 u = at(i + 1) - a;
    const double uu = sqr_length(u);
    if (right < i + 1) right = i + 1;
    while (right < i + k && dot(u, at(right + 1) - at(right)) > 0.0) ++right;
    if (top < right) top = right;
    while (top < i + k && perp_dot(u, at(top + 1) - at(top)) > 0.0) ++top;
    if (left < top) left = top;
    while (left < i + k + 1 && dot(u, at(left + 1) - at(left)) < 0.0) ++left;
    const double smax = dot(u, at(right) - a), smin = dot(u, at(left) - a);
    const double tmax = perp_dot(u, at(top) - a);
    const double area = (smax - smin) * tmax / uu;
    if (area < best.area) {
      const double len = std::sqrt(uu);
      best.area = area;
      best.axis0 = (1.0 / len) * u;
      best.extent[0] = 0.5 * (smax - smin) / len;
      best.extent[1] = 0.5 * tmax / len;
      best.center = a + (0.5 * (smax + smin) / uu) * u + best.extent[1] * perp(best.axis0);
    }
    if (!(tmax > 0.0)) {
      sec2 = tan2 = inf;
      continue;
    }
    const double w2 = tmax * tmax / uu;  // (width at the edge normal)^2
    chord(i, top, w2);
    chord(i + 1, top, w2);
    const double tie = 1e-9 * tmax;
    if (perp_dot(u, at(top + 1) - at(top)) > -tie) chord(i + 1, top + 1, w2);
    if (perp_dot(u, at(top + k - 1) - at(top)) > -tie) chord(i, top + k - 1, w2);
  }
  best.sec = std::sqrt(sec2);
  best.tan = std::sqrt(tan2);
  return best;
}

// A lower bound of width(R x) / width(x) over rotations R by at most angle d about an axis
// perpendicular to the normal n, for x = n or x perpendicular to n with chord ratios sec and
// tan (see Frame): width(R x) >= (R x) . chord, and with R x - x = sin d (p cross x) +
// (1 - cos d) p cross (p cross x) for the unit axis p, (R x - x) . chord >=
// -(1 - cos d) |chord| - sin d |p . (x cross chord)|, the last factor at most tan * width(x);
// 1 - cos d <= d^2 / 2 and sin d <= d. 0 when unknown.
double chord_factor(double sec, double tan, double d) {
  return std::max(0.0, 1.0 - (0.5 * d * d * sec + d * tan) * (1.0 + 4.0 * eps));
}

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
  // asin(sine) of `centre` (sine = 2 when that angle reaches pi / 2); blocks of cells the same
  // way (the cells of a block are consecutive).
  struct Cell {
    V3 centre;
    double sine;
    std::uint32_t begin, end;  // range in `edges` (cells) or `cells` (blocks)
  };
  std::vector<Cell> cells, blocks;
  // The silhouette test data of `edges` (same order): the facet normals rounded to float and
  // a bound on the error of a dot product of a unit vector with either of them.
  struct SilhouetteEdge {
    float nf[3], ng[3];
    float err;
    std::uint32_t a, b;
  };
  std::vector<SilhouetteEdge> sil;
  // Cube-map lookup: the cube face and grid of the cells, and per grid square the index of
  // an end vertex of one of its edges (UINT32_MAX if none): a start near the vertex of
  // maximum x . v for x in that square.
  std::size_t grid = 0;
  std::vector<std::uint32_t> square_vertex;
  std::size_t square(const V3& c) const {
    const V3 a = cwise_abs(c);
    const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    const double s = a[k] > 0.0 ? 1.0 / a[k] : 0.0;
    const auto cell = [&](double x) {
      const double t = (x * s + 1.0) * 0.5 * static_cast<double>(grid);
      return t > 0.0 ? std::min(grid - 1, static_cast<std::size_t>(t)) : std::size_t{0};
    };
    const std::size_t face = static_cast<std::size_t>(2 * k + (c[k] < 0.0 ? 1 : 0));
    return (face * grid + cell(c[(k + 1) % 3])) * grid + cell(c[(k + 2) % 3]);
  }

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
    height_.clear();
    const auto take = [&](std::uint32_t i) {
      if (stamp_[i] == tick_) return;
      stamp_[i] = tick_;
      proj_.push_back({dot(u, m_.verts[i]), dot(v, m_.verts[i])});
      height_.push_back(dot(w, m_.verts[i]));
    };
    // An edge is kept when one of its facets may face n (n . N >= 0) and one may face away
    // (n . N <= 0), given the error bound of the rounded normals.
    const auto dotf = [&](const float* x) {
      return w.x * static_cast<double>(x[0]) + w.y * static_cast<double>(x[1]) +
             w.z * static_cast<double>(x[2]);
    };
    work_ = m_.blocks.size();
    for (const Mesh::Cell& blk : all ? std::span<const Mesh::Cell>() : std::span(m_.blocks)) {
      // A block or cell whose normals all lie strictly on one side of the plane n^perp has no
      // silhouette edge.
      if (std::abs(dot(w, blk.centre)) > blk.sine + 4.0 * eps) continue;
      work_ += blk.end - blk.begin;
      for (std::uint32_t ci = blk.begin; ci < blk.end; ++ci) {
        const Mesh::Cell& c = m_.cells[ci];
        if (std::abs(dot(w, c.centre)) > c.sine + 4.0 * eps) continue;
        work_ += c.end - c.begin;
        for (std::uint32_t k = c.begin; k < c.end; ++k) {
          const Mesh::SilhouetteEdge& e = m_.sil[k];
          const double df = dotf(e.nf), dg = dotf(e.ng), err = static_cast<double>(e.err);
          if (std::max(df, dg) >= -err && std::min(df, dg) <= err) {
            take(e.a);
            take(e.b);
          }
        }
      }
    }
    if (all || proj_.size() < 3)
      for (std::uint32_t i = 0; i < m_.verts.size(); ++i) take(i);
    work_ += proj_.size();
    double hmin = inf, hmax = -inf;
    out.sec_width = out.tan_width = inf;
    if (m_.neighbours.empty()) {
      for (const V3& p : m_.verts) {
        const double h = dot(w, p);
        hmin = std::min(hmin, h);
        hmax = std::max(hmax, h);
      }
      work_ += m_.verts.size();
    } else {
      // Start the ascents at a vertex of the cube-map square of +-w when it has one.
      const std::uint32_t up = m_.square_vertex[m_.square(w)],
                          down = m_.square_vertex[m_.square(-w)];
      if (up != std::numeric_limits<std::uint32_t>::max()) top_ = up;
      if (down != std::numeric_limits<std::uint32_t>::max()) bottom_ = down;
      top_ = m_.climb(w, top_, work_);
      bottom_ = m_.climb(-w, bottom_, work_);
      hmax = dot(w, m_.verts[top_]);
      hmin = dot(w, m_.verts[bottom_]);
      const V3 chord = m_.verts[top_] - m_.verts[bottom_];
      if (hmax - hmin > 0.0) {
        out.sec_width = length(chord) / (hmax - hmin);
        out.tan_width = length(chord - dot(w, chord) * w) / (hmax - hmin);
      }
    }
    hull2_.compute(proj_, Hull2Options{}, h2_);
    if (h2_.status != Status::ok || h2_.dimension != 2) return false;
    poly_.resize(h2_.indices.size());
    poly_z_.resize(h2_.indices.size());
    for (std::size_t i = 0; i < poly_.size(); ++i) {
      poly_[i] = proj_[h2_.indices[i]];
      poly_z_[i] = height_[h2_.indices[i]];
    }
    const PolygonRect r = rect_of_polygon(poly_, poly_z_);
    out.sec_rect = r.sec;
    out.tan_rect = r.tan;
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
  std::vector<double> height_, poly_z_;  // heights along the normal of proj_, poly_
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

// The box of a frame of the vertices scaled by `scale` (a power of two), scaled back.
template <Real T>
OrientedBox<T, 3> to_box(const Frame& f, const V3& ref, double scale) {
  OrientedBox<T, 3> b;
  b.center = vec_cast<T>(ref + f.center / scale);
  for (int k = 0; k < 3; ++k) b.axis[k] = vec_cast<T>(f.axis[k]);
  b.extent = {static_cast<T>(f.extent[0] / scale), static_cast<T>(f.extent[1] / scale),
              static_cast<T>(f.extent[2] / scale)};
  return b;
}

// ---- min_box, step by step ----

// Step 1: the hull as a mesh over local vertex indices (hull.vertices is sorted): triangles in
// a canonical order, rounded facet normals with their error bounds, and edges with their two
// triangles.
void build_mesh(const Hull3Result& hull, Mesh& m) {
  const auto local = [&](std::uint32_t i) {
    return static_cast<std::uint32_t>(
        std::lower_bound(hull.vertices.begin(), hull.vertices.end(), i) - hull.vertices.begin());
  };
  const std::size_t nt = hull.triangles.size();
  // The triangles in a canonical order (each rotated to start at its smallest vertex, then
  // sorted), so that the result depends on the hull alone and not on the order in which
  // convex_hull lists it, which changes with the input (duplicated points, say); the rounding
  // of the normals and the order of the evaluations would otherwise differ in the last bits.
  std::vector<std::array<std::uint32_t, 3>> adjacency(nt);
  m.tris.resize(nt);
  {
    std::vector<std::array<std::uint32_t, 3>> tri(nt), adj(nt);
    for (std::size_t t = 0; t < nt; ++t) {
      std::size_t rot = 0;
      for (std::size_t k = 1; k < 3; ++k)
        if (hull.triangles[t][k] < hull.triangles[t][rot]) rot = k;
      for (std::size_t k = 0; k < 3; ++k) {
        tri[t][k] = local(hull.triangles[t][(k + rot) % 3]);
        adj[t][k] = hull.adjacency[t][(k + rot) % 3];
      }
    }
    std::vector<std::uint32_t> order(nt), index(nt);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return tri[a] < tri[b]; });
    for (std::size_t i = 0; i < nt; ++i) index[order[i]] = static_cast<std::uint32_t>(i);
    for (std::size_t i = 0; i < nt; ++i) {
      m.tris[i] = tri[order[i]];
      for (std::size_t k = 0; k < 3; ++k) adjacency[i][k] = index[adj[order[i]][k]];
    }
  }
  m.normal.resize(nt);
  m.normal_err.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const V3 e1 = m.verts[m.tris[t][1]] - m.verts[m.tris[t][0]],
             e2 = m.verts[m.tris[t][2]] - m.verts[m.tris[t][0]];
    const V3 n = cross(e1, e2);
    const double sine = length(n) / (length(e1) * length(e2));
    m.normal[t] = normalize(n);
    m.normal_err[t] = sine > 1e-8 ? 16.0 * eps / sine : inf;
  }
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t e = 0; e < 3; ++e) {
      const std::uint32_t u = adjacency[t][e];
      if (u < t) continue;  // each edge once
      m.edges.push_back({m.tris[t][e], m.tris[t][(e + 1) % 3], static_cast<std::uint32_t>(t), u});
    }
}

// Step 2: the edges grouped in cube-map cells and blocks with bounding cones, the vertices
// renumbered in the order the cells reach them, and the silhouette test data.
void build_cells(Mesh& m) {
  {
    // Cube-map cells of about 2 edges (16 above 16384 edges, where the blocks' tests would
    // cost more than the edges' saved), keyed by the mean normal of each edge's facets, in
    // blocks of 4 x 4 cells (sorted by block, then by cell, so a block's cells are consecutive).
    const double per_cell = m.edges.size() <= 16384 ? 2.0 : 16.0;
    m.grid = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(
                                          static_cast<double>(m.edges.size()) / (6.0 * per_cell))));
    const std::size_t g = m.grid, bg = (g + 3) / 4;
    const auto key = [&](const Mesh::Edge& e) {
      const std::size_t sq = m.square(m.normal[e.f] + m.normal[e.g]);
      const std::size_t face = sq / (g * g), i = sq / g % g, j = sq % g;
      return ((((face * bg + i / 4) * bg + j / 4) * 4 + i % 4) * 4 + j % 4) * g * g * 6 + sq;
    };
    std::vector<std::pair<std::size_t, Mesh::Edge>> keyed;
    keyed.reserve(m.edges.size());
    for (const Mesh::Edge& e : m.edges) keyed.push_back({key(e), e});
    std::sort(keyed.begin(), keyed.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < keyed.size(); ++i) m.edges[i] = keyed[i].second;
    {
      // Renumber the vertices in the order the cells first reach them, so the vertices of a
      // silhouette (and of an ascent) lie close in memory.
      std::vector<std::uint32_t> id(m.verts.size(), std::numeric_limits<std::uint32_t>::max());
      std::vector<V3> verts;
      verts.reserve(m.verts.size());
      const auto renumber = [&](std::uint32_t& v) {
        if (id[v] == std::numeric_limits<std::uint32_t>::max()) {
          id[v] = static_cast<std::uint32_t>(verts.size());
          verts.push_back(m.verts[v]);
        }
        v = id[v];
      };
      for (Mesh::Edge& e : m.edges) {
        renumber(e.a);
        renumber(e.b);
      }
      for (std::uint32_t v = 0; v < m.verts.size(); ++v) {  // (every vertex has an edge)
        std::uint32_t u = v;
        renumber(u);
      }
      for (auto& t : m.tris)
        for (std::uint32_t& v : t) v = id[v];
      m.verts = std::move(verts);
    }
    m.square_vertex.assign(6 * g * g, std::numeric_limits<std::uint32_t>::max());
    const std::size_t per_block = 6 * g * g * 16;
    // Widest angle from the unit centre c (rounded up) of the normals of edges [i, j), as a
    // sine; 2 = not bounded below pi / 2.
    const auto cone = [&](V3 c, std::size_t i, std::size_t j) {
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
      return Mesh::Cell{c, sine, 0, 0};
    };
    for (std::size_t i = 0; i < keyed.size();) {
      const std::size_t block_key = keyed[i].first / per_block;
      const std::size_t block_begin = i;
      V3 block_sum{};
      const auto first_cell = static_cast<std::uint32_t>(m.cells.size());
      while (i < keyed.size() && keyed[i].first / per_block == block_key) {
        std::size_t j = i;
        V3 c{};
        while (j < keyed.size() && keyed[j].first == keyed[i].first) {
          c += m.normal[m.edges[j].f] + m.normal[m.edges[j].g];
          ++j;
        }
        m.square_vertex[keyed[i].first % (6 * g * g)] = m.edges[i].a;
        Mesh::Cell cell = cone(c, i, j);
        cell.begin = static_cast<std::uint32_t>(i);
        cell.end = static_cast<std::uint32_t>(j);
        m.cells.push_back(cell);
        block_sum += c;
        i = j;
      }
      Mesh::Cell block = cone(block_sum, block_begin, i);
      block.begin = first_cell;
      block.end = static_cast<std::uint32_t>(m.cells.size());
      m.blocks.push_back(block);
    }
    m.sil.resize(m.edges.size());
    for (std::size_t i = 0; i < m.edges.size(); ++i) {
      const Mesh::Edge& e = m.edges[i];
      Mesh::SilhouetteEdge& s = m.sil[i];
      for (int k = 0; k < 3; ++k) {
        s.nf[k] = static_cast<float>(m.normal[e.f][k]);
        s.ng[k] = static_cast<float>(m.normal[e.g][k]);
      }
      // Float rounding moves a unit normal by at most 2^-24 (relative, per component).
      const double err = std::max(m.normal_err[e.f], m.normal_err[e.g]) + 1.2e-7 + 8.0 * eps;
      s.err = static_cast<float>(err);
      if (static_cast<double>(s.err) < err)
        s.err = std::nextafter(s.err, std::numeric_limits<float>::infinity());
      s.a = e.a;
      s.b = e.b;
    }
  }
}

// Step 3: the vertex graph (the neighbours of each vertex), for the support ascents.
void build_vertex_graph(Mesh& m) {
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
}

// f at n with the end data of the bounds: value (f), width along n, chord cosines.
struct Sample {
  double value = inf, width = 0.0, sec_width = inf, tan_width = inf, sec_rect = inf, tan_rect = inf;
};

// Steps 4-6: the search over normals for the smallest f (facet normals, edge pairs, the branch
// and bound over arcs or regions, descents), with the budget and the best frame found.
class BoxSearch {
 public:
  BoxSearch(const Mesh& m, const MinBoxOptions& options)
      : m_(m), options_(options), ev_(m), h_(m.verts.size()), nt_(m.tris.size()) {
    best_.volume = inf;
    bound_widths();
  }

  void run();

  const Frame& best() const { return best_; }
  bool exhausted() const { return exhausted_; }
  std::size_t candidates() const { return candidates_; }
  std::size_t arcs() const { return arcs_; }
  bool certified() const { return certified_; }

 private:
  // A candidate's volume is trusted only after the box of all vertices in its frame confirms it.
  void consider(const Frame& f) {
    if (!(f.volume < best_.volume)) return;
    Frame g;
    ev_.fit(f.axis, g);
    if (g.volume < best_.volume) best_ = g;
  }
  bool evaluate(const V3& n, Sample& out) {
    if (work_ > options_.max_work) {
      exhausted_ = true;
      return false;
    }
    ++candidates_;
    Frame f;
    out = Sample{};
    bool ok = ev_.candidate(n, f);
    work_ += ev_.last_work();
    if (!ok) return true;
    if (f.volume < best_.volume) {
      // A new best must be confirmed by the box of all vertices in its frame; if that box is
      // larger, the silhouette culling missed a vertex (rounding): evaluate again without it.
      Frame g;
      ev_.fit(f.axis, g);
      work_ += h_;
      if (g.volume > f.volume * (1.0 + 1e-9)) {
        ok = ev_.candidate(n, f, true);
        work_ += ev_.last_work();
        if (!ok) return true;
      }
    }
    out = {f.volume, 2.0 * f.extent[2], f.sec_width, f.tan_width, f.sec_rect, f.tan_rect};
    last_ = f;
    consider(f);
    return true;
  }

  void bound_widths() {
    // The centre of the vertices is inside the hull; diam bounds its diameter and min_width every
    // width of it (0 when the hull is flat to rounding: then no bound is usable).
    centre_ = V3{};
    for (const V3& p : m_.verts) centre_ += p;
    centre_ = (1.0 / static_cast<double>(h_)) * centre_;
    double radius = 0.0;
    for (const V3& p : m_.verts) radius = std::max(radius, length(p - centre_));
    diam_ = 2.0 * radius * (1.0 + 1e-12);
    double inradius = inf;
    all_trusted_ = true;
    for (std::size_t t = 0; t < nt_; ++t) {
      if (!std::isfinite(m_.normal_err[t])) {
        all_trusted_ = false;
        continue;
      }
      const double dist = dot(m_.normal[t], m_.verts[m_.tris[t][0]] - centre_);
      inradius = std::min(inradius, dist - (m_.normal_err[t] + 8.0 * eps) * diam_);
    }
    min_width_ = 2.0 * std::max(0.0, inradius);
    tol_ = options_.certify_tol > 0.0 ? options_.certify_tol : 1e-3;
  }

  // Branch and bound over regions of normals (for hulls with very many facets, where
  // evaluating every facet normal would be the main cost). Since f(-n) = f(n), the normals are
  // those of the three cube faces +x, +y, +z (every n or -n lies on one); a region is a square
  // of a face in gnomonic coordinates, bounded by the largest angle r from its centre's
  // normal n0 to its corners (the set of normals within an angle of n0 is convex there, so the
  // corners are the farthest points). Every frame with a normal in the region is a frame at
  // n0 rotated by at most r, so f >= f(n0) times the chord factor of the width along n0 and
  // the squared chord factor of the rectangle (or the Lipschitz factors, whichever is larger).
  void search_regions() {
    struct Region {
      double bound;
      int face;
      double u0, u1, v0, v1;
      double angle, value, slope;  // r, f(n0), first-order relative loss of the bound per radian
    };
    const auto later = [](const Region& x, const Region& y) { return x.bound > y.bound; };
    std::vector<Region> heap;  // min-heap on bound
    const auto normal_at = [](int face, double a, double b) {
      V3 n{};
      n[face] = 1.0;
      n[(face + 1) % 3] = a;
      n[(face + 2) % 3] = b;
      return normalize(n);
    };
    bool proved = true;
    // The best frames evaluated (starts of descents when the search stops unproved).
    std::vector<Frame> starts;
    starts.reserve(8);
    const auto keep_start = [&](const Sample& s) {
      if (!std::isfinite(s.value) ||
          (starts.size() == starts.capacity() && !(s.value < starts.back().volume)))
        return;
      if (starts.size() == starts.capacity()) starts.pop_back();
      starts.insert(
          std::upper_bound(starts.begin(), starts.end(), last_,
                           [](const Frame& x, const Frame& y) { return x.volume < y.volume; }),
          last_);
    };
    // Evaluate the centre_, bound the region, keep it when the bound is below the threshold.
    const auto visit = [&](int face, double u0, double u1, double v0, double v1) {
      const V3 n0 = normal_at(face, 0.5 * (u0 + u1), 0.5 * (v0 + v1));
      double angle = 0.0;
      for (double a : {u0, u1})
        for (double b : {v0, v1}) {
          const V3 c = normal_at(face, a, b);
          angle = std::max(angle, std::atan2(length(cross(n0, c)), dot(n0, c)));
        }
      angle = angle * (1.0 + 1e-12) + 1e-14;
      Sample s;
      if (!evaluate(n0, s)) return false;
      keep_start(s);
      double bound = 0.0, slope = inf;
      if (std::isfinite(s.value) && s.width > 0.0) {
        const double rect = s.value / s.width;
        const double kw =
            std::max(chord_factor(s.sec_width, s.tan_width, angle), 1.0 - angle * diam_ / s.width);
        // (min_width bounds every width only when every facet normal is trusted.)
        const double g = all_trusted_ ? 1.0 + angle * diam_ / min_width_ : inf;
        const double ka = std::max(chord_factor(s.sec_rect, s.tan_rect, angle), 1.0 / g);
        bound = s.width * kw * rect * ka * ka * (1.0 - 8.0 * eps);
        slope =
            std::min(s.tan_width, diam_ / s.width) + 2.0 * std::min(s.tan_rect, diam_ / min_width_);
      }
      if (bound < (1.0 - tol_) * best_.volume) {
        if (angle < 1e-10) {
          proved = false;  // splitting cannot help further
        } else {
          heap.push_back({bound, face, u0, u1, v0, v1, angle, s.value, slope});
          std::push_heap(heap.begin(), heap.end(), later);
        }
      }
      return true;
    };
    // Regions still to prove predict more work than the budget has left: the search stops
    // as if the budget had run out (after a sixteenth of it, for the quality of the box).
    // Each needs about (r / r') ^ 2 evaluations, r' the radius at which the first-order loss
    // of its bound would leave it above the threshold, at most 1024 (five levels of splits:
    // near the minimum f grows away from the centre_, so the estimate is far too high there).
    const std::size_t evaluations_before = candidates_;
    const auto hopeless = [&] {
      if (work_ < options_.max_work / 16) return false;
      double need = 0.0;
      for (const Region& q : heap) {
        const double gap = 1.0 - (1.0 - tol_) * best_.volume / q.value;
        const double r1 = gap / q.slope;
        need += r1 * 32.0 > q.angle ? sqr(q.angle / r1) : 1024.0;
      }
      const double per_evaluation =
          static_cast<double>(work_) /
          static_cast<double>(std::max<std::size_t>(1, candidates_ - evaluations_before));
      return need * per_evaluation >
             static_cast<double>(options_.max_work - std::min(work_, options_.max_work));
    };
    constexpr int grid = 4;
    for (int face = 0; face < 3 && !exhausted_; ++face)
      for (int i = 0; i < grid && !exhausted_; ++i)
        for (int j = 0; j < grid && !exhausted_; ++j)
          visit(face, -1.0 + 2.0 * i / grid, -1.0 + 2.0 * (i + 1) / grid, -1.0 + 2.0 * j / grid,
                -1.0 + 2.0 * (j + 1) / grid);
    std::size_t splits = 0;
    bool given_up = false;
    while (!heap.empty() && !exhausted_) {
      std::pop_heap(heap.begin(), heap.end(), later);
      const Region q = heap.back();
      heap.pop_back();
      if (q.bound >= (1.0 - tol_) * best_.volume) {
        heap.clear();
        break;
      }
      const double um = 0.5 * (q.u0 + q.u1), vm = 0.5 * (q.v0 + q.v1);
      if (!visit(q.face, q.u0, um, q.v0, vm) || !visit(q.face, um, q.u1, q.v0, vm) ||
          !visit(q.face, q.u0, um, vm, q.v1) || !visit(q.face, um, q.u1, vm, q.v1))
        break;
      if (++splits % 128 == 0 && hopeless()) {
        exhausted_ = given_up = true;
        break;
      }
    }
    certified_ = proved && heap.empty() && !exhausted_ && options_.certify_tol > 0.0;
    if (given_up) {
      // Facet normals (where f has its local minima more often than at region centres), in a
      // stride order spreading them over the hull, with up to an eighth of the budget.
      std::size_t stride = 7919;  // coprime with nt: j -> j * stride mod nt is a permutation
      while (std::gcd(stride, nt_) != 1) stride += 2;
      const std::uint64_t stop = work_ + options_.max_work / 8;
      Sample s;
      for (std::size_t j = 0; j < nt_ && work_ < stop; ++j) {
        const std::size_t t = (j * stride) % nt_;
        if (!std::isfinite(m_.normal_err[t])) continue;
        if (!evaluate(m_.normal[t], s)) break;
        keep_start(s);
      }
    }
    if (options_.refine) {
      refine(ev_, m_, best_, work_, options_.max_work + options_.max_work / 16);
      // Unproved: f is flat or the budget small, descend from the other best frames too (the
      // minimum may be in another basin).
      if (!certified_)
        for (Frame& f : starts) {
          refine(ev_, m_, f, work_, options_.max_work + options_.max_work / 8);
          if (f.volume < best_.volume) best_ = f;
        }
    }
  }

  // The facet normals after the first `head` (every one, or in a stride order that spreads
  // the ones the budget reaches over the hull).
  void facet_pass(std::size_t head, double predicted) {
    std::size_t stride = 1;
    if (predicted > static_cast<double>(options_.max_work)) {
      stride = 7919;  // a prime, made coprime with nt: j -> j * stride mod nt is a permutation
      while (std::gcd(stride, nt_) != 1) stride += 2;
    }
    for (std::size_t j = 0; j < nt_ && !exhausted_; ++j) {
      const std::size_t t = (j * stride) % nt_;
      if (t >= head && std::isfinite(m_.normal_err[t])) evaluate(m_.normal[t], fsample_[t]);
    }
  }

  // The cross products of edge pairs of small hulls; the coordinate axes when the budget
  // allowed no candidate at all.
  void edge_pairs() {
    if (m_.edges.size() <= options_.max_pair_edges)
      for (std::size_t i = 0; i < m_.edges.size() && !exhausted_; ++i)
        for (std::size_t j = i + 1; j < m_.edges.size() && !exhausted_; ++j) {
          const V3 n = cross(m_.verts[m_.edges[i].b] - m_.verts[m_.edges[i].a],
                             m_.verts[m_.edges[j].b] - m_.verts[m_.edges[j].a]);
          Sample pair;
          if (sqr_length(n) > 0.0) evaluate(normalize(n), pair);
        }
    if (!(best_.volume < inf)) {
      // Budget too small for a single candidate: the box of the coordinate axes.
      const V3 axes[3] = {V3{1, 0, 0}, V3{0, 1, 0}, V3{0, 0, 1}};
      ev_.fit(axes, best_);
    }
  }

  // Branch and bound over the arcs (the bound: docs/notes/bounding.md).
  void search_arcs() {
    // Branch and bound over the arcs (see the header comment for the bound).

    struct Arc {
      V3 a, b;        // n(t) = cos(t) a + sin(t) b
      double margin;  // angular error of the arc's ends
      double diam;    // diameter bound of the hull's projection along the arc's pole a x b
      bool coarse;    // diam is the hull's (the projection's is computed when first needed)
    };
    struct Piece {
      double bound;
      std::uint32_t arc;
      double lo, hi;    // angle interval
      Sample slo, shi;  // f, width along n and chord cosines at its ends
      bool operator<(const Piece& o) const { return bound > o.bound; }  // min-heap
    };
    std::vector<Arc> arcs;
    std::priority_queue<Piece> heap;
    // Lower bound of f over the piece (and within the arc's margin of it). The width along n
    // is concave on the arc: at least its chord between the ends. The rectangle area at t is
    // at least the area at an end t' shrunk by the rotation by |t - t'| (plus the margin) that
    // maps the frames at t' to those at t: the larger of the chord factor (chord_factor, per
    // side) and the Lipschitz factor of the header comment. On each of K sub-intervals the
    // bound is the smaller chord width times the larger of the two ends' area bounds at the
    // sub-interval's far points.
    const auto lower_bound = [&](const Piece& p) {
      if (!(std::isfinite(p.slo.value) && std::isfinite(p.shi.value) && min_width_ > 0.0))
        return 0.0;
      if (!(p.slo.width > 0.0 && p.shi.width > 0.0)) return 0.0;
      const Arc& arc = arcs[p.arc];
      const double wm = 4.0 * arc.margin * diam_;
      const double alo = p.slo.value / p.slo.width, ahi = p.shi.value / p.shi.width;
      const auto area = [&](double a, const Sample& e, double d) {
        const double g =
            1.0 + (0.7071067811865476 * d * arc.diam + arc.margin * diam_) / min_width_;
        const double k = chord_factor(e.sec_rect, e.tan_rect, d + arc.margin);
        return a * std::max(1.0 / (g * g), k * k);
      };
      constexpr int K = 8;
      const double len = p.hi - p.lo;
      double bound = inf;
      for (int j = 0; j < K; ++j) {
        const double x0 = len * j / K, x1 = len * (j + 1) / K;
        const double w0 = p.slo.width + (p.shi.width - p.slo.width) * (j / double(K));
        const double w1 = p.slo.width + (p.shi.width - p.slo.width) * ((j + 1) / double(K));
        const double w = std::min(w0, w1) * (1.0 - 4.0 * eps) - wm;
        if (!(w > 0.0)) return 0.0;
        const double rect = std::max(area(alo, p.slo, x1), area(ahi, p.shi, len - x0));
        bound = std::min(bound, w * rect);
      }
      return bound;
    };
    // Projection diameters per arc cost O(h) each; above this the global one is used.
    const bool per_arc_diam = m_.edges.size() * h_ <= 50000000u;
    bool proved = all_trusted_ && min_width_ > 0.0;
    // (A hull flat to rounding has no usable width bound: its arcs are left unsearched.)
    for (const Mesh::Edge& e : (min_width_ > 0.0 ? std::span<const Mesh::Edge>(m_.edges)
                                                 : std::span<const Mesh::Edge>())) {
      if (!std::isfinite(m_.normal_err[e.f]) || !std::isfinite(m_.normal_err[e.g])) continue;
      const V3 a = m_.normal[e.f];
      const double c = dot(a, m_.normal[e.g]);
      const V3 s = m_.normal[e.g] - c * a;
      const double sn = length(s);
      const V3 b = sn > 0.0 ? (1.0 / sn) * s : complete_basis(a).axis[1];
      arcs.push_back(
          {a, b, m_.normal_err[e.f] + m_.normal_err[e.g] + 8.0 * eps, diam_, per_arc_diam});
      Piece p{0.0,           static_cast<std::uint32_t>(arcs.size() - 1),
              0.0,           std::atan2(sn, c),
              fsample_[e.f], fsample_[e.g]};
      p.bound = lower_bound(p);
      if (p.bound < (1.0 - tol_) * best_.volume) heap.push(p);
    }
    arcs_ = arcs.size();
    const double best_before = best_.volume;
    while (!heap.empty()) {
      const double threshold = (1.0 - tol_) * best_.volume;
      if (heap.top().bound >= threshold) break;  // every piece left is proved
      Piece p = heap.top();
      heap.pop();
      if (arcs[p.arc].coarse) {
        // The diameter of the projection along the pole (O(h)) before the first split.
        Arc& arc = arcs[p.arc];
        const V3 pole = normalize(cross(arc.a, arc.b));
        double r2 = 0.0;
        for (const V3& q : m_.verts) {
          const V3 d = q - centre_;
          const double z = dot(d, pole);
          r2 = std::max(r2, sqr_length(d) - z * z);
        }
        arc.diam = std::min(diam_, 2.0 * std::sqrt(r2) * (1.0 + 1e-12) + 8.0 * eps * diam_);
        arc.coarse = false;
        p.bound = std::max(p.bound, lower_bound(p));
        if (p.bound < threshold) heap.push(p);
        continue;
      }
      // Splitting cannot help a piece below 1e-12 rad, nor one with an end whose own bound
      // at zero distance fails (the arc ends' normal errors alone exceed the tolerance).
      Piece at_lo = p, at_hi = p;
      at_lo.hi = at_lo.lo;
      at_lo.shi = at_lo.slo;
      at_hi.lo = at_hi.hi;
      at_hi.slo = at_hi.shi;
      if (p.hi - p.lo < 1e-12 || lower_bound(at_lo) < threshold || lower_bound(at_hi) < threshold) {
        proved = false;
        continue;
      }
      const Arc& arc = arcs[p.arc];
      const double mid = 0.5 * (p.lo + p.hi);
      Sample sm;
      if (!evaluate(normalize(std::cos(mid) * arc.a + std::sin(mid) * arc.b), sm)) break;
      Piece left{0.0, p.arc, p.lo, mid, p.slo, sm};
      Piece right{0.0, p.arc, mid, p.hi, sm, p.shi};
      left.bound = lower_bound(left);
      right.bound = lower_bound(right);
      const double t2 = (1.0 - tol_) * best_.volume;
      if (left.bound < t2) heap.push(left);
      if (right.bound < t2) heap.push(right);
    }
    certified_ = proved && !exhausted_ && options_.certify_tol > 0.0;
    if (best_.volume < best_before && options_.refine && !exhausted_)
      refine(ev_, m_, best_, work_, options_.max_work);
  }

  const Mesh& m_;
  const MinBoxOptions& options_;
  Evaluator ev_;
  const std::size_t h_, nt_;
  std::uint64_t work_ = 0;
  bool exhausted_ = false;
  Frame best_{};
  Frame last_{};  // the frame of the last evaluation
  std::size_t candidates_ = 0, arcs_ = 0;
  bool certified_ = false;
  std::vector<Sample> fsample_;  // f at each facet normal (the ends of the arcs)
  // The centre of the vertices (inside the hull), a bound on its diameter and one on every
  // width of it (0 when the hull is flat to rounding: then no bound is usable).
  V3 centre_{};
  double diam_ = 0.0, min_width_ = 0.0, tol_ = 0.0;
  bool all_trusted_ = true;
};

void BoxSearch::run() {
  // Every facet normal (the ends of the arcs; the facet-flush boxes). When the first ones
  // show that the facet pass alone would take half the budget (a hull with very many
  // vertices, e.g. points on a sphere), the arcs are replaced by the branch and bound over
  // regions (with edge_arcs), or the facets are visited in a stride order that spreads the
  // ones the budget reaches over the hull (without it, or when the regions cannot be bounded).
  fsample_.assign(nt_, Sample{});
  const std::size_t head = std::min<std::size_t>(64, nt_);
  std::uint64_t head_work = 0;  // (without the confirmations of new best boxes)
  for (std::size_t t = 0; t < head && !exhausted_; ++t)
    if (std::isfinite(m_.normal_err[t])) {
      evaluate(m_.normal[t], fsample_[t]);
      head_work += ev_.last_work();
    }
  const double predicted =
      static_cast<double>(head_work) / static_cast<double>(head) * static_cast<double>(nt_);
  if (options_.edge_arcs && min_width_ > 0.0 && !exhausted_ &&
      (options_.search == MinBoxSearch::regions ||
       (options_.search == MinBoxSearch::automatic &&
        predicted > 0.5 * static_cast<double>(options_.max_work)))) {
    search_regions();
  } else {
    facet_pass(head, predicted);
    edge_pairs();
    if (options_.refine) refine(ev_, m_, best_, work_, options_.max_work + options_.max_work / 16);
    if (options_.edge_arcs && !exhausted_) search_arcs();
  }
}

}  // namespace

template <Real T>
MinBoxResult<T> min_box(std::span<const Vec3<T>> points, const MinBoxOptions& options) {
  MinBoxResult<T> r;
  const Hull3Result hull = convex_hull(points);
  r.status = hull.status;
  if (hull.status != Status::ok) return r;
  // Hull vertices relative to the first one (keeps far-from-origin sets precise), scaled by a
  // power of two when products of their coordinates (volumes, the calipers' areas over squared
  // lengths) could leave the range (distance/detail/rescale.hpp); the box is scaled back
  // exactly, so it scales exactly with the input.
  const V3 ref = vec_cast<double>(points[hull.vertices[0]]);
  Mesh m;
  m.verts.resize(hull.vertices.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < m.verts.size(); ++i) {
    m.verts[i] = vec_cast<double>(points[hull.vertices[i]]) - ref;
    largest = std::max(largest, max_abs(m.verts[i]));
  }
  const double scale =
      detail::outside_product_range<double, 6>(largest) ? normalising_scale(largest) : 1.0;
  if (scale != 1.0)
    for (V3& v : m.verts) v = scale * v;

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
      const V3 d = scale * (vec_cast<double>(points[hull.polygon[1]]) -
                            vec_cast<double>(points[hull.polygon[0]]));
      ev.fit(complete_basis(d).axis.data(), f);
    } else {
      const V3 a = vec_cast<double>(points[hull.polygon[0]]),
               b = vec_cast<double>(points[hull.polygon[1]]),
               c = vec_cast<double>(points[hull.polygon[2]]);
      // The flat direction is axis[2].
      if (!ev.candidate(normalize(cross(scale * (b - a), scale * (c - a))), f)) {
        r.status = Status::degenerate_input;
        return r;
      }
    }
    r.box = to_box<T>(f, ref, scale);
    r.volume = T(0);
    r.candidates = 1;
    r.certified = true;  // a flat box is a minimum
    return r;
  }

  build_mesh(hull, m);
  build_cells(m);
  build_vertex_graph(m);

  BoxSearch search(m, options);
  search.run();
  r.candidates = search.candidates();
  r.arcs = search.arcs();
  r.certified = search.certified();
  r.box = to_box<T>(search.best(), ref, scale);
  r.volume = static_cast<T>(search.best().volume / scale / scale / scale);
  if (search.exhausted()) r.status = Status::limit_exceeded;
  return r;
}

template MinBoxResult<float> min_box<float>(std::span<const Vec3<float>>, const MinBoxOptions&);
template MinBoxResult<double> min_box<double>(std::span<const Vec3<double>>, const MinBoxOptions&);

}  // namespace locus
