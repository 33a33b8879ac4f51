// SPDX-License-Identifier: BSL-1.0
// 2D convex hull (cg.hull2): the three methods of include/locus/hull/hull2.hpp, compiled once
// for float and double.

#include <locus/hull/hull2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace locus {

namespace {

// From this many points to sort, the LSD radix sort (radix_sorted) replaces the bucket sort;
// below, the bucket array fits in the caches and one scatter beats the radix passes.
constexpr std::size_t radix_min_points = std::size_t{1} << 15;
// At most 2^10 top-level buckets: 1024 write streams, whose open cache lines fit in L2 and
// whose pages fit in the second-level TLB (4096 streams measured slower).
constexpr unsigned radix_top_bits = 10;

template <class Item>
[[nodiscard]] inline bool item_less(const Item& a, const Item& b) noexcept {
  if (a.p.y != b.p.y) return a.p.y < b.p.y;
  if (a.p.x != b.p.x) return a.p.x < b.p.x;
  return a.index < b.index;
}

// Function objects rather than function pointers, so every sort inlines its comparison.
struct ItemLess {
  template <class Item>
  [[nodiscard]] bool operator()(const Item& a, const Item& b) const noexcept {
    return item_less(a, b);
  }
};
// For the items of radix_sorted: keys are a non-decreasing function of y, so a smaller key means
// a smaller y and only equal keys need the exact comparison.
struct KeyedItemLess {
  template <class Item>
  [[nodiscard]] bool operator()(const Item& a, const Item& b) const noexcept {
    return a.key != b.key ? a.key < b.key : item_less(a, b);
  }
};

template <class Item, class Less = ItemLess>
void insertion_sort(Item* first, Item* last, Less less = {}) noexcept {
  for (Item* i = first + 1; i < last; ++i) {
    Item v = *i;
    Item* j = i;
    while (j > first && less(v, *(j - 1))) {
      *j = *(j - 1);
      --j;
    }
    *j = v;
  }
}

// The strict hull (CCW, from the lowest-leftmost point) of at most a handful of points, by the
// monotone chain; used for the filter polygon.
template <Real T>
std::size_t tiny_hull(Vec2<T>* pts, std::size_t n, Vec2<T>* out) noexcept {
  std::sort(pts, pts + n, [](const Vec2<T>& a, const Vec2<T>& b) {
    return a.y < b.y || (a.y == b.y && a.x < b.x);
  });
  n = static_cast<std::size_t>(std::unique(pts, pts + n) - pts);
  if (n < 3) return n;
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (k >= 2 && orient2d(out[k - 2], out[k - 1], pts[i]) != Sign::positive) --k;
    out[k++] = pts[i];
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = n - 1; i-- > 0;) {
    while (k >= lower && orient2d(out[k - 2], out[k - 1], pts[i]) != Sign::positive) --k;
    out[k++] = pts[i];
  }
  return k - 1;
}

template <Real T>
[[nodiscard]] bool strictly_inside(const Vec2<T>* poly, std::size_t n, const Vec2<T>& q) noexcept {
  for (std::size_t i = 0; i < n; ++i) {
    if (orient2d(poly[i], poly[(i + 1) % n], q) != Sign::positive) return false;
  }
  return true;
}

}  // namespace

template <Real T>
Hull2Result ConvexHull2<T>::compute(std::span<const Vec2<T>> points, const Hull2Options& options) {
  Hull2Result r;
  compute(points, options, r);
  return r;
}

