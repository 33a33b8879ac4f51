// SPDX-License-Identifier: BSL-1.0
// The BSP tree of a polyhedron (see include/locus/bsp/bsp3.hpp and docs/notes/bsp3.md).

#include <locus/bsp/bsp3.hpp>

#include "bsp3_keyed.hpp"

#include <locus/core/plane_side.hpp>
#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace locus {

namespace {

using bsp3_detail::LineKey;
using bsp3_detail::VertexKey;

template <Real T>
[[nodiscard]] Vec2<T> drop_axis(const Vec3<T>& v, int k) noexcept {
  return k == 0 ? Vec2<T>{v.y, v.z} : (k == 1 ? Vec2<T>{v.z, v.x} : Vec2<T>{v.x, v.y});
}

template <Real T>
[[nodiscard]] bool finite3(const Vec3<T>& v) noexcept {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// An axis k whose projection keeps abc non-degenerate (exact), or -1 when abc is collinear;
/// sign receives the orientation of the projected triangle.
template <Real T>
[[nodiscard]] int projection_axis(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                  Sign& sign) noexcept {
  // Prefer the dominant normal component (best conditioned), but decide exactly.
  const Vec3<double> n =
      cross(vec_cast<double>(b) - vec_cast<double>(a), vec_cast<double>(c) - vec_cast<double>(a));
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&n](int i, int j) { return std::abs(n[i]) > std::abs(n[j]); });
  for (const int k : order) {
    sign = orient2d(drop_axis(a, k), drop_axis(b, k), drop_axis(c, k));
    if (sign != Sign::zero) return k;
  }
  sign = Sign::zero;
  return -1;
}

/// A splitting plane: three input points plus what cutting needs.
template <Real T>
struct PlaneRef {
  Vec3<T> a, b, c;
  Vec3<double> n;   // (b - a) x (c - a), rounded
  double offset;    // dot(n, a), accurate
  int axis_normal;  // k when the plane is x_k = a_k exactly, else -1
  int proj;         // projection axis (projection_axis)
  Sign proj_sign;

  PlaneRef(const Vec3<T>& a_, const Vec3<T>& b_, const Vec3<T>& c_) noexcept : a(a_), b(b_), c(c_) {
    n = cross(vec_cast<double>(b) - vec_cast<double>(a), vec_cast<double>(c) - vec_cast<double>(a));
    offset = dot_accurate(n, vec_cast<double>(a));
    axis_normal = -1;
    for (int k = 0; k < 3; ++k)
      if (a[k] == b[k] && a[k] == c[k]) axis_normal = k;
    proj = projection_axis(a, b, c, proj_sign);
  }
  [[nodiscard]] Sign side(const Vec3<T>& p) const noexcept { return orient3d(a, b, c, p); }
  [[nodiscard]] Sign side_d(const Vec3<double>& p) const noexcept {
    if constexpr (std::is_same_v<T, double>) {
      return orient3d(a, b, c, p);
    } else {
      return orient3d(vec_cast<double>(a), vec_cast<double>(b), vec_cast<double>(c), p);
    }
  }
  [[nodiscard]] bool contains_triangle(const Vec3<T>& p, const Vec3<T>& q,
                                       const Vec3<T>& r) const noexcept {
    return side(p) == Sign::zero && side(q) == Sign::zero && side(r) == Sign::zero;
  }
  /// The rounded crossing of the edge from u (positive side) to v (negative side), in double
  /// whatever T is; see the header.
  [[nodiscard]] Vec3<double> cut(const Vec3<double>& u, const Vec3<double>& v) const noexcept {
    const double du = plane_value(n, offset, u), dv = plane_value(n, offset, v);
    const double denom = du - dv;
    Vec3<double> p;
    // u is on the positive side, v on the negative one (exact). A rounded value of the wrong
    // sign means that end is within rounding of the plane: the crossing is that end.
    if (!(du > 0)) return u;
    if (!(dv < 0)) return v;
    for (int i = 0; i < 3; ++i) {
      double x = u[i] == v[i] ? u[i] : u[i] + ((v[i] - u[i]) * du) / denom;
      if (!std::isfinite(x)) x = 0.5 * u[i] + 0.5 * v[i];  // products overflowed (|x| ~ 1e100+)
      p[i] = std::clamp(x, std::min(u[i], v[i]), std::max(u[i], v[i]));
    }
    if (axis_normal >= 0) p[axis_normal] = double(a[axis_normal]);
    return p;
  }
};

