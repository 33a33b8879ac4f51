// SPDX-License-Identifier: BSL-1.0
// The BSP tree of a polyhedron (see include/locus/bsp/bsp3.hpp and docs/notes/bsp3.md).

#include <locus/bsp/bsp3.hpp>

#include <locus/core/plane_side.hpp>
#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace locus {

namespace {

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
/// corners a (positive side) and b (negative side) with the plane of face `face`.
template <Real T>
struct PointRec {
  Vec3<double> p;  // exact for input points; cut points are kept in double even when T = float
  std::uint32_t a = bsp3_none, b = bsp3_none, face = bsp3_none;
};

/// Corners with their provenance. The side of a cut point against a later plane follows from
/// its two parents when they do not straddle that plane (the true crossing lies on the segment
/// between them, a convex combination); only when they do is the rounded point tested. So a
/// plane through a vertex never sees the cut points near that vertex on its wrong side.
template <Real T>
struct PointPool {
  std::vector<PointRec<T>> recs;
  static constexpr int max_depth = 8;  // bounds the recursion (2^8 predicates at worst)

  std::uint32_t add_exact(const Vec3<T>& p) {
    recs.push_back({vec_cast<double>(p), bsp3_none, bsp3_none, bsp3_none});
    return static_cast<std::uint32_t>(recs.size() - 1);
  }
  std::uint32_t add_cut(const PlaneRef<T>& h, std::uint32_t face, std::uint32_t pos,
                        std::uint32_t neg) {
    const Vec3<double> x = h.cut(recs[pos].p, recs[neg].p);
    recs.push_back({x, pos, neg, face});
    return static_cast<std::uint32_t>(recs.size() - 1);
  }
  [[nodiscard]] Sign side(const PlaneRef<T>& h, std::uint32_t face, std::uint32_t i,
                          int depth = max_depth) const noexcept {
    const PointRec<T>& r = recs[i];
    if (r.a == bsp3_none) return h.side_d(r.p);
    if (r.face == face) return Sign::zero;
    if (depth == 0) return h.side_d(r.p);
    const Sign s0 = side(h, face, r.a, depth - 1), s1 = side(h, face, r.b, depth - 1);
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

/// Splits a convex polygon (corner indices) with vertex signs s (some positive, some
/// negative). Pieces are kept even when rounding flattened them: a sliver along an edge must
/// reach the same cells as its neighbour's sliver, or the cell labels disagree.
template <Real T>
void split_polygon(PointPool<T>& pool, const PlaneRef<T>& h, std::uint32_t face,
                   std::span<const std::uint32_t> poly, std::span<const Sign> s,
                   std::vector<std::uint32_t>& front, std::vector<std::uint32_t>& back) {
  front.clear();
  back.clear();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (s[i] != Sign::negative) front.push_back(poly[i]);
    if (s[i] != Sign::positive) back.push_back(poly[i]);
    if (to_int(s[i]) * to_int(s[j]) < 0) {
      // Cut from the positive end so that an edge shared by two fragments is cut at
      // bit-identical points.
      const std::uint32_t x = s[i] == Sign::positive ? pool.add_cut(h, face, poly[i], poly[j])
                                                     : pool.add_cut(h, face, poly[j], poly[i]);
      front.push_back(x);
      back.push_back(x);
    }
  }
}

enum class Rel { front, back, on, straddle };

template <Real T>
[[nodiscard]] Rel relate(const PointPool<T>& pool, const PlaneRef<T>& h, std::uint32_t face,
                         std::span<const std::uint32_t> poly, std::vector<Sign>& s) {
  s.resize(poly.size());
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    s[i] = pool.side(h, face, poly[i]);
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
        for (const Poly<T>& p : polys) {
          switch (relate<T>(pool, h, polys[idx].face, p.idx, signs)) {
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
      switch (relate<T>(pool, h, split_face, p.idx, signs)) {
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
  Bsp3Location loc;
};

/// The partition walk of Bsp3::partition (see the header).
template <Real T>
struct Partitioner {
  std::span<const Vec3<T>> vertices;
  std::span<const std::array<std::uint32_t, 3>> faces;
  std::span<const Bsp3Node> nodes;
  Vec3<T> da, db, dc;  // the polygon's defining triangle (exact)
  PointPool<T> pool;   // the polygon's corners, then the cut points

  [[nodiscard]] PlaneRef<T> plane(const Bsp3Node& nd) const noexcept {
    const auto& t = faces[nd.face];
    return PlaneRef<T>(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
  }

  static Bsp3Location combine(Bsp3Location f, Bsp3Location b, int orientation) noexcept {
    using L = Bsp3Location;
    if (f == L::outside && b == L::inside)
      return orientation > 0 ? L::coincident_same : L::coincident_opposite;
    if (f == L::inside && b == L::outside)
      return orientation > 0 ? L::coincident_opposite : L::coincident_same;
    return f;  // both sides agree (or a sliver reported a coincidence below: keep it)
  }

  void run(std::int32_t node, std::vector<std::uint32_t> poly, std::vector<Labeled<T>>& out) {
    std::vector<Sign> s;
    std::vector<std::uint32_t> fpts, bpts;
    while (node >= 0) {
      const Bsp3Node& nd = nodes[static_cast<std::size_t>(node)];
      const PlaneRef<T> h = plane(nd);
      Rel rel = Rel::on;
      const bool defining_on = h.contains_triangle(da, db, dc);
      bool on = defining_on;
      if (!on) {
        rel = relate<T>(pool, h, nd.face, poly, s);
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
        run(nd.front, std::move(poly), front_pieces);
        for (Labeled<T>& f : front_pieces) {
          std::vector<Labeled<T>> back_pieces;
          run(nd.back, std::move(f.idx), back_pieces);
          for (Labeled<T>& b : back_pieces)
            out.push_back({std::move(b.idx), combine(f.loc, b.loc, orientation)});
        }
        return;
      }
      if (rel == Rel::front) {
        node = nd.front;
      } else if (rel == Rel::back) {
        node = nd.back;
      } else {
        split_polygon<T>(pool, h, nd.face, poly, s, fpts, bpts);
        if (!fpts.empty()) run(nd.front, fpts, out);
        if (bpts.empty()) return;
        poly = bpts;
        node = nd.back;
      }
    }
    out.push_back(
        {std::move(poly), node == bsp3_inside ? Bsp3Location::inside : Bsp3Location::outside});
  }
};

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
  if (polygon.size() < 3) return r;
  // The defining triangle: the first three non-collinear points (exact).
  const Vec3<T> a = polygon[0];
  std::size_t j = 1;
  while (j < polygon.size() && polygon[j] == a) ++j;
  if (j == polygon.size()) return r;
  std::size_t k = j + 1;
  Sign o = Sign::zero;
  for (; k < polygon.size(); ++k)
    if (projection_axis(a, polygon[j], polygon[k], o) >= 0) break;
  if (k == polygon.size()) return r;
  r.status = Status::ok;
  Partitioner<T> walk{vertices_, faces_, nodes_, a, polygon[j], polygon[k], {}};
  std::vector<std::uint32_t> idx;
  for (const auto& p : polygon) idx.push_back(walk.pool.add_exact(p));
  std::vector<Labeled<T>> pieces;
  walk.run(root_, std::move(idx), pieces);
  for (const Labeled<T>& p : pieces) {
    r.pieces.push_back({static_cast<std::uint32_t>(r.points.size()),
                        static_cast<std::uint32_t>(p.idx.size()), p.loc});
    for (const std::uint32_t i : p.idx) r.points.push_back(vec_cast<T>(walk.pool.recs[i].p));
  }
  return r;
}

template class Bsp3<float>;
template class Bsp3<double>;

}  // namespace locus