template <Real T>
void ConvexHull2<T>::compute(std::span<const Vec2<T>> points, const Hull2Options& options,
                             Hull2Result& out) {
  out.indices.clear();
  out.dimension = -1;
  const std::size_t n = points.size();
  if (n == 0) {
    out.status = Status::empty_input;
    return;
  }
  if (n > std::numeric_limits<std::uint32_t>::max()) {
    out.status = Status::invalid_input;
    return;
  }
  constexpr T big = std::numeric_limits<T>::max();
  items_.clear();
  double ymin = std::numeric_limits<double>::quiet_NaN(), ymax = ymin;
  const bool filter = options.method == Hull2Method::monotone_chain && n >= 256;
  const std::uint32_t* selected = nullptr;  // the points to sort (nullptr: all)
  std::size_t m = n;
  if (!filter) {
    double lo_y = std::numeric_limits<double>::infinity(), hi_y = -lo_y;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2<T> p = points[i];
      if (!(std::abs(p.x) <= big && std::abs(p.y) <= big)) {
        out.status = Status::non_finite_input;
        return;
      }
      lo_y = std::min(lo_y, static_cast<double>(p.y));
      hi_y = std::max(hi_y, static_cast<double>(p.y));
    }
    ymin = lo_y;
    ymax = hi_y;
  } else {
    // Akl-Toussaint: extreme points in the directions y, x, x + y, x - y (heuristic values in
    // double; the polygon they span is inside the hull whatever the rounding).
    double ext_min[4], ext_max[4];
    std::size_t arg_min[4] = {0, 0, 0, 0}, arg_max[4] = {0, 0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      ext_min[k] = std::numeric_limits<double>::infinity();
      ext_max[k] = -std::numeric_limits<double>::infinity();
    }
    bool finite = true;
    // Blocks: a branch-free pass takes each block's extreme values; only a block that beats a
    // running extreme (rare after the first few) is scanned again for the index, with the same
    // strict comparisons, so the result is the one of a single scan.
    constexpr std::size_t block = 256;
    for (std::size_t b0 = 0; b0 < n; b0 += block) {
      const std::size_t b1 = std::min(n, b0 + block);
      double lo[4], hi[4];
      for (int k = 0; k < 4; ++k) lo[k] = ext_min[k], hi[k] = ext_max[k];
      for (std::size_t i = b0; i < b1; ++i) {
        const Vec2<T> p = points[i];
        finite &= std::abs(p.x) <= big && std::abs(p.y) <= big;
        const double x = static_cast<double>(p.x), y = static_cast<double>(p.y);
        const double v[4] = {y, x, x + y, x - y};
        for (int k = 0; k < 4; ++k) {
          lo[k] = v[k] < lo[k] ? v[k] : lo[k];
          hi[k] = v[k] > hi[k] ? v[k] : hi[k];
        }
      }
      bool improves = false;
      for (int k = 0; k < 4; ++k) improves |= (lo[k] < ext_min[k]) | (hi[k] > ext_max[k]);
      if (!improves) continue;
      for (std::size_t i = b0; i < b1; ++i) {
        const double x = static_cast<double>(points[i].x), y = static_cast<double>(points[i].y);
        const double v[4] = {y, x, x + y, x - y};
        for (int k = 0; k < 4; ++k) {
          if (v[k] < ext_min[k]) {
            ext_min[k] = v[k];
            arg_min[k] = i;
          }
          if (v[k] > ext_max[k]) {
            ext_max[k] = v[k];
            arg_max[k] = i;
          }
        }
      }
    }
    if (!finite) {
      out.status = Status::non_finite_input;
      return;
    }
    ymin = ext_min[0];
    ymax = ext_max[0];
    Vec2<T> cand[8], poly[9];
    for (int k = 0; k < 4; ++k) {
      cand[2 * k] = points[arg_min[k]];
      cand[2 * k + 1] = points[arg_max[k]];
    }
    const Vec2<T> sw = points[arg_min[2]], ne = points[arg_max[2]];
    const Vec2<T> nw = points[arg_min[3]], se = points[arg_max[3]];
    const std::size_t pn = tiny_hull(cand, 8, poly);
    Vec2<T> lo{std::max(sw.x, nw.x), std::max(sw.y, se.y)};
    Vec2<T> hi{std::min(se.x, ne.x), std::min(nw.y, ne.y)};
    bool use_box = false;
    if (pn >= 3 && lo.x < hi.x && lo.y < hi.y) {
      const Vec2<T> c{lo.x / T(2) + hi.x / T(2), lo.y / T(2) + hi.y / T(2)};
      for (const T f :
           {T(1), T(1) - T(0x1p-20), T(1) - T(0x1p-12), T(1) - T(0x1p-6), T(0.9), T(0.5)}) {
        const Vec2<T> l{c.x + f * (lo.x - c.x), c.y + f * (lo.y - c.y)};
        const Vec2<T> h{c.x + f * (hi.x - c.x), c.y + f * (hi.y - c.y)};
        if (strictly_inside(poly, pn, l) && strictly_inside(poly, pn, h) &&
            strictly_inside(poly, pn, Vec2<T>{l.x, h.y}) &&
            strictly_inside(poly, pn, Vec2<T>{h.x, l.y})) {
          lo = l;
          hi = h;
          use_box = true;
          break;
        }
      }
    }
    if (use_box) {
      // The closed box lies strictly inside the hull of input points, so no point in it is on
      // the hull boundary.
      const auto outside = [&](const Vec2<T>& p) {
        return !((p.x >= lo.x) & (p.x <= hi.x) & (p.y >= lo.y) & (p.y <= hi.y));
      };
      // When most points survive (all on the hull, say), selecting them only adds a pass and an
      // indirection: a strided sample decides.
      const std::size_t samples = std::min<std::size_t>(n, 1024), stride = n / samples;
      std::size_t sampled_out = 0;
      for (std::size_t i = 0; i < samples; ++i) sampled_out += outside(points[i * stride]);
      if (2 * sampled_out < samples) {
        aux_.clear();
        aux_.reserve(std::min<std::size_t>(n, 1u << 16));
        for (std::size_t i = 0; i < n; ++i)
          if (outside(points[i])) aux_.push_back(static_cast<std::uint32_t>(i));
        selected = aux_.data();
        m = aux_.size();
      }
    }
  }
  gather_sorted(points, selected, m, ymin, ymax);
  if (options.method == Hull2Method::monotone_chain) {
    out.status = Status::ok;
    monotone_chain(options.keep_collinear, out);
    return;
  }
  // Duplicates are adjacent; the first (smallest index) represents them.
  {
    std::size_t k = 0;
    for (std::size_t i = 0; i < items_.size(); ++i) {
      if (k > 0 && items_[i].p.x == items_[k - 1].p.x && items_[i].p.y == items_[k - 1].p.y)
        continue;
      items_[k++] = items_[i];
    }
    items_.resize(k);
  }
  out.status = Status::ok;
  if (items_.size() == 1) {
    out.dimension = 0;
    out.indices.push_back(items_[0].index);
    return;
  }
  switch (options.method) {
    case Hull2Method::monotone_chain:
      monotone_chain(options.keep_collinear, out);
      return;
    case Hull2Method::incremental:
      incremental(out);
      emit_strict(options.keep_collinear, out);
      return;
    case Hull2Method::divide_and_conquer:
      divide_and_conquer(out);
      emit_strict(options.keep_collinear, out);
      return;
  }
}