/// Exact: p (on the plane of the non-degenerate triangle abc) lies in the closed triangle.
template <Real T>
[[nodiscard]] bool in_coplanar_triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                        const Vec3<T>& p) noexcept {
  Sign o;
  const int k = projection_axis(a, b, c, o);
  if (k < 0) return false;
  const Vec2<T> a2 = drop_axis(a, k), b2 = drop_axis(b, k), c2 = drop_axis(c, k),
                p2 = drop_axis(p, k);
  return to_int(orient2d(a2, b2, p2) * o) >= 0 && to_int(orient2d(b2, c2, p2) * o) >= 0 &&
         to_int(orient2d(c2, a2, p2) * o) >= 0;
}

/// Exact orientation of a polygon lying in a plane, projected along axis k: the first non-zero
/// orient2d of the fan triangles (a convex polygon's fan triangles all agree).
template <Real T>
[[nodiscard]] Sign fan_orientation(std::span<const Vec3<T>> poly, int k) noexcept {
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const Sign s =
        orient2d(drop_axis(poly[0], k), drop_axis(poly[i], k), drop_axis(poly[i + 1], k));
    if (s != Sign::zero) return s;
  }
  return Sign::zero;
}

/// A fragment corner: an input point (a == bsp3_none), or the crossing of the segment between
/// corners a (positive side) and b (negative side) with plane id `plane`; `key` names it
/// symbolically (bsp3_keyed.hpp; unique when nobody asks).
template <Real T>
struct PointRec {
  Vec3<double> p;  // exact for input points; cut points are kept in double even when T = float
  std::uint32_t a = bsp3_none, b = bsp3_none, plane = bsp3_none;
  VertexKey key{};
};

/// Corners with their provenance. The side of a cut point against a later plane follows from
/// its two parents when they do not straddle that plane (the true crossing lies on the segment
/// between them, a convex combination); only when they do is the rounded point tested. So a
/// plane through a vertex never sees the cut points near that vertex on its wrong side. A corner
/// whose key names three planes lies on each of them (exactly, symbolically).
template <Real T>
struct PointPool {
  std::vector<PointRec<T>> recs;
  static constexpr int max_depth = 8;  // bounds the recursion (2^8 predicates at worst)

  std::uint32_t add_exact(const Vec3<T>& p, const VertexKey& key = {}) {
    recs.push_back({vec_cast<double>(p), bsp3_none, bsp3_none, bsp3_none, key});
    return static_cast<std::uint32_t>(recs.size() - 1);
  }
  std::uint32_t add_cut(const PlaneRef<T>& h, std::uint32_t plane, std::uint32_t pos,
                        std::uint32_t neg, const VertexKey& key = {}) {
    const Vec3<double> x = h.cut(recs[pos].p, recs[neg].p);
    recs.push_back({x, pos, neg, plane, key});
    return static_cast<std::uint32_t>(recs.size() - 1);
  }
  /// kplane: the plane's key id; a cut point whose key names it lies on it (symbolically: the
  /// key's planes are equal or equal up to rounding of the input, docs/notes/bsp3.md).
  [[nodiscard]] Sign side(const PlaneRef<T>& h, std::uint32_t plane, std::uint32_t i,
                          std::uint32_t kplane = bsp3_none, int depth = max_depth) const noexcept {
    const PointRec<T>& r = recs[i];
    if (r.a == bsp3_none) return h.side_d(r.p);
    if (r.plane == plane) return Sign::zero;
    if (kplane != bsp3_none &&
        ((r.key[0] == bsp3_detail::vertex_planes &&
          (r.key[1] == kplane || r.key[2] == kplane || r.key[3] == kplane)) ||
         (r.key[0] == bsp3_detail::vertex_edge_plane && r.key[4] == kplane)))
      return Sign::zero;
    if (depth == 0) return h.side_d(r.p);
    const Sign s0 = side(h, plane, r.a, kplane, depth - 1),
               s1 = side(h, plane, r.b, kplane, depth - 1);
    if (s0 == s1) return s0;
    if (s0 == Sign::zero) return s1;
    if (s1 == Sign::zero) return s0;
    // The parents straddle the plane: only then does the rounded point decide.
    return h.side_d(r.p);
  }
  [[nodiscard]] std::vector<Vec3<double>> coords(std::span<const std::uint32_t> idx) const {
    std::vector<Vec3<double>> r;
    r.reserve(idx.size());
    for (const std::uint32_t i : idx) r.push_back(recs[i].p);
    return r;
  }
};

