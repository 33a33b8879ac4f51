// SPDX-License-Identifier: BSL-1.0
// 3D Delaunay tetrahedralization (see include/locus/delaunay/delaunay3.hpp for the contract).
//
// Internal representation: a closed triangulated 3-sphere. Real cells are positively oriented;
// every hull face is matched by a ghost cell (a, b, c, kGhost) with the ghost vertex always at
// corner 3 and face 3 = (a, b, c) oriented with the outside on its positive side, so "is ghost"
// is one load and the adjacency has no boundary: the cavity code has no hull special case.
// neighbors[i] holds 4 * cell + face (the face index of this face in the neighbouring cell).

#include <locus/delaunay/delaunay3.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace locus {

namespace {

constexpr std::uint32_t kGhost = 0xFFFFFFFFu;
constexpr std::uint32_t kDead = 0xFFFFFFFEu;  // vertices[3] of a free slot
constexpr std::uint32_t kNone = 0xFFFFFFFFu;
constexpr std::size_t kMaxPoints = std::size_t(1) << 26;  // 4 * cells + 3 fits in int32

constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

#if defined(__GNUC__) || defined(__clang__)
#define LOCUS_D3_INLINE [[gnu::always_inline]] inline
#define LOCUS_D3_NOINLINE [[gnu::noinline]]
#else
#define LOCUS_D3_INLINE inline
#define LOCUS_D3_NOINLINE
#endif

template <class T>
[[nodiscard]] bool same_point(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

// a, b, c on one line (exactly): every coordinate projection is degenerate.
template <class T>
[[nodiscard]] bool collinear(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) noexcept {
  return orient2d(Vec2<T>{a.x, a.y}, Vec2<T>{b.x, b.y}, Vec2<T>{c.x, c.y}) == Sign::zero &&
         orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{c.y, c.z}) == Sign::zero &&
         orient2d(Vec2<T>{a.x, a.z}, Vec2<T>{b.x, b.z}, Vec2<T>{c.x, c.z}) == Sign::zero;
}

// The synthetic apex of a coplanar input (see the header): `a` with its coordinate along the
// first axis not parallel to the plane of a, b, c (non-collinear) changed, so it is off the
// plane exactly. The faces opposite the apex are oriented toward it; `flip` says to reverse
// them so that their normals have a positive component along that axis.
template <class T>
struct PlanarApex {
  Vec3<T> point;
  bool flip;
};

template <class T>
[[nodiscard]] PlanarApex<T> planar_apex(const Vec3<T>& a, const Vec3<T>& b,
                                        const Vec3<T>& c) noexcept {
  int axis = 2;  // the normal's x component is the orientation of the (y, z) projection, ...
  if (orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{c.y, c.z}) != Sign::zero)
    axis = 0;
  else if (orient2d(Vec2<T>{a.z, a.x}, Vec2<T>{b.z, b.x}, Vec2<T>{c.z, c.x}) != Sign::zero)
    axis = 1;
  PlanarApex<T> r{a, false};
  r.point[axis] = a[axis] != T(0) ? a[axis] / T(2) : T(1);
  r.flip = r.point[axis] < a[axis];
  return r;
}

// Position along the 3D Hilbert curve of the cell x[0..2] < 2^bits (Skilling, "Programming the
// Hilbert curve", 2004: the coordinates are transformed in place into the "transposed" index,
// whose bits interleaved most significant first are the curve position).
[[nodiscard]] std::uint32_t hilbert_index3(std::uint32_t x0, std::uint32_t x1, std::uint32_t x2,
                                           int bits) noexcept {
  std::uint32_t x[3] = {x0, x1, x2};
  const std::uint32_t top = 1u << (bits - 1);
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
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) d = (d << 1) | ((x[i] >> b) & 1u);
  return d;
}

// Maps v in [lo, hi] to 0 .. 1023 without overflow for any finite lo <= v <= hi.
template <class T>
[[nodiscard]] std::uint32_t quantize10(T v, T lo, T hi) noexcept {
  const double half_span = 0.5 * double(hi) - 0.5 * double(lo);
  if (!(half_span > 0.0)) return 0;
  const double q = (0.5 * double(v) - 0.5 * double(lo)) / half_span * 1023.0;
  if (!(q > 0.0)) return 0;
  if (q >= 1023.0) return 1023;
  return static_cast<std::uint32_t>(q);
}

// Sorts (key << 32 | index) values ascending: two 16-bit LSD radix passes on the key (stable),
// or std::sort for short ranges.
void radix_sort_keys(std::uint64_t* keys, std::size_t n, std::vector<std::uint64_t>& tmp_buf) {
  if (n < (1u << 14)) {
    std::sort(keys, keys + n);
    return;
  }
  tmp_buf.resize(n);
  std::uint64_t* src = keys;
  std::uint64_t* dst = tmp_buf.data();
  std::vector<std::uint32_t> count(1u << 16);
  for (int pass = 0; pass < 2; ++pass) {
    const int shift = 32 + 16 * pass;
    std::fill(count.begin(), count.end(), 0u);
    for (std::size_t i = 0; i < n; ++i) ++count[(src[i] >> shift) & 0xFFFFu];
    std::uint32_t sum = 0;
    for (auto& c : count) {
      const std::uint32_t c0 = c;
      c = sum;
      sum += c0;
    }
    for (std::size_t i = 0; i < n; ++i) dst[count[(src[i] >> shift) & 0xFFFFu]++] = src[i];
    std::swap(src, dst);
  }
}

// Keys (Hilbert position << 32 | base + i) of points[i] on a grid over their bounding box with
// about 8 cells per point.
template <class T>
void hilbert_keys(std::span<const Vec3<T>> points, std::uint32_t base,
                  std::vector<std::uint64_t>& keys) {
  const std::size_t n = points.size();
  keys.resize(n);
  if (n == 0) return;
  Vec3<T> lo = points[0], hi = lo;
  for (const auto& q : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], q[i]);
      hi[i] = std::max(hi[i], q[i]);
    }
  int bits = 2;
  while (bits < 10 && (std::size_t(1) << (3 * bits)) < 8 * n) ++bits;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<T>& q = points[i];
    const std::uint32_t h = hilbert_index3(quantize10(q.x, lo.x, hi.x) >> (10 - bits),
                                           quantize10(q.y, lo.y, hi.y) >> (10 - bits),
                                           quantize10(q.z, lo.z, hi.z) >> (10 - bits), bits);
    keys[i] = (std::uint64_t(h) << 32) | std::uint64_t(base + i);
  }
}

// Biased randomized insertion order (Amenta, Choi, Rote 2003): a fixed-seed shuffle, then the
// last 7/8 of every prefix sorted along the curve and the first 1/8 recursively.
void brio_order(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& tmp) {
  const std::size_t n = keys.size();
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (std::size_t i = n; i > 1; --i) {
    state += 0x9E3779B97F4A7C15ull;  // splitmix64
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    std::swap(keys[i - 1], keys[static_cast<std::size_t>(z % i)]);
  }
  std::size_t end = n;
  while (end > 256) {
    const std::size_t mid = end / 8;
    radix_sort_keys(keys.data() + mid, end - mid, tmp);
    end = mid;
  }
  radix_sort_keys(keys.data(), end, tmp);
}

// True when x - y is computed exactly (Knuth's two-difference has a zero tail).
[[nodiscard]] inline bool exact_difference(double x, double y, double diff) noexcept {
  const double bvirt = x - diff;
  const double avirt = diff + bvirt;
  return (x - avirt) + (bvirt - y) == 0.0;
}

// u is an integer, for |u| < 2^52 (adding 2^52 rounds to an integer; no libm call).
[[nodiscard]] inline bool is_small_integer(double u) noexcept {
  const double a = std::abs(u);
  return (a + 0x1p52) - 0x1p52 == a;
}

// The exponent ex with 2^(ex-1) <= m < 2^ex (frexp's) for a normal m > 0, without a libm call;
// 0 for subnormal m, which the callers' range checks reject.
[[nodiscard]] inline int binary_exponent(double m) noexcept {
  const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(m) >> 52) & 0x7FFu);
  return biased == 0 ? 0 : biased - 1022;
}

// 2^k for -1022 <= k <= 1023.
[[nodiscard]] inline double power_of_two(int k) noexcept {
  return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

// orient3d for the zero-heavy perturbation: when the nine differences to d are exact integer
// multiples of a power of two q with |difference| < 2^16 q, the double determinant (products
// below 2^32 q^2, the sum below 2^51 q^3) is exact; otherwise the exact predicate decides.
template <class T>
[[nodiscard]] Sign orient3d_lattice(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc,
                                    const Vec3<T>& pd) noexcept {
  const Vec3<double> a = detail::to_double(pa), b = detail::to_double(pb),
                     c = detail::to_double(pc), d = detail::to_double(pd);
  const Vec3<double>* p[3] = {&a, &b, &c};
  double dv[3][3];
  double m = 0.0;
  bool exact = true;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      dv[i][k] = (*p[i])[k] - d[k];
      exact = exact && exact_difference((*p[i])[k], d[k], dv[i][k]);
      m = std::max(m, std::abs(dv[i][k]));
    }
  if (exact && m > 0.0 && std::isfinite(m)) {
    const int ex = binary_exponent(m);
    bool on_lattice = ex > -300 && ex < 300;
    const double inv_q = on_lattice ? power_of_two(16 - ex) : 0.0;
    for (int i = 0; i < 3 && on_lattice; ++i)
      for (int k = 0; k < 3 && on_lattice; ++k) on_lattice = is_small_integer(dv[i][k] * inv_q);
    if (on_lattice) {
      const double* u = dv[0];
      const double* v = dv[1];
      const double* w = dv[2];
      // det[a - d; b - d; c - d] is Shewchuk's orient3d, the negation of ours.
      const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                         u[2] * (v[0] * w[1] - v[1] * w[0]);
      return -sign_of(det);
    }
  }
  return orient3d(pa, pb, pc, pd);
}

