// SPDX-License-Identifier: BSL-1.0
// Bvh (include/locus/spatial/bvh.hpp): binned-SAH build, collapse to 8-wide nodes, and the
// ray, overlap and nearest-point traversals, compiled once for float and double. The ray
// traversals are compiled for three instruction sets (src/core/lanes.hpp) and picked at the
// call. Design and error analysis of the conservative slab test: docs/notes/spatial.md.

#include <locus/distance/point_triangle.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/spatial/bvh.hpp>

#include "../core/lanes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace locus {

namespace detail {

void* bvh_allocate(std::size_t bytes, std::size_t align) {
  align = std::max(align, alignof(std::max_align_t));
  void* p = ::operator new(bytes, std::align_val_t(align));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only (ignored where unsupported), given before the first touch so that the faults
  // themselves map huge pages: the 2 MiB-aligned interior of a block of 4 MiB or more (such
  // blocks are the allocator's own fresh mappings).
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21;
  if (bytes >= 2 * huge) {
    const auto first = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t begin = (first + huge - 1) & ~(huge - 1);
    const std::uintptr_t end = (first + bytes) & ~(huge - 1);
    if (end > begin) (void)::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#endif
  return p;
}

void bvh_deallocate(void* p, std::size_t, std::size_t align) noexcept {
  // Unsized: clang before 19 declares the sized forms only with -fsized-deallocation.
  align = std::max(align, alignof(std::max_align_t));
  ::operator delete(p, std::align_val_t(align));
}

namespace {

namespace l3 = detail::linear3;

typedef float F8 __attribute__((vector_size(32)));
typedef int I8 __attribute__((vector_size(32)));
constexpr int kWidth = Bvh<float>::width;
typedef double D4 __attribute__((vector_size(32)));
typedef long long L4 __attribute__((vector_size(32)));

constexpr float kInf = std::numeric_limits<float>::infinity();
// Stack capacity of a traversal: the build bounds the depth by kMaxDepth binary levels (the SAH
// levels, then object medians), and a traversal holds at most kWidth - 1 entries per level.
constexpr int kSahDepth = 40;
constexpr int kStack = (kWidth - 1) * (kSahDepth + 32) + 8;

/// The float nearest x rounded down (up): outward rounding of box bounds.
inline float round_down(double x) noexcept {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -kInf);
  return f;
}
inline float round_up(double x) noexcept {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, kInf);
  return f;
}

LOCUS_ALWAYS_INLINE inline F8 load8(const float* p) noexcept {
  F8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
LOCUS_ALWAYS_INLINE inline F8 splat8(float x) noexcept { return F8{x, x, x, x, x, x, x, x}; }

/// The ray in the scaled float frame of the boxes (docs/notes/spatial.md, "Conservative slabs"):
/// per axis, the near plane (lo when the direction is non-negative), origins moved by
/// delta = 2^-20 (1 + max |o'|) so that the near parameter only decreases and the far one only
/// increases, and the rounded reciprocal direction.
struct RayFrame {
  float on[3], of[3], inv[3];
  int near_row[3], far_row[3];
  double tscale;  // t' (frame) = t (input) * tscale
  bool cull;
};

template <Real T>
bool make_frame(const Ray3<T>& ray, int scale_exp, RayFrame& f) noexcept {
  const Vec3<double> o = vec_cast<double>(ray.origin), d = vec_cast<double>(ray.direction);
  if (!is_finite(o) || !is_finite(d)) return false;
  const double dm = max_abs(d);
  if (dm == 0.0) return false;
  int e = 0;
  (void)std::frexp(dm, &e);
  double om = 0.0;
  Vec3<double> os{}, ds{};
  for (int a = 0; a < 3; ++a) {
    os[a] = std::ldexp(o[a], -scale_exp);
    ds[a] = std::ldexp(d[a], -e);
    om = std::max(om, std::abs(os[a]));
  }
  f.tscale = std::ldexp(1.0, e - scale_exp);
  f.cull = om < 0x1p100 && std::isfinite(f.tscale) && f.tscale > 0.0;
  const double delta = 0x1p-20 * (1.0 + om);
  for (int a = 0; a < 3; ++a) {
    const float df = static_cast<float>(ds[a]);
    const bool pos = !std::signbit(df);
    f.inv[a] = 1.0f / df;  // +-inf for a zero component: handled by the NaN rule of slab
    f.near_row[a] = pos ? a : a + 3;
    f.far_row[a] = pos ? a + 3 : a;
    f.on[a] = static_cast<float>(pos ? os[a] + delta : os[a] - delta);
    f.of[a] = static_cast<float>(pos ? os[a] - delta : os[a] + delta);
  }
  return true;
}

/// t (input units) in the frame, rounded up; +inf when it overflows or is not a number.
inline float frame_t(const RayFrame& f, double t) noexcept {
  const double s = t * f.tscale;
  if (!(s < 0x1p127)) return kInf;
  return round_up(s);
}

/// The children's slab intervals against [0, tmax]: bit k set when child k may be met;
/// tn receives the (conservative) entry parameters. A NaN lane of one axis (0 * inf) imposes
/// no constraint: `t > tn ? t : tn` keeps tn.
template <class Node>
LOCUS_ALWAYS_INLINE inline unsigned slab(const Node& nd, const RayFrame& r, float tmax,
                                         F8& tn) noexcept {
  if (!r.cull) {
    tn = splat8(0.0f);
    unsigned m = 0;
    for (int k = 0; k < kWidth; ++k)
      if (nd.count[k] != 0) m |= 1u << k;
    return m;
  }
  F8 lo = splat8(0.0f), hi = splat8(tmax);
  for (int a = 0; a < 3; ++a) {
    const F8 inv = splat8(r.inv[a]);
    const F8 t0 = (load8(nd.box[r.near_row[a]]) - splat8(r.on[a])) * inv;
    const F8 t1 = (load8(nd.box[r.far_row[a]]) - splat8(r.of[a])) * inv;
    lo = t0 > lo ? t0 : lo;
    hi = t1 < hi ? t1 : hi;
  }
  const I8 m = lo <= hi;
  tn = lo;
  unsigned bits = 0;
  for (int k = 0; k < kWidth; ++k) bits |= (m[k] ? 1u : 0u) << k;
  return bits;
}

LOCUS_ALWAYS_INLINE inline D4 splatd(double x) noexcept { return D4{x, x, x, x}; }
LOCUS_ALWAYS_INLINE inline D4 absd(D4 x) noexcept { return x < 0.0 ? -x : x; }

/// The lanes of a packet that watertight_hit's edge filter (l3::filtered_edge_signs) cannot
/// reject: the same products, sums and error bound, lane by lane; a lane is rejected only when
/// two certified edge signs differ, which l3::hit rejects as well.
template <Real T>
LOCUS_ALWAYS_INLINE inline unsigned packet_candidates(const typename Bvh<T>::Packet& pk,
                                                      const l3::V& o, const l3::V& d) noexcept {
  D4 a[3][3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) {
      D4 v;
      for (int j = 0; j < 4; ++j) v[j] = static_cast<double>(pk.v[k][c][j]);
      a[k][c] = v - splatd(o[c]);
    }
  const D4 dx = splatd(d.x), dy = splatd(d.y), dz = splatd(d.z);
  const D4 adx = absd(dx), ady = absd(dy), adz = absd(dz);
  L4 pos{}, neg{};
  for (int i = 0; i < 3; ++i) {
    const D4* x = a[i];
    const D4* y = a[(i + 1) % 3];
    const D4 p0 = x[1] * y[2], q0 = x[2] * y[1], p1 = x[2] * y[0], q1 = x[0] * y[2],
             p2 = x[0] * y[1], q2 = x[1] * y[0];
    const D4 v = dx * (p0 - q0) + dy * (p1 - q1) + dz * (p2 - q2);
    const D4 perm =
        adx * (absd(p0) + absd(q0)) + ady * (absd(p1) + absd(q1)) + adz * (absd(p2) + absd(q2));
    const L4 dec = (perm > splatd(0x1p-960)) & (perm < splatd(0x1p1000)) &
                   (absd(v) > splatd(7.772e-16) * perm);
    const L4 gt = v > splatd(0.0);
    pos |= dec & gt;
    neg |= dec & ~gt;
  }
  const L4 reject = pos & neg;
  unsigned m = 0;
  for (int j = 0; j < 4; ++j)
    if (!reject[j]) m |= 1u << j;
  return m;
}

#ifdef LOCUS_BVH_STATS
}  // namespace
std::size_t g_nodes = 0, g_packets = 0;
namespace {
#endif

struct Entry {
  std::uint32_t child, count;
  float tn;
};

}  // namespace

template <Real T>
struct BvhCore {
  using B = Bvh<T>;

