// SPDX-License-Identifier: BSL-1.0
#pragma once
// Private to the library's SIMD kernels: W queries at once in the lanes of one SIMD register, for
// the batched distance queries of include/locus/distance/batch.hpp (src/distance/batch*.cpp) and
// the BVH traversal (src/spatial/bvh.cpp); in core because both areas use it. The version in use
// is core's detail::batch_isa() (include/locus/core/detail/batch_isa.hpp).
//
// Lanes<T>::V is a GCC/Clang vector of W = 32 / sizeof(T) values (4 doubles or 8 floats: one AVX
// register; the compiler splits it into two SSE registers where AVX is not enabled). Arithmetic is
// the compiler's element-wise + - * /, each lane rounded exactly as the scalar operation, so a
// kernel that performs the same operations in the same order as a scalar query gives the same
// bits in every lane (with floating-point contraction off: batch*.cpp are compiled with
// -ffp-contract=off). Comparisons give Lanes<T>::M, a mask of all-ones / all-zeros integers per
// lane; sel(m, a, b) is the lane-wise m ? a : b (a blend), which is how the scalar queries'
// selects and `x < y ? x : y` minima are mirrored.
//
// Objects are read in groups of W consecutive queries (Group, gather()): lane k holds query i + k;
// the last, partial group is copied to a local array with the last query repeated (its lanes are
// computed and discarded), so a kernel never reads out of bounds and needs no scalar tail loop.
// The W objects of a group are consecutive, so gather3() reads a Vec3 inside them with one vector
// load per object and transposes in registers (load_columns4).
// A source with stride 0 is one object broadcast to every query (the "one against many"
// overloads).

#include <locus/config.hpp>
#include <locus/core/detail/batch_isa.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstddef>
#include <cstring>
#include <functional>
#include <type_traits>
#include <utility>

// Everything a kernel calls is inlined into the driver (LOCUS_ALWAYS_INLINE, and
// LOCUS_ALWAYS_INLINE_LAMBDA for lambdas), so that it is compiled for the driver's instruction set
// and no vector crosses a call.

// The batch drivers are compiled three times on x86-64 (LOCUS_LANE_VERSIONS): for x86-64-v4
// (AVX-512: the same 32-byte vectors, but 32 registers, so fewer spills, and mask registers), for
// AVX2 and for the baseline instruction set; detail::batch_isa() (simd_level.cpp) picks one at
// the call from the running processor, capped by detail::set_batch_isa() so that tests exercise
// every version on one machine. Elsewhere, or with -DLOCUS_NO_MULTIVERSION, once, for whatever
// the compiler targets. The kernels are inlined into each version (a callee without a target
// attribute may be inlined into any target), so each is compiled for its version's instructions.
#if defined(__x86_64__) && defined(__has_attribute) && !defined(LOCUS_NO_MULTIVERSION)
#if __has_attribute(target)
#define LOCUS_LANE_MULTIVERSION 1
#endif
#endif