// The zero case of insphere_perturbed: point q's lift |q|^2 is raised by eps_q, larger for
// lexicographically larger q. The perturbed determinant is insphere + sum eps_q * C_q with
// C_e = -orient3d(a, b, c, d) (raising e moves it outside) and, by antisymmetry, C_q for a
// vertex q = orient3d of (a, b, c, d) with q replaced by e. The largest eps with a nonzero
// cofactor decides.
// order[] = 0 .. 4 sorted so that p[order[0]] is the lexicographically largest (insertion
// sort: five points).
template <class T>
void lexicographic_descending(const Vec3<T>* const p[5], int order[5]) noexcept {
  for (int i = 0; i < 5; ++i) order[i] = i;
  for (int i = 1; i < 5; ++i) {
    const int k = order[i];
    int j = i;
    while (j > 0 && lexicographic_compare(*p[order[j - 1]], *p[k]) == Sign::negative) {
      order[j] = order[j - 1];
      --j;
    }
    order[j] = k;
  }
}

template <class T>
LOCUS_D3_NOINLINE Sign perturbed_zero_case(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                           const Vec3<T>& d, const Vec3<T>& e) noexcept {
  const Vec3<T>* const p[5] = {&a, &b, &c, &d, &e};
  int order[5];
  lexicographic_descending(p, order);
  for (const int k : order) {
    Sign s;
    if (k == 4) {
      s = -orient3d_lattice(a, b, c, d);
    } else {
      const Vec3<T>* q[4] = {&a, &b, &c, &d};
      q[k] = &e;
      s = orient3d_lattice(*q[0], *q[1], *q[2], *q[3]);
    }
    if (s != Sign::zero) return s;
  }
  return Sign::zero;  // only when a, b, c, d are coplanar and e lies on their plane
}

// p > q lexicographically (x, then y, then z).
[[nodiscard]] inline bool lexicographically_greater(const Vec3<double>& p,
                                                    const Vec3<double>& q) noexcept {
  if (p.x != q.x) return p.x > q.x;
  if (p.y != q.y) return p.y > q.y;
  return p.z > q.z;
}

// The perturbed sign of an exactly cospherical a, b, c, d, e from the exact minors of the
// differences p - e (see insphere_perturbed_slow): the lexicographically largest point with a
// nonzero cofactor decides.
LOCUS_D3_NOINLINE Sign perturbed_from_minors(const Vec3<double>& a, const Vec3<double>& b,
                                             const Vec3<double>& c, const Vec3<double>& d,
                                             const Vec3<double>& e,
                                             const double minor[4]) noexcept {
  const double cofactor[5] = {minor[0], -minor[1], minor[2], -minor[3],
                              -((minor[0] - minor[1]) + (minor[2] - minor[3]))};
  const Vec3<double>* const pts[5] = {&a, &b, &c, &d, &e};
  int top = -1;
  for (int k = 0; k < 5; ++k)
    if (cofactor[k] != 0.0 && (top < 0 || lexicographically_greater(*pts[k], *pts[top]))) top = k;
  return top < 0 ? Sign::zero  // a, b, c, d coplanar and e on their plane
                 : detail::nonzero_sign(cofactor[top]);
}

// The insphere filter fails on every exactly cospherical quintuple (grids!) and the adaptive
// predicate costs 1.5-3 us there. When the twelve differences p - e are exact and are integer
// multiples of a power of two q with |difference| < 2^9 q, every product and sum of the double
// evaluation below is an integer multiple of q^k (k its degree) below 2^53 q^k (the largest,
// the final sum, is below 4 * 3 * 2^18 * 3 * 2^28 < 2^52), so the double determinant is exact
// and so is its sign. An exact zero is then perturbed with the same minors: with e at the
// origin, the cofactors of perturbed_zero_case are orient3d(e, b, c, d) = minor[0],
// orient3d(a, e, c, d) = -minor[1], orient3d(a, b, e, d) = minor[2], orient3d(a, b, c, e) =
// -minor[3] and orient3d(a, b, c, d) = minor[0] - minor[1] + minor[2] - minor[3] (row
// operations), all exact in double (below 4 * 6 * 2^27 q^3). Off the lattice: the exact
// predicate, then perturbed_zero_case.
LOCUS_D3_NOINLINE Sign insphere_perturbed_slow(const Vec3<double>& a, const Vec3<double>& b,
                                               const Vec3<double>& c, const Vec3<double>& d,
                                               const Vec3<double>& e) noexcept {
  const Vec3<double>* p[4] = {&a, &b, &c, &d};
  double dv[4][3];
  double m = 0.0;
  bool exact = true;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) {
      dv[i][k] = (*p[i])[k] - e[k];
      exact = exact && exact_difference((*p[i])[k], e[k], dv[i][k]);
      m = std::max(m, std::abs(dv[i][k]));
    }
  if (exact && m > 0.0 && std::isfinite(m)) {
    const int ex = binary_exponent(m);  // m < 2^ex
    // q^5 must not underflow (5 (ex - 9) >= -1074) nor 2^53 q^5 overflow.
    bool on_lattice = ex > -200 && ex < 190;
    const double inv_q = on_lattice ? power_of_two(9 - ex) : 0.0;  // 1 / q, q = 2^(ex - 9)
    for (int i = 0; i < 4 && on_lattice; ++i)
      for (int k = 0; k < 3 && on_lattice; ++k) on_lattice = is_small_integer(dv[i][k] * inv_q);
    if (on_lattice) {
      double lift[4], minor[4];
      for (int i = 0; i < 4; ++i)
        lift[i] = dv[i][0] * dv[i][0] + dv[i][1] * dv[i][1] + dv[i][2] * dv[i][2];
      // minor[i] = det of the 3x3 (x, y, z) rows other than i, in increasing row order.
      for (int i = 0; i < 4; ++i) {
        int r[3], k = 0;
        for (int j = 0; j < 4; ++j)
          if (j != i) r[k++] = j;
        const double* u = dv[r[0]];
        const double* v = dv[r[1]];
        const double* w = dv[r[2]];
        minor[i] = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                   u[2] * (v[0] * w[1] - v[1] * w[0]);
      }
      // det[p - e, lift] expanded along the lift column: sum (-1)^(i+3) lift_i minor_i; our
      // insphere is its negation.
      const double det =
          (lift[1] * minor[1] + lift[3] * minor[3]) - (lift[0] * minor[0] + lift[2] * minor[2]);
      if (det != 0.0) return -detail::nonzero_sign(det);
      return perturbed_from_minors(a, b, c, d, e, minor);
    }
  }
  const Sign s = insphere(a, b, c, d, e);
  if (s != Sign::zero) return s;
  return perturbed_zero_case(a, b, c, d, e);
}

// The insphere determinant of core/predicates.hpp (Shewchuk's sign), evaluated in the same order
// (so the same bits), with the pieces the callers below reuse: the differences to e per axis, the
// 3x3 minors {bcd, cda, dab, abc} and the lifts |x - e|^2.
struct InsphereDet {
  double x[4], y[4], z[4];  // a - e, b - e, c - e, d - e per axis
  double minor[4];          // bcd, cda, dab, abc
  double lift[4];           // alift, blift, clift, dlift
  double det;
};
LOCUS_D3_INLINE InsphereDet insphere_det(const Vec3<double>& a, const Vec3<double>& b,
                                         const Vec3<double>& c, const Vec3<double>& d,
                                         const Vec3<double>& e) noexcept {
  const double aex = a.x - e.x, bex = b.x - e.x, cex = c.x - e.x, dex = d.x - e.x;
  const double aey = a.y - e.y, bey = b.y - e.y, cey = c.y - e.y, dey = d.y - e.y;
  const double aez = a.z - e.z, bez = b.z - e.z, cez = c.z - e.z, dez = d.z - e.z;
  const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  return {{aex, bex, cex, dex}, {aey, bey, cey, dey},         {aez, bez, cez, dez},
          {bcd, cda, dab, abc}, {alift, blift, clift, dlift}, det};
}

