// SPDX-License-Identifier: BSL-1.0
// Hilbert curve and BRIO insertion order (see include/locus/core/detail/spatial_sort.hpp).

#include <locus/core/detail/spatial_sort.hpp>

#include <algorithm>
#include <array>
#include <bit>

namespace locus::detail {
namespace {

// One level of the 2D Hilbert curve: the frame of each sub-square is the parent's composed with
// "flip both axes if rx" and "swap", and flips commute with the swap, so the accumulated frame
// is two bits (flip, swap). Returns the quadrant's 2-bit position and updates the frame.
constexpr std::uint32_t hilbert_level(std::uint32_t xbit, std::uint32_t ybit, std::uint32_t& flip,
                                      std::uint32_t& swap) noexcept {
  std::uint32_t rx = xbit ^ flip;
  std::uint32_t ry = ybit ^ flip;
  const std::uint32_t t = (rx ^ ry) & swap;
  rx ^= t;
  ry ^= t;
  const std::uint32_t turn = ry ^ 1u;
  flip ^= rx & turn;
  swap ^= turn;
  return (3u * rx) ^ ry;
}

// Two levels at a time: entry [frame << 4 | x2 << 2 | y2] holds the 4 digit bits and the new
// frame (bits 4-5), frame = flip << 1 | swap.
constexpr std::array<std::uint8_t, 64> hilbert_table2 = [] {
  std::array<std::uint8_t, 64> table{};
  for (std::uint32_t k = 0; k < 64; ++k) {
    std::uint32_t flip = (k >> 5) & 1u, swap = (k >> 4) & 1u;
    const std::uint32_t x2 = (k >> 2) & 3u, y2 = k & 3u;
    std::uint32_t d = hilbert_level(x2 >> 1, y2 >> 1, flip, swap);
    d = (d << 2) | hilbert_level(x2 & 1u, y2 & 1u, flip, swap);
    table[k] = static_cast<std::uint8_t>(d | (flip << 5) | (swap << 4));
  }
  return table;
}();

// Maps v in [lo, hi] to 0 .. 65535 without overflow for any finite lo <= v <= hi.
template <Real T>
[[nodiscard]] std::uint32_t quantize16(T v, T lo, T hi) noexcept {
  const double half_span = 0.5 * double(hi) - 0.5 * double(lo);
  if (!(half_span > 0.0)) return 0;
  const double u = (0.5 * double(v) - 0.5 * double(lo)) / half_span;  // in [0, 1]
  const double q = u * 65535.0;
  if (!(q > 0.0)) return 0;
  if (q >= 65535.0) return 65535;
  return static_cast<std::uint32_t>(q);
}

// Sorts keys[0, n) ((key << 32 | index) values, key < 2^bits) ascending: LSD radix passes of at
// most 12 bits on the key (stable, so ties stay in index order; 4096 buckets keep every pass's
// write streams in cache), or std::sort for short ranges.
void radix_sort_keys(std::uint64_t* keys, std::size_t n, unsigned bits,
                     std::vector<std::uint64_t>& tmp_buf) {
  if (n < (1u << 14)) {
    std::sort(keys, keys + n);
    return;
  }
  const unsigned passes = std::max(1u, (bits + 11) / 12);
  const unsigned digit = (bits + passes - 1) / passes;
  const std::uint64_t mask = (std::uint64_t{1} << digit) - 1;
  tmp_buf.resize(n);
  std::array<std::uint32_t, 4096> count;
  const std::size_t buckets = std::size_t{1} << digit;
  std::uint64_t* src = keys;
  std::uint64_t* dst = tmp_buf.data();
  for (unsigned pass = 0; pass < passes; ++pass) {
    const unsigned shift = 32 + digit * pass;
    std::fill(count.begin(), count.begin() + static_cast<std::ptrdiff_t>(buckets), 0u);
    for (std::size_t i = 0; i < n; ++i) ++count[(src[i] >> shift) & mask];
    std::uint32_t sum = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
      const std::uint32_t c0 = count[b];
      count[b] = sum;
      sum += c0;
    }
    for (std::size_t i = 0; i < n; ++i) dst[count[(src[i] >> shift) & mask]++] = src[i];
    std::swap(src, dst);
  }
  if (src != keys) std::copy(src, src + n, keys);
}

// A fixed pseudo-random 64-bit value per index (splitmix64's output function).
[[nodiscard]] inline std::uint64_t index_hash(std::uint64_t i) noexcept {
  std::uint64_t z = (i + 1) * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

constexpr unsigned kMaxRounds = 21;

// On entry keys[i] = (Hilbert key << 32 | i); on exit `order` is the insertion order: the
// points grouped by round (a stable counting partition, so memory is touched in order, unlike a
// shuffle), each round radix-sorted by key.
void rounds_then_order(std::vector<std::uint64_t>& keys, unsigned key_bits,
                       std::vector<std::uint64_t>& tmp, std::vector<std::uint32_t>& order) {
  const std::size_t n = keys.size();
  const unsigned rounds = brio_rounds(n);
  std::size_t start[kMaxRounds + 1] = {};
  for (std::size_t i = 0; i < n; ++i) ++start[brio_round(i, rounds) + 1];
  for (unsigned r = 0; r < rounds; ++r) start[r + 1] += start[r];
  std::size_t cursor[kMaxRounds];
  std::copy(start, start + rounds, cursor);
  tmp.resize(n);
  for (std::size_t i = 0; i < n; ++i) tmp[cursor[brio_round(i, rounds)]++] = keys[i];
  keys.swap(tmp);
  for (unsigned r = 0; r < rounds; ++r)
    radix_sort_keys(keys.data() + start[r], start[r + 1] - start[r], key_bits, tmp);
  order.resize(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(keys[k]);
}

template <class T, int N>
void bounding_box(std::span<const Vec<T, N>> points, Vec<T, N>& lo, Vec<T, N>& hi) noexcept {
  lo = points[0];
  hi = lo;
  for (const auto& q : points)
    for (int i = 0; i < N; ++i) {
      lo[i] = std::min(lo[i], q[i]);
      hi[i] = std::max(hi[i], q[i]);
    }
}

}  // namespace

std::uint32_t hilbert_index2(std::uint32_t x, std::uint32_t y, int levels) noexcept {
  std::uint32_t d = 0, flip = 0, swap = 0;
  int l = levels;
  if (l % 2 != 0) {
    --l;
    d = hilbert_level((x >> l) & 1u, (y >> l) & 1u, flip, swap);
  }
  std::uint32_t frame = flip << 1 | swap;
  while (l > 0) {
    l -= 2;
    const std::uint32_t e = hilbert_table2[frame << 4 | ((x >> l) & 3u) << 2 | ((y >> l) & 3u)];
    d = (d << 4) | (e & 15u);
    frame = e >> 4;
  }
  return d;
}

std::uint32_t hilbert_index3(std::uint32_t x0, std::uint32_t x1, std::uint32_t x2,
                             int levels) noexcept {
  // Skilling: the coordinates are transformed in place into the "transposed" index, whose bits
  // interleaved most significant first are the curve position.
  std::uint32_t x[3] = {x0, x1, x2};
  const std::uint32_t top = 1u << (levels - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (x[i] & q) {
        x[0] ^= p;
      } else {
        const std::uint32_t t = (x[0] ^ x[i]) & p;
        x[0] ^= t;
        x[i] ^= t;
      }
    }
  }
  x[1] ^= x[0];
  x[2] ^= x[1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[2] & q) t ^= q - 1;
  for (auto& xi : x) xi ^= t;
  std::uint32_t d = 0;
  for (int b = levels - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) d = (d << 1) | ((x[i] >> b) & 1u);
  return d;
}

unsigned brio_rounds(std::size_t n) noexcept {
  unsigned rounds = 1;
  while (rounds < kMaxRounds && (n >> (3 * rounds)) > 256) ++rounds;
  return rounds;
}

unsigned brio_round(std::size_t i, unsigned rounds) noexcept {
  const unsigned j = static_cast<unsigned>(std::countl_zero(index_hash(i))) / 3;
  return rounds - 1 - std::min(j, rounds - 1);
}

template <Real T>
void brio_order(std::span<const Vec2<T>> points, std::vector<std::uint32_t>& order,
                std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp) {
  const std::size_t n = points.size();
  keys.resize(n);
  if (n == 0) {
    order.clear();
    return;
  }
  Vec2<T> lo, hi;
  bounding_box<T, 2>(points, lo, hi);
  // About 16 cells per point: finer levels cost time without improving locality.
  int levels = 4;
  while (levels < 16 && (std::size_t(1) << (2 * levels)) < 16 * n) ++levels;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t h =
        hilbert_index2(quantize16(points[i].x, lo.x, hi.x) >> (16 - levels),
                       quantize16(points[i].y, lo.y, hi.y) >> (16 - levels), levels);
    keys[i] = (std::uint64_t(h) << 32) | std::uint64_t(i);
  }
  rounds_then_order(keys, static_cast<unsigned>(2 * levels), tmp, order);
}