/// Names cut points and cut lines of a polygon lying in plane id `polygon_plane`.
struct Keyer {
  std::uint32_t polygon_plane = bsp3_none;
  std::uint32_t* serial = nullptr;

  [[nodiscard]] VertexKey cut_key(const LineKey& line, std::uint32_t plane) const noexcept {
    using namespace bsp3_detail;
    if (line[0] == line_planes && plane != bsp3_none && plane != line[1] && plane != line[2]) {
      std::array<std::uint32_t, 3> k{line[1], line[2], plane};
      std::sort(k.begin(), k.end());
      return {vertex_planes, k[0], k[1], k[2], 0};
    }
    if (line[0] == line_edge && plane != bsp3_none)
      return {vertex_edge_plane, line[1], line[2], line[3], plane};
    return {vertex_unique, (*serial)++, 0, 0, 0};
  }
  [[nodiscard]] LineKey cut_line(std::uint32_t plane) const noexcept {
    using namespace bsp3_detail;
    if (polygon_plane != bsp3_none && plane != bsp3_none && plane != polygon_plane)
      return {line_planes, std::min(plane, polygon_plane), std::max(plane, polygon_plane), 0};
    return {line_unique, (*serial)++, 0, 0};
  }
};

/// Splits a convex polygon (corner indices) with vertex signs s (some positive, some
/// negative). Pieces are kept even when rounding flattened them: a sliver along an edge must
/// reach the same cells as its neighbour's sliver, or the cell labels disagree. With a keyer,
/// lines[i] (the line of edge i -> i + 1) is carried to the pieces' edges and cut points and the
/// cut chord are named.
template <Real T>
void split_polygon(PointPool<T>& pool, const PlaneRef<T>& h, std::uint32_t plane,
                   std::span<const std::uint32_t> poly, std::span<const Sign> s,
                   std::vector<std::uint32_t>& front, std::vector<std::uint32_t>& back,
                   const Keyer* keyer = nullptr, std::uint32_t key_plane = bsp3_none,
                   std::span<const LineKey> lines = {}, std::vector<LineKey>* front_lines = nullptr,
                   std::vector<LineKey>* back_lines = nullptr) {
  front.clear();
  back.clear();
  if (keyer != nullptr) {
    front_lines->clear();
    back_lines->clear();
  }
  const std::size_t n = poly.size();
  LineKey chord{};
  bool have_chord = false;
  const auto chord_line = [&]() {
    if (!have_chord) chord = keyer->cut_line(key_plane);
    have_chord = true;
    return chord;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (s[i] != Sign::negative) {
      front.push_back(poly[i]);
      if (keyer != nullptr)
        front_lines->push_back(s[j] != Sign::negative || s[i] == Sign::positive ? lines[i]
                                                                                : chord_line());
    }
    if (s[i] != Sign::positive) {
      back.push_back(poly[i]);
      if (keyer != nullptr)
        back_lines->push_back(s[j] != Sign::positive || s[i] == Sign::negative ? lines[i]
                                                                               : chord_line());
    }
    if (to_int(s[i]) * to_int(s[j]) < 0) {
      // Cut from the positive end so that an edge shared by two fragments is cut at
      // bit-identical points.
      const VertexKey key = keyer != nullptr ? keyer->cut_key(lines[i], key_plane) : VertexKey{};
      const std::uint32_t x = s[i] == Sign::positive
                                  ? pool.add_cut(h, plane, poly[i], poly[j], key)
                                  : pool.add_cut(h, plane, poly[j], poly[i], key);
      front.push_back(x);
      back.push_back(x);
      if (keyer != nullptr) {
        front_lines->push_back(s[i] == Sign::positive ? chord_line() : lines[i]);
        back_lines->push_back(s[i] == Sign::negative ? chord_line() : lines[i]);
      }
    }
  }
}

enum class Rel { front, back, on, straddle };