// items_ = the selected points sorted by (y, x, index). A counting pass on a monotone
// (non-decreasing) function of y puts every point in a bucket no later than any larger point's
// bucket; exact ties and the order inside a bucket are settled by a comparison sort, so the
// result is exactly sorted. The points are scattered straight from the input (no copy first).
template <Real T>
void ConvexHull2<T>::gather_sorted(std::span<const Vec2<T>> points, const std::uint32_t* selected,
                                   std::size_t m, double ymin, double ymax) {
  const auto id = [&](std::size_t k) -> std::uint32_t {
    return selected ? selected[k] : static_cast<std::uint32_t>(k);
  };
  items_.resize(m);
  Item* a = items_.data();
  const double range = ymax - ymin;
  const std::size_t nb = m / 2;
  const double scale = static_cast<double>(nb) / range;
  if (m < 1024 || !(range > 0.0) || !std::isfinite(scale) || !(scale > 0.0)) {
    for (std::size_t k = 0; k < m; ++k) a[k] = Item{points[id(k)], id(k)};
    if (m <= 32)
      insertion_sort(a, a + m);
    else
      std::sort(a, a + m, ItemLess{});
    return;
  }
  if (m >= radix_min_points && radix_sorted(points, selected, m, ymin, ymax)) return;
  // Clamped both ways: ymin/ymax may come from a superset of the selected points.
  const double top = static_cast<double>(nb - 1);
  const auto bucket = [&](T y) {
    const double t = std::max(0.0, (static_cast<double>(y) - ymin) * scale);
    return static_cast<std::size_t>(std::min(t, top));
  };
  counts_.assign(nb + 1, 0);
  for (std::size_t k = 0; k < m; ++k) ++counts_[bucket(points[id(k)].y) + 1];
  for (std::size_t b = 0; b < nb; ++b) counts_[b + 1] += counts_[b];
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t i = id(k);
    a[counts_[bucket(points[i].y)]++] = Item{points[i], i};
  }
  // counts_[b] is now the end of bucket b; bucket b starts at counts_[b - 1] (0 for b = 0).
  std::size_t begin = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t end = counts_[b];
    if (end - begin > 1) {
      if (end - begin <= 32)
        insertion_sort(a + begin, a + end);
      else
        std::sort(a + begin, a + end, ItemLess{});
    }
    begin = end;
  }
}