  static Triangle3<T> tri(const B& b, std::uint32_t slot) noexcept {
    const auto& pk = b.tris_[slot / 4];
    const std::uint32_t j = slot % 4;
    Triangle3<T> t;
    Vec3<T>* v[3] = {&t.v0, &t.v1, &t.v2};
    for (int k = 0; k < 3; ++k) *v[k] = Vec3<T>{pk.v[k][0][j], pk.v[k][1][j], pk.v[k][2][j]};
    return t;
  }

  // Generic traversal: Leaf(first slot, count, float& tmax_frame) -> false to stop.
  template <class Leaf>
  LOCUS_ALWAYS_INLINE static void traverse(const B& b, const RayFrame& fr, float& tb, bool sorted,
                                           Leaf&& leaf) {
    if (b.nodes_.empty()) return;
    Entry stack[kStack];
    int sp = 0;
    stack[sp++] = {0, B::internal_child, 0.0f};
    while (sp > 0) {
      const Entry e = stack[--sp];
      if (e.tn > tb) continue;
      if (e.count != B::internal_child) {
        if (!leaf(e.child, e.count, tb)) return;
        continue;
      }
      const typename B::Node& nd = b.nodes_[e.child];
#ifdef LOCUS_BVH_STATS
      ++g_nodes;
#endif
      F8 tn;
      unsigned m = slab(nd, fr, tb, tn);
      if (!m) continue;
      Entry hit[kWidth];
      int nh = 0;
      for (int k = 0; k < kWidth; ++k)
        if (m & (1u << k)) hit[nh++] = {nd.child[k], nd.count[k], tn[k]};
      if (sorted)  // nearest last, so that it is popped first
        for (int i = 1; i < nh; ++i)
          for (int j = i; j > 0 && hit[j - 1].tn < hit[j].tn; --j) std::swap(hit[j - 1], hit[j]);
      for (int i = 0; i < nh; ++i) {
        if (hit[i].count == B::internal_child) {
          const char* q = reinterpret_cast<const char*>(&b.nodes_[hit[i].child]);
          for (std::size_t c = 0; c < sizeof(typename B::Node); c += 64) __builtin_prefetch(q + c);
        } else if (!b.tris_.empty()) {
          const char* q = reinterpret_cast<const char*>(b.tris_.data() + hit[i].child / 4);
          for (std::size_t c = 0; c < sizeof(typename B::Packet); c += 64)
            __builtin_prefetch(q + c);
          __builtin_prefetch(q + sizeof(typename B::Packet) - 1);
        }
        stack[sp++] = hit[i];
      }
    }
  }

