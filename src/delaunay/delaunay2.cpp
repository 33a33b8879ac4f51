// SPDX-License-Identifier: BSL-1.0
// 2D Delaunay triangulation (see include/locus/delaunay/delaunay2.hpp for the contract).
//
// Internal representation: a closed triangulated sphere. Real triangles are counter-clockwise;
// every hull edge u -> v (interior on its left) is matched by a ghost triangle (v, u, kGhost)
// whose "interior" is the open half-plane beyond the edge. Ghost triangles always keep the ghost
// vertex at corner 2 so "is ghost" is one load. adj()[e] is the opposite half-edge of e and is
// always defined (the surface has no boundary), which removes every hull special case from the
// split and flip code.

#include <locus/config.hpp>
#include <locus/delaunay/delaunay2.hpp>

#include <locus/core/detail/spatial_sort.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace locus {

namespace {

// Delaunay2 addresses its std::array triangles as flat half-edge slots (delaunay2.hpp).
static_assert(sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(std::uint32_t));

constexpr std::uint32_t kGhost = 0xFFFFFFFFu;
constexpr std::uint32_t kNone = 0xFFFFFFFFu;

[[nodiscard]] inline std::uint32_t nxt(std::uint32_t e) noexcept {
  return e % 3 == 2 ? e - 2 : e + 1;
}
[[nodiscard]] inline std::uint32_t prv(std::uint32_t e) noexcept {
  return e % 3 == 0 ? e + 2 : e - 1;
}

template <Real T>
[[nodiscard]] bool same_point(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.x == b.x && a.y == b.y;
}

// p strictly inside the segment ab, given that a, b, p are collinear and a != b.
template <Real T>
[[nodiscard]] bool strictly_between(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& p) noexcept {
  return to_int(lexicographic_compare(a, p)) * to_int(lexicographic_compare(p, b)) > 0;
}

// The general case of Delaunay2::set_triangle: a ghost vertex at corner 0 or 1 is rotated to
// corner 2.
[[gnu::noinline]] void set_triangle_rotated(std::uint32_t* tri, std::uint32_t* adj, std::uint32_t t,
                                            const std::uint32_t* v, const std::uint32_t* o,
                                            std::uint32_t* out) noexcept {
  const int shift = v[0] == kGhost ? 1 : 2;  // original corner src lands at (src - shift) mod 3
  const std::uint32_t base = 3 * t;
  for (int i = 0; i < 3; ++i) {
    const int src = (i + shift) % 3;
    const std::uint32_t e = base + static_cast<std::uint32_t>(i);
    tri[e] = v[src];
    out[src] = e;
    adj[e] = o[src];
    if (o[src] != kNone) adj[o[src]] = e;
  }
}

}  // namespace

// ---- locate on a result -----------------------------------------------------------------

template <Real T>
LocateResult locate(const Delaunay2Result& dt, std::span<const Vec2<T>> points, const Vec2<T>& p,
                    std::int32_t start, std::size_t max_steps) noexcept {
  LocateResult r;
  r.status = Status::ok;
  const std::size_t nt = dt.triangles.size();
  if (nt == 0 || dt.adjacency.size() != nt) {
    r.status = Status::empty_input;
    return r;
  }
  if (!is_finite(p.x) || !is_finite(p.y)) {
    r.status = Status::non_finite_input;
    return r;
  }
  if (max_steps == 0) max_steps = 4 * nt + 16;
  std::uint32_t t =
      (start >= 0 && static_cast<std::size_t>(start) < nt) ? static_cast<std::uint32_t>(start) : 0u;
  std::uint32_t came = kNoTriangle;  // the triangle the walk came from (p is beyond that edge)
  for (std::size_t step = 0; step < max_steps; ++step) {
    r.steps = step + 1;
    const std::array<std::uint32_t, 3>& v = dt.triangles[t];
    const std::array<std::uint32_t, 3>& nb = dt.adjacency[t];
    unsigned zero_mask = 0;
    bool moved = false;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t o = nb[i];
      if (o != kNoTriangle && o == came) continue;
      const std::uint32_t a = v[i], b = v[i == 2 ? 0 : i + 1];
      if (a >= points.size() || b >= points.size() || (o != kNoTriangle && o >= nt)) {
        r.status = Status::invalid_input;
        return r;
      }
      const Sign s = orient2d(points[a], points[b], p);
      if (s == Sign::negative) {
        if (o == kNoTriangle) {
          r.location = Location::outside;
          r.triangle = static_cast<std::int32_t>(t);
          r.corner = static_cast<int>(i);
          return r;
        }
        came = t;
        t = o;
        moved = true;
        break;
      }
      if (s == Sign::zero) zero_mask |= 1u << i;
    }
    if (moved) continue;
    r.triangle = static_cast<std::int32_t>(t);
    const int zeros = std::popcount(zero_mask);  // not hot: locate() on a result
    if (zeros == 0) {
      r.location = Location::inside;
    } else if (zeros == 1) {
      r.location = Location::on_edge;
      r.corner = std::countr_zero(zero_mask);
    } else {
      // Two edges through p: p is their shared vertex (edges i and i + 1 share vertex i + 1).
      r.location = Location::on_vertex;
      r.corner = zero_mask == 3u ? 1 : (zero_mask == 6u ? 2 : 0);
    }
    return r;
  }
  r.status = Status::limit_exceeded;
  r.triangle = -1;
  return r;
}