// items_ = the selected points sorted by (y, x, index), for many points. The one-level bucket
// scatter of gather_sorted writes every item to a random place of an array far larger than the
// caches; on points that all survive the filter (a circle, say) that scatter was most of the
// hull's time. Here each point gets a key, a monotone (non-decreasing) quantisation of y to 32
// bits, and two bucket levels keep every memory access in order or in cache:
//   1. the input is read in order and each item is scattered by its key's top bits into at most
//      2^12 buckets: 4096 sequential write streams, whose open cache lines fit in L2;
//   2. each bucket (a few hundred items, in cache) is bucket-sorted again by the rest of its key
//      through a scratch buffer, and each small sub-bucket is sorted by the exact comparison.
// Keys only place items; the exact comparison orders every sub-bucket and equal keys share one,
// so the result is exactly sorted whatever the rounding of the keys.
template <Real T>
bool ConvexHull2<T>::radix_sorted(std::span<const Vec2<T>> points, const std::uint32_t* selected,
                                  std::size_t m, double ymin, double ymax) {
  constexpr double levels = 0x1p32;
  const double scale = levels / (ymax - ymin);
  if (!std::isfinite(scale)) return false;  // y range below ~1e-300: the bucket path copes
  // Clamped both ways: ymin/ymax may come from a superset of the selected points.
  const auto key_of = [&](T y) {
    return static_cast<std::uint32_t>(
        std::min(std::max(0.0, (static_cast<double>(y) - ymin) * scale), levels - 1.0));
  };
  const auto id = [&](std::size_t k) -> std::uint32_t {
    return selected ? selected[k] : static_cast<std::uint32_t>(k);
  };
  // About 256 items per top bucket, at most 2^12 buckets.
  unsigned top_bits = 1;
  while (top_bits < radix_top_bits && (std::size_t{256} << top_bits) < m) ++top_bits;
  const unsigned low_bits = 32 - top_bits;
  const std::size_t nb = std::size_t{1} << top_bits;
  counts_.assign(nb + 1, 0);
  std::uint32_t* start = counts_.data();
  for (std::size_t k = 0; k < m; ++k) ++start[(key_of(points[id(k)].y) >> low_bits) + 1];
  std::uint32_t largest = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    largest = std::max(largest, start[b + 1]);
    start[b + 1] += start[b];
  }
  items_.resize(m);
  Item* a = items_.data();
  {
    // Write cursors in a copy: start[] keeps the bucket boundaries for step 2.
    sub_counts_.assign(start, start + nb);
    std::uint32_t* cursor = sub_counts_.data();
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t i = id(k);
      const Vec2<T> p = points[i];
      const std::uint32_t q = key_of(p.y);
      a[cursor[q >> low_bits]++] = Item{p, i, q};
    }
  }
  // Step 2: about two items per sub-bucket.
  items2_.resize(largest);
  Item* scratch = items2_.data();
  const std::uint64_t low_mask = (std::uint64_t{1} << low_bits) - 1;
  for (std::size_t b = 0; b < nb; ++b) {
    Item* first = a + start[b];
    const std::size_t size = start[b + 1] - start[b];
    if (size <= 32) {
      if (size > 1) insertion_sort(first, first + size, KeyedItemLess{});
      continue;
    }
    const std::uint64_t ns = size / 2;
    const auto sub = [&](std::uint32_t key) {
      return static_cast<std::size_t>(((key & low_mask) * ns) >> low_bits);
    };
    sub_counts_.assign(ns + 1, 0);
    std::uint32_t* c = sub_counts_.data();
    for (std::size_t k = 0; k < size; ++k) ++c[sub(first[k].key) + 1];
    for (std::size_t j = 0; j < ns; ++j) c[j + 1] += c[j];
    for (std::size_t k = 0; k < size; ++k) scratch[c[sub(first[k].key)]++] = first[k];
    std::copy(scratch, scratch + size, first);
    // c[j] is now the end of sub-bucket j.
    std::size_t begin = 0;
    for (std::size_t j = 0; j < ns; ++j) {
      const std::size_t end = c[j];
      if (end - begin > 1) {
        if (end - begin <= 32)
          insertion_sort(first + begin, first + end, KeyedItemLess{});
        else
          std::sort(first + begin, first + end, KeyedItemLess{});
      }
      begin = end;
    }
  }
  return true;
}