  // Runs `f(slot, TriangleHit<T>)` for every triangle of the leaf that watertight_hit hits.
  template <class F>
  LOCUS_ALWAYS_INLINE static bool leaf_hits(const B& b, const l3::Lin& lin, std::uint32_t first,
                                            std::uint32_t count, F&& f) {
    const std::uint32_t end = first + count;
    for (std::uint32_t p = first / 4; p * 4 < end; ++p) {
#ifdef LOCUS_BVH_STATS
      ++g_packets;
#endif
      unsigned m = packet_candidates<T>(b.tris_[p], lin.o, lin.d);
      for (std::uint32_t j = 0; j < 4; ++j) {
        const std::uint32_t s = p * 4 + j;
        if (!(m & (1u << j)) || s >= end) continue;
        const Triangle3<T> t = tri(b, s);
        const auto h = l3::hit(lin, l3::as_tri(t));
        if (!h.hit) continue;
        if (!f(s, l3::cast_hit<T>(h))) return false;
      }
    }
    return true;
  }

  LOCUS_ALWAYS_INLINE static void closest(const B& b, const Ray3<T>& ray, T tmax, MeshHit<T>& out) {
    out = MeshHit<T>{};
    RayFrame fr;
    if (b.tris_.empty() || !(tmax >= T(0)) || !make_frame(ray, b.scale_exp_, fr)) return;
    const l3::Lin lin = l3::as_lin(ray);
    float tb = frame_t(fr, static_cast<double>(tmax));
    T best = tmax;
    traverse(b, fr, tb, true,
             [&](std::uint32_t first, std::uint32_t count, float& tbr) LOCUS_ALWAYS_INLINE_LAMBDA {
               return leaf_hits(
                   b, lin, first, count,
                   [&](std::uint32_t s, const TriangleHit<T>& h) LOCUS_ALWAYS_INLINE_LAMBDA {
                     const std::uint32_t id = b.tris_[s / 4].id[s % 4];
                     const bool better = out.triangle == MeshHit<T>::none
                                             ? h.t <= best
                                             : (h.t < best || (h.t == best && id < out.triangle));
                     if (better) {
                       out = {id, h.t, h.barycentric, h.front};
                       best = h.t;
                       tbr = frame_t(fr, static_cast<double>(best));
                     }
                     return true;
                   });
             });
  }

  LOCUS_ALWAYS_INLINE static void any(const B& b, const Ray3<T>& ray, T tmax, bool& out) {
    out = false;
    RayFrame fr;
    if (b.tris_.empty() || !(tmax >= T(0)) || !make_frame(ray, b.scale_exp_, fr)) return;
    const l3::Lin lin = l3::as_lin(ray);
    float tb = frame_t(fr, static_cast<double>(tmax));
    traverse(b, fr, tb, false,
             [&](std::uint32_t first, std::uint32_t count, float&) LOCUS_ALWAYS_INLINE_LAMBDA {
               return leaf_hits(b, lin, first, count,
                                [&](std::uint32_t, const TriangleHit<T>& h)
                                    LOCUS_ALWAYS_INLINE_LAMBDA {
                                      if (h.t <= tmax) out = true;
                                      return !out;
                                    });
             });
  }