// ---- Delaunay2 ---------------------------------------------------------------------------

template <Real T>
void Delaunay2<T>::reset() {
  tri_.clear();
  adj_.clear();
  nt_ = 0;
  order_.clear();
  last_ = 0;
  dimension_ = -1;
  dirty_ = true;
  status_ = Status::ok;
  result_.duplicate_of.clear();
  sorted_.clear();
  orig_.clear();
}

template <Real T>
const Delaunay2Result& Delaunay2<T>::compute(std::span<const Vec2<T>> points) {
  points_.assign(points.begin(), points.end());
  run(points_);
  return result();
}

template <Real T>
LOCUS_ALWAYS_INLINE inline void Delaunay2<T>::set_triangle(
    std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t opp_ab,
    std::uint32_t opp_bc, std::uint32_t opp_ca, std::uint32_t* out) noexcept {
  const std::uint32_t base = 3 * t;
  if (a != kGhost && b != kGhost) [[likely]] {
    tri()[base] = a;
    tri()[base + 1] = b;
    tri()[base + 2] = c;
    out[0] = base;
    out[1] = base + 1;
    out[2] = base + 2;
    adj()[base] = opp_ab;
    adj()[base + 1] = opp_bc;
    adj()[base + 2] = opp_ca;
    if (opp_ab != kNone) adj()[opp_ab] = base;
    if (opp_bc != kNone) adj()[opp_bc] = base + 1;
    if (opp_ca != kNone) adj()[opp_ca] = base + 2;
    return;
  }
  const std::uint32_t v[3] = {a, b, c};
  const std::uint32_t o[3] = {opp_ab, opp_bc, opp_ca};
  set_triangle_rotated(tri(), adj(), t, v, o, out);
}

template <Real T>
bool Delaunay2<T>::in_conflict(std::uint32_t v, std::uint32_t e) const noexcept {
  const std::uint32_t o = adj()[e];
  const std::uint32_t base = o - o % 3;
  const Vec2<T>* pts = sorted_.data();
  const Vec2<T>& p = pts[v];
  if (tri()[base + 2] == kGhost) {
    const Vec2<T>& u = pts[tri()[base]];
    const Vec2<T>& w = pts[tri()[base + 1]];
    const Sign s = orient2d(u, w, p);
    return s == Sign::positive || (s == Sign::zero && strictly_between(u, w, p));
  }
  return incircle(pts[tri()[o]], pts[tri()[nxt(o)]], pts[tri()[prv(o)]], p) == Sign::positive;
}

template <Real T>
std::uint32_t Delaunay2<T>::scan(const Vec2<T>& p, std::uint32_t* duplicate) const noexcept {
  const Vec2<T>* pts = sorted_.data();
  const std::uint32_t nt = nt_;
  for (std::uint32_t t = 0; t < nt; ++t) {
    const std::uint32_t base = 3 * t;
    if (tri()[base + 2] == kGhost) continue;
    unsigned zero_mask = 0;
    bool inside = true;
    for (std::uint32_t i = 0; i < 3 && inside; ++i) {
      const Sign s = orient2d(pts[tri()[base + i]], pts[tri()[nxt(base + i)]], p);
      if (s == Sign::negative) inside = false;
      if (s == Sign::zero) zero_mask |= 1u << i;
    }
    if (!inside) continue;
    if ((zero_mask & (zero_mask - 1)) != 0) {  // two edges through p (no popcount call)
      const std::uint32_t corner = zero_mask == 3u ? 1u : (zero_mask == 6u ? 2u : 0u);
      *duplicate = tri()[base + corner];
    }
    return t;
  }
  for (std::uint32_t t = 0; t < nt; ++t) {
    const std::uint32_t base = 3 * t;
    if (tri()[base + 2] != kGhost) continue;
    if (orient2d(pts[tri()[base]], pts[tri()[base + 1]], p) == Sign::positive) return t;
  }
  return 0;  // unreachable for a valid triangulation
}