// Stage-A bound of core/predicates.hpp with a cheaper permanent. That bound is
// insphere_bound_a * P, P the permanent evaluated in floating point. With mx, my, mz the
// largest |differences| per axis, every 2x2 permanent term is at most 2 mx my, every 3x3 one at
// most 6 mx my mz, so P <= 6 mx my mz (alift + blift + clift + dlift) up to the few roundings
// of the two evaluation orders (under 16 units of 2^-53 relative), which the factor
// 1 + 2^-40 covers. The determinant is evaluated exactly as in core/predicates.hpp.
constexpr double kInsphereSemiStatic = detail::insphere_bound_a * (1.0 + 0x1p-40);

template <class T>
LOCUS_D3_INLINE Sign insphere_fast(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc,
                                   const Vec3<T>& pd, const Vec3<T>& pe) noexcept {
  const Vec3<double> a = detail::to_double(pa), b = detail::to_double(pb),
                     c = detail::to_double(pc), d = detail::to_double(pd),
                     e = detail::to_double(pe);
  const InsphereDet q = insphere_det(a, b, c, d, e);
  const auto max4 = [](const double* v) {
    return std::max(std::max(std::abs(v[0]), std::abs(v[1])),
                    std::max(std::abs(v[2]), std::abs(v[3])));
  };
  const double k = 6.0 * ((max4(q.x) * max4(q.y)) * max4(q.z));
  const double bound =
      kInsphereSemiStatic * (k * ((q.lift[0] + q.lift[1]) + (q.lift[2] + q.lift[3])));
  // Shewchuk's sign convention: ours is the negation.
  if (std::abs(q.det) > bound) [[likely]]
    return -detail::nonzero_sign(q.det);
  return insphere_perturbed_slow(a, b, c, d, e);
}

// The perturbed insphere (float input is promoted exactly; the perturbation only compares and
// takes orientations, so deciding it on the doubles is the same).
template <class T>
LOCUS_D3_INLINE Sign insphere_perturbed_inline(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                               const Vec3<T>& d, const Vec3<T>& e) noexcept {
  return insphere_fast(a, b, c, d, e);
}

// Input on a small lattice: every coordinate an integer multiple of one power of two q and
// every coordinate difference below 2^9 q (integer grids, voxels). Then the double evaluation of
// insphere_fast is exact (every product and sum an integer multiple of q^k below 2^53 q^k, as in
// insphere_perturbed_slow, whose minors are abc, bcd, cda, dab here), so no filter is needed,
// and an exact zero is perturbed from the same minors.
template <class T>
LOCUS_D3_INLINE Sign insphere_perturbed_lattice(const Vec3<T>& pa, const Vec3<T>& pb,
                                                const Vec3<T>& pc, const Vec3<T>& pd,
                                                const Vec3<T>& pe) noexcept {
  const Vec3<double> a = detail::to_double(pa), b = detail::to_double(pb),
                     c = detail::to_double(pc), d = detail::to_double(pd),
                     e = detail::to_double(pe);
  const InsphereDet q = insphere_det(a, b, c, d, e);
  if (q.det != 0.0) [[likely]]
    return -detail::nonzero_sign(q.det);
  return perturbed_from_minors(a, b, c, d, e, q.minor);
}

// orient3d on a small lattice: the double determinant is exact (products below 6 * 2^27 q^3).
template <class T>
LOCUS_D3_INLINE Sign orient3d_on_lattice(const Vec3<T>& pa, const Vec3<T>& pb, const Vec3<T>& pc,
                                         const Vec3<T>& pd) noexcept {
  const double ux = double(pb.x) - double(pa.x), uy = double(pb.y) - double(pa.y),
               uz = double(pb.z) - double(pa.z);
  const double vx = double(pc.x) - double(pa.x), vy = double(pc.y) - double(pa.y),
               vz = double(pc.z) - double(pa.z);
  const double wx = double(pd.x) - double(pa.x), wy = double(pd.y) - double(pa.y),
               wz = double(pd.z) - double(pa.z);
  return sign_of(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx));
}

// True when `points` lie on a small lattice (above): q = 2^(ex - 9) from the largest extent,
// every coordinate k q with |k| < 2^52 and every extent below 2^9 q, checked on the integers k.
template <class T>
[[nodiscard]] bool on_small_lattice(std::span<const Vec3<T>> points) noexcept {
  if (points.empty()) return false;
  Vec3<double> lo = detail::to_double(points[0]), hi = lo;
  for (const auto& p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], double(p[i]));
      hi[i] = std::max(hi[i], double(p[i]));
    }
  const double m = std::max(std::max(hi.x - lo.x, hi.y - lo.y), hi.z - lo.z);
  if (!(m > 0.0) || !std::isfinite(m)) return false;
  const int ex = binary_exponent(m);
  if (!(ex > -200 && ex < 190)) return false;
  const double inv_q = power_of_two(9 - ex);
  for (int i = 0; i < 3; ++i) {
    const double klo = lo[i] * inv_q, khi = hi[i] * inv_q;
    if (!is_small_integer(klo) || !is_small_integer(khi) || !(khi - klo < 512.0)) return false;
  }
  const double q = power_of_two(ex - 9);
  for (const auto& p : points)
    for (int i = 0; i < 3; ++i) {
      const double k = double(p[i]) * inv_q;
      if (!is_small_integer(k) || k * q != double(p[i])) return false;  // (no underflow)
    }
  return true;
}

}  // namespace

template <Real T>
Sign insphere_perturbed(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Vec3<T>& d,
                        const Vec3<T>& e) noexcept {
  return insphere_perturbed_inline(a, b, c, d, e);
}

// ---- Delaunay3 ----------------------------------------------------------------------------

template <Real T>
const Delaunay3Result& Delaunay3<T>::compute(std::span<const Vec3<T>> points) {
  points_.assign(points.begin(), points.end());
  run();
  compact(false);
  return result_;
}