  static void all(const B& b, const Ray3<T>& ray, T tmax, std::vector<MeshHit<T>>& out) {
    out.clear();
    RayFrame fr;
    if (b.tris_.empty() || !(tmax >= T(0)) || !make_frame(ray, b.scale_exp_, fr)) return;
    const l3::Lin lin = l3::as_lin(ray);
    float tb = frame_t(fr, static_cast<double>(tmax));
    traverse(b, fr, tb, false, [&](std::uint32_t first, std::uint32_t count, float&) {
      return leaf_hits(b, lin, first, count, [&](std::uint32_t s, const TriangleHit<T>& h) {
        if (h.t <= tmax) out.push_back({b.tris_[s / 4].id[s % 4], h.t, h.barycentric, h.front});
        return true;
      });
    });
    std::sort(out.begin(), out.end(), [](const MeshHit<T>& x, const MeshHit<T>& y) {
      return x.t < y.t || (x.t == y.t && x.triangle < y.triangle);
    });
  }

  static void closest_batch(const B& b, const Ray3<T>* rays, MeshHit<T>* out, std::size_t n,
                            T tmax);
  static void any_batch(const B& b, const Ray3<T>* rays, std::uint8_t* out, std::size_t n, T tmax);
};

namespace {

template <Real T>
LOCUS_ALWAYS_INLINE inline void closest_run(const Bvh<T>& b, const Ray3<T>* rays, MeshHit<T>* out,
                                            std::size_t n, T tmax) {
  for (std::size_t i = 0; i < n; ++i) BvhCore<T>::closest(b, rays[i], tmax, out[i]);
}
template <Real T>
LOCUS_ALWAYS_INLINE inline void any_run(const Bvh<T>& b, const Ray3<T>* rays, std::uint8_t* out,
                                        std::size_t n, T tmax) {
  for (std::size_t i = 0; i < n; ++i) {
    bool h = false;
    BvhCore<T>::any(b, rays[i], tmax, h);
    out[i] = h ? 1 : 0;
  }
}

LOCUS_LANE_VERSIONS(closest_f,
                    (const Bvh<float>& b, const Ray3<float>* r, MeshHit<float>* o, std::size_t n,
                     float t),
                    closest_run<float>(b, r, o, n, t))
LOCUS_LANE_VERSIONS(closest_d,
                    (const Bvh<double>& b, const Ray3<double>* r, MeshHit<double>* o, std::size_t n,
                     double t),
                    closest_run<double>(b, r, o, n, t))
LOCUS_LANE_VERSIONS(any_f,
                    (const Bvh<float>& b, const Ray3<float>* r, std::uint8_t* o, std::size_t n,
                     float t),
                    any_run<float>(b, r, o, n, t))
LOCUS_LANE_VERSIONS(any_d,
                    (const Bvh<double>& b, const Ray3<double>* r, std::uint8_t* o, std::size_t n,
                     double t),
                    any_run<double>(b, r, o, n, t))

}  // namespace

template <Real T>
void BvhCore<T>::closest_batch(const B& b, const Ray3<T>* rays, MeshHit<T>* out, std::size_t n,
                               T tmax) {
  if constexpr (std::is_same_v<T, float>)
    closest_f_versions.pick()(b, rays, out, n, tmax);
  else
    closest_d_versions.pick()(b, rays, out, n, tmax);
}
template <Real T>
void BvhCore<T>::any_batch(const B& b, const Ray3<T>* rays, std::uint8_t* out, std::size_t n,
                           T tmax) {
  if constexpr (std::is_same_v<T, float>)
    any_f_versions.pick()(b, rays, out, n, tmax);
  else
    any_d_versions.pick()(b, rays, out, n, tmax);
}

namespace {

// ---------------------------------------------------------------------------------------------
// Build.

struct Prim {
  float lo[3], hi[3], c[3];
  std::uint32_t id;
};

struct Bounds {
  float lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  void grow(const float* l, const float* h) noexcept {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], l[a]);
      hi[a] = std::max(hi[a], h[a]);
    }
  }
  void grow(const Bounds& b) noexcept { grow(b.lo, b.hi); }
  [[nodiscard]] double area() const noexcept {
    if (!(lo[0] <= hi[0])) return 0.0;
    const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
    return 2.0 * (x * y + y * z + z * x);
  }
};

struct BNode {
  Bounds box;
  std::uint32_t a = 0, b = 0;  // leaf: [a, a + b) of the primitives; internal: children a and b
  bool leaf = true;
};

/// The bin of centroid coordinate c: floor((c - lo) k) clamped to [0, bins - 1].
inline int bin_of(float c, float lo, float k, int bins) noexcept {
  return std::min(bins - 1, static_cast<int>((c - lo) * k));
}