// Andrew's monotone chain over the sorted items, split by the line from the lowest point F to
// the highest point L: the right chain (from F up to L) is the chain of the points right of FL,
// the left chain that of the points left of it. One pass in sorted order builds both chains from
// F up to L: the right one keeps only left turns, the left one only right turns (or, keeping
// collinear points, also straight continuations). The points strictly between F and L on FL are
// never hull vertices; they are on the boundary only when one side is empty (then that side's
// chain is F, those points, L), so the pass leaves them out and only counts them. Duplicates are
// skipped (the first of equal items has the smallest index). The hull is the right chain
// followed by the left chain reversed.
//
// Memory: the two chains share one stack array growing from both ends (positions in items_,
// for the turn tests) and the output itself, growing the same way (input indices, written while
// the item is in cache): every distinct point is in at most one chain but F and L are in both,
// so last + 3 entries never overlap.
template <Real T>
void ConvexHull2<T>::monotone_chain(bool keep_collinear, Hull2Result& out) {
  const std::size_t m = items_.size();
  const Item* it = items_.data();
  std::size_t last = m - 1;
  while (last > 0 && it[last - 1].p == it[m - 1].p) --last;
  if (last == 0) {
    out.dimension = 0;
    out.indices.push_back(it[0].index);
    return;
  }
  const std::size_t top = last + 2;  // the bottom of the left chain
  hull_.resize(top + 1);
  out.indices.resize(top + 1);
  std::uint32_t* pos = hull_.data();
  std::uint32_t* ids = out.indices.data();
  const Vec2<T> f = it[0].p, l = it[last].p;
  // Whether the top of a chain goes: `a`, `b` are its top two entries, `pop_sign` the turn
  // that removes b (a straight continuation, zero, removes it too unless collinear points are
  // kept).
  const auto pops = [&](std::uint32_t a, std::uint32_t b, std::size_t i, Sign pop_sign) {
    const Sign s = orient2d(it[a].p, it[b].p, it[i].p);
    return s == pop_sign || (s == Sign::zero && !keep_collinear);
  };
  std::size_t kr = 1, kl = 1, n_on = 0;
  pos[0] = pos[top] = 0;
  ids[0] = ids[top] = it[0].index;
  bool any_right = false, any_left = false;
  for (std::size_t i = 1; i <= last; ++i) {
    if (it[i].p == it[i - 1].p) continue;
    const Sign s = i == last ? Sign::zero : orient2d(f, l, it[i].p);
    if (s == Sign::zero && i != last) {
      ++n_on;
      continue;
    }
    const auto at = static_cast<std::uint32_t>(i);
    if (s != Sign::positive) {
      any_right |= s == Sign::negative;
      while (kr >= 2 && pops(pos[kr - 2], pos[kr - 1], i, Sign::negative)) --kr;
      pos[kr] = at;
      ids[kr++] = it[i].index;
    }
    if (s != Sign::negative) {
      any_left |= s == Sign::positive;
      while (kl >= 2 && pops(pos[top - (kl - 2)], pos[top - (kl - 1)], i, Sign::positive)) --kl;
      pos[top - kl] = at;
      ids[top - kl++] = it[i].index;
    }
  }
  if (!any_right && !any_left) {
    out.dimension = 1;
    out.indices.clear();
    if (keep_collinear) {
      for (std::size_t i = 0; i <= last; ++i)
        if (i == 0 || !(it[i].p == it[i - 1].p)) out.indices.push_back(it[i].index);
    } else {
      out.indices = {it[0].index, it[last].index};
    }
    return;
  }
  out.dimension = 2;
  // The left chain from below L down to above F lies at ids[top - (kl - 2), top): move it
  // after the right chain (the ranges do not overlap in a way that a forward copy could spoil:
  // the destination starts before the source).
  std::copy(ids + top - (kl - 2), ids + top, ids + kr);
  out.indices.resize(kr + kl - 2);
  // With both sides nonempty, FL is inside the hull; with one side empty, FL is an edge and
  // that side's chain is F, the points on FL, L.
  if (!keep_collinear || n_on == 0 || (any_right && any_left)) return;
  // Right side empty: the right chain is F, L; the points go between them. Left side empty:
  // they come last, from L down to F.
  const auto on_fl = [&](std::size_t i) {
    return !(it[i].p == it[i - 1].p) && orient2d(f, l, it[i].p) == Sign::zero;
  };
  if (!any_right) {
    aux_.assign(out.indices.begin() + 1, out.indices.end());  // L, then the left chain
    out.indices.resize(1);
    for (std::size_t i = 1; i < last; ++i)
      if (on_fl(i)) out.indices.push_back(it[i].index);
    out.indices.insert(out.indices.end(), aux_.begin(), aux_.end());
  } else {
    for (std::size_t i = last; i-- > 1;)
      if (on_fl(i)) out.indices.push_back(it[i].index);
  }
}

