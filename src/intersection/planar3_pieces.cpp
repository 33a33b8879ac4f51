// SPDX-License-Identifier: BSL-1.0
// The pieces of a 2D component (the frame image of a linear component lying in a planar
// polygon's plane) inside the closed polygon; row int3.linear-polygon, book section 11.3.
// Every position along the component where the boundary meets it is named exactly (an edge
// crossed transversally, or an input point on the component's line: a vertex, an end of the
// component) and ordered by compare_crossing_params (detail/linear_polyline2.hpp). Between two
// consecutive positions the open span does not meet the boundary, or lies on a collinear edge;
// it is inside iff the edges crossed before it (the half-open rule: a vertex on the line counts
// as on its negative side) are odd in number. docs/notes/intersection.md.

#include <locus/intersection/detail/planar3.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace locus::detail::planar3 {
namespace {

namespace lp = linear_polyline2;

enum class What : std::uint8_t { start, end, vertex, crossing };

/// A position along the component's line: where the boundary meets it, or a domain end.
struct Event {
  lp::Key key;
  V2 p, q;  // the vertex or domain end (p); a transversal crossing: its edge p q
  What what;
  bool boundary;  // a point of the boundary
  int flip;       // edges changing the even-odd count here (half-open rule)
  int cover;      // +1: a collinear edge starts here along the line, -1: one ends
};

struct Group {
  std::size_t rep;  // the event giving the position's parameter and point
  bool boundary = false;
  int flip = 0, cover = 0;
};

/// The rank of an event for choosing a group's representative: exact ends first.
int precision_rank(What w) noexcept {
  switch (w) {
    case What::start:
    case What::end:
      return 0;
    case What::vertex:
      return 1;
    case What::crossing:
      return 2;
  }
  return 3;
}

/// The parameter (rounded, within the domain) and the frame point of an event in the domain.
void locate(const linear2::Lin& l, const Event& e, double& t, V2& st) noexcept {
  switch (e.what) {
    case What::start:
      t = 0.0, st = l.o;
      return;
    case What::end:
      t = 1.0, st = l.b;
      return;
    case What::vertex:
      t = linear2::project(l, e.p), st = e.p;
      return;
    case What::crossing: {
      const linear2::Result x =
          linear2::intersect<true>(l, linear2::Lin{e.p, e.q, e.p, true, true});
      if (x.kind == Kind::point) {
        t = x.param_a[0], st = x.point[0];
        return;
      }
      // Not reached for finite data in the exact range (the same exact decision); a fallback.
      t = linear2::clamp_param(l, linear2::crossing_param(l, {e.p, e.q, e.p, true, true}).t);
      st = l.o + t * linear2::dir(l);
      return;
    }
  }
}

}  // namespace