/// Binned SAH (cost counted in packets of four triangles) into a binary tree; reorders prims
/// into leaf order. Below kSahDepth levels, object medians bound the depth.
std::vector<BNode> build_binary(std::vector<Prim>& prims, int bins, int leaf_size) {
  std::vector<BNode> nodes;
  const std::uint32_t n = static_cast<std::uint32_t>(prims.size());
  nodes.reserve(2 * static_cast<std::size_t>(n / 2 + 1));
  struct Work {
    std::uint32_t b, e, node;
    int depth;
  };
  std::vector<Work> work;
  nodes.push_back({});
  work.push_back({0, n, 0, 0});
  struct Bin {
    Bounds box;
    std::uint32_t count = 0;
  };
  const auto nb = static_cast<std::size_t>(bins);
  std::vector<Bin> bin(3 * nb);
  std::vector<double> right_area(nb);
  std::vector<std::uint32_t> right_count(nb);
  while (!work.empty()) {
    const Work w = work.back();
    work.pop_back();
    Bounds box, cb;
    for (std::uint32_t i = w.b; i < w.e; ++i) {
      const Prim& p = prims[i];
      box.grow(p.lo, p.hi);
      cb.grow(p.c, p.c);
    }
    nodes[w.node].box = box;
    const std::uint32_t cnt = w.e - w.b;
    if (cnt <= 1 || (cnt <= 4 && cnt <= static_cast<std::uint32_t>(leaf_size))) {
      nodes[w.node].a = w.b;
      nodes[w.node].b = cnt;
      continue;
    }
    int best_axis = -1, best_bin = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    float k[3] = {0, 0, 0};
    if (w.depth < kSahDepth) {
      for (auto& bb : bin) bb = Bin{};
      for (int a = 0; a < 3; ++a) {
        // float binning: (c - lo) k lies in [0, bins (1 + 2^-22)]; an extent too small for a
        // finite k (or none) leaves the axis out.
        const float ext = cb.hi[a] - cb.lo[a];
        k[a] = ext > 0x1p-100f ? static_cast<float>(bins) / ext : 0.0f;
      }
      for (std::uint32_t i = w.b; i < w.e; ++i) {
        const Prim& p = prims[i];
        for (int a = 0; a < 3; ++a) {
          Bin& bb = bin[static_cast<std::size_t>(a) * nb +
                        static_cast<std::size_t>(bin_of(p.c[a], cb.lo[a], k[a], bins))];
          bb.box.grow(p.lo, p.hi);
          ++bb.count;
        }
      }
      for (int a = 0; a < 3; ++a) {
        if (k[a] == 0.0f) continue;
        const Bin* ab = &bin[static_cast<std::size_t>(a) * nb];
        Bounds acc;
        std::uint32_t c = 0;
        for (int j = bins - 1; j > 0; --j) {
          const auto& bb = ab[j];
          if (bb.count) acc.grow(bb.box);
          c += bb.count;
          right_area[static_cast<std::size_t>(j)] = acc.area();
          right_count[static_cast<std::size_t>(j)] = c;
        }
        Bounds left;
        c = 0;
        for (int j = 0; j < bins - 1; ++j) {
          const auto& bb = ab[j];
          if (bb.count) left.grow(bb.box);
          c += bb.count;
          const std::uint32_t rc = right_count[static_cast<std::size_t>(j + 1)];
          if (c == 0 || rc == 0) continue;
          // Cost in packets of four: a leaf tests its triangles four at a time.
          const double cost = left.area() * ((c + 3) / 4) +
                              right_area[static_cast<std::size_t>(j + 1)] * ((rc + 3) / 4);
          if (cost < best_cost) best_cost = cost, best_axis = a, best_bin = j;
        }
      }
    }
    const double parent = box.area();
    if (cnt <= static_cast<std::uint32_t>(leaf_size) &&
        (best_axis < 0 || parent * ((cnt + 3) / 4) <= parent + best_cost)) {
      nodes[w.node].a = w.b;
      nodes[w.node].b = cnt;
      continue;
    }
    std::uint32_t mid = w.b;
    if (best_axis >= 0) {
      const int a = best_axis;
      const float lo = cb.lo[a];
      const float ka = k[a];
      mid = static_cast<std::uint32_t>(
          std::partition(prims.begin() + w.b, prims.begin() + w.e,
                         [&](const Prim& p) { return bin_of(p.c[a], lo, ka, bins) <= best_bin; }) -
          prims.begin());
    }
    if (mid == w.b || mid == w.e) {  // object median on the widest centroid axis
      int a = 0;
      for (int j = 1; j < 3; ++j)
        if (double(cb.hi[j]) - cb.lo[j] > double(cb.hi[a]) - cb.lo[a]) a = j;
      mid = w.b + cnt / 2;
      std::nth_element(prims.begin() + w.b, prims.begin() + mid, prims.begin() + w.e,
                       [&](const Prim& x, const Prim& y) {
                         return x.c[a] < y.c[a] || (x.c[a] == y.c[a] && x.id < y.id);
                       });
    }
    const std::uint32_t l = static_cast<std::uint32_t>(nodes.size());
    nodes.push_back({});
    nodes.push_back({});
    nodes[w.node].leaf = false;
    nodes[w.node].a = l;
    nodes[w.node].b = l + 1;
    work.push_back({mid, w.e, l + 1, w.depth + 1});
    work.push_back({w.b, mid, l, w.depth + 1});
  }
  return nodes;
}

}  // namespace

}  // namespace detail