template <Real T>
std::uint32_t Delaunay2<T>::walk(const Vec2<T>& p, std::uint32_t t,
                                 std::uint32_t* duplicate) noexcept {
  // A visibility walk in a Delaunay triangulation never revisits a triangle (Edelsbrunner), so
  // it ends within the triangle count; the budget is a guard against a corrupted structure.
  const std::size_t budget = std::size_t(nt_) + 64;
  const Vec2<T>* pts = sorted_.data();
  std::uint32_t came = kNone;
  for (std::size_t step = 0; step < budget; ++step) {
    const std::uint32_t base = 3 * t;
    if (tri()[base + 2] == kGhost) {
      if (orient2d(pts[tri()[base]], pts[tri()[base + 1]], p) == Sign::positive) return t;
      t = adj()[base] / 3;
      came = kNone;  // p may lie on that hull edge: test it again from inside
      continue;
    }
    unsigned zero_mask = 0;
    bool moved = false;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t e = base + i;
      if (e == came) continue;
      const Sign s = orient2d(pts[tri()[e]], pts[tri()[nxt(e)]], p);
      if (s == Sign::negative) {
        came = adj()[e];
        t = came / 3;
        moved = true;
        break;
      }
      if (s == Sign::zero) zero_mask |= 1u << i;
    }
    if (moved) continue;
    if ((zero_mask & (zero_mask - 1)) != 0) {  // two edges through p (no popcount call)
      const std::uint32_t corner = zero_mask == 3u ? 1u : (zero_mask == 6u ? 2u : 0u);
      *duplicate = tri()[base + corner];
    }
    return t;
  }
  return scan(p, duplicate);
}

template <Real T>
bool Delaunay2<T>::insert_vertex(std::uint32_t v) {
  std::uint32_t dup = kNone;
  const std::uint32_t t = walk(sorted_[v], last_, &dup);
  if (dup != kNone) {
    result_.duplicate_of[orig_[v]] = orig_[dup];
    last_ = t;
    return true;
  }
  const std::uint32_t base = 3 * t;
  const std::uint32_t a = tri()[base], b = tri()[base + 1], c = tri()[base + 2];
  const std::uint32_t oab = adj()[base], obc = adj()[base + 1], oca = adj()[base + 2];
  // run() sized the arrays for every point; insert() may need more.
  if (std::size_t(nt_) + 2 > tri_.size()) {
    const std::size_t size = std::max(2 * tri_.size(), std::size_t(nt_) + 2);
    tri_.resize(size);
    adj_.resize(size);
  }
  const std::uint32_t t1 = nt_;
  const std::uint32_t t2 = t1 + 1;
  nt_ += 2;
  std::uint32_t e0[3], e1[3], e2[3];
  set_triangle(t, a, b, v, oab, kNone, kNone, e0);
  set_triangle(t1, b, c, v, obc, kNone, kNone, e1);
  set_triangle(t2, c, a, v, oca, kNone, kNone, e2);
  adj()[e0[1]] = e1[2];
  adj()[e1[2]] = e0[1];
  adj()[e1[1]] = e2[2];
  adj()[e2[2]] = e1[1];
  adj()[e2[1]] = e0[2];
  adj()[e0[2]] = e2[1];
  // The stack of link edges to test, with an inline push (no out-of-line vector growth call).
  std::size_t depth = 0;
  const auto push = [&](std::uint32_t e) {
    if (depth == stack_.size()) stack_.resize(2 * depth + 16);
    stack_[depth++] = e;
  };
  push(e0[0]);
  push(e1[0]);
  push(e2[0]);
  last_ = t;

  // Lawson: flip link edges while v is strictly inside the circle across them. Each flip adds
  // an edge at v, so the number of flips is below the vertex count; the budget only guards.
  std::size_t budget = 3 * std::size_t(nt_) + 64;
  const Vec2<T>* pts = sorted_.data();
  const Vec2<T> pv = pts[v];
  while (depth > 0) {
    if (budget-- == 0) return false;
    const std::uint32_t e = stack_[--depth];
    const std::uint32_t o = adj()[e];
    const std::uint32_t ob = o - o % 3;
    const std::uint32_t x = tri()[e], y = tri()[nxt(e)];
    const std::uint32_t z = tri()[prv(o)];
    // The opposite triangle is (y, x, z); a ghost one (z or x or y at infinity) is rare.
    if (tri()[ob + 2] == kGhost) [[unlikely]] {
      if (!in_conflict(v, e)) continue;
    } else if (incircle(pts[y], pts[x], pts[z], pv) != Sign::positive) {
      continue;
    }
    const std::uint32_t a1 = adj()[nxt(e)], a2 = adj()[prv(e)];
    const std::uint32_t b1 = adj()[nxt(o)], b2 = adj()[prv(o)];
    const std::uint32_t ta = e / 3, tb = o / 3;
    std::uint32_t f[3], g[3];
    set_triangle(ta, v, x, z, a2, b1, kNone, f);
    set_triangle(tb, v, z, y, kNone, b2, a1, g);
    adj()[f[2]] = g[0];
    adj()[g[0]] = f[2];
    push(f[1]);
    push(g[1]);
    last_ = ta;
  }
  return true;
}

