// SPDX-License-Identifier: BSL-1.0
// Incremental horizontal trapezoidal map with a point-location DAG (trapezoid_map.hpp).
// The DAG's leaves are trapezoids; a point node routes by the symbolic height order, a segment
// node by the side of the segment. A leaf node is rewritten in place when its trapezoid is
// split, so every parent sees the split; a merged-away trapezoid's leaf becomes a redirect to
// the survivor's leaf. Walking along a new segment relocates the point of the segment just
// above the previous trapezoid's top through the DAG: at a segment node the question "is the
// new segment left of that one" has one exact answer over their common height range because
// the segments do not cross, so no neighbour links are kept.

#include <locus/core/predicates.hpp>
#include <locus/triangulate/trapezoid_map.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace locus {

namespace {

constexpr std::uint32_t none = trapezoid_unbounded;
enum : std::uint8_t { leaf_node = 0, point_node = 1, segment_node = 2, redirect_node = 3 };

// Strictly below in the symbolic order: smaller y, ties broken by LARGER x.
template <Real T>
bool below_xy(const Vec2<T>& a, const Vec2<T>& b) noexcept {
  return a.y < b.y || (a.y == b.y && a.x > b.x);
}

template <Real T>
bool finite(const Vec2<T>& p) noexcept {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

// splitmix64: a portable generator for the insertion shuffle (same order on every platform).
std::uint64_t next_random(std::uint64_t& s) noexcept {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

template <Real T>
bool TrapezoidMap2<T>::below(std::uint32_t a, std::uint32_t b) const noexcept {
  return below_xy(points_[a], points_[b]);
}

template <Real T>
std::uint32_t TrapezoidMap2<T>::add_trapezoid(const MapTrapezoid& t, std::uint32_t leaf) {
  const auto id = static_cast<std::uint32_t>(traps_.size());
  traps_.push_back(t);
  leaf_of_.push_back(leaf);
  nodes_[leaf] = Node{leaf_node, id, {none, none}};
  return id;
}

template <Real T>
void TrapezoidMap2<T>::remove_trapezoid(std::uint32_t id) {
  const auto last = static_cast<std::uint32_t>(traps_.size() - 1);
  if (id != last) {
    traps_[id] = traps_[last];
    leaf_of_[id] = leaf_of_[last];
    nodes_[leaf_of_[id]].key = id;
  }
  traps_.pop_back();
  leaf_of_.pop_back();
}

template <Real T>
Status TrapezoidMap2<T>::begin(std::span<const Vec2<T>> points,
                               std::span<const std::array<std::uint32_t, 2>> segments,
                               TrapezoidMapOptions options) {
  points_ = points;
  options_ = options;
  canon_.resize(points.size());
  std::iota(canon_.begin(), canon_.end(), 0u);
  segs_.clear();
  has_point_.assign(points.size(), 0);
  inserted_.assign(segments.size(), 0);
  traps_.clear();
  leaf_of_.clear();
  nodes_.clear();
  for (const auto& s : segments)
    if (s[0] >= points.size() || s[1] >= points.size()) return status_ = Status::invalid_input;
  std::vector<std::uint32_t> used;
  used.reserve(2 * segments.size());
  for (const auto& s : segments)
    for (const std::uint32_t i : s) {
      if (!finite(points[i])) return status_ = Status::non_finite_input;
      used.push_back(i);
    }
  // Equal coordinates are one point: the smallest index.
  std::sort(used.begin(), used.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Sign c = lexicographic_compare(points[a], points[b]);
    return c == Sign::negative || (c == Sign::zero && a < b);
  });
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (std::size_t k = 1; k < used.size(); ++k)
    if (points[used[k]] == points[used[k - 1]]) canon_[used[k]] = canon_[used[k - 1]];
  segs_.reserve(segments.size());
  for (const auto& s : segments) {
    std::uint32_t a = canon_[s[0]], b = canon_[s[1]];
    if (below(b, a)) std::swap(a, b);
    segs_.push_back({a, b});
  }
  nodes_.push_back(Node{leaf_node, 0, {none, none}});
  add_trapezoid(MapTrapezoid{}, 0);
  return status_ = segments.empty() ? Status::empty_input : Status::ok;
}

template <Real T>
std::uint32_t TrapezoidMap2<T>::locate(const Vec2<T>& q) const noexcept {
  if (nodes_.empty()) return none;
  std::uint32_t n = 0;
  for (;;) {
    const Node& node = nodes_[n];
    switch (node.kind) {
      case leaf_node:
        return node.key;
      case point_node:
        n = node.child[below_xy(q, points_[node.key]) ? 0 : 1];
        break;
      case segment_node: {
        const auto& s = segs_[node.key];
        n = node.child[orient2d(points_[s[0]], points_[s[1]], q) == Sign::positive ? 0 : 1];
        break;
      }
      default:
        n = node.child[0];
    }
  }
}

// -1: segment s is left of `other` over their common height range; +1: right; 0: they touch
// (a shared lower endpoint with collinear directions, or an endpoint on the other's line).
template <Real T>
int TrapezoidMap2<T>::segment_side(std::uint32_t s, std::uint32_t other) const noexcept {
  const auto& a = segs_[s];
  const auto& c = segs_[other];
  const Vec2<T>& c0 = points_[c[0]];
  const Vec2<T>& c1 = points_[c[1]];
  Sign o;
  if (a[0] == c[0]) {
    o = orient2d(c0, c1, points_[a[1]]);
  } else if (below(c[0], a[0])) {
    o = orient2d(c0, c1, points_[a[0]]);
  } else {
    o = orient2d(points_[a[0]], points_[a[1]], c0);
    return o == Sign::positive ? 1 : o == Sign::negative ? -1 : 0;
  }
  return o == Sign::positive ? -1 : o == Sign::negative ? 1 : 0;
}

// Whether segments s and other meet anywhere but at one shared endpoint.
template <Real T>
bool TrapezoidMap2<T>::segments_touch(std::uint32_t s, std::uint32_t other) const noexcept {
  const auto& a = segs_[s];
  const auto& c = segs_[other];
  const auto on_segment = [&](std::uint32_t p, const std::array<std::uint32_t, 2>& e) {
    return orient2d(points_[e[0]], points_[e[1]], points_[p]) == Sign::zero && !below(p, e[0]) &&
           !below(e[1], p);
  };
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (a[std::size_t(i)] == c[std::size_t(j)]) {
        // One shared endpoint: they meet elsewhere only when collinear and on the same side.
        const std::uint32_t x = a[std::size_t(i)], p = a[std::size_t(1 - i)],
                            q = c[std::size_t(1 - j)];
        return p == q || (orient2d(points_[x], points_[p], points_[q]) == Sign::zero &&
                          below(p, x) == below(q, x));
      }
  const Sign o1 = orient2d(points_[a[0]], points_[a[1]], points_[c[0]]);
  const Sign o2 = orient2d(points_[a[0]], points_[a[1]], points_[c[1]]);
  const Sign o3 = orient2d(points_[c[0]], points_[c[1]], points_[a[0]]);
  const Sign o4 = orient2d(points_[c[0]], points_[c[1]], points_[a[1]]);
  if (o1 != Sign::zero && o2 != Sign::zero && o3 != Sign::zero && o4 != Sign::zero)
    return o1 != o2 && o3 != o4;
  return on_segment(c[0], a) || on_segment(c[1], a) || on_segment(a[0], c) || on_segment(a[1], c);
}

// The leaf node of the trapezoid holding the points of segment s just above the height of
// point `from` (s's lower endpoint or a point level with s's interior); none if s touches a
// segment on the way.
template <Real T>
std::uint32_t TrapezoidMap2<T>::locate_along(std::uint32_t s, std::uint32_t from) const noexcept {
  std::uint32_t n = 0;
  for (;;) {
    const Node& node = nodes_[n];
    switch (node.kind) {
      case leaf_node:
        return n;
      case point_node:
        n = node.child[node.key != from && below(from, node.key) ? 0 : 1];
        break;
      case segment_node: {
        const int side = segment_side(s, node.key);
        if (side == 0) return none;
        n = node.child[side < 0 ? 0 : 1];
        break;
      }
      default:
        n = node.child[0];
    }
  }
}

template <Real T>
Status TrapezoidMap2<T>::split_at(std::uint32_t point) {
  if (nodes_.empty()) return status_;
  if (point >= points_.size()) return Status::invalid_input;
  if (!finite(points_[point])) return Status::non_finite_input;
  const std::uint32_t p = canon_[point];
  if (has_point_[p]) return Status::ok;
  has_point_[p] = 1;
  std::uint32_t n = 0;
  while (nodes_[n].kind != leaf_node) {
    const Node& node = nodes_[n];
    if (node.kind == point_node)
      n = node.child[below(p, node.key) ? 0 : 1];
    else if (node.kind == segment_node)
      n = node.child[orient2d(points_[segs_[node.key][0]], points_[segs_[node.key][1]],
                              points_[p]) == Sign::positive
                         ? 0
                         : 1];
    else
      n = node.child[0];
  }
  const MapTrapezoid t = traps_[nodes_[n].key];
  remove_trapezoid(nodes_[n].key);
  const auto lower_leaf = static_cast<std::uint32_t>(nodes_.size());
  nodes_.resize(nodes_.size() + 2);
  MapTrapezoid lower = t, upper = t;
  lower.top = p;
  upper.bottom = p;
  add_trapezoid(lower, lower_leaf);
  add_trapezoid(upper, lower_leaf + 1);
  nodes_[n] = Node{point_node, p, {lower_leaf, lower_leaf + 1}};
  return Status::ok;
}

template <Real T>
Status TrapezoidMap2<T>::insert(std::uint32_t segment) {
  if (nodes_.empty()) return status_;
  if (segment >= segs_.size()) return Status::invalid_input;
  if (inserted_[segment]) return Status::ok;
  const auto [lo, hi] = segs_[segment];
  if (lo == hi) {  // zero length: skipped
    inserted_[segment] = 1;
    return Status::ok;
  }
  (void)split_at(lo);
  (void)split_at(hi);
  // Walk up along the segment, collecting the leaves of the trapezoids it crosses.
  std::vector<std::uint32_t> crossed;
  std::uint32_t from = lo;
  const Vec2<T>& a = points_[lo];
  const Vec2<T>& b = points_[hi];
  for (std::size_t guard = 0; guard <= traps_.size(); ++guard) {
    const std::uint32_t n = locate_along(segment, from);
    if (n == none) return Status::invalid_topology;
    const MapTrapezoid& t = traps_[nodes_[n].key];
    if (t.bottom != from || t.top == none) return Status::invalid_topology;
    if ((t.left != none && segments_touch(segment, t.left)) ||
        (t.right != none && segments_touch(segment, t.right)))
      return Status::invalid_topology;
    crossed.push_back(n);
    if (t.top == hi) break;
    // A point level with the interior of the segment must not lie on it.
    if (!below(t.top, hi) || orient2d(a, b, points_[t.top]) == Sign::zero)
      return Status::invalid_topology;
    from = t.top;
  }
  if (crossed.empty() || traps_[nodes_[crossed.back()].key].top != hi)
    return Status::invalid_topology;
  inserted_[segment] = 1;
  std::vector<std::uint32_t> left_leaves, right_leaves;
  left_leaves.reserve(crossed.size());
  right_leaves.reserve(crossed.size());
  for (const std::uint32_t n : crossed) {
    const MapTrapezoid t = traps_[nodes_[n].key];
    remove_trapezoid(nodes_[n].key);
    const auto leaf = static_cast<std::uint32_t>(nodes_.size());
    nodes_.resize(nodes_.size() + 2);
    add_trapezoid(MapTrapezoid{t.bottom, t.top, t.left, segment}, leaf);
    add_trapezoid(MapTrapezoid{t.bottom, t.top, segment, t.right}, leaf + 1);
    nodes_[n] = Node{segment_node, segment, {leaf, leaf + 1}};
    left_leaves.push_back(leaf);
    right_leaves.push_back(leaf + 1);
  }
  if (options_.merge_each_insertion) {
    // Pieces on one side cut from the same old horizontal split join (the old split's point is
    // on the other side of the new segment).
    for (const auto* side : {&left_leaves, &right_leaves}) {
      std::uint32_t acc = (*side)[0];
      for (std::size_t j = 1; j < side->size(); ++j) {
        const std::uint32_t n = (*side)[j];
        MapTrapezoid& keep = traps_[nodes_[acc].key];
        const MapTrapezoid& next = traps_[nodes_[n].key];
        if (keep.left == next.left && keep.right == next.right) {
          keep.top = next.top;
          remove_trapezoid(nodes_[n].key);
          nodes_[n] = Node{redirect_node, none, {acc, none}};
        } else {
          acc = n;
        }
      }
    }
  }
  return Status::ok;
}

template <Real T>
void TrapezoidMap2<T>::merge() {
  if (nodes_.empty()) return;
  std::vector<std::uint32_t> leaves(leaf_of_.begin(), leaf_of_.end());
  const auto key = [&](std::uint32_t leaf) -> const MapTrapezoid& {
    return traps_[nodes_[leaf].key];
  };
  std::sort(leaves.begin(), leaves.end(), [&](std::uint32_t x, std::uint32_t y) {
    const MapTrapezoid& s = key(x);
    const MapTrapezoid& t = key(y);
    if (s.left != t.left) return s.left < t.left;
    if (s.right != t.right) return s.right < t.right;
    if (s.bottom == t.bottom) return false;
    if (s.bottom == none) return true;
    if (t.bottom == none) return false;
    return below(s.bottom, t.bottom);
  });
  std::size_t k = 0;
  while (k < leaves.size()) {
    const std::uint32_t acc = leaves[k++];
    while (k < leaves.size()) {
      MapTrapezoid& keep = traps_[nodes_[acc].key];
      const MapTrapezoid& next = key(leaves[k]);
      if (next.left != keep.left || next.right != keep.right || keep.top == none ||
          next.bottom != keep.top)
        break;
      keep.top = next.top;
      remove_trapezoid(nodes_[leaves[k]].key);
      nodes_[leaves[k]] = Node{redirect_node, none, {acc, none}};
      ++k;
    }
  }
}

template <Real T>
Status TrapezoidMap2<T>::build(std::span<const Vec2<T>> points,
                               std::span<const std::array<std::uint32_t, 2>> segments,
                               TrapezoidMapOptions options) {
  const Status st = begin(points, segments, options);
  if (st != Status::ok) return st;
  std::vector<std::uint32_t> order(segments.size());
  std::iota(order.begin(), order.end(), 0u);
  if (options.shuffle_seed != 0) {
    std::uint64_t state = options.shuffle_seed;
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[next_random(state) % i]);
  }
  for (const std::uint32_t s : order) {
    const Status r = insert(s);
    if (r != Status::ok) {
      merge();
      return status_ = r;
    }
  }
  merge();
  return status_ = Status::ok;
}

template <Real T>
TrapezoidMap trapezoid_map(std::span<const Vec2<T>> points,
                           std::span<const std::array<std::uint32_t, 2>> segments,
                           TrapezoidMapOptions options) {
  TrapezoidMap2<T> m;
  TrapezoidMap r;
  r.status = m.build(points, segments, options);
  r.trapezoids.assign(m.trapezoids().begin(), m.trapezoids().end());
  return r;
}

template <Real T>
std::array<Vec2<T>, 4> trapezoid_map_corners(std::span<const Vec2<T>> points,
                                             std::span<const std::array<std::uint32_t, 2>> segments,
                                             const MapTrapezoid& t, const Vec2<T>& lo,
                                             const Vec2<T>& hi) noexcept {
  const T yb = t.bottom == none ? lo.y : std::clamp(points[t.bottom].y, lo.y, hi.y);
  const T yt = t.top == none ? hi.y : std::clamp(points[t.top].y, lo.y, hi.y);
  const auto x_at = [&](std::uint32_t s, T y, bool upper_corner, T fallback) {
    if (s == none) return fallback;
    Vec2<T> a = points[segments[s][0]], b = points[segments[s][1]];
    if (below_xy(b, a)) std::swap(a, b);
    T x;
    if (a.y == b.y)
      x = upper_corner ? b.x : a.x;  // level segment: its symbolic tilt puts b above a
    else
      x = a.x + (std::clamp(y, a.y, b.y) - a.y) / (b.y - a.y) * (b.x - a.x);
    return std::clamp(x, lo.x, hi.x);
  };
  return {Vec2<T>{x_at(t.left, yb, false, lo.x), yb}, Vec2<T>{x_at(t.right, yb, false, hi.x), yb},
          Vec2<T>{x_at(t.right, yt, true, hi.x), yt}, Vec2<T>{x_at(t.left, yt, true, lo.x), yt}};
}

template class TrapezoidMap2<float>;
template class TrapezoidMap2<double>;
template TrapezoidMap trapezoid_map<float>(std::span<const Vec2<float>>,
                                           std::span<const std::array<std::uint32_t, 2>>,
                                           TrapezoidMapOptions);
template TrapezoidMap trapezoid_map<double>(std::span<const Vec2<double>>,
                                            std::span<const std::array<std::uint32_t, 2>>,
                                            TrapezoidMapOptions);
template std::array<Vec2<float>, 4> trapezoid_map_corners<float>(
    std::span<const Vec2<float>>, std::span<const std::array<std::uint32_t, 2>>,
    const MapTrapezoid&, const Vec2<float>&, const Vec2<float>&) noexcept;
template std::array<Vec2<double>, 4> trapezoid_map_corners<double>(
    std::span<const Vec2<double>>, std::span<const std::array<std::uint32_t, 2>>,
    const MapTrapezoid&, const Vec2<double>&, const Vec2<double>&) noexcept;

}  // namespace locus