template <Real T>
void Bvh<T>::build(std::vector<AlignedBox3<T>> boxes, BvhOptions options, bool packets) {
  using detail::Prim;
  const int bins = std::clamp(options.bins, 2, 64);
  const int leaf_size = std::clamp(options.leaf_size, 1, 16);
  count_ = boxes.size();
  double m = 0.0;
  for (const auto& b : boxes) m = std::max({m, double(max_abs(b.min)), double(max_abs(b.max))});
  int e = 0;
  if (m > 0.0) (void)std::frexp(m, &e);
  scale_exp_ = e;
  std::vector<Prim> prims(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      prims[i].lo[a] = detail::round_down(std::ldexp(double(boxes[i].min[a]), -e));
      prims[i].hi[a] = detail::round_up(std::ldexp(double(boxes[i].max[a]), -e));
      prims[i].c[a] = 0.5f * prims[i].lo[a] + 0.5f * prims[i].hi[a];
    }
    prims[i].id = static_cast<std::uint32_t>(i);
  }
  const std::vector<detail::BNode> bn = detail::build_binary(prims, bins, leaf_size);

  // Collapse: each 8-wide node takes the children of a binary node, then repeatedly opens its
  // internal child of largest area until it has eight.
  nodes_.clear();
  ids_.clear();
  boxes_.clear();
  struct Work {
    std::uint32_t bnode, node;
  };
  std::vector<Work> work;
  nodes_.push_back({});
  work.push_back({0, 0});
  while (!work.empty()) {
    const Work w = work.back();
    work.pop_back();
    std::uint32_t list[width];
    int nl = 0;
    if (bn[w.bnode].leaf) {
      list[nl++] = w.bnode;
    } else {
      list[nl++] = bn[w.bnode].a;
      list[nl++] = bn[w.bnode].b;
    }
    while (nl < width) {
      int pick = -1;
      double area = -1.0;
      for (int j = 0; j < nl; ++j)
        if (!bn[list[j]].leaf && bn[list[j]].box.area() > area)
          pick = j, area = bn[list[j]].box.area();
      if (pick < 0) break;
      const detail::BNode& p = bn[list[pick]];
      list[pick] = p.a;
      list[nl++] = p.b;
    }
    Node nd;
    for (int j = 0; j < width; ++j) {
      for (int a = 0; a < 3; ++a) {
        nd.box[a][j] = j < nl ? bn[list[j]].box.lo[a] : detail::kInf;
        nd.box[a + 3][j] = j < nl ? bn[list[j]].box.hi[a] : -detail::kInf;
      }
      nd.child[j] = 0;
      nd.count[j] = 0;
      if (j >= nl) continue;
      const detail::BNode& c = bn[list[j]];
      if (c.leaf) {
        if (packets)
          while (ids_.size() % 4) ids_.push_back(MeshHit<T>::none);
        nd.child[j] = static_cast<std::uint32_t>(ids_.size());
        nd.count[j] = c.b;
        for (std::uint32_t i = c.a; i < c.a + c.b; ++i) ids_.push_back(prims[i].id);
      } else {
        nd.child[j] = static_cast<std::uint32_t>(nodes_.size());
        nd.count[j] = internal_child;
        nodes_.push_back({});
        work.push_back({list[j], nd.child[j]});
      }
    }
    nodes_[w.node] = nd;
  }
  if (packets)
    while (ids_.size() % 4) ids_.push_back(MeshHit<T>::none);
  slot_.assign(count_, 0);
  boxes_.resize(ids_.size());
  for (std::size_t s = 0; s < ids_.size(); ++s) {
    if (ids_[s] == MeshHit<T>::none) continue;
    slot_[ids_[s]] = static_cast<std::uint32_t>(s);
    boxes_[s] = boxes[ids_[s]];
  }
}