template <Real T>
[[nodiscard]] Rel relate(const PointPool<T>& pool, const PlaneRef<T>& h, std::uint32_t face,
                         std::uint32_t kplane, std::span<const std::uint32_t> poly,
                         std::vector<Sign>& s) {
  s.resize(poly.size());
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    s[i] = pool.side(h, face, poly[i], kplane);
    pos |= s[i] == Sign::positive;
    neg |= s[i] == Sign::negative;
  }
  if (pos && neg) return Rel::straddle;
  if (pos) return Rel::front;
  if (neg) return Rel::back;
  return Rel::on;
}

template <Real T>
struct Poly {
  std::uint32_t face;
  std::vector<std::uint32_t> idx;
};

/// Deterministic (platform-independent) Fisher-Yates with splitmix64.
template <class V>
void seeded_shuffle(V& v, std::uint64_t seed) {
  std::uint64_t state = seed;
  const auto next = [&state]() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  };
  for (std::size_t i = v.size(); i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(next() % i);
    std::swap(v[i - 1], v[j]);
  }
}

}  // namespace

template <Real T>
Status Bsp3<T>::build(std::span<const Vec3<T>> vertices,
                      std::span<const std::array<std::uint32_t, 3>> triangles,
                      Bsp3Options options) {
  status_ = Status::empty_input;
  root_ = bsp3_outside;
  depth_ = 0;
  vertices_.assign(vertices.begin(), vertices.end());
  faces_.clear();
  nodes_.clear();
  fragments_.clear();
  points_.clear();
  if (triangles.empty()) return status_;
  for (const auto& t : triangles)
    for (const std::uint32_t i : t)
      if (i >= vertices.size()) return status_ = Status::invalid_input;
  for (const auto& v : vertices)
    if (!finite3(v)) return status_ = Status::non_finite_input;
  for (const auto& t : triangles) {
    Sign o;
    if (projection_axis(vertices[t[0]], vertices[t[1]], vertices[t[2]], o) >= 0)
      faces_.push_back(t);
  }
  if (faces_.empty()) return status_ = Status::degenerate_input;
  status_ = Status::ok;

  PointPool<T> pool;  // corners 0 .. |V| - 1 are the input vertices
  pool.recs.reserve(vertices_.size() * 2);
  for (const auto& v : vertices_) pool.add_exact(v);
  std::vector<Poly<T>> initial;
  initial.reserve(faces_.size());
  for (std::uint32_t f = 0; f < faces_.size(); ++f)
    initial.push_back({f, {faces_[f][0], faces_[f][1], faces_[f][2]}});
  if (options.split == Bsp3Split::random_order) seeded_shuffle(initial, options.seed);

  struct Job {
    std::vector<Poly<T>> polys;
    std::int32_t parent;
    bool front_child;
    std::uint32_t depth;
  };
  std::vector<Job> stack;
  stack.push_back({std::move(initial), -1, false, 1});
  std::vector<Sign> signs;
  std::vector<std::uint32_t> fpts, bpts;
  while (!stack.empty()) {
    Job job = std::move(stack.back());
    stack.pop_back();
    std::vector<Poly<T>>& polys = job.polys;
    // Choose the splitter.
    constexpr std::size_t score_sample = 64;
    std::size_t pick = 0;
    if (options.split == Bsp3Split::balanced && polys.size() > 1) {
      const std::size_t m =
          std::min<std::size_t>(std::max<std::uint32_t>(options.sample, 1u), polys.size());
      long long best = -1;
      for (std::size_t c = 0; c < m; ++c) {
        const std::size_t idx = c * polys.size() / m;
        const auto& t = faces_[polys[idx].face];
        const PlaneRef<T> h(vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]);
        long long nf = 0, nb = 0, ns = 0;
        // Score on at most score_sample evenly spaced fragments: a node then costs O(n) (the
        // split itself), not O(sample n); the estimate only steers the choice.
        const std::size_t stride = std::max<std::size_t>(1, polys.size() / score_sample);
        for (std::size_t q = 0; q < polys.size(); q += stride) {
          const Poly<T>& p = polys[q];
          switch (relate<T>(pool, h, polys[idx].face, bsp3_none, p.idx, signs)) {
            case Rel::front:
              ++nf;
              break;
            case Rel::back:
              ++nb;
              break;
            case Rel::straddle:
              ++ns;
              break;
            case Rel::on:
              break;
          }
        }
        const long long cost =
            static_cast<long long>(options.split_cost) * ns + (nf > nb ? nf - nb : nb - nf);
        if (best < 0 || cost < best) {
          best = cost;
          pick = idx;
        }
      }
    }
    const std::uint32_t split_face = polys[pick].face;
    const auto& st = faces_[split_face];
    const PlaneRef<T> h(vertices_[st[0]], vertices_[st[1]], vertices_[st[2]]);

    const auto node = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(
        {split_face, bsp3_outside, bsp3_inside, static_cast<std::uint32_t>(fragments_.size()), 0});
    if (job.parent >= 0) {
      Bsp3Node& par = nodes_[static_cast<std::size_t>(job.parent)];
      (job.front_child ? par.front : par.back) = node;
    } else {
      root_ = node;
    }
    depth_ = std::max(depth_, job.depth);

    std::vector<Poly<T>> front, back;
    for (Poly<T>& p : polys) {
      const auto& t = faces_[p.face];
      if (h.contains_triangle(vertices_[t[0]], vertices_[t[1]], vertices_[t[2]])) {
        fragments_.push_back({p.face, static_cast<std::uint32_t>(points_.size()),
                              static_cast<std::uint32_t>(p.idx.size())});
        for (const std::uint32_t i : p.idx) points_.push_back(vec_cast<T>(pool.recs[i].p));
        continue;
      }
      switch (relate<T>(pool, h, split_face, bsp3_none, p.idx, signs)) {
        case Rel::front:
          front.push_back(std::move(p));
          break;
        case Rel::back:
          back.push_back(std::move(p));
          break;
        case Rel::on:
          break;  // a rounded sliver lying in the plane: no area to keep
        case Rel::straddle:
          split_polygon<T>(pool, h, split_face, p.idx, signs, fpts, bpts);
          if (fpts.size() >= 3) front.push_back({p.face, fpts});
          if (bpts.size() >= 3) back.push_back({p.face, bpts});
          break;
      }
    }
    nodes_[static_cast<std::size_t>(node)].count = static_cast<std::uint32_t>(fragments_.size()) -
                                                   nodes_[static_cast<std::size_t>(node)].first;
    if (!back.empty()) stack.push_back({std::move(back), node, false, job.depth + 1});
    if (!front.empty()) stack.push_back({std::move(front), node, true, job.depth + 1});
  }
  return status_;
}