template <Real T>
void Delaunay2<T>::lower_dimensional(std::span<const Vec2<T>> in) {
  // All distinct points collinear (or a single one): sort lexicographically; equal neighbours
  // are duplicates of the first of their run (smallest index, as the sort is stable on ties).
  const std::size_t n = in.size();
  std::vector<std::uint32_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0u);
  std::stable_sort(idx.begin(), idx.end(), [&](std::uint32_t i, std::uint32_t j) {
    return lexicographic_compare(in[i], in[j]) == Sign::negative;
  });
  result_.hull.clear();
  std::uint32_t kept = idx[0];
  result_.hull.push_back(kept);
  result_.duplicate_of[kept] = kept;
  for (std::size_t k = 1; k < n; ++k) {
    const std::uint32_t i = idx[k];
    if (same_point(in[i], in[kept])) {
      result_.duplicate_of[i] = kept;
    } else {
      kept = i;
      result_.duplicate_of[i] = i;
      result_.hull.push_back(i);
    }
  }
  dimension_ = result_.hull.size() == 1 ? 0 : 1;
}

template <Real T>
void Delaunay2<T>::run(std::span<const Vec2<T>> in) {
  reset();
  const std::size_t n = in.size();
  result_.duplicate_of.resize(n);
  std::iota(result_.duplicate_of.begin(), result_.duplicate_of.end(), 0u);
  if (n == 0) {
    status_ = Status::empty_input;
    return;
  }
  if (n >= std::size_t(0x7FFFFFFF) / 3) {  // 6 (n + 1) half-edge indices must fit in uint32
    status_ = Status::invalid_input;
    return;
  }
  bool finite = true;
  for (const auto& q : in) finite = finite && is_finite(q.x) && is_finite(q.y);
  if (!finite) {
    status_ = Status::non_finite_input;
    return;
  }

  // BRIO rounds in Hilbert order (core/detail/spatial_sort.hpp).
  detail::brio_order(in, orig_, keys_, keys_tmp_);
  // The triangulation works on a copy of the points in Hilbert order (vertex k is input point
  // orig_[k]), so the coordinates a walk or an incircle test reads are close in memory.
  sorted_.resize(n);
  // The reads of `in` are in random order: prefetching a few iterations ahead overlaps them.
  constexpr std::size_t ahead = 16;
  for (std::size_t k = 0; k < n; ++k) {
#if defined(__GNUC__) || defined(__clang__)
    if (k + ahead < n) __builtin_prefetch(&in[orig_[k + ahead]]);
#endif
    sorted_[k] = in[orig_[k]];
  }

  // A first non-degenerate triangle: the first point, the first different one, the first one
  // off their line.
  const Vec2<T>* pts = sorted_.data();
  const std::uint32_t p0 = 0;
  std::size_t k1 = 1;
  while (k1 < n && same_point(pts[k1], pts[p0])) ++k1;
  if (k1 == n) {
    lower_dimensional(in);
    return;
  }
  const std::uint32_t p1 = static_cast<std::uint32_t>(k1);
  std::size_t k2 = k1 + 1;
  while (k2 < n && orient2d(pts[p0], pts[p1], pts[k2]) == Sign::zero) ++k2;
  if (k2 == n) {
    lower_dimensional(in);
    return;
  }
  dimension_ = 2;
  const std::uint32_t p2 = static_cast<std::uint32_t>(k2);
  std::uint32_t a = p0, b = p1, c = p2;
  if (orient2d(pts[a], pts[b], pts[c]) == Sign::negative) std::swap(b, c);

  // A closed triangulation of n + 1 vertices (the ghost one included) has 2 (n + 1) - 4
  // triangles: allocate them all now, not six entries per insertion.
  tri_.resize(2 * (n + 1));
  adj_.resize(2 * (n + 1));
  nt_ = 4;
  // t0 = (a, b, c); ghosts t1 = (b, a, G), t2 = (c, b, G), t3 = (a, c, G).
  const std::uint32_t init_tri[12] = {a, b, c, b, a, kGhost, c, b, kGhost, a, c, kGhost};
  // Opposite half-edges: a->b (0) / b->a (3); b->c (1) / c->b (6); c->a (2) / a->c (9);
  // a->G (4) / G->a (11); b->G (7) / G->b (5); c->G (10) / G->c (8).
  const std::uint32_t init_adj[12] = {3, 6, 9, 0, 11, 7, 1, 5, 10, 2, 8, 4};
  std::copy(init_tri, init_tri + 12, tri());
  std::copy(init_adj, init_adj + 12, adj());
  last_ = 0;

  for (std::size_t k = 1; k < k1; ++k) result_.duplicate_of[orig_[k]] = orig_[p0];
  bool ok = true;
  for (std::size_t k = k1 + 1; k < n && ok; ++k) {
    if (k == k2) continue;
    ok = insert_vertex(static_cast<std::uint32_t>(k));
  }
  if (!ok) status_ = Status::limit_exceeded;
}