template <Real T>
Bvh<T>::Bvh(std::span<const Vec3<T>> vertices,
            std::span<const std::array<std::uint32_t, 3>> triangles, BvhOptions options) {
  if (triangles.empty()) {
    status_ = Status::empty_input;
    return;
  }
  std::vector<AlignedBox3<T>> boxes(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    for (int k = 0; k < 3; ++k) {
      if (t[static_cast<std::size_t>(k)] >= vertices.size()) {
        status_ = Status::invalid_input;
        return;
      }
    }
    const Vec3<T>&a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    if (!is_finite(a) || !is_finite(b) || !is_finite(c)) {
      status_ = Status::non_finite_input;
      return;
    }
    boxes[i].min = cwise_min(cwise_min(a, b), c);
    boxes[i].max = cwise_max(cwise_max(a, b), c);
  }
  build(std::move(boxes), options, true);
  tris_.assign(ids_.size() / 4, Packet{});
  for (std::size_t s = 0; s < ids_.size(); ++s) {
    tris_[s / 4].id[s % 4] = ids_[s];
    if (ids_[s] == MeshHit<T>::none) continue;
    const auto& t = triangles[ids_[s]];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        tris_[s / 4].v[k][a][s % 4] = vertices[t[static_cast<std::size_t>(k)]][a];
  }
  status_ = Status::ok;
}

template <Real T>
Bvh<T> Bvh<T>::from_boxes(std::span<const AlignedBox3<T>> boxes, BvhOptions options) {
  Bvh<T> b;
  if (boxes.empty()) return b;
  for (const auto& x : boxes) {
    if (!is_finite(x.min) || !is_finite(x.max)) {
      b.status_ = Status::non_finite_input;
      return b;
    }
  }
  b.build(std::vector<AlignedBox3<T>>(boxes.begin(), boxes.end()), options, false);
  b.status_ = Status::ok;
  return b;
}

template <Real T>
Triangle3<T> Bvh<T>::triangle(std::uint32_t id) const noexcept {
  LOCUS_ASSERT(id < count_ && !tris_.empty(), "triangle index out of range");
  return detail::BvhCore<T>::tri(*this, slot_[id]);
}

template <Real T>
MeshHit<T> Bvh<T>::closest_hit(const Ray3<T>& ray, T tmax) const noexcept {
  MeshHit<T> h;
  detail::BvhCore<T>::closest_batch(*this, &ray, &h, 1, tmax);
  return h;
}

template <Real T>
bool Bvh<T>::any_hit(const Ray3<T>& ray, T tmax) const noexcept {
  std::uint8_t h = 0;
  detail::BvhCore<T>::any_batch(*this, &ray, &h, 1, tmax);
  return h != 0;
}

template <Real T>
void Bvh<T>::all_hits(const Ray3<T>& ray, T tmax, std::vector<MeshHit<T>>& out) const {
  detail::BvhCore<T>::all(*this, ray, tmax, out);
}

namespace {

template <class F>
void split_over_threads(std::size_t n, unsigned threads, F&& f) {
  const std::size_t k = std::min<std::size_t>(std::max(threads, 1u), std::max<std::size_t>(n, 1));
  if (k <= 1) {
    f(std::size_t(0), n);
    return;
  }
  std::vector<std::thread> pool;
  const std::size_t step = (n + k - 1) / k;
  for (std::size_t b = step; b < n; b += step)
    pool.emplace_back([&f, b, n, step] { f(b, std::min(n, b + step)); });
  f(std::size_t(0), std::min(n, step));
  for (auto& t : pool) t.join();
}

}  // namespace

template <Real T>
void Bvh<T>::closest_hits(std::span<const Ray3<T>> rays, std::span<MeshHit<T>> out, T tmax,
                          unsigned threads) const {
  LOCUS_ASSERT(out.size() >= rays.size(), "output span too short");
  split_over_threads(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    detail::BvhCore<T>::closest_batch(*this, rays.data() + b, out.data() + b, e - b, tmax);
  });
}

template <Real T>
void Bvh<T>::any_hits(std::span<const Ray3<T>> rays, std::span<std::uint8_t> out, T tmax,
                      unsigned threads) const {
  LOCUS_ASSERT(out.size() >= rays.size(), "output span too short");
  split_over_threads(rays.size(), threads, [&](std::size_t b, std::size_t e) {
    detail::BvhCore<T>::any_batch(*this, rays.data() + b, out.data() + b, e - b, tmax);
  });
}

template <Real T>
void Bvh<T>::visit_ray_impl(const Ray3<T>& ray, T tmax, void* ctx,
                            T (*fn)(void*, std::uint32_t, T)) const {
  detail::RayFrame fr;
  if (nodes_.empty() || !(tmax >= T(0)) || !detail::make_frame(ray, scale_exp_, fr)) return;
  float tb = detail::frame_t(fr, static_cast<double>(tmax));
  T cur = tmax;
  detail::BvhCore<T>::traverse(*this, fr, tb, true,
                               [&](std::uint32_t first, std::uint32_t count, float& tbr) {
                                 for (std::uint32_t s = first; s < first + count; ++s) {
                                   const T nt = fn(ctx, ids_[s], cur);
                                   if (nt < T(0)) return false;
                                   if (nt < cur) {
                                     cur = nt;
                                     tbr = detail::frame_t(fr, static_cast<double>(cur));
                                   }
                                 }
                                 return true;
                               });
}

