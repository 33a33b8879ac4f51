// SPDX-License-Identifier: BSL-1.0
// The slab decomposition of PolygonLocator2 (containment/point_in_polygon.hpp; row cg.pip),
// compiled once for float and double. The slab count and its bound: docs/notes/containment.md.

#include <locus/containment/point_in_polygon.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

template <Real T>
void PolygonLocator2<T>::build(std::span<const std::span<const Vec2<T>>> rings) {
  std::size_t n = 0;
  for (const auto& r : rings) {
    if (!detail::all_finite(r)) {
      status_ = Status::non_finite_input;
      return;
    }
    n += r.size();
  }
  if (n == 0) {
    status_ = Status::empty_input;
    return;
  }
  edges_.reserve(n);
  ylo_ = rings[0].empty() ? T(0) : rings[0][0].y;
  bool first = true;
  for (const auto& r : rings) {
    for (std::size_t i = 0, j = r.empty() ? 0 : r.size() - 1; i < r.size(); j = i++) {
      edges_.push_back({r[j], r[i], std::max(r[j].x, r[i].x)});
      if (first) {
        ylo_ = yhi_ = r[i].y;
        first = false;
      }
      ylo_ = std::min(ylo_, r[i].y);
      yhi_ = std::max(yhi_, r[i].y);
    }
  }
  // About one slab per edge, fewer when the edges are tall: the entries number about
  // n + slabs * sum(edge height) / height, kept below 8 n.
  const T height = yhi_ - ylo_;
  double spans = 0.0;
  if (height > T(0) && is_finite(height))
    for (const Edge& e : edges_)
      spans += (double(std::max(e.a.y, e.b.y)) - double(std::min(e.a.y, e.b.y))) / double(height);
  double want = double(std::min<std::size_t>(edges_.size(), std::size_t(1) << 20));
  if (spans * want > 8.0 * double(edges_.size())) want = 8.0 * double(edges_.size()) / spans;
  slabs_ = std::max<std::size_t>(1, static_cast<std::size_t>(want));
  // Counting sort of (slab, edge) entries into compressed rows. An edge spanning L slab
  // heights meets up to L + 2 slabs, not L + 1: short edges straddling slab boundaries can push
  // the total up to slabs * spans + 2 n, i.e. 10 n. So count, and while the total exceeds 8 n
  // use fewer slabs (one slab holds exactly n entries, so this ends).
  const double cap = 8.0 * double(edges_.size());
  for (;;) {
    inv_height_ = height > T(0) ? static_cast<T>(slabs_) / height : T(0);
    if (!is_finite(inv_height_) || !(inv_height_ > T(0))) {
      slabs_ = 1;
      inv_height_ = T(0);
    }
    offsets_.assign(slabs_ + 1, 0);
    double total = 0.0;
    for (const Edge& e : edges_) {
      const std::size_t s0 = slab_of(std::min(e.a.y, e.b.y));
      const std::size_t s1 = slab_of(std::max(e.a.y, e.b.y));
      for (std::size_t s = s0; s <= s1; ++s) ++offsets_[s + 1];
      total += double(s1 - s0 + 1);
    }
    if (total <= cap || slabs_ == 1) break;
    slabs_ = std::min(slabs_ - 1, static_cast<std::size_t>(double(slabs_) * 0.75));
    slabs_ = std::max<std::size_t>(1, slabs_);
  }
  for (std::size_t s = 0; s < slabs_; ++s) offsets_[s + 1] += offsets_[s];
  entries_.assign(offsets_[slabs_], 0);
  std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    const std::size_t s0 = slab_of(std::min(e.a.y, e.b.y)), s1 = slab_of(std::max(e.a.y, e.b.y));
    for (std::size_t s = s0; s <= s1; ++s) entries_[fill[s]++] = static_cast<std::uint32_t>(i);
  }
  for (std::size_t s = 0; s < slabs_; ++s)
    std::sort(entries_.begin() + offsets_[s], entries_.begin() + offsets_[s + 1],
              [&](std::uint32_t x, std::uint32_t y) { return edges_[x].xmax > edges_[y].xmax; });
  status_ = Status::ok;
}

template void PolygonLocator2<float>::build(std::span<const std::span<const Vec2<float>>>);
template void PolygonLocator2<double>::build(std::span<const std::span<const Vec2<double>>>);

}  // namespace locus