template <Real T>
Side Bsp3<T>::classify_at(std::int32_t node, const Vec3<T>& p) const noexcept {
  while (node >= 0) {
    const Bsp3Node& nd = nodes_[static_cast<std::size_t>(node)];
    const auto& t = faces_[nd.face];
    const Sign s = orient3d(vertices_[t[0]], vertices_[t[1]], vertices_[t[2]], p);
    if (s == Sign::positive) {
      node = nd.front;
    } else if (s == Sign::negative) {
      node = nd.back;
    } else {
      for (std::uint32_t f = nd.first; f < nd.first + nd.count; ++f) {
        const auto& ft = faces_[fragments_[f].face];
        if (in_coplanar_triangle(vertices_[ft[0]], vertices_[ft[1]], vertices_[ft[2]], p))
          return Side::boundary;
      }
      // Off the surface on this plane: both sides agree unless a face met in a subtree holds p.
      const Side a = classify_at(nd.front, p);
      if (a == Side::boundary) return a;
      const Side b = classify_at(nd.back, p);
      return a == b ? a : Side::boundary;
    }
  }
  return node == bsp3_inside ? Side::inside : Side::outside;
}

template <Real T>
Side Bsp3<T>::classify(const Vec3<T>& p) const noexcept {
  if (!finite3(p)) return Side::outside;
  return classify_at(root_, p);
}

namespace {

template <Real T>
struct Labeled {
  std::vector<std::uint32_t> idx;
  std::vector<LineKey> lines;  // lines[i] supports idx[i] -> idx[i + 1]
  Bsp3Location loc;
};

/// The partition walk of Bsp3::partition (see the header); plane ids from plane_of_face (the
/// face index when empty), corners and edges named through the keyer.
template <Real T>
struct Partitioner {
  std::span<const Vec3<T>> vertices;
  std::span<const std::array<std::uint32_t, 3>> faces;
  std::span<const Bsp3Node> nodes;
  std::span<const std::uint32_t> plane_of_face;  // exact plane ids (sides)
  std::span<const std::uint32_t> key_of_face;    // plane ids for naming (keys)
  Vec3<T> da, db, dc;                            // the polygon's defining triangle (exact)
  Keyer keyer;
  PointPool<T> pool;  // the polygon's corners, then the cut points