// LOCUS_LANE_VERSIONS(name, (params), call): defines name_v4, name_avx2 and name_baseline, each
// with the parameter list params and the body `call;` compiled for its instruction set, and
// name_versions, whose pick() is the version detail::batch_isa() permits.
#ifdef LOCUS_LANE_MULTIVERSION
#define LOCUS_LANE_VERSIONS(name, params, call)                                      \
  __attribute__((target("arch=x86-64-v4"))) void name##_v4 params { call; }          \
  __attribute__((target("avx2"))) void name##_avx2 params { call; }                  \
  void name##_baseline params { call; }                                              \
  [[maybe_unused]] constexpr auto name##_versions =                                  \
      ::locus::lanes::Versions<decltype(&name##_baseline)>{&name##_v4, &name##_avx2, \
                                                           &name##_baseline};
#else
#define LOCUS_LANE_VERSIONS(name, params, call)                                                \
  void name##_baseline params { call; }                                                        \
  [[maybe_unused]] constexpr auto name##_versions =                                            \
      ::locus::lanes::Versions<decltype(&name##_baseline)>{&name##_baseline, &name##_baseline, \
                                                           &name##_baseline};
#endif

namespace locus::lanes {

/// The versions of one driver, best instruction set first; pick() is the one detail::batch_isa()
/// permits.
template <class Fn>
struct Versions {
  Fn v4, avx2, baseline;
  [[nodiscard]] Fn pick() const noexcept {
    switch (detail::batch_isa()) {
      case detail::BatchIsa::x86_64_v4:
        return v4;
      case detail::BatchIsa::avx2:
        return avx2;
      default:
        return baseline;
    }
  }
};

template <Real T>
struct Lanes {
  static constexpr int W = static_cast<int>(32 / sizeof(T));
  typedef T V __attribute__((vector_size(32)));
  using M = decltype(V{} < V{});
};

template <Real T>
using V = typename Lanes<T>::V;
template <Real T>
using M = typename Lanes<T>::M;

/// Every lane = x.
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> splat(T x) {
  return V<T>{} + x;
}

/// Lane-wise m ? a : b.
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> sel(M<T> m, V<T> a, V<T> b) {
  return m ? a : b;
}

/// Lane-wise (x < lo ? lo : x), then (hi < that ? hi : that): detail::clamp_minmax.
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> clamp_minmax(V<T> x, V<T> lo, V<T> hi) {
  const V<T> above = sel<T>(x < lo, lo, x);
  return sel<T>(hi < above, hi, above);
}

/// Lane-wise |x|.
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> abs(V<T> x) {
  return sel<T>(x < T(0), -x, x);
}

/// Lanes whose value is finite (x - x is 0 for finite x, NaN otherwise).
template <Real T>
LOCUS_ALWAYS_INLINE inline M<T> finite(V<T> x) {
  return (x - x) == V<T>{};
}

/// True when some lane of m is set.
template <Real T>
LOCUS_ALWAYS_INLINE inline bool any(M<T> m) {
  for (int k = 0; k < Lanes<T>::W; ++k)
    if (m[k]) return true;
  return false;
}

/// True when every lane of m is set.
template <Real T>
LOCUS_ALWAYS_INLINE inline bool all(M<T> m) {
  for (int k = 0; k < Lanes<T>::W; ++k)
    if (!m[k]) return false;
  return true;
}

/// Lane-wise two_sum (core/error_free.hpp): s + e = a + b exactly, the same operations.
template <Real T>
LOCUS_ALWAYS_INLINE inline void two_sum(V<T> a, V<T> b, V<T>& s, V<T>& e) {
  s = a + b;
  const V<T> b_virtual = s - a;
  const V<T> a_virtual = s - b_virtual;
  e = (a - a_virtual) + (b - b_virtual);
}

/// Lane-wise product_error of core/error_free.hpp without FMA (Dekker's product with Veltkamp's
/// split), for double: a b - p exactly in the range that header states, where it equals the
/// FMA's error.
template <class T = double>
LOCUS_ALWAYS_INLINE inline V<T> product_error_dekker(V<T> a, V<T> b, V<T> p) {
  static_assert(std::is_same_v<T, double>, "the splitting constant is double's");
  constexpr T splitter = 0x1p27 + 1.0;
  const V<T> ta = splitter * a, tb = splitter * b;
  const V<T> ah = ta - (ta - a), al = a - ah;
  const V<T> bh = tb - (tb - b), bl = b - bh;
  return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

/// A 3D vector per lane, with the scalar Vec3 operations in the same evaluation order as
/// core/vec.hpp (dot = (x x' + y y') + z z').
template <Real T>
struct V3 {
  V<T> x, y, z;
};
template <Real T>
LOCUS_ALWAYS_INLINE inline V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <Real T>
LOCUS_ALWAYS_INLINE inline V3<T> operator+(const V3<T>& a, const V3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <Real T>
LOCUS_ALWAYS_INLINE inline V3<T> operator*(V<T> s, const V3<T>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
/// detail::sqr_cross_norm for N = 3: the squared 2x2 minors (x, y), (x, z), (y, z) summed in that
/// order onto 0.
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> sqr_cross_norm(const V3<T>& a, const V3<T>& b) {
  const V<T> m01 = a.x * b.y - a.y * b.x, m02 = a.x * b.z - a.z * b.x;
  const V<T> m12 = a.y * b.z - a.z * b.y;
  return ((V<T>{} + m01 * m01) + m02 * m02) + m12 * m12;
}
/// core/vec.hpp lerp: (1 - t) a + t b per coordinate.
template <Real T>
LOCUS_ALWAYS_INLINE inline V3<T> lerp(const V3<T>& a, const V3<T>& b, V<T> t) {
  const V<T> u = T(1) - t;
  return {u * a.x + t * b.x, u * a.y + t * b.y, u * a.z + t * b.z};
}
template <Real T>
LOCUS_ALWAYS_INLINE inline V3<T> sel(M<T> m, const V3<T>& a, const V3<T>& b) {
  return {sel<T>(m, a.x, b.x), sel<T>(m, a.y, b.y), sel<T>(m, a.z, b.z)};
}
/// finite_zero of one vector: (x 0 + y 0) + z 0 (0 for finite coordinates, NaN otherwise).
template <Real T>
LOCUS_ALWAYS_INLINE inline V<T> finite_zero(const V3<T>& a) {
  return a.x * T(0) + a.y * T(0) + a.z * T(0);
}

/// One input of a batch: `stride` 1 for an array of objects, 0 for one object shared by all.
template <class Obj>
struct Source {
  const Obj* data;
  std::size_t stride;
};

/// The objects of W consecutive queries: lane k reads p[k] (kStep) or *p (a broadcast object).
/// The step is a compile-time constant so that every lane's fields are loaded at fixed offsets.
template <class Obj, bool kStep>
struct Group {
  static constexpr bool kBroadcast = !kStep;  // one object in every lane
  const Obj* p;
  [[nodiscard]] LOCUS_ALWAYS_INLINE inline const Obj& operator[](std::size_t k) const {
    return kStep ? p[k] : *p;
  }
};

/// Lane k = field(group[k]) for a scalar field.
template <class T, class G, class Field>
LOCUS_ALWAYS_INLINE inline V<T> gather(const G& g, Field field) {
  return [&]<std::size_t... k>(std::index_sequence<k...>) LOCUS_ALWAYS_INLINE_LAMBDA {
    return V<T>{field(g[k])...};
  }
  (std::make_index_sequence<Lanes<T>::W>{});
}

/// An unaligned load of n scalars T (a whole vector by default) from any object's bytes, as one
/// instruction. (A memcpy into a vector was split by GCC, for AVX2, into two 16-byte moves through
/// the stack, and the 32-byte reload stalled on store forwarding: 2x-3x slower kernels.)
template <class T, int n = Lanes<T>::W>
LOCUS_ALWAYS_INLINE inline auto load_unaligned(const void* p) {
  typedef T U __attribute__((vector_size(n * sizeof(T)), aligned(alignof(T)), may_alias));
  typedef T R __attribute__((vector_size(n * sizeof(T))));
  return R(*static_cast<const U*>(p));
}

/// Scalars start .. start + 3 of each of W consecutive objects made of scalars T, transposed:
/// element j of the result holds scalar start + j of every object. One 4-scalar load per object
/// and two rounds of in-lane or half-swapping shuffles, instead of W scalar loads and inserts per
/// result.
template <class T, class Obj>
LOCUS_ALWAYS_INLINE inline std::array<V<T>, 4> load_columns4(const Obj* objs, int start) {
  const auto at = [&](int k) LOCUS_ALWAYS_INLINE_LAMBDA {
    return reinterpret_cast<const unsigned char*>(objs + k) + start * sizeof(T);
  };
  if constexpr (Lanes<T>::W == 4) {
    const V<T> r0 = load_unaligned<T>(at(0)), r1 = load_unaligned<T>(at(1));
    const V<T> r2 = load_unaligned<T>(at(2)), r3 = load_unaligned<T>(at(3));
    const V<T> t0 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6);  // c0 c0 c2 c2
    const V<T> t1 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);  // c1 c1 c3 c3
    const V<T> t2 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6);
    const V<T> t3 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
    return {
        __builtin_shufflevector(t0, t2, 0, 1, 4, 5), __builtin_shufflevector(t1, t3, 0, 1, 4, 5),
        __builtin_shufflevector(t0, t2, 2, 3, 6, 7), __builtin_shufflevector(t1, t3, 2, 3, 6, 7)};
  } else {
    static_assert(Lanes<T>::W == 8);
    // Objects k and k + 4, one per half.
    const auto pair = [&](int k) LOCUS_ALWAYS_INLINE_LAMBDA {
      return __builtin_shufflevector(load_unaligned<T, 4>(at(k)), load_unaligned<T, 4>(at(k + 4)),
                                     0, 1, 2, 3, 4, 5, 6, 7);
    };
    const V<T> r0 = pair(0), r1 = pair(1), r2 = pair(2), r3 = pair(3);
    const V<T> t0 = __builtin_shufflevector(r0, r1, 0, 8, 1, 9, 4, 12, 5, 13);    // c0 c0 c1 c1
    const V<T> t1 = __builtin_shufflevector(r0, r1, 2, 10, 3, 11, 6, 14, 7, 15);  // c2 c2 c3 c3
    const V<T> t2 = __builtin_shufflevector(r2, r3, 0, 8, 1, 9, 4, 12, 5, 13);
    const V<T> t3 = __builtin_shufflevector(r2, r3, 2, 10, 3, 11, 6, 14, 7, 15);
    return {__builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13),
            __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15),
            __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13),
            __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15)};
  }
}