std::vector<Piece2> polygon_pieces2(const linear2::Lin& l_in, std::span<const V2> v_in) {
  std::vector<Piece2> out;
  const std::size_t n = v_in.size();
  if (n == 0) return out;
  // Far from 1 the problem is scaled by a power of two (exact; parameters are unchanged), so
  // that positions are compared in compare_crossing_params' exact range.
  const int e = -range_exponent(l_in, v_in);
  std::vector<V2> v_scaled;
  if (e != 0) {
    v_scaled.reserve(n);
    for (const V2& p : v_in) v_scaled.push_back(scaled(p, e));
  }
  const std::span<const V2> v = e != 0 ? std::span<const V2>(v_scaled) : v_in;
  const linear2::Lin l{scaled(l_in.a, e), scaled(l_in.b, e), scaled(l_in.o, e), l_in.lo, l_in.hi};
  const auto unscaled = [&]() {
    if (e != 0)
      for (Piece2& p : out)
        for (V2& st : p.st) st = scaled(st, -e);
    return out;
  };
  if (l.a == l.b) {  // the component is its point o (parameter 0)
    if (in_polygon(v, l.o)) out.push_back({1, {0.0, 0.0}, {l_in.o, l_in.o}});
    return out;
  }
  std::vector<Event> ev;
  ev.reserve(2 * n + 2);
  for (std::size_t i = 0; i < n; ++i) {
    const V2 p = v[i], q = v[(i + 1) % n];
    const Sign sp = linear2::side(l, p), sq = linear2::side(l, q);
    if (sp == Sign::zero && sq == Sign::zero) {
      // On the line (or a zero-length edge on it): a closed interval of the boundary.
      const lp::Key kp = lp::through(l, p), kq = lp::through(l, q);
      const int c = lp::compare(l, kp, kq);
      ev.push_back({kp, p, p, What::vertex, true, 0, c});
      if (c != 0) ev.push_back({kq, q, q, What::vertex, true, 0, -c});
      continue;
    }
    // Half-open rule: a vertex on the line counts as negative; the count changes where the
    // edge's ends fall on different sides under that rule.
    const int flip = (sp == Sign::positive) != (sq == Sign::positive) ? 1 : 0;
    if (sp == Sign::zero)
      ev.push_back({lp::through(l, p), p, p, What::vertex, true, flip, 0});
    else if (sq == Sign::zero)
      ev.push_back({lp::through(l, q), q, q, What::vertex, true, flip, 0});
    else if (sp != sq)
      ev.push_back({lp::Key{p, q}, p, q, What::crossing, true, 1, 0});
  }
  if (ev.empty()) return out;  // the line misses the boundary: the polygon is bounded
  if (l.lo) ev.push_back({lp::through(l, l.o), l.o, l.o, What::start, false, 0, 0});
  if (l.hi) ev.push_back({lp::through(l, l.b), l.b, l.b, What::end, false, 0, 0});
  std::sort(ev.begin(), ev.end(),
            [&l](const Event& a, const Event& b) { return lp::compare(l, a.key, b.key) > 0; });

  // Equal positions (exactly) form one group.
  std::vector<Group> groups;
  std::size_t first = 0, start = 0, end = 0;
  bool has_start = false, has_end = false;
  for (std::size_t i = 0; i < ev.size(); ++i) {
    if (groups.empty() || lp::compare(l, ev[first].key, ev[i].key) != 0) {
      groups.push_back({i});
      first = i;
    }
    Group& g = groups.back();
    const Event& x = ev[i];
    g.boundary = g.boundary || x.boundary;
    g.flip += x.flip;
    g.cover += x.cover;
    if (precision_rank(x.what) < precision_rank(ev[g.rep].what)) g.rep = i;
    if (x.what == What::start) start = groups.size() - 1, has_start = true;
    if (x.what == What::end) end = groups.size() - 1, has_end = true;
  }
  const std::size_t gs = has_start ? start : 0, ge = has_end ? end : groups.size() - 1;
  // inside[g]: the open span after group g lies in the closed polygon (odd count of edges
  // crossed before it, or on a collinear edge).
  std::vector<char> inside(groups.size());
  int parity = 0, cover = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    parity ^= groups[g].flip & 1;
    cover += groups[g].cover;
    inside[g] = parity != 0 || cover > 0;
  }
  double last = -std::numeric_limits<double>::infinity();
  const auto end_of = [&](std::size_t g, double& t, V2& st) {
    locate(l, ev[groups[g].rep], t, st);
    // The positions are in exact order; rounded parameters may be out of order by an ulp.
    t = std::max(t, last);
    last = t;
  };
  std::size_t from = gs;
  for (std::size_t g = gs; g <= ge; ++g) {
    const bool left_in = g > gs && inside[g - 1] != 0, right_in = g < ge && inside[g] != 0;
    if (!groups[g].boundary && !left_in && !right_in) continue;
    if (!left_in) from = g;
    if (right_in) continue;
    Piece2 piece;
    piece.count = from == g ? 1 : 2;
    end_of(from, piece.t[0], piece.st[0]);
    if (piece.count == 2)
      end_of(g, piece.t[1], piece.st[1]);
    else
      piece.t[1] = piece.t[0], piece.st[1] = piece.st[0];
    out.push_back(piece);
  }
  return unscaled();
}

}  // namespace locus::detail::planar3