// The book's incremental method on sorted input: each new point is the lexicographic maximum so
// far, hence outside the current hull and a vertex of the new one. The hull is a circular list;
// the two tangent points are found by walking from the previous maximum (figure 13.34). While the
// hull is a segment, the five cases of figure 13.35 reduce (the new point is never before the
// segment's end) to: on the line beyond the end (extend), left or right (make a triangle).
template <Real T>
void ConvexHull2<T>::incremental(Hull2Result& out) {
  (void)out;
  const std::size_t m = items_.size();
  const Item* it = items_.data();
  aux_.assign(m, 0);   // next (counter-clockwise)
  aux2_.assign(m, 0);  // prev
  std::uint32_t* next = aux_.data();
  std::uint32_t* prev = aux2_.data();
  std::uint32_t top = 1;
  bool collinear = true;
  for (std::uint32_t i = 2; i < m; ++i) {
    const Vec2<T>& p = it[i].p;
    if (collinear) {
      const Sign s = orient2d(it[0].p, it[top].p, p);
      if (s == Sign::zero) {
        top = i;
        continue;
      }
      collinear = false;
      const std::uint32_t a = s == Sign::positive ? top : i, b = s == Sign::positive ? i : top;
      next[0] = a, next[a] = b, next[b] = 0;
      prev[0] = b, prev[b] = a, prev[a] = 0;
      top = i;
      continue;
    }
    std::uint32_t a = top, b = top;
    for (std::size_t guard = 0; guard < m && orient2d(it[prev[a]].p, it[a].p, p) != Sign::positive;
         ++guard)
      a = prev[a];
    for (std::size_t guard = 0; guard < m && orient2d(it[b].p, it[next[b]].p, p) != Sign::positive;
         ++guard)
      b = next[b];
    next[a] = i, prev[i] = a, next[i] = b, prev[b] = i;
    top = i;
  }
  hull_.clear();
  if (collinear) {
    hull_.push_back(0);
    hull_.push_back(top);
    return;
  }
  std::uint32_t v = 0;
  do {
    hull_.push_back(v);
    v = next[v];
  } while (v != 0 && hull_.size() <= m);
}