/// Lanes of a Vec3 of the objects: std::invoke(member, obj) is that Vec3 (a pointer to a data
/// member such as &Triangle3<T>::v0, std::identity{} for the objects themselves, or a lambda).
/// A Vec3 inside consecutive objects made of at least 4 scalars (member returns a reference into
/// the object) is loaded by load_columns4, from its first scalar on, or from the object's last 4
/// scalars when it ends the object, so that no load reads past the group's last object; anything
/// else lane by lane.
template <class T, class G, class Member>
LOCUS_ALWAYS_INLINE inline V3<T> gather3(const G& g, Member member) {
  using Obj = std::remove_cvref_t<decltype(g[0])>;
  constexpr int K = static_cast<int>(sizeof(Obj) / sizeof(T));
  if constexpr (!G::kBroadcast &&
                std::is_lvalue_reference_v<std::invoke_result_t<Member, const Obj&>> &&
                std::is_trivially_copyable_v<Obj> && sizeof(Obj) == K * sizeof(T) && K >= 4) {
    const int off =
        static_cast<int>((reinterpret_cast<const unsigned char*>(&std::invoke(member, *g.p)) -
                          reinterpret_cast<const unsigned char*>(g.p)) /
                         sizeof(T));
    const int start = off + 4 <= K ? off : K - 4;
    const std::array<V<T>, 4> c = load_columns4<T>(g.p, start);
    return {c[off - start], c[off - start + 1], c[off - start + 2]};
  }
  return {gather<T>(g, [&](const auto& o)
                           LOCUS_ALWAYS_INLINE_LAMBDA { return std::invoke(member, o).x; }),
          gather<T>(g, [&](const auto& o)
                           LOCUS_ALWAYS_INLINE_LAMBDA { return std::invoke(member, o).y; }),
          gather<T>(g, [&](const auto& o)
                           LOCUS_ALWAYS_INLINE_LAMBDA { return std::invoke(member, o).z; })};
}