template <Real T>
const Delaunay3Result& Delaunay3<T>::compute(const T* xyz, std::size_t n) {
  points_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    points_[i] = Vec3<T>{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  run();
  compact(false);
  return result_;
}

template <Real T>
Delaunay3Result Delaunay3<T>::take_result() {
  if (dirty_) compact(false);
  Delaunay3Result r = std::move(result_);
  result_ = Delaunay3Result{};
  points_.clear();
  sorted_.clear();
  orig_.clear();
  cells_.clear();
  mark_.clear();
  free_.clear();
  dimension_ = -1;
  status_ = Status::empty_input;
  dirty_ = false;
  last_out_ = 0;
  return r;
}

template <Real T>
const Delaunay3Result& Delaunay3<T>::result() {
  if (dirty_) compact(false);
  return result_;
}

template <Real T>
Status Delaunay3<T>::insert(const Vec3<T>& p) {
  return insert(std::span<const Vec3<T>>(&p, 1));
}

template <Real T>
Status Delaunay3<T>::insert(std::span<const Vec3<T>> points) {
  for (const auto& q : points)
    if (!is_finite(q.x) || !is_finite(q.y) || !is_finite(q.z)) return Status::non_finite_input;
  const std::size_t n0 = points_.size();
  if (n0 + points.size() > kMaxPoints) return Status::invalid_input;
  if (points.empty()) return status_;
  points_.insert(points_.end(), points.begin(), points.end());
  if (dimension_ != 3 || status_ != Status::ok) {
    // Lower-dimensional (or empty, or failed) so far: the new points may raise the dimension.
    run();
    compact(false);
    return status_;
  }
  lattice_ = false;  // (the general predicates are exact too; re-checking would cost O(n))
  result_.duplicate_of.resize(points_.size());
  std::iota(result_.duplicate_of.begin() + std::ptrdiff_t(n0), result_.duplicate_of.end(),
            static_cast<std::uint32_t>(n0));
  hilbert_keys(points, static_cast<std::uint32_t>(n0), keys_);
  brio_order(keys_, keys_tmp_);
  for (const std::uint64_t key : keys_) {
    const std::uint32_t i = static_cast<std::uint32_t>(key);
    const std::uint32_t v = static_cast<std::uint32_t>(sorted_.size());
    sorted_.push_back(points_[i]);
    orig_.push_back(i);
    if (!insert_vertex(v)) {
      status_ = Status::limit_exceeded;
      break;
    }
  }
  keys_.clear();
  dirty_ = true;
  return status_;
}

template <Real T>
Locate3Result Delaunay3<T>::locate(const Vec3<T>& p, std::size_t max_steps) {
  const Delaunay3Result& r = result();
  return ::locus::locate<T>(r, std::span<const Vec3<T>>(points_), p, last_out_, max_steps);
}

template <Real T>
NearestVertex3Result Delaunay3<T>::nearest_vertex(const Vec3<T>& p) {
  const Delaunay3Result& r = result();
  return ::locus::nearest_vertex<T>(r, std::span<const Vec3<T>>(points_), p, last_out_);
}

// Open addressing over (u, v, value, generation) slots; a slot is live only in the current
// generation, so starting a new use is one increment (no clearing). The hash of u + v is
// symmetric: an edge and its reverse share one probe sequence, so "find the reverse, else
// insert" is a single scan. Every key is matched at most once, and a matched slot is left in
// place (marked consumed) so the chains through it stay intact.
template <Real T>
void Delaunay3<T>::edges_begin(std::size_t entries) {
  std::size_t cap = 256;
  while (cap < 4 * entries) cap *= 2;
  if (edge_table_.size() < cap || ++edge_gen_ == 0) {
    edge_table_.assign(std::max(cap, edge_table_.size()), EdgeSlot{0, 0, 0, 0});
    edge_gen_ = 1;
  }
  edge_bits_ = std::countr_zero(cap);
}

template <Real T>
LOCUS_D3_INLINE std::uint32_t Delaunay3<T>::edge_match(std::uint32_t u, std::uint32_t v,
                                                       std::uint32_t code) noexcept {
  const std::uint32_t mask = (1u << edge_bits_) - 1u;
  std::uint32_t h = ((u + v) * 0x9E3779B1u) >> (32 - edge_bits_);
  EdgeSlot* table = edge_table_.data();
  for (;;) {
    EdgeSlot& e = table[h];
    if (e.gen != edge_gen_) {
      e = EdgeSlot{u, v, code, edge_gen_};
      return kNone;
    }
    if (e.u == v && e.v == u) {
      e.u = kDead;  // consumed
      return e.code;
    }
    h = (h + 1) & mask;
  }
}

template <Real T>
LOCUS_D3_INLINE void Delaunay3<T>::glue(std::uint32_t code, std::uint32_t other) noexcept {
  if (other == kNone) return;
  cells_[code >> 2].neighbors[code & 3u] = static_cast<std::int32_t>(other);
  cells_[other >> 2].neighbors[other & 3u] = static_cast<std::int32_t>(code);
}

// Links the faces through `apex` of the given cells: the face through apex and edge x -> y
// (in the face's orientation) meets the face of another cell with the edge y -> x.
template <Real T>
void Delaunay3<T>::link_around(std::span<const std::uint32_t> cells, std::uint32_t apex) {
  edges_begin(3 * cells.size());
  for (const std::uint32_t t : cells) {
    const auto& v = cells_[t].vertices;
    if (v[3] == apex) {
      // The common case (a, b, c, apex): faces 0, 1, 2 are (apex, c, b), (apex, a, c) and
      // (apex, b, a) once rotated to start at the apex (kFace).
      glue(4 * t + 0, edge_match(v[2], v[1], 4 * t + 0));
      glue(4 * t + 1, edge_match(v[0], v[2], 4 * t + 1));
      glue(4 * t + 2, edge_match(v[1], v[0], 4 * t + 2));
      continue;
    }
    for (int i = 0; i < 4; ++i) {
      if (v[std::size_t(i)] == apex) continue;
      const std::uint32_t f[3] = {v[std::size_t(kFace[i][0])], v[std::size_t(kFace[i][1])],
                                  v[std::size_t(kFace[i][2])]};
      const int at = f[0] == apex ? 0 : (f[1] == apex ? 1 : 2);
      const std::uint32_t code = 4 * t + std::uint32_t(i);
      glue(code, edge_match(f[(at + 1) % 3], f[(at + 2) % 3], code));
    }
  }
}

template <Real T>
LOCUS_D3_INLINE bool Delaunay3<T>::in_conflict(std::uint32_t t, std::uint32_t v) const noexcept {
  const Delaunay3Cell& c = cells_[t];
  const Vec3<T>* pts = sorted_.data();
  const Vec3<T>& p = pts[v];
  if (c.vertices[3] == kGhost) [[unlikely]] {
    const Vec3<T>&a = pts[c.vertices[0]], &b = pts[c.vertices[1]], &cc = pts[c.vertices[2]];
    const Sign s = lattice_ ? orient3d_on_lattice(a, b, cc, p) : orient3d(a, b, cc, p);
    if (s != Sign::zero) return s == Sign::positive;
    // On the hull plane: the ghost goes with the real cell under the face, so the face is
    // either inside the cavity or not on its boundary (never a flat new cell).
    const Delaunay3Cell& r = cells_[std::uint32_t(c.neighbors[3]) >> 2];
    const Vec3<T>&ra = pts[r.vertices[0]], &rb = pts[r.vertices[1]], &rc = pts[r.vertices[2]],
          &rd = pts[r.vertices[3]];
    return (lattice_ ? insphere_perturbed_lattice(ra, rb, rc, rd, p)
                     : insphere_perturbed_inline(ra, rb, rc, rd, p)) == Sign::positive;
  }
  const Vec3<T>&a = pts[c.vertices[0]], &b = pts[c.vertices[1]], &cc = pts[c.vertices[2]],
        &d = pts[c.vertices[3]];
  if (lattice_) return insphere_perturbed_lattice(a, b, cc, d, p) == Sign::positive;
  return insphere_perturbed_inline(a, b, cc, d, p) == Sign::positive;
}

template <Real T>
std::uint32_t Delaunay3<T>::scan(std::uint32_t v, std::uint32_t* duplicate) noexcept {
  const Vec3<T>* pts = sorted_.data();
  const Vec3<T>& p = pts[v];
  const std::uint32_t nc = static_cast<std::uint32_t>(cells_.size());
  for (std::uint32_t t = 0; t < nc; ++t) {
    const Delaunay3Cell& c = cells_[t];
    if (c.vertices[3] >= kDead) continue;
    bool inside = true;
    for (int i = 0; i < 4 && inside; ++i)
      inside = orient3d(pts[c.vertices[std::size_t(kFace[i][0])]],
                        pts[c.vertices[std::size_t(kFace[i][1])]],
                        pts[c.vertices[std::size_t(kFace[i][2])]], p) != Sign::negative;
    if (!inside) continue;
    for (int i = 0; i < 4; ++i)
      if (same_point(pts[c.vertices[std::size_t(i)]], p)) *duplicate = c.vertices[std::size_t(i)];
    return t;
  }
  for (std::uint32_t t = 0; t < nc; ++t)
    if (cells_[t].vertices[3] == kGhost && in_conflict(t, v)) return t;
  return kNone;
}

template <Real T>
std::uint32_t Delaunay3<T>::walk(std::uint32_t v, std::uint32_t t,
                                 std::uint32_t* duplicate) noexcept {
  // A visibility walk in a Delaunay tetrahedralization visits no cell twice (Edelsbrunner's
  // acyclicity of the in-front relation), so it ends within the cell count; the budget guards
  // a corrupted structure. The face order is varied per step (a remembering stochastic walk).
  const std::size_t budget = cells_.size() + 64;
  const Vec3<T>* pts = sorted_.data();
  const Vec3<T> p = pts[v];
  std::uint32_t came = kNone;
  std::uint32_t rng = walk_rng_;
  for (std::size_t step = 0; step < budget; ++step) {
    const Delaunay3Cell& c = cells_[t];
    if (c.vertices[3] == kGhost) {
      const Vec3<T>&a = pts[c.vertices[0]], &b = pts[c.vertices[1]], &cc = pts[c.vertices[2]];
      if ((lattice_ ? orient3d_on_lattice(a, b, cc, p) : orient3d(a, b, cc, p)) == Sign::positive) {
        walk_rng_ = rng;
        return t;
      }
      // p is on the real side of the hull face or on its plane: test every face from inside.
      came = kNone;
      t = std::uint32_t(c.neighbors[3]) >> 2;
      continue;
    }
    rng = rng * 1664525u + 1013904223u;
    const int start = static_cast<int>(rng >> 30);
    int zeros = 0;
    bool moved = false;
    for (int j = 0; j < 4; ++j) {
      const int i = (start + j) & 3;
      const std::uint32_t nb = std::uint32_t(c.neighbors[std::size_t(i)]) >> 2;
      if (nb == came) continue;
      const Vec3<T>& a = pts[c.vertices[std::size_t(kFace[i][0])]];
      const Vec3<T>& b = pts[c.vertices[std::size_t(kFace[i][1])]];
      const Vec3<T>& cc = pts[c.vertices[std::size_t(kFace[i][2])]];
      const Sign s = lattice_ ? orient3d_on_lattice(a, b, cc, p) : orient3d(a, b, cc, p);
      if (s == Sign::negative) {
        came = t;
        t = nb;
        moved = true;
        break;
      }
      if (s == Sign::zero) ++zeros;
    }
    if (moved) continue;
    if (zeros >= 3) {
      for (int i = 0; i < 4; ++i)
        if (same_point(pts[c.vertices[std::size_t(i)]], p)) *duplicate = c.vertices[std::size_t(i)];
    }
    walk_rng_ = rng;
    return t;
  }
  walk_rng_ = rng;
  return scan(v, duplicate);
}

template <Real T>
bool Delaunay3<T>::insert_vertex(std::uint32_t v) {
  std::uint32_t dup = kNone;
  const std::uint32_t t0 = walk(v, last_, &dup);
  if (dup != kNone) {
    // Keep the smallest input index of equal points, as the lifted-hull method does, so that
    // the result does not depend on the insertion order: the internal slots v and dup hold equal
    // coordinates, so their labels can be swapped. duplicate_of then points to the label kept
    // at that time, always a smaller index; compact() follows these chains to the final one.
    if (orig_[v] < orig_[dup]) std::swap(orig_[v], orig_[dup]);
    result_.duplicate_of[orig_[v]] = orig_[dup];
    return true;
  }
  if (t0 == kNone) return false;
  ++epoch_;
  const std::uint32_t in = 2 * epoch_, out = in + 1;
  std::uint32_t* mark = mark_.data();
  cavity_.clear();
  boundary_.clear();
  stack_.clear();
  stack_.push_back(t0);
  cavity_.push_back(t0);
  mark[t0] = in;
  // Every cell is marked at most once, so the search ends within the cell count.
  std::size_t budget = cells_.size() + 16;
  while (!stack_.empty()) {
    if (budget-- == 0) return false;
    const std::uint32_t c = stack_.back();
    stack_.pop_back();
    for (int i = 0; i < 4; ++i) {
      const std::int32_t code = cells_[c].neighbors[std::size_t(i)];
      const std::uint32_t nb = std::uint32_t(code) >> 2;
      const std::uint32_t m = mark[nb];
      if (m == in) continue;
      if (m != out) {
        if (in_conflict(nb, v)) {
          mark[nb] = in;
          stack_.push_back(nb);
          cavity_.push_back(nb);
          continue;
        }
        mark[nb] = out;
      }
      const Delaunay3Cell& cc = cells_[c];
      boundary_.push_back({cc.vertices[std::size_t(kFace[i][0])],
                           cc.vertices[std::size_t(kFace[i][1])],
                           cc.vertices[std::size_t(kFace[i][2])], code});
    }
  }
  // New cells: the cavity's slots first (a cavity with all its vertices on its boundary has
  // two cells fewer than faces), then free slots, then new ones.
  const std::size_t nb_faces = boundary_.size();
  fresh_.clear();
  for (std::size_t k = 0; k < nb_faces; ++k) {
    std::uint32_t s;
    if (k < cavity_.size()) {
      s = cavity_[k];
    } else if (!free_.empty()) {
      s = free_.back();
      free_.pop_back();
    } else {
      s = static_cast<std::uint32_t>(cells_.size());
      cells_.push_back({});
      mark_.push_back(0);
      mark = mark_.data();
    }
    fresh_.push_back(s);
  }
  for (std::size_t k = nb_faces; k < cavity_.size(); ++k) {
    cells_[cavity_[k]].vertices = {kNone, kNone, kNone, kDead};
    free_.push_back(cavity_[k]);
  }
  for (std::size_t k = 0; k < nb_faces; ++k) {
    const Boundary& f = boundary_[k];
    const std::uint32_t s = fresh_[k];
    Delaunay3Cell& cell = cells_[s];
    // (a, b, c, v) is positive: v sees the face from the cavity side. A ghost vertex is moved
    // to corner 3 by an even permutation.
    int apex_corner = 3;
    if (f.a == kGhost) {
      cell.vertices = {v, f.c, f.b, kGhost};
      apex_corner = 0;
    } else if (f.b == kGhost) {
      cell.vertices = {f.c, v, f.a, kGhost};
      apex_corner = 1;
    } else if (f.c == kGhost) {
      cell.vertices = {f.b, f.a, v, kGhost};
      apex_corner = 2;
    } else {
      cell.vertices = {f.a, f.b, f.c, v};
    }
    cell.neighbors[std::size_t(apex_corner)] = f.outside;
    cells_[std::uint32_t(f.outside) >> 2].neighbors[std::uint32_t(f.outside) & 3u] =
        static_cast<std::int32_t>(4 * s + std::uint32_t(apex_corner));
  }
  link_around(fresh_, v);
  last_ = fresh_[0];
  return true;
}

template <Real T>
void Delaunay3<T>::lower_dimensional(int dimension) {
  const std::size_t n = points_.size();
  std::vector<std::uint32_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0u);
  std::stable_sort(idx.begin(), idx.end(), [&](std::uint32_t i, std::uint32_t j) {
    return lexicographic_compare(points_[i], points_[j]) == Sign::negative;
  });
  std::uint32_t kept = idx[0];
  result_.chain.assign(1, kept);
  for (std::size_t k = 1; k < n; ++k) {
    const std::uint32_t i = idx[k];
    if (same_point(points_[i], points_[kept])) {
      result_.duplicate_of[i] = kept;
    } else {
      kept = i;
      result_.chain.push_back(kept);  // lexicographic order is the order along the line
    }
  }
  dimension_ = dimension;
}