// The result: the real triangles packed into slots [0, count) with input point indices, their
// neighbours as triangle indices (kNoTriangle on the hull), the hull. Ghost triangles are few (one
// per hull edge) and form one cycle around the hull, so instead of renumbering every triangle, the
// hull walk lists them, their real neighbours' half-edges are cut (kNone, equal to kNoTriangle),
// and each ghost slot below count receives the real triangle of a slot at or above count (its
// neighbours' back links follow): O(h) moves, then one pass maps vertices to input indices and
// half-edges to triangles. In place (from take_result(), the internal arrays are not needed any
// more) the arrays, already in the result's type, are packed themselves and handed over: no
// second pair of 12-byte-per-triangle arrays is allocated or touched (fresh pages cost as much
// as the pass); otherwise copies are packed. Both give the same numbering.
template <Real T>
void Delaunay2<T>::compact(bool in_place) {
  Delaunay2Result& r = result_;
  r.status = status_;
  r.dimension = dimension_;
  r.triangles.clear();
  r.adjacency.clear();
  r.duplicate_count = 0;
  for (std::size_t i = 0; i < r.duplicate_of.size(); ++i)
    r.duplicate_count += r.duplicate_of[i] != i ? 1u : 0u;
  if (dimension_ < 2) {
    if (dimension_ < 0) r.hull.clear();
    return;
  }
  r.hull.clear();
  const std::uint32_t nt = nt_;
  const std::uint32_t* opp = adj();
  std::uint32_t some_ghost = 0;
  while (some_ghost + 1 < nt && tri()[3 * some_ghost + 2] != kGhost) ++some_ghost;
  // Hull: ghost (u, v, G) lies beyond hull edge v -> u; the ghost across its half-edge G -> u
  // is (w, u, G), so visiting u, w, ... follows the hull counter-clockwise.
  std::vector<std::uint32_t>& ghosts = order_;
  ghosts.clear();
  {
    std::uint32_t g = some_ghost;
    for (std::uint32_t guard = 0; guard < nt; ++guard) {
      r.hull.push_back(orig_[tri()[3 * g]]);
      ghosts.push_back(g);
      g = opp[3 * g + 2] / 3;
      if (g == some_ghost) break;
    }
    const auto smallest = std::min_element(r.hull.begin(), r.hull.end());
    std::rotate(r.hull.begin(), smallest, r.hull.end());
  }
  const auto count = static_cast<std::uint32_t>(nt - ghosts.size());
  // Triangle of the last point (a real one), followed through the moves: the walk start of
  // locate().
  std::uint32_t last_real = tri()[3 * last_ + 2] == kGhost ? opp[3 * last_] / 3 : last_;
  std::uint32_t* tri_out = tri();
  std::uint32_t* adj_out = adj();
  if (!in_place) {
    r.triangles.assign(tri_.begin(), tri_.begin() + std::ptrdiff_t(nt));
    r.adjacency.assign(adj_.begin(), adj_.begin() + std::ptrdiff_t(nt));
    tri_out = flat(r.triangles);
    adj_out = flat(r.adjacency);
  }
  for (const std::uint32_t g : ghosts) adj_out[adj_out[3 * g]] = kNone;
  std::sort(ghosts.begin(), ghosts.end());
  std::size_t above = static_cast<std::size_t>(
      std::lower_bound(ghosts.begin(), ghosts.end(), count) - ghosts.begin());
  std::uint32_t from = count;
  for (std::size_t k = 0; k < ghosts.size() && ghosts[k] < count; ++k) {
    const std::uint32_t hole = ghosts[k];
    while (above < ghosts.size() && ghosts[above] == from) ++above, ++from;
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t o = adj_out[3 * from + i];
      tri_out[3 * hole + i] = tri_out[3 * from + i];
      adj_out[3 * hole + i] = o;
      if (o != kNone) adj_out[o] = 3 * hole + i;
    }
    if (from == last_real) last_real = hole;
    ++from;
  }
  last_out_ = last_real;
  static_assert(kNone == kNoTriangle);
  const std::uint32_t* orig = orig_.data();
  for (std::size_t e = 0; e < 3 * std::size_t(count); ++e) {
    tri_out[e] = orig[tri_out[e]];
    adj_out[e] = adj_out[e] == kNone ? kNoTriangle : adj_out[e] / 3;
  }
  if (in_place) {
    tri_.resize(count);
    adj_.resize(count);
    r.triangles.swap(tri_);
    r.adjacency.swap(adj_);
    tri_.clear();
    adj_.clear();
    nt_ = 0;
    dimension_ = -1;
  } else {
    r.triangles.resize(count);
    r.adjacency.resize(count);
  }
  ghosts.clear();
}