// The book's divide and conquer: hulls of the lower and upper halves (in (y, x) order, so they
// are separated), merged through their two tangents (figures 13.36-13.38). Hulls are stored
// counter-clockwise from their lexicographically smallest point in hull_[lo, lo + size).
template <Real T>
void ConvexHull2<T>::divide_and_conquer(Hull2Result& out) {
  (void)out;
  const std::size_t m = items_.size();
  hull_.assign(m, 0);
  aux_.resize(m);
  const std::uint32_t h = dc_recurse(0, static_cast<std::uint32_t>(m));
  hull_.resize(h);
}

template <Real T>
std::uint32_t ConvexHull2<T>::dc_recurse(std::uint32_t lo, std::uint32_t hi) {
  if (hi - lo <= 2) {
    for (std::uint32_t i = lo; i < hi; ++i) hull_[i] = i;
    return hi - lo;
  }
  const std::uint32_t mid = lo + (hi - lo) / 2;
  const std::uint32_t hl = dc_recurse(lo, mid);
  const std::uint32_t hr = dc_recurse(mid, hi);
  const std::uint32_t* L = hull_.data() + lo;
  const std::uint32_t* R = hull_.data() + mid;
  const Item* it = items_.data();
  const auto P = [&](std::uint32_t k) -> const Vec2<T>& { return it[k].p; };
  // Positions in items_ are in lexicographic order, so comparing positions compares points.
  std::uint32_t top = 0;
  for (std::uint32_t i = 1; i < hl; ++i)
    if (L[i] > L[top]) top = i;
  const std::size_t guard_max = 4 * (static_cast<std::size_t>(hl) + hr) + 8;
  // Tangent with every point on its right (ia moves counter-clockwise on L, ib clockwise on R).
  std::uint32_t ia = top, ib = 0;
  for (std::size_t guard = 0; guard < guard_max; ++guard) {
    bool moved = false;
    for (;;) {
      const std::uint32_t an = (ia + 1) % hl;
      if (an == ia) break;
      const Sign s = orient2d(P(L[ia]), P(R[ib]), P(L[an]));
      if (s == Sign::positive || (s == Sign::zero && L[an] < L[ia])) {
        ia = an;
        moved = true;
      } else {
        break;
      }
    }
    for (;;) {
      const std::uint32_t bp = (ib + hr - 1) % hr;
      if (bp == ib) break;
      const Sign s = orient2d(P(L[ia]), P(R[ib]), P(R[bp]));
      if (s == Sign::positive || (s == Sign::zero && R[bp] > R[ib])) {
        ib = bp;
        moved = true;
      } else {
        break;
      }
    }
    if (!moved) break;
  }
  // Tangent with every point on its left (ja clockwise on L, jb counter-clockwise on R).
  std::uint32_t ja = top, jb = 0;
  for (std::size_t guard = 0; guard < guard_max; ++guard) {
    bool moved = false;
    for (;;) {
      const std::uint32_t ap = (ja + hl - 1) % hl;
      if (ap == ja) break;
      const Sign s = orient2d(P(L[ja]), P(R[jb]), P(L[ap]));
      if (s == Sign::negative || (s == Sign::zero && L[ap] < L[ja])) {
        ja = ap;
        moved = true;
      } else {
        break;
      }
    }
    for (;;) {
      const std::uint32_t bn = (jb + 1) % hr;
      if (bn == jb) break;
      const Sign s = orient2d(P(L[ja]), P(R[jb]), P(R[bn]));
      if (s == Sign::negative || (s == Sign::zero && R[bn] > R[jb])) {
        jb = bn;
        moved = true;
      } else {
        break;
      }
    }
    if (!moved) break;
  }
  // Counter-clockwise from L[0]: L[0..ja], R[jb .. ib] (counter-clockwise), L[ia .. end).
  std::uint32_t* o = aux_.data();
  std::uint32_t k = 0;
  for (std::uint32_t i = 0; i <= ja; ++i) o[k++] = L[i];
  for (std::uint32_t i = jb;; i = (i + 1) % hr) {
    o[k++] = R[i];
    if (i == ib) break;
  }
  if (ia != 0)
    for (std::uint32_t i = ia; i < hl; ++i) o[k++] = L[i];
  std::copy(o, o + k, hull_.data() + lo);
  return k;
}