template <Real T>
void Delaunay3<T>::run() {
  cells_.clear();
  mark_.clear();
  free_.clear();
  epoch_ = 0;
  last_ = 0;
  walk_rng_ = 0x2545F491u;
  dimension_ = -1;
  dirty_ = false;
  lattice_ = false;
  last_out_ = 0;
  status_ = Status::ok;
  result_ = Delaunay3Result{};
  const std::size_t n = points_.size();
  result_.duplicate_of.resize(n);
  std::iota(result_.duplicate_of.begin(), result_.duplicate_of.end(), 0u);
  if (n == 0) {
    status_ = Status::empty_input;
    return;
  }
  if (n > kMaxPoints) {
    status_ = Status::invalid_input;
    return;
  }
  bool finite = true;
  for (const auto& q : points_)
    finite = finite && is_finite(q.x) && is_finite(q.y) && is_finite(q.z);
  if (!finite) {
    status_ = Status::non_finite_input;
    return;
  }

  // Hilbert order on a grid of about 8 cells per point.
  hilbert_keys(std::span<const Vec3<T>>(points_), 0, keys_);
  brio_order(keys_, keys_tmp_);
  orig_.resize(n);
  sorted_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    orig_[k] = static_cast<std::uint32_t>(keys_[k]);
    sorted_[k] = points_[orig_[k]];
  }
  keys_.clear();
  keys_.shrink_to_fit();
  keys_tmp_.clear();
  keys_tmp_.shrink_to_fit();

  // A first non-degenerate tetrahedron: the first point, the first different one, the first
  // one off their line, the first one off their plane.
  const Vec3<T>* pts = sorted_.data();
  std::size_t k1 = 1;
  while (k1 < n && same_point(pts[k1], pts[0])) ++k1;
  if (k1 == n) {
    lower_dimensional(0);
    return;
  }
  std::size_t k2 = k1 + 1;
  while (k2 < n && collinear(pts[0], pts[k1], pts[k2])) ++k2;
  if (k2 == n) {
    lower_dimensional(1);
    return;
  }
  std::size_t k3 = k2 + 1;
  while (k3 < n && orient3d(pts[0], pts[k1], pts[k2], pts[k3]) == Sign::zero) ++k3;
  dimension_ = 3;
  if (k3 == n) {
    // Coplanar: tetrahedralize with a synthetic apex off the plane (internal index n, never
    // mapped to the output); the faces opposite it are the planar Delaunay triangles.
    const PlanarApex<T> apex = planar_apex(pts[0], pts[k1], pts[k2]);
    sorted_.push_back(apex.point);
    orig_.push_back(kNone);
    pts = sorted_.data();
    apex_ = static_cast<std::uint32_t>(n);
    apex_flip_ = apex.flip;
    dimension_ = 2;
  }
  lattice_ = on_small_lattice(std::span<const Vec3<T>>(sorted_));
  std::uint32_t a = 0, b = static_cast<std::uint32_t>(k1), c = static_cast<std::uint32_t>(k2),
                d = static_cast<std::uint32_t>(k3);
  if (orient3d(pts[a], pts[b], pts[c], pts[d]) == Sign::negative) std::swap(c, d);

  cells_.reserve(7 * n + 64);
  mark_.reserve(7 * n + 64);
  cells_.resize(5);
  mark_.assign(5, 0);
  cells_[0].vertices = {a, b, c, d};
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t f0 = cells_[0].vertices[std::size_t(kFace[i][0])];
    const std::uint32_t f1 = cells_[0].vertices[std::size_t(kFace[i][1])];
    const std::uint32_t f2 = cells_[0].vertices[std::size_t(kFace[i][2])];
    const std::uint32_t g = 1 + std::uint32_t(i);
    cells_[g].vertices = {f0, f2, f1, kGhost};  // the outside on the positive side
    cells_[g].neighbors[3] = static_cast<std::int32_t>(4 * 0 + std::uint32_t(i));
    cells_[0].neighbors[std::size_t(i)] = static_cast<std::int32_t>(4 * g + 3);
  }
  const std::uint32_t ghosts[4] = {1, 2, 3, 4};
  link_around(ghosts, kGhost);
  last_ = 0;

  for (std::size_t k = 1; k < n; ++k) {
    if (k == k1 || k == k2 || k == k3) continue;
    if (!insert_vertex(static_cast<std::uint32_t>(k))) {
      status_ = Status::limit_exceeded;
      break;
    }
  }
}