/// What a kernel returns for W queries: the squared distances, and the lanes the kernel does not
/// handle (they are recomputed by the scalar query).
template <Real T>
struct Result {
  V<T> sqr;
  M<T> scalar;
};

template <class T, int kUnroll, bool kStepA, bool kStepB, class A, class B, class Kernel,
          class Scalar>
LOCUS_ALWAYS_INLINE inline void run_groups(const Source<A>& a, const Source<B>& b, T* out,
                                           std::size_t n, Kernel kernel, Scalar scalar) {
  constexpr std::size_t W = Lanes<T>::W;
  const auto finish = [&](const Result<T>& r, std::size_t i,
                          std::size_t m) LOCUS_ALWAYS_INLINE_LAMBDA {
    T values[W];
    std::memcpy(values, &r.sqr, sizeof values);
    if (any<T>(r.scalar))
      for (std::size_t k = 0; k < m; ++k)
        if (r.scalar[k]) values[k] = scalar(a.data[(i + k) * a.stride], b.data[(i + k) * b.stride]);
    std::memcpy(out + i, values, m * sizeof(T));
  };
  // One call site of the kernel (it is large): the last, partial group reads copies of its
  // queries with the last one repeated to fill the group.
  A ta[W];
  B tb[W];
  // A broadcast object is copied first: out cannot alias the copy, so the compiler may hoist
  // the kernel's work on that object out of the loop.
  const A one_a = *a.data;
  const B one_b = *b.data;
  std::size_t i0 = 0;
  if constexpr (kUnroll == 2) {
    // Two independent groups per step: their dependency chains (divisions feeding projections)
    // overlap in the out-of-order window, which one large group's cannot.
    for (; i0 + 2 * W <= n; i0 += 2 * W) {
      const Result<T> r0 = kernel(Group<A, kStepA>{kStepA ? a.data + i0 : &one_a},
                                  Group<B, kStepB>{kStepB ? b.data + i0 : &one_b});
      const Result<T> r1 = kernel(Group<A, kStepA>{kStepA ? a.data + i0 + W : &one_a},
                                  Group<B, kStepB>{kStepB ? b.data + i0 + W : &one_b});
      finish(r0, i0, W);
      finish(r1, i0 + W, W);
    }
  }
  for (std::size_t i = i0; i < n; i += W) {
    const A* pa = kStepA ? a.data + i : &one_a;
    const B* pb = kStepB ? b.data + i : &one_b;
    const std::size_t m = n - i < W ? n - i : W;
    if (m < W) {
      for (std::size_t k = 0; k < W; ++k) {
        const std::size_t j = i + (k < m ? k : m - 1);
        if constexpr (kStepA) ta[k] = a.data[j];
        if constexpr (kStepB) tb[k] = b.data[j];
      }
      if constexpr (kStepA) pa = ta;
      if constexpr (kStepB) pb = tb;
    }
    finish(kernel(Group<A, kStepA>{pa}, Group<B, kStepB>{pb}), i, m);
  }
}

/// Runs kernel(group_a, group_b) over the n queries W at a time, writes the squared distances to
/// out, and recomputes the lanes the kernel hands back with the scalar query (scalar(a, b)).
/// kUnroll = 2 evaluates two groups per step (for the smaller kernels: it doubles the code).
template <class T, int kUnroll = 1, class A, class B, class Kernel, class Scalar>
LOCUS_ALWAYS_INLINE inline void run(const Source<A>& a, const Source<B>& b, T* out, std::size_t n,
                                    Kernel kernel, Scalar scalar) {
  if (n == 0) return;  // the spans' data may then be null
  if (a.stride != 0 && b.stride != 0)
    run_groups<T, kUnroll, true, true>(a, b, out, n, kernel, scalar);
  else if (a.stride != 0)
    run_groups<T, kUnroll, true, false>(a, b, out, n, kernel, scalar);
  else
    run_groups<T, kUnroll, false, true>(a, b, out, n, kernel, scalar);
}

}  // namespace locus::lanes