template <Real T>
const Delaunay2Result& Delaunay2<T>::result() {
  if (dirty_) {
    compact(false);
    dirty_ = false;
  }
  return result_;
}

template <Real T>
Delaunay2Result Delaunay2<T>::take_result() {
  if (dirty_) compact(true);
  Delaunay2Result r = std::move(result_);
  result_ = Delaunay2Result{};
  points_.clear();
  run(points_);
  dirty_ = true;
  return r;
}

template <Real T>
Status Delaunay2<T>::insert(const Vec2<T>& p) {
  if (!is_finite(p.x) || !is_finite(p.y)) return Status::non_finite_input;
  if (status_ == Status::non_finite_input) return status_;
  points_.push_back(p);
  dirty_ = true;
  if (dimension_ < 2) {
    run(points_);
    return status_;
  }
  const std::uint32_t v = static_cast<std::uint32_t>(sorted_.size());
  result_.duplicate_of.push_back(static_cast<std::uint32_t>(points_.size() - 1));
  sorted_.push_back(p);
  orig_.push_back(static_cast<std::uint32_t>(points_.size() - 1));
  if (!insert_vertex(v)) status_ = Status::limit_exceeded;
  return status_;
}

template <Real T>
LocateResult Delaunay2<T>::locate(const Vec2<T>& p, std::size_t max_steps) {
  const Delaunay2Result& r = result();
  return ::locus::locate<T>(r, std::span<const Vec2<T>>(points_), p,
                            static_cast<std::int32_t>(last_out_), max_steps);
}

// The one-call forms triangulate the caller's points where they are (no copy into points_,
// which only insert() and locate() need) and pack the result in place (take_result's compact).
template <Real T>
Delaunay2Result delaunay(std::span<const Vec2<T>> points) {
  Delaunay2<T> d;
  d.run(points);
  return d.take_result();
}

template class Delaunay2<float>;
template class Delaunay2<double>;
template Delaunay2Result delaunay<float>(std::span<const Vec2<float>>);
template Delaunay2Result delaunay<double>(std::span<const Vec2<double>>);
template LocateResult locate<float>(const Delaunay2Result&, std::span<const Vec2<float>>,
                                    const Vec2<float>&, std::int32_t, std::size_t) noexcept;
template LocateResult locate<double>(const Delaunay2Result&, std::span<const Vec2<double>>,
                                     const Vec2<double>&, std::int32_t, std::size_t) noexcept;

}  // namespace locus