template <Real T>
void Delaunay3<T>::compact(bool in_place) {
  Delaunay3Result& r = result_;
  r.status = status_;
  r.dimension = status_ == Status::ok || status_ == Status::limit_exceeded ? dimension_ : -1;
  r.tetrahedra.clear();
  r.hull.clear();
  r.duplicate_count = 0;
  // duplicate_of[i] < i for a duplicate (insert_vertex), so one ascending pass resolves chains.
  for (std::size_t i = 0; i < r.duplicate_of.size(); ++i) {
    r.duplicate_of[i] = r.duplicate_of[r.duplicate_of[i]];
    r.duplicate_count += r.duplicate_of[i] != i ? 1u : 0u;
  }
  dirty_ = false;
  last_out_ = 0;
  if (dimension_ == 2) {
    planar_triangles(in_place);
    return;
  }
  if (dimension_ < 3) return;
  // New index of each real cell (mark_ is reused as the map); ghosts and free slots map to -1.
  const std::uint32_t nc = static_cast<std::uint32_t>(cells_.size());
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < nc; ++t)
    mark_[t] = cells_[t].vertices[3] >= kDead ? kNone : count++;
  auto map_neighbor = [&](std::int32_t code) {
    const std::uint32_t m = mark_[std::uint32_t(code) >> 2];
    return m == kNone ? std::int32_t(-1) : static_cast<std::int32_t>(m);
  };
  if (in_place) {
    // Slot mark_[t] <= t, so a forward pass packs the array without overwriting unread cells.
    for (std::uint32_t t = 0; t < nc; ++t) {
      const Delaunay3Cell c = cells_[t];
      if (c.vertices[3] == kGhost) {
        r.hull.push_back({orig_[c.vertices[0]], orig_[c.vertices[1]], orig_[c.vertices[2]]});
        continue;
      }
      if (c.vertices[3] == kDead) continue;
      Delaunay3Cell& o = cells_[mark_[t]];
      for (std::size_t i = 0; i < 4; ++i) {
        o.vertices[i] = orig_[c.vertices[i]];
        o.neighbors[i] = map_neighbor(c.neighbors[i]);
      }
    }
    cells_.resize(count);
    r.tetrahedra.swap(cells_);
    cells_.clear();
    mark_.clear();
    mark_.shrink_to_fit();
    sorted_.clear();
    sorted_.shrink_to_fit();
    orig_.clear();
    orig_.shrink_to_fit();
    dimension_ = -1;
    return;
  }
  r.tetrahedra.resize(count);
  for (std::uint32_t t = 0; t < nc; ++t) {
    const Delaunay3Cell& c = cells_[t];
    if (c.vertices[3] == kGhost) {
      r.hull.push_back({orig_[c.vertices[0]], orig_[c.vertices[1]], orig_[c.vertices[2]]});
      continue;
    }
    if (c.vertices[3] == kDead) continue;
    Delaunay3Cell& o = r.tetrahedra[mark_[t]];
    for (std::size_t i = 0; i < 4; ++i) {
      o.vertices[i] = orig_[c.vertices[i]];
      o.neighbors[i] = map_neighbor(c.neighbors[i]);
    }
  }
  // The query start: a real cell of the last inserted point (under it when last_ is a ghost).
  std::uint32_t last = last_;
  if (cells_[last].vertices[3] == kGhost) last = std::uint32_t(cells_[last].neighbors[3]) >> 2;
  last_out_ = mark_[last] == kNone ? 0 : static_cast<std::int32_t>(mark_[last]);
  // The marks were overwritten: restart the epochs.
  std::fill(mark_.begin(), mark_.end(), 0u);
  epoch_ = 0;
}

// Dimension 2: every real cell has the synthetic apex as a vertex; its opposite face is a
// planar Delaunay triangle.
template <Real T>
void Delaunay3<T>::planar_triangles(bool in_place) {
  Delaunay3Result& r = result_;
  r.triangles.clear();
  for (const Delaunay3Cell& c : cells_) {
    if (c.vertices[3] >= kDead) continue;
    int j = 0;
    while (j < 3 && c.vertices[std::size_t(j)] != apex_) ++j;
    std::array<std::uint32_t, 3> t;
    for (int k = 0; k < 3; ++k) t[std::size_t(k)] = orig_[c.vertices[std::size_t(kFace[j][k])]];
    if (apex_flip_) std::swap(t[1], t[2]);
    r.triangles.push_back(t);
  }
  if (in_place) {
    cells_.clear();
    cells_.shrink_to_fit();
    mark_.clear();
    mark_.shrink_to_fit();
    sorted_.clear();
    sorted_.shrink_to_fit();
    orig_.clear();
    orig_.shrink_to_fit();
    dimension_ = -1;
  }
}

// ---- the lifted-hull method: a 4D convex hull by beneath-beyond -------------------------

namespace {

// The hull of the lifted points p' = (p, |p|^2) closed above by the point at vertical infinity
// kGhost. Facets are 4-tuples of point indices: a lower facet (a, b, c, d) has
// orient3d(a, b, c, d) > 0 and is a Delaunay tetrahedron; a facet (a, b, c, kGhost) stands on
// the hull face abc with the outside on its positive side. nb[i] is the facet across the ridge
// opposite v[i]. Replacing one vertex of a facet by a point keeps the facet's orientation, so a
// new facet is a copy of a removed one with the apex put in.
template <class T>
class LiftedHull {
 public:
  explicit LiftedHull(std::span<const Vec3<T>> points) : p_(points) {}

  struct Facet {
    std::array<std::uint32_t, 4> v;
    std::array<std::uint32_t, 4> nb;
    std::uint32_t head;  // first point of the outside set (kNone: empty)
    bool alive;
  };

  // Builds the hull, inserting the points in `order` (all distinct, not all coplanar).
  bool build(std::span<const std::uint32_t> order);

  std::vector<Facet> facets;

 private:
  struct Horizon {
    std::uint32_t facet, face, other;
  };

  // p sees facet f: p' lies strictly on the outer side of its hyperplane.
  bool sees(std::uint32_t f, std::uint32_t q) const noexcept {
    const Facet& F = facets[f];
    const Vec3<T>* p = p_.data();
    if (F.v[3] == kGhost) {
      const Sign s = orient3d(p[F.v[0]], p[F.v[1]], p[F.v[2]], p[q]);
      if (s != Sign::zero) return s == Sign::positive;
      // On the plane of the hull face: seen together with the lower facet under the face.
      const Facet& G = facets[F.nb[3]];
      return insphere_perturbed_inline(p[G.v[0]], p[G.v[1]], p[G.v[2]], p[G.v[3]], p[q]) ==
             Sign::positive;
    }
    return insphere_perturbed_inline(p[F.v[0]], p[F.v[1]], p[F.v[2]], p[F.v[3]], p[q]) ==
           Sign::positive;
  }

  std::uint32_t any_visible(std::uint32_t q) const noexcept {
    for (std::uint32_t f = 0; f < facets.size(); ++f)
      if (facets[f].alive && sees(f, q)) return f;
    return kNone;
  }

  void assign(std::uint32_t q, std::uint32_t f) noexcept {
    owner_[q] = f;
    next_[q] = facets[f].head;
    facets[f].head = q;
  }

  std::uint32_t new_facet(const Facet& f) {
    if (!free_.empty()) {
      const std::uint32_t s = free_.back();
      free_.pop_back();
      facets[s] = f;
      return s;
    }
    facets.push_back(f);
    return static_cast<std::uint32_t>(facets.size() - 1);
  }

  // Glues the ridges through `apex` among the given facets: the ridge of facet f opposite v[j]
  // (v[j] != apex) is named by its two vertices other than the apex.
  bool link(std::span<const std::uint32_t> list, std::uint32_t apex) {
    open_.clear();
    for (const std::uint32_t f : list)
      for (std::uint32_t j = 0; j < 4; ++j) {
        const auto& v = facets[f].v;
        if (v[j] == apex) continue;
        std::uint32_t e[2], k = 0;
        for (std::uint32_t i = 0; i < 4; ++i)
          if (i != j && v[i] != apex) e[k++] = v[i];
        const std::uint64_t key =
            (std::uint64_t(std::min(e[0], e[1])) << 32) | std::max(e[0], e[1]);
        const auto it = open_.find(key);
        if (it == open_.end()) {
          open_.emplace(key, std::pair<std::uint32_t, std::uint32_t>{f, j});
        } else {
          facets[f].nb[j] = it->second.first;
          facets[it->second.first].nb[it->second.second] = f;
          open_.erase(it);
        }
      }
    return open_.empty();
  }