// From a strict hull in hull_ (positions, counter-clockwise from position 0) to the result,
// adding the boundary points when asked: a point lies on the right chain (positions increase
// from 0 to the top) or on the left chain (they decrease back to 0); a binary search by position
// finds the only edge that can hold it and orient2d decides.
template <Real T>
void ConvexHull2<T>::emit_strict(bool keep_collinear, Hull2Result& out) {
  const std::size_t m = items_.size();
  const Item* it = items_.data();
  const std::size_t h = hull_.size();
  if (h <= 2) {
    out.dimension = static_cast<int>(h) - 1;
    if (h == 2 && keep_collinear) {
      out.indices.resize(m);
      for (std::size_t i = 0; i < m; ++i) out.indices[i] = it[i].index;
    } else {
      for (std::size_t i = 0; i < h; ++i) out.indices.push_back(it[hull_[i]].index);
    }
    return;
  }
  out.dimension = 2;
  if (!keep_collinear) {
    out.indices.resize(h);
    for (std::size_t i = 0; i < h; ++i) out.indices[i] = it[hull_[i]].index;
    return;
  }
  std::size_t t = 0;
  for (std::size_t i = 1; i < h; ++i)
    if (hull_[i] > hull_[t]) t = i;
  aux2_.assign(m, 0);
  for (std::size_t i = 0; i <= t; ++i) aux2_[hull_[i]] = 1;
  for (std::size_t i = t + 1; i < h; ++i) aux2_[hull_[i]] = 2;
  // Left chain as an increasing sequence: hull_[0], hull_[h-1], ..., hull_[t].
  aux_.clear();
  aux_.push_back(hull_[0]);
  for (std::size_t i = h; i-- > t;) aux_.push_back(hull_[i]);
  const std::uint32_t* right_begin = hull_.data();
  const std::uint32_t* right_end = hull_.data() + t + 1;
  for (std::uint32_t q = 0; q < m; ++q) {
    if (aux2_[q] != 0) continue;
    const std::uint32_t* e = std::upper_bound(right_begin, right_end, q) - 1;
    if (orient2d(it[e[0]].p, it[e[1]].p, it[q].p) == Sign::zero) {
      aux2_[q] = 1;
      continue;
    }
    const std::uint32_t* f = std::upper_bound(aux_.data(), aux_.data() + aux_.size(), q) - 1;
    if (orient2d(it[f[0]].p, it[f[1]].p, it[q].p) == Sign::zero) aux2_[q] = 2;
  }
  for (std::uint32_t q = 0; q < m; ++q)
    if (aux2_[q] == 1) out.indices.push_back(it[q].index);
  for (std::uint32_t q = static_cast<std::uint32_t>(m); q-- > 0;)
    if (aux2_[q] == 2) out.indices.push_back(it[q].index);
}

template class ConvexHull2<float>;
template class ConvexHull2<double>;

}  // namespace locus