  [[nodiscard]] PlaneRef<T> plane(const Bsp3Node& nd) const noexcept {
    const auto& t = faces[nd.face];
    return PlaneRef<T>(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
  }
  [[nodiscard]] std::uint32_t plane_id(const Bsp3Node& nd) const noexcept {
    return plane_of_face.empty() ? nd.face : plane_of_face[nd.face];
  }
  [[nodiscard]] std::uint32_t key_id(const Bsp3Node& nd) const noexcept {
    return key_of_face.empty() ? nd.face : key_of_face[nd.face];
  }

  static Bsp3Location combine(Bsp3Location f, Bsp3Location b, int orientation) noexcept {
    using L = Bsp3Location;
    if (f == L::outside && b == L::inside)
      return orientation > 0 ? L::coincident_same : L::coincident_opposite;
    if (f == L::inside && b == L::outside)
      return orientation > 0 ? L::coincident_opposite : L::coincident_same;
    return f;  // both sides agree (or a sliver reported a coincidence below: keep it)
  }

  void run(std::int32_t node, std::vector<std::uint32_t> poly, std::vector<LineKey> lines,
           std::vector<Labeled<T>>& out) {
    std::vector<Sign> s;
    std::vector<std::uint32_t> fpts, bpts;
    std::vector<LineKey> flines, blines;
    while (node >= 0) {
      const Bsp3Node& nd = nodes[static_cast<std::size_t>(node)];
      const PlaneRef<T> h = plane(nd);
      const std::uint32_t pid = plane_id(nd);
      Rel rel = Rel::on;
      const bool defining_on = h.contains_triangle(da, db, dc);
      bool on = defining_on;
      if (!on) {
        // The key shortcut only across clusters: a polygon (nearly) coplanar with the node
        // keeps the exact and provenance decisions (coincident faces).
        const std::uint32_t kid =
            key_of_face.empty() || key_id(nd) == keyer.polygon_plane ? bsp3_none : key_id(nd);
        rel = relate<T>(pool, h, pid, kid, poly, s);
        on = rel == Rel::on;
      }
      if (on) {
        if (h.proj < 0) return;
        const Sign o = defining_on ? orient2d(drop_axis(da, h.proj), drop_axis(db, h.proj),
                                              drop_axis(dc, h.proj))
                                   : fan_orientation<double>(pool.coords(poly), h.proj);
        const int orientation = to_int(o * h.proj_sign);
        if (orientation == 0) return;  // a flat sliver
        std::vector<Labeled<T>> front_pieces;
        run(nd.front, std::move(poly), std::move(lines), front_pieces);
        for (Labeled<T>& f : front_pieces) {
          std::vector<Labeled<T>> back_pieces;
          run(nd.back, std::move(f.idx), std::move(f.lines), back_pieces);
          for (Labeled<T>& b : back_pieces)
            out.push_back(
                {std::move(b.idx), std::move(b.lines), combine(f.loc, b.loc, orientation)});
        }
        return;
      }
      if (rel == Rel::front) {
        node = nd.front;
      } else if (rel == Rel::back) {
        node = nd.back;
      } else {
        split_polygon<T>(pool, h, pid, poly, s, fpts, bpts, &keyer, key_id(nd), lines, &flines,
                         &blines);
        if (!fpts.empty()) run(nd.front, fpts, flines, out);
        if (bpts.empty()) return;
        poly = bpts;
        lines = blines;
        node = nd.back;
      }
    }
    out.push_back({std::move(poly), std::move(lines),
                   node == bsp3_inside ? Bsp3Location::inside : Bsp3Location::outside});
  }
};

/// The defining triangle of a polygon: indices j, k with polygon[0], polygon[j], polygon[k] not
/// collinear (exact), the first such; false when there is none.
template <Real T>
[[nodiscard]] bool defining_triangle(std::span<const Vec3<T>> polygon, std::size_t& j,
                                     std::size_t& k) noexcept {
  if (polygon.size() < 3) return false;
  const Vec3<T> a = polygon[0];
  j = 1;
  while (j < polygon.size() && polygon[j] == a) ++j;
  if (j == polygon.size()) return false;
  k = j + 1;
  Sign o = Sign::zero;
  for (; k < polygon.size(); ++k)
    if (projection_axis(a, polygon[j], polygon[k], o) >= 0) return true;
  return false;
}

}  // namespace

template <Real T>
Bsp3PolygonPartition<T> Bsp3<T>::partition(std::span<const Vec3<T>> polygon) const {
  Bsp3PolygonPartition<T> r;
  if (status_ == Status::invalid_input || status_ == Status::non_finite_input) {
    r.status = status_;
    return r;
  }
  for (const auto& v : polygon)
    if (!finite3(v)) {
      r.status = Status::non_finite_input;
      return r;
    }
  r.status = Status::degenerate_input;
  std::size_t j = 0, k = 0;
  if (!defining_triangle(polygon, j, k)) return r;
  r.status = Status::ok;
  std::uint32_t serial = 0;
  Partitioner<T> walk{
      vertices_, faces_, nodes_, {}, {}, polygon[0], polygon[j], polygon[k], {bsp3_none, &serial},
      {}};
  std::vector<std::uint32_t> idx;
  std::vector<LineKey> lines;
  for (const auto& p : polygon) {
    idx.push_back(walk.pool.add_exact(p));
    lines.push_back({bsp3_detail::line_unique, serial++, 0, 0});
  }
  std::vector<Labeled<T>> pieces;
  walk.run(root_, std::move(idx), std::move(lines), pieces);
  for (const Labeled<T>& p : pieces) {
    r.pieces.push_back({static_cast<std::uint32_t>(r.points.size()),
                        static_cast<std::uint32_t>(p.idx.size()), p.loc});
    for (const std::uint32_t i : p.idx) r.points.push_back(vec_cast<T>(walk.pool.recs[i].p));
  }
  return r;
}

namespace bsp3_detail {

template <Real T>
std::vector<KeyedPiece> partition_keyed(const Bsp3<T>& tree,
                                        std::span<const std::uint32_t> plane_of_face,
                                        std::span<const std::uint32_t> key_of_face,
                                        std::span<const Vec3<T>> polygon,
                                        std::span<const VertexKey> keys,
                                        std::span<const LineKey> lines, std::uint32_t polygon_plane,
                                        std::uint32_t& serial) {
  std::vector<KeyedPiece> out;
  std::size_t j = 0, k = 0;
  if (!defining_triangle(polygon, j, k)) return out;
  Partitioner<T> walk{tree.vertices(),
                      tree.faces(),
                      tree.nodes(),
                      plane_of_face,
                      key_of_face,
                      polygon[0],
                      polygon[j],
                      polygon[k],
                      {polygon_plane, &serial},
                      {}};
  std::vector<std::uint32_t> idx;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    idx.push_back(walk.pool.add_exact(polygon[i], keys[i]));
  std::vector<Labeled<T>> pieces;
  walk.run(tree.root(), std::move(idx), std::vector<LineKey>(lines.begin(), lines.end()), pieces);
  out.reserve(pieces.size());
  for (Labeled<T>& p : pieces) {
    KeyedPiece q;
    for (const std::uint32_t i : p.idx) {
      q.points.push_back(walk.pool.recs[i].p);
      q.keys.push_back(walk.pool.recs[i].key);
      q.input.push_back(walk.pool.recs[i].a == bsp3_none ? 1 : 0);
    }
    q.lines = std::move(p.lines);
    q.location = p.loc;
    out.push_back(std::move(q));
  }
  return out;
}

#define LOCUS_BSP3_KEYED_INSTANTIATE(T)                                               \
  template std::vector<KeyedPiece> partition_keyed(                                   \
      const Bsp3<T>&, std::span<const std::uint32_t>, std::span<const std::uint32_t>, \
      std::span<const Vec3<T>>, std::span<const VertexKey>, std::span<const LineKey>, \
      std::uint32_t, std::uint32_t&);
LOCUS_BSP3_KEYED_INSTANTIATE(float)
LOCUS_BSP3_KEYED_INSTANTIATE(double)
#undef LOCUS_BSP3_KEYED_INSTANTIATE

}  // namespace bsp3_detail

template class Bsp3<float>;
template class Bsp3<double>;

}  // namespace locus