  std::span<const Vec3<T>> p_;
  std::vector<std::uint32_t> owner_, next_, mark_, free_, stack_, visible_, fresh_;
  std::vector<Horizon> horizon_;
  std::map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> open_;
  std::uint32_t epoch_ = 0;
};

template <class T>
bool LiftedHull<T>::build(std::span<const std::uint32_t> order) {
  const Vec3<T>* p = p_.data();
  const std::size_t m = order.size();
  owner_.assign(p_.size(), kNone);
  next_.assign(p_.size(), kNone);
  std::vector<char> inserted(p_.size(), 0);
  // The first simplex: the first point, the next one, the first off their line, the first off
  // their plane.
  std::size_t i2 = 2;
  while (i2 < m && collinear(p[order[0]], p[order[1]], p[order[i2]])) ++i2;
  std::size_t i3 = i2 + 1;
  while (i3 < m && orient3d(p[order[0]], p[order[1]], p[order[i2]], p[order[i3]]) == Sign::zero)
    ++i3;
  if (i3 >= m) return false;
  std::uint32_t a = order[0], b = order[1], c = order[i2], d = order[i3];
  if (orient3d(p[a], p[b], p[c], p[d]) == Sign::negative) std::swap(c, d);
  facets.assign(5, Facet{{a, b, c, d}, {kNone, kNone, kNone, kNone}, kNone, true});
  for (std::uint32_t i = 0; i < 4; ++i) {
    const auto& v = facets[0].v;
    facets[1 + i].v = {v[std::size_t(kFace[i][0])], v[std::size_t(kFace[i][2])],
                       v[std::size_t(kFace[i][1])], kGhost};
    facets[1 + i].nb[3] = 0;
    facets[0].nb[i] = 1 + i;
  }
  const std::uint32_t ghosts[4] = {1, 2, 3, 4};
  if (!link(ghosts, kGhost)) return false;
  for (const std::uint32_t q : {a, b, c, d}) inserted[q] = 1;
  for (const std::uint32_t q : order) {
    if (inserted[q]) continue;
    const std::uint32_t f = any_visible(q);
    if (f == kNone) return false;  // a lifted point is always a hull vertex
    assign(q, f);
  }
  mark_.assign(facets.size(), 0);

  for (const std::uint32_t q : order) {
    if (inserted[q]) continue;
    inserted[q] = 1;
    std::uint32_t f0 = owner_[q];
    // A facet on the hull plane of q may stop being seen when the lower facet under it changed.
    if (!sees(f0, q)) f0 = any_visible(q);
    if (f0 == kNone) return false;
    // The visible facets: a connected region, searched from f0.
    ++epoch_;
    const std::uint32_t in = 2 * epoch_, out = in + 1;
    if (mark_.size() < facets.size()) mark_.resize(facets.size(), 0);
    visible_.assign(1, f0);
    stack_.assign(1, f0);
    horizon_.clear();
    mark_[f0] = in;
    while (!stack_.empty()) {
      const std::uint32_t f = stack_.back();
      stack_.pop_back();
      for (std::uint32_t i = 0; i < 4; ++i) {
        const std::uint32_t g = facets[f].nb[i];
        if (mark_[g] == in) continue;
        if (mark_[g] != out) {
          if (sees(g, q)) {
            mark_[g] = in;
            stack_.push_back(g);
            visible_.push_back(g);
            continue;
          }
          mark_[g] = out;
        }
        horizon_.push_back({f, i, g});
      }
    }
    // The cone from q over the horizon ridges.
    fresh_.clear();
    for (const Horizon& h : horizon_) {
      Facet nf = facets[h.facet];
      nf.v[h.face] = q;
      nf.nb = {kNone, kNone, kNone, kNone};
      nf.nb[h.face] = h.other;
      nf.head = kNone;
      nf.alive = true;
      const std::uint32_t s = new_facet(nf);
      auto& back = facets[h.other].nb;
      for (auto& x : back)
        if (x == h.facet) x = s;
      fresh_.push_back(s);
    }
    if (!link(fresh_, q)) return false;
    if (mark_.size() < facets.size()) mark_.resize(facets.size(), 0);
    // Re-assign the outside sets of the removed facets to the new ones.
    for (const std::uint32_t f : visible_) {
      facets[f].alive = false;
      for (std::uint32_t x = facets[f].head; x != kNone;) {
        const std::uint32_t nx = next_[x];
        if (!inserted[x]) {
          std::uint32_t g = kNone;
          for (const std::uint32_t s : fresh_)
            if (sees(s, x)) {
              g = s;
              break;
            }
          if (g == kNone) g = any_visible(x);
          if (g == kNone) return false;
          assign(x, g);
        }
        x = nx;
      }
      facets[f].head = kNone;
    }
    for (const std::uint32_t f : visible_) free_.push_back(f);
  }
  return true;
}

// The points with their duplicates removed (the smallest index of equal points is kept, in
// lexicographic order) and their affine dimension.
template <class T>
int dedupe_and_dimension(std::span<const Vec3<T>> pts, Delaunay3Result& r,
                         std::vector<std::uint32_t>& kept) {
  const std::size_t n = pts.size();
  std::vector<std::uint32_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0u);
  std::stable_sort(idx.begin(), idx.end(), [&](std::uint32_t i, std::uint32_t j) {
    return lexicographic_compare(pts[i], pts[j]) == Sign::negative;
  });
  kept.clear();
  for (const std::uint32_t i : idx) {
    if (!kept.empty() && same_point(pts[i], pts[kept.back()])) {
      r.duplicate_of[i] = kept.back();
      ++r.duplicate_count;
    } else {
      kept.push_back(i);
    }
  }
  const std::size_t m = kept.size();
  if (m == 1) return 0;
  std::size_t i2 = 2;
  while (i2 < m && collinear(pts[kept[0]], pts[kept[1]], pts[kept[i2]])) ++i2;
  if (i2 == m) return 1;
  for (std::size_t i3 = i2 + 1; i3 < m; ++i3)
    if (orient3d(pts[kept[0]], pts[kept[1]], pts[kept[i2]], pts[kept[i3]]) != Sign::zero) return 3;
  return 2;
}

template <class T>
Delaunay3Result delaunay_lifted(std::span<const Vec3<T>> pts) {
  Delaunay3Result r;
  const std::size_t n = pts.size();
  r.duplicate_of.resize(n);
  std::iota(r.duplicate_of.begin(), r.duplicate_of.end(), 0u);
  if (n == 0) return r;
  for (const auto& q : pts) {
    if (!is_finite(q.x) || !is_finite(q.y) || !is_finite(q.z)) {
      r.status = Status::non_finite_input;
      return r;
    }
  }
  if (n > kMaxPoints) {
    r.status = Status::invalid_input;
    return r;
  }
  r.status = Status::ok;
  std::vector<std::uint32_t> kept;
  const int dim = dedupe_and_dimension(pts, r, kept);
  r.dimension = dim;
  if (dim < 2) {
    r.chain = kept;  // lexicographic order is the order along the line
    return r;
  }
  // Internal point k is input kept[k]; dimension 2 appends the synthetic apex.
  std::vector<Vec3<T>> q(kept.size());
  for (std::size_t k = 0; k < kept.size(); ++k) q[k] = pts[kept[k]];
  PlanarApex<T> apex{};
  if (dim == 2) {
    std::size_t i2 = 2;
    while (collinear(q[0], q[1], q[i2])) ++i2;
    apex = planar_apex(q[0], q[1], q[i2]);
    q.push_back(apex.point);
  }
  const std::uint32_t m = static_cast<std::uint32_t>(q.size());
  // A fixed-seed shuffle: random insertion order, no spatial sorting.
  std::vector<std::uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  std::uint64_t state = 0x243F6A8885A308D3ull;
  for (std::uint32_t i = m; i > 1; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(order[i - 1], order[static_cast<std::uint32_t>((state >> 33) % i)]);
  }
  LiftedHull<T> hull{std::span<const Vec3<T>>(q)};
  if (!hull.build(order)) {
    r.status = Status::invalid_topology;  // impossible with a consistent perturbation
    return r;
  }
  const std::uint32_t apex_id = dim == 2 ? m - 1 : kNone;
  std::vector<std::int32_t> index(hull.facets.size(), -1);
  std::int32_t count = 0;
  for (std::size_t f = 0; f < hull.facets.size(); ++f)
    if (hull.facets[f].alive && hull.facets[f].v[3] != kGhost) index[f] = count++;
  for (std::size_t f = 0; f < hull.facets.size(); ++f) {
    const auto& F = hull.facets[f];
    if (!F.alive) continue;
    if (dim == 2) {
      if (F.v[3] == kGhost) continue;
      int j = 0;
      while (F.v[std::size_t(j)] != apex_id) ++j;
      std::array<std::uint32_t, 3> t;
      for (int k = 0; k < 3; ++k) t[std::size_t(k)] = kept[F.v[std::size_t(kFace[j][k])]];
      if (apex.flip) std::swap(t[1], t[2]);
      r.triangles.push_back(t);
      continue;
    }
    if (F.v[3] == kGhost) {
      r.hull.push_back({kept[F.v[0]], kept[F.v[1]], kept[F.v[2]]});
      continue;
    }
    Delaunay3Cell c;
    for (std::size_t i = 0; i < 4; ++i) {
      c.vertices[i] = kept[F.v[i]];
      c.neighbors[i] = index[F.nb[i]];
    }
    r.tetrahedra.push_back(c);
  }
  return r;
}

}  // namespace

// ---- queries on a result ---------------------------------------------------------------