template <Real T>
void brio_order(std::span<const Vec3<T>> points, std::vector<std::uint32_t>& order,
                std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp) {
  const std::size_t n = points.size();
  keys.resize(n);
  if (n == 0) {
    order.clear();
    return;
  }
  Vec3<T> lo, hi;
  bounding_box<T, 3>(points, lo, hi);
  // About 8 cells per point.
  int levels = 2;
  while (levels < 10 && (std::size_t(1) << (3 * levels)) < 8 * n) ++levels;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<T>& q = points[i];
    const std::uint32_t h = hilbert_index3(quantize16(q.x, lo.x, hi.x) >> (16 - levels),
                                           quantize16(q.y, lo.y, hi.y) >> (16 - levels),
                                           quantize16(q.z, lo.z, hi.z) >> (16 - levels), levels);
    keys[i] = (std::uint64_t(h) << 32) | std::uint64_t(i);
  }
  rounds_then_order(keys, static_cast<unsigned>(3 * levels), tmp, order);
}

template void brio_order<float>(std::span<const Vec2<float>>, std::vector<std::uint32_t>&,
                                std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);
template void brio_order<double>(std::span<const Vec2<double>>, std::vector<std::uint32_t>&,
                                 std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);
template void brio_order<float>(std::span<const Vec3<float>>, std::vector<std::uint32_t>&,
                                std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);
template void brio_order<double>(std::span<const Vec3<double>>, std::vector<std::uint32_t>&,
                                 std::vector<std::uint64_t>&, std::vector<std::uint64_t>&);

}  // namespace locus::detail