template <Real T>
void Bvh<T>::visit_overlaps_impl(const AlignedBox3<T>& q, void* ctx,
                                 bool (*fn)(void*, std::uint32_t)) const {
  if (nodes_.empty() || !is_finite(q.min) || !is_finite(q.max)) return;
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = detail::round_down(std::ldexp(double(q.min[a]), -scale_exp_));
    hi[a] = detail::round_up(std::ldexp(double(q.max[a]), -scale_exp_));
  }
  std::uint32_t stack[detail::kStack];
  int sp = 0;
  stack[sp++] = 0;
  while (sp > 0) {
    const Node& nd = nodes_[stack[--sp]];
    for (int k = 0; k < width; ++k) {
      if (nd.count[k] == 0) continue;
      bool meet = true;
      for (int a = 0; a < 3; ++a) meet = meet && nd.box[a][k] <= hi[a] && lo[a] <= nd.box[a + 3][k];
      if (!meet) continue;
      if (nd.count[k] == internal_child) {
        stack[sp++] = nd.child[k];
        continue;
      }
      for (std::uint32_t s = nd.child[k]; s < nd.child[k] + nd.count[k]; ++s) {
        const AlignedBox3<T>& b = boxes_[s];
        bool m = true;
        for (int a = 0; a < 3; ++a) m = m && b.min[a] <= q.max[a] && q.min[a] <= b.max[a];
        if (m && !fn(ctx, ids_[s])) return;
      }
    }
  }
}

template <Real T>
Distance<T, 3, NoParam, MeshPoint<T>> Bvh<T>::nearest(const Vec3<T>& p) const noexcept {
  if (tris_.empty() || status_ != Status::ok || !is_finite(p))
    return detail::mesh_nan_distance<T>();
  Vec3<double> ps{};
  double pm = 0.0;
  for (int a = 0; a < 3; ++a) {
    ps[a] = std::ldexp(double(p[a]), -scale_exp_);
    pm = std::max(pm, std::abs(ps[a]));
  }
  // A box is skipped when its distance exceeds the best one by more than any rounding of the
  // point-triangle distances (docs/notes/spatial.md).
  const double slack = 0x1p-16 * (1.0 + pm);
  T best = std::numeric_limits<T>::infinity();
  double bound2 = std::numeric_limits<double>::infinity();
  std::uint32_t best_id = MeshPoint<T>::none;
  Vec3<T> q{};
  Vec3<T> bary{};
  struct E {
    std::uint32_t child, count;
    double lb;
  };
  E stack[detail::kStack];
  int sp = 0;
  stack[sp++] = {0, internal_child, 0.0};
  while (sp > 0) {
    const E e = stack[--sp];
    if (e.lb > bound2) continue;
    if (e.count != internal_child) {
      for (std::uint32_t s = e.child; s < e.child + e.count; ++s) {
        const std::uint32_t id = ids_[s];
        const auto r = distance(p, detail::BvhCore<T>::tri(*this, s));
        if (r.sqr_distance < best || (r.sqr_distance == best && id < best_id)) {
          best = r.sqr_distance;
          best_id = id;
          q = r.closest[1];
          bary = r.param_b;
          const double b = std::sqrt(std::ldexp(double(best), -2 * scale_exp_)) + slack;
          bound2 = b * b * (1.0 + 0x1p-40);
        }
      }
      continue;
    }
    const Node& nd = nodes_[e.child];
    E hit[width];
    int nh = 0;
    for (int k = 0; k < width; ++k) {
      if (nd.count[k] == 0) continue;
      double lb = 0.0;
      for (int a = 0; a < 3; ++a) {
        const double lo = nd.box[a][k], hi = nd.box[a + 3][k];
        const double x = ps[a] < lo ? lo - ps[a] : (ps[a] > hi ? ps[a] - hi : 0.0);
        lb += x * x;
      }
      if (lb > bound2) continue;
      hit[nh++] = {nd.child[k], nd.count[k], lb};
    }
    for (int i = 1; i < nh; ++i)
      for (int j = i; j > 0 && hit[j - 1].lb < hit[j].lb; --j) std::swap(hit[j - 1], hit[j]);
    for (int i = 0; i < nh; ++i) stack[sp++] = hit[i];
  }
  return detail::make_distance(p, q, NoParam{}, MeshPoint<T>{best_id, bary}, true);
}

template class Bvh<float>;
template class Bvh<double>;

}  // namespace locus