namespace {

// Fills r for a point inside or on the closed tetrahedron t; bit i of zero_mask says the point
// is on the plane of face i (the face opposite corner i).
void classify_location(Locate3Result& r, std::size_t t, unsigned zero_mask) noexcept {
  r.tetrahedron = static_cast<std::int32_t>(t);
  const int zeros = std::popcount(zero_mask);
  if (zeros == 0) {
    r.location = Location3::inside;
  } else if (zeros == 1) {
    r.location = Location3::on_face;
    r.face = std::countr_zero(zero_mask);
  } else if (zeros == 2) {
    // Faces i and j share the edge of the two other corners.
    r.location = Location3::on_edge;
    const unsigned rest = ~zero_mask & 15u;
    r.edge = {std::countr_zero(rest), 31 - std::countl_zero(rest)};
  } else {
    // Three faces share the corner none of them is opposite to.
    r.location = Location3::on_vertex;
    r.corner = std::countr_zero(~zero_mask & 15u);
  }
}

[[nodiscard]] bool valid_cell(const Delaunay3Cell& c, std::size_t np, std::size_t nt) noexcept {
  for (std::size_t i = 0; i < 4; ++i)
    if (c.vertices[i] >= np || (c.neighbors[i] >= 0 && std::size_t(c.neighbors[i]) >= nt))
      return false;
  return true;
}

template <class T>
[[nodiscard]] Sign face_side(std::span<const Vec3<T>> pts, const Delaunay3Cell& c, int i,
                             const Vec3<T>& p) noexcept {
  return orient3d(pts[c.vertices[std::size_t(kFace[i][0])]],
                  pts[c.vertices[std::size_t(kFace[i][1])]],
                  pts[c.vertices[std::size_t(kFace[i][2])]], p);
}

}  // namespace

template <Real T>
Locate3Result locate(const Delaunay3Result& dt, std::span<const Vec3<T>> points, const Vec3<T>& p,
                     std::int32_t start, std::size_t max_steps) noexcept {
  Locate3Result r;
  r.status = Status::ok;
  const std::size_t nt = dt.tetrahedra.size();
  if (nt == 0) {
    r.status = Status::empty_input;
    return r;
  }
  if (!is_finite(p.x) || !is_finite(p.y) || !is_finite(p.z)) {
    r.status = Status::non_finite_input;
    return r;
  }
  const std::size_t np = points.size();
  if (max_steps == 0) max_steps = nt + 64;
  // The visibility walk: leave through the first face p is strictly beyond. In a Delaunay
  // tetrahedralization it visits no tetrahedron twice (acyclicity of the in-front relation).
  std::size_t t = start >= 0 && std::size_t(start) < nt ? std::size_t(start) : 0;
  std::size_t came = nt;
  for (std::size_t step = 0; step < max_steps; ++step) {
    r.steps = step + 1;
    const Delaunay3Cell& c = dt.tetrahedra[t];
    if (!valid_cell(c, np, nt)) {
      r.status = Status::invalid_input;
      return r;
    }
    unsigned zero_mask = 0;
    bool moved = false;
    for (int i = 0; i < 4; ++i) {
      const std::int32_t nb = c.neighbors[std::size_t(i)];
      if (nb >= 0 && std::size_t(nb) == came) continue;  // p is strictly on this side
      const Sign s = face_side(points, c, i, p);
      if (s == Sign::negative) {
        if (nb < 0) {  // beyond a hull face: outside the convex hull
          r.location = Location3::outside;
          r.tetrahedron = static_cast<std::int32_t>(t);
          r.face = i;
          return r;
        }
        came = t;
        t = std::size_t(nb);
        moved = true;
        break;
      }
      if (s == Sign::zero) zero_mask |= 1u << i;
    }
    if (!moved) {
      classify_location(r, t, zero_mask);
      return r;
    }
  }
  // Out of steps: an exact scan.
  r.scanned = true;
  for (std::size_t u = 0; u < nt; ++u) {
    const Delaunay3Cell& c = dt.tetrahedra[u];
    if (!valid_cell(c, np, nt)) {
      r.status = Status::invalid_input;
      return r;
    }
    unsigned zero_mask = 0;
    bool in = true;
    for (int i = 0; i < 4 && in; ++i) {
      const Sign s = face_side(points, c, i, p);
      in = s != Sign::negative;
      if (s == Sign::zero) zero_mask |= 1u << i;
    }
    if (in) {
      classify_location(r, u, zero_mask);
      return r;
    }
  }
  for (std::size_t u = 0; u < nt; ++u)
    for (int i = 0; i < 4; ++i)
      if (dt.tetrahedra[u].neighbors[std::size_t(i)] < 0 &&
          face_side(points, dt.tetrahedra[u], i, p) == Sign::negative) {
        r.location = Location3::outside;
        r.tetrahedron = static_cast<std::int32_t>(u);
        r.face = i;
        return r;
      }
  r.status = Status::invalid_input;  // not a tetrahedralization of a convex region
  return r;
}

template <Real T>
NearestVertex3Result nearest_vertex(const Delaunay3Result& dt, std::span<const Vec3<T>> points,
                                    const Vec3<T>& p, std::int32_t start) noexcept {
  NearestVertex3Result r;
  r.status = Status::ok;
  if (!is_finite(p.x) || !is_finite(p.y) || !is_finite(p.z)) {
    r.status = Status::non_finite_input;
    return r;
  }
  const std::size_t np = points.size();
  // Every kept point by an exact comparison: lower dimensions, and the fallback below.
  auto scan = [&]() noexcept {
    r.tetrahedron = -1;
    bool found = false;
    for (std::size_t i = 0; i < np; ++i) {
      if (i < dt.duplicate_of.size() && dt.duplicate_of[i] != i) continue;
      if (!found || compare_sqr_distance(p, points[i], points[r.vertex]) == Sign::negative)
        r.vertex = static_cast<std::uint32_t>(i);
      found = true;
    }
    r.status = found ? Status::ok : Status::empty_input;
  };
  if (dt.tetrahedra.empty()) {
    scan();
    return r;
  }
  const Locate3Result loc = locate(dt, points, p, start, 0);
  if (loc.status != Status::ok) {
    r.status = loc.status;
    return r;
  }
  std::size_t t = std::size_t(loc.tetrahedron);
  std::uint32_t best = dt.tetrahedra[t].vertices[0];
  for (const std::uint32_t v : dt.tetrahedra[t].vertices)
    if (compare_sqr_distance(p, points[v], points[best]) == Sign::negative) best = v;
  // Greedy descent: search the star of `best` (the tetrahedra around it, reached across the
  // faces through it) for a strictly closer vertex. Each move strictly decreases the distance.
  constexpr std::size_t kStar = 512;
  std::uint32_t star[kStar];
  for (;;) {
    std::size_t count = 1, head = 0;
    star[0] = static_cast<std::uint32_t>(t);
    bool moved = false;
    while (head < count && !moved) {
      const std::uint32_t s = star[head++];
      const Delaunay3Cell& c = dt.tetrahedra[s];
      if (!valid_cell(c, np, dt.tetrahedra.size())) {
        r.status = Status::invalid_input;
        return r;
      }
      for (std::size_t i = 0; i < 4 && !moved; ++i) {
        const std::uint32_t w = c.vertices[i];
        if (w == best) continue;
        if (compare_sqr_distance(p, points[w], points[best]) == Sign::negative) {
          best = w;
          t = s;
          moved = true;
          break;
        }
        // Face i contains `best` (it is opposite another corner): its neighbour is in the star.
        const std::int32_t nb = c.neighbors[i];
        if (nb < 0) continue;
        bool seen = false;
        for (std::size_t k = 0; k < count && !seen; ++k) seen = star[k] == std::uint32_t(nb);
        if (seen) continue;
        if (count == kStar) {  // an unusually large star: decide by scanning
          scan();
          return r;
        }
        star[count++] = static_cast<std::uint32_t>(nb);
      }
    }
    if (!moved) break;
  }
  r.vertex = best;
  r.tetrahedron = static_cast<std::int32_t>(t);
  return r;
}

template <Real T>
Delaunay3Result delaunay(std::span<const Vec3<T>> points, const Delaunay3Options& options) {
  if (options.method == Delaunay3Method::lifted_hull) return delaunay_lifted(points);
  Delaunay3<T> d;
  d.points_.assign(points.begin(), points.end());
  d.run();
  d.compact(true);
  return d.take_result();
}

template class Delaunay3<float>;
template class Delaunay3<double>;
template Delaunay3Result delaunay<float>(std::span<const Vec3<float>>, const Delaunay3Options&);
template Delaunay3Result delaunay<double>(std::span<const Vec3<double>>, const Delaunay3Options&);
template Locate3Result locate<float>(const Delaunay3Result&, std::span<const Vec3<float>>,
                                     const Vec3<float>&, std::int32_t, std::size_t) noexcept;
template Locate3Result locate<double>(const Delaunay3Result&, std::span<const Vec3<double>>,
                                      const Vec3<double>&, std::int32_t, std::size_t) noexcept;
template NearestVertex3Result nearest_vertex<float>(const Delaunay3Result&,
                                                    std::span<const Vec3<float>>,
                                                    const Vec3<float>&, std::int32_t) noexcept;
template NearestVertex3Result nearest_vertex<double>(const Delaunay3Result&,
                                                     std::span<const Vec3<double>>,
                                                     const Vec3<double>&, std::int32_t) noexcept;
template Sign insphere_perturbed<float>(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&,
                                        const Vec3<float>&, const Vec3<float>&) noexcept;
template Sign insphere_perturbed<double>(const Vec3<double>&, const Vec3<double>&,
                                         const Vec3<double>&, const Vec3<double>&,
                                         const Vec3<double>&) noexcept;

}  // namespace locus
