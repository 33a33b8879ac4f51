// SPDX-License-Identifier: BSL-1.0
// Welzl's move-to-front smallest enclosing ball in 2D and 3D (bounding/min_circle.hpp,
// bounding/min_sphere.hpp; row cg.minball).

#include <locus/bounding/detail/ball_predicates.hpp>
#include <locus/bounding/min_circle.hpp>
#include <locus/bounding/min_sphere.hpp>
#include <locus/bounding/simplex_balls.hpp>
#include <locus/core/predicates.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace locus {
namespace {

// splitmix64: a tiny, portable generator so a seed gives the same permutation everywhere.
struct SplitMix {
  std::uint64_t state;
  std::uint64_t next() noexcept {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, bound) by rejection (no modulo bias).
  std::uint64_t below(std::uint64_t bound) noexcept {
    const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                                std::numeric_limits<std::uint64_t>::max() % bound;
    for (;;) {
      const std::uint64_t x = next();
      if (x < limit) return x % bound;
    }
  }
};

// The directions whose extreme points seed the search (both ends of each).
template <int D>
inline constexpr int kDirs = D == 2 ? 4 : 7;

template <int D>
void keys_of(const Vec<double, D>& p, double* key) noexcept {
  if constexpr (D == 2) {
    key[0] = p.x, key[1] = p.y, key[2] = p.x + p.y, key[3] = p.x - p.y;
  } else {
    key[0] = p.x, key[1] = p.y, key[2] = p.z, key[3] = p.x + p.y + p.z;
    key[4] = p.x + p.y - p.z, key[5] = p.x - p.y + p.z, key[6] = -p.x + p.y + p.z;
  }
}

template <class T, int D>
void extremes_of(std::span<const Vec<T, D>> pts, std::uint32_t* lo, std::uint32_t* hi) noexcept {
  double lov[kDirs<D>], hiv[kDirs<D>];
  for (int k = 0; k < kDirs<D>; ++k) {
    lov[k] = std::numeric_limits<double>::infinity();
    hiv[k] = -lov[k];
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    double key[kDirs<D>];
    keys_of<D>(vec_cast<double>(pts[i]), key);
    for (int k = 0; k < kDirs<D>; ++k) {
      if (key[k] < lov[k]) lov[k] = key[k], lo[k] = static_cast<std::uint32_t>(i);
      if (key[k] > hiv[k]) hiv[k] = key[k], hi[k] = static_cast<std::uint32_t>(i);
    }
  }
}

template <int D>
void extremes(const std::vector<Vec<double, D>>& pts, std::uint32_t* lo,
              std::uint32_t* hi) noexcept {
  extremes_of<double, D>(std::span<const Vec<double, D>>(pts), lo, hi);
}

// The move-to-front engine over points of type Vec<T, D>. Support sets of size k define the
// smallest ball with those k points on its boundary; `outside` is an exact decision against
// them, the centre/radius are only for the output.
template <int D>
class Engine {
 public:
  using P = Vec<double, D>;

  Engine(const std::vector<P>& pts, std::vector<std::uint32_t>& next,
         std::vector<std::uint32_t>& prev, std::uint64_t budget) noexcept
      : pts_(pts), next_(next), prev_(prev), budget_(budget) {}

  // Returns false when the budget ran out or an impossible degeneracy showed up.
  bool run(std::uint32_t head, std::uint32_t tail) {
    head_ = head;
    mtf(tail, 0);
    return !failed_;
  }

  int support_count() const noexcept { return cur_k_; }
  std::uint32_t support(int i) const noexcept { return cur_[i]; }
  std::uint64_t tests() const noexcept { return tests_; }
  /// Exact: is p strictly outside the current ball?
  bool outside_point(const P& p) const noexcept { return outside_p(p); }
  bool exhausted() const noexcept { return exhausted_; }

  // The rounded centre and radius of the current ball.
  void ball(P& center, double& radius) const noexcept {
    P s[D + 1] = {};
    for (int i = 0; i < cur_k_; ++i) s[i] = point(cur_[i]);
    if (cur_k_ == 1) {
      center = s[0];
    } else if (cur_k_ == 2) {
      center = 0.5 * s[0] + 0.5 * s[1];  // no overflow for huge coordinates
    } else if (cur_k_ == 3) {
      center = detail::circumcenter(s[0], s[1], s[2]);
    } else {
      if constexpr (D == 3) center = detail::circumcenter(s[0], s[1], s[2], s[3]);
    }
    radius = 0.0;
    for (int i = 0; i < cur_k_; ++i)
      radius = std::max(radius, detail::scaled_length(s[i] - center));
  }

 private:
  const P& point(std::uint32_t i) const noexcept { return pts_[i]; }

  // Exact: is point i strictly outside the current ball? (The deep-inside shortcut is
  // explained in min_circle.hpp.)
  bool outside(std::uint32_t i) const noexcept { return outside_p(point(i)); }
  bool outside_p(const P& p) const noexcept {
    if (use_shortcut_ && sqr_length(p - center_) <= inner_r2_) return false;
    switch (cur_k_) {
      case 0:
        return true;
      case 1:
        return !(p == s_[0]);
      case 2:
        return detail::diametral_side<D>(p, s_[0], s_[1]) == Sign::positive;
      case 3:
        if constexpr (D == 2) {
          return incircle(s_[0], s_[1], s_[2], p) * orientation_ == Sign::negative;
        } else {
          return detail::circumcircle_sphere_side(s_[0], s_[1], s_[2], p) == Sign::positive;
        }
      default:
        if constexpr (D == 3) {
          return insphere(s_[0], s_[1], s_[2], s_[3], p) * orientation_ == Sign::negative;
        } else {
          return false;
        }
    }
  }

  // Make stack_[0..k) the current support set. Returns false for an affinely dependent set,
  // which exact decisions never produce (kept as a guard, reported as a failure).
  bool set_support(int k) noexcept {
    cur_k_ = k;
    for (int i = 0; i < k; ++i) {
      cur_[i] = stack_[i];
      s_[i] = point(stack_[i]);
    }
    bool ok = true;
    if constexpr (D == 2) {
      if (k == 3) {
        orientation_ = orient2d(s_[0], s_[1], s_[2]);
        ok = orientation_ != Sign::zero;
      }
    } else {
      if (k == 3) ok = !is_degenerate(Triangle<double, 3>{s_[0], s_[1], s_[2]});
      if (k == 4) {
        orientation_ = orient3d(s_[0], s_[1], s_[2], s_[3]);
        ok = orientation_ != Sign::zero;
      }
    }
    update_shortcut();
    return ok;
  }

  // The rounded ball and whether its deep interior may skip the exact test: only when the
  // support set's condition estimate kappa bounds the centre's error far below the margin.
  void update_shortcut() noexcept {
    use_shortcut_ = false;
    if (cur_k_ < 2) return;
    // kappa is a ratio of products of up to six edge coordinates: computed on the edges scaled
    // by a power of two, so it is the same at every scale of the input.
    double kappa = 1.0;
    P e[D] = {};
    double m = 0.0;
    for (int i = 1; i < cur_k_; ++i) {
      e[i - 1] = s_[i] - s_[0];
      m = std::max(m, max_abs(e[i - 1]));
    }
    const double f = detail::product_scale<6>(m);
    const P u = f * e[0];
    if (cur_k_ == 3) {
      const P v = f * e[1];
      double area2 = 0.0;
      if constexpr (D == 2) {
        area2 = std::abs(perp_dot(u, v));
      } else {
        area2 = length(cross(u, v));
      }
      kappa = (sqr_length(u) + sqr_length(v)) / area2;
    } else if (cur_k_ == 4) {
      if constexpr (D == 3) {
        const P v = f * e[1], w = f * e[2];
        const double det = std::abs(dot(u, cross(v, w)));
        const double adj =
            std::sqrt(sqr_length(cross(v, w)) + sqr_length(cross(w, u)) + sqr_length(cross(u, v)));
        kappa = std::sqrt(sqr_length(u) + sqr_length(v) + sqr_length(w)) * adj / det;
      }
    }
    if (!(kappa <= 0x1p20)) return;
    double radius = 0.0;
    ball(center_, radius);
    // Absolute roundings (the centre = s0 + offset, the differences p - c) are eps |s0|: keep
    // them below 2^-33 r as well.
    if (!(max_abs(s_[0]) <= 0x1p20 * radius)) return;
    inner_r2_ = radius * radius * (1.0 - 0x1p-20);
    use_shortcut_ = std::isfinite(inner_r2_) && inner_r2_ > 0x1p-900 && is_finite(center_);
  }

  void move_to_front(std::uint32_t it) noexcept {
    const std::uint32_t p = prev_[it], n = next_[it];
    if (p == head_) return;
    next_[p] = n;
    prev_[n] = p;
    const std::uint32_t first = next_[head_];
    next_[it] = first;
    prev_[first] = it;
    next_[head_] = it;
    prev_[it] = head_;
  }

  // The smallest ball of the list's points before `end` with stack_[0..k) on its boundary,
  // assuming the current ball already has them on its boundary.
  void mtf(std::uint32_t end, int k) {
    if (k == D + 1) return;
    std::uint32_t it = next_[head_];
    while (it != end) {
      if (++tests_ > budget_) {
        exhausted_ = failed_ = true;
        return;
      }
      if (outside(it)) {
        stack_[k] = it;
        if (!set_support(k + 1)) {
          failed_ = true;
          return;
        }
        mtf(it, k + 1);
        if (failed_) return;
        const std::uint32_t n = next_[it];
        move_to_front(it);
        it = n;
      } else {
        it = next_[it];
      }
    }
  }

  const std::vector<P>& pts_;
  std::vector<std::uint32_t>& next_;
  std::vector<std::uint32_t>& prev_;
  std::uint64_t budget_;
  std::uint64_t tests_ = 0;
  std::uint32_t head_ = 0;
  std::uint32_t stack_[D + 1] = {};
  std::uint32_t cur_[D + 1] = {};
  P s_[D + 1] = {};
  int cur_k_ = 0;
  Sign orientation_ = Sign::zero;
  P center_{};
  double inner_r2_ = 0.0;
  bool use_shortcut_ = false;
  bool failed_ = false;
  bool exhausted_ = false;
};

// The power of two by which the input is scaled, exactly, before the search. Far from 1 (at
// 2^-500) the predicates' filters underflow and the deep-inside shortcut (which needs r^2 above
// 2^-900) is off, so every decision takes the exact path, about 200 times slower: such input is
// brought to largest |coordinate| hi in [1, 2). Scaling up is always exact; scaling down stops
// where the smallest nonzero |coordinate| would leave the normal range. Within [2^-256, 2^256]
// the fast paths work as they are and the input is used unscaled (the decisions are exact and
// the constructions scale-covariant, so the result is the same either way).
template <class T, int D>
double input_scale(std::span<const Vec<T, D>> pts, double hi) noexcept {
  if (hi >= 0x1p-256 && hi <= 0x1p256) return 1.0;
  const double f = normalising_scale(hi);
  if (f >= 1.0) return f;
  double lo = std::numeric_limits<double>::infinity();
  for (const Vec<T, D>& p : pts)
    for (int i = 0; i < D; ++i) {
      const double a = std::abs(static_cast<double>(p[i]));
      if (a > 0.0) lo = std::min(lo, a);
    }
  if (!(lo < std::numeric_limits<double>::infinity())) return f;
  // lo * 2^j stays normal for j >= min_exponent - 1 - ilogb(lo).
  const int floor_exp = std::numeric_limits<double>::min_exponent - 1 - std::ilogb(lo);
  return floor_exp >= 0 ? 1.0 : std::max(f, std::ldexp(1.0, floor_exp));
}

struct Solved {
  Status status;
  int support_count;
  std::uint32_t support[4];
  std::uint64_t tests;
};

// Fills copy/order with the points `ids` (original indices) in a seeded random order, the
// extreme points along a few fixed directions first (a heuristic: the first ball is then nearly
// final; the result does not depend on it), and links them into the list head -> ... -> tail.
template <class T, int D>
void prepare(std::span<const Vec<T, D>> pts, double scale, std::span<const std::uint32_t> ids,
             const MinBallOptions& options, std::vector<std::uint32_t>& next,
             std::vector<std::uint32_t>& prev, std::vector<std::uint32_t>& order,
             std::vector<Vec<double, D>>& copy) {
  const auto m = static_cast<std::uint32_t>(ids.size());
  const std::uint32_t head = m, tail = m + 1;
  next.resize(m + 2u);
  prev.resize(m + 2u);
  order.assign(ids.begin(), ids.end());
  copy.resize(m);
  if (options.shuffle) {
    SplitMix rng{options.seed};
    for (std::uint32_t i = m - 1; i > 0; --i) {
      const auto j = static_cast<std::uint32_t>(rng.below(std::uint64_t{i} + 1));
      std::swap(order[i], order[j]);
    }
  }
  for (std::uint32_t i = 0; i < m; ++i) copy[i] = vec_cast<double>(pts[order[i]]) * scale;
  std::uint32_t lo[kDirs<D>] = {}, hi[kDirs<D>] = {};
  extremes<D>(copy, lo, hi);
  std::uint32_t front = 0;
  for (int k = 0; k < 2 * kDirs<D>; ++k) {
    const std::uint32_t pos = k % 2 == 0 ? lo[k / 2] : hi[k / 2];
    if (pos < front) continue;  // already moved (a repeated extreme)
    std::swap(copy[pos], copy[front]);
    std::swap(order[pos], order[front]);
    for (int q = k + 1; q < 2 * kDirs<D>; ++q) {  // extremes that were at `front` are now at pos
      std::uint32_t& r = q % 2 == 0 ? lo[q / 2] : hi[q / 2];
      if (r == front) r = pos;
    }
    ++front;
  }
  next[head] = m == 0 ? tail : 0;
  prev[head] = head;
  for (std::uint32_t i = 0; i < m; ++i) {
    next[i] = i + 1 < m ? i + 1 : tail;
    prev[i] = i == 0 ? head : i - 1;
  }
  prev[tail] = m == 0 ? head : m - 1;
  next[tail] = tail;
}

// The ball of the engine's support set, back in the input's units (division by a power of two).
template <int D>
void finish(const Engine<D>& engine, double scale, Vec<double, D>& center, double& radius) {
  engine.ball(center, radius);
  center = center / scale;
  radius = radius / scale;
}

template <class T, int D>
Solved solve(std::span<const Vec<T, D>> pts, const MinBallOptions& options,
             std::vector<std::uint32_t>& next, std::vector<std::uint32_t>& prev,
             std::vector<std::uint32_t>& order, std::vector<Vec<double, D>>& copy,
             Vec<double, D>& center, double& radius) {
  Solved out{Status::empty_input, 0, {}, 0};
  if (pts.empty()) return out;
  if (pts.size() > std::numeric_limits<std::uint32_t>::max() - 2u) {
    out.status = Status::invalid_input;
    return out;
  }
  // One pass for the finiteness check and the largest |coordinate|, without early exit and
  // with one accumulator per coordinate (independent chains: this pass is on the critical path
  // of a search that costs a few ns a point).
  double cmax[D] = {};
  bool finite = true;
  for (const Vec<T, D>& p : pts)
    for (int i = 0; i < D; ++i) {
      const double a = std::abs(static_cast<double>(p[i]));
      finite &= a <= std::numeric_limits<double>::max();
      cmax[i] = a > cmax[i] ? a : cmax[i];
    }
  if (!finite) {
    out.status = Status::non_finite_input;
    return out;
  }
  const auto n = static_cast<std::uint32_t>(pts.size());
  const double scale = input_scale(pts, *std::max_element(cmax, cmax + D));
  const std::uint64_t budget =
      options.max_tests != 0 ? options.max_tests : 1000u * std::uint64_t{n} + 1000000u;
  std::uint64_t tests = 0;

  // Rounds on a growing subset S (a core set): S starts as the extreme points; the smallest
  // ball of S is computed by move-to-front; one sequential scan of all points adds those outside
  // it. When none is outside, the ball of S is the ball of all points (it contains them and no
  // smaller ball contains S). After a few rounds, or when S would grow large, the plain
  // algorithm runs on all points (so the expected O(n) bound holds whatever the input).
  std::vector<std::uint32_t> subset;
  {
    std::uint32_t lo[kDirs<D>] = {}, hi[kDirs<D>] = {};
    extremes_of<T, D>(pts, lo, hi);
    for (int k = 0; k < kDirs<D>; ++k) {
      subset.push_back(lo[k]);
      subset.push_back(hi[k]);
    }
    std::sort(subset.begin(), subset.end());
    subset.erase(std::unique(subset.begin(), subset.end()), subset.end());
  }
  const std::size_t subset_limit = std::max<std::size_t>(256, n / 16);
  std::vector<std::uint32_t> extra;
  bool use_all = subset.size() >= n;
  for (int round = 0; !use_all; ++round) {
    if (round == 8 || subset.size() > subset_limit) {
      use_all = true;
      break;
    }
    prepare<T, D>(pts, scale, subset, options, next, prev, order, copy);
    const auto m = static_cast<std::uint32_t>(subset.size());
    Engine<D> engine(copy, next, prev, budget - std::min(budget, tests));
    const bool ok = engine.run(m, m + 1);
    tests += engine.tests();
    if (!ok) {
      out.status = engine.exhausted() ? Status::limit_exceeded : Status::degenerate_input;
      out.tests = tests;
      out.support_count = engine.support_count();
      for (int i = 0; i < out.support_count; ++i) out.support[i] = order[engine.support(i)];
      finish(engine, scale, center, radius);
      return out;
    }
    extra.clear();
    for (std::uint32_t i = 0; i < n && extra.size() <= subset_limit; ++i) {
      if (++tests > budget) break;
      if (engine.outside_point(vec_cast<double>(pts[i]) * scale)) extra.push_back(i);
    }
    if (extra.empty() && tests <= budget) {
      out.status = Status::ok;
      out.tests = tests;
      out.support_count = engine.support_count();
      for (int i = 0; i < out.support_count; ++i) out.support[i] = order[engine.support(i)];
      finish(engine, scale, center, radius);
      return out;
    }
    if (tests > budget) {
      out.status = Status::limit_exceeded;
      out.tests = tests;
      out.support_count = engine.support_count();
      for (int i = 0; i < out.support_count; ++i) out.support[i] = order[engine.support(i)];
      finish(engine, scale, center, radius);
      return out;
    }
    subset.insert(subset.end(), extra.begin(), extra.end());
  }

  subset.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) subset[i] = i;
  prepare<T, D>(pts, scale, subset, options, next, prev, order, copy);
  Engine<D> engine(copy, next, prev, budget - std::min(budget, tests));
  const bool ok = engine.run(n, n + 1);
  out.tests = tests + engine.tests();
  out.support_count = engine.support_count();
  for (int i = 0; i < out.support_count; ++i) out.support[i] = order[engine.support(i)];
  finish(engine, scale, center, radius);
  out.status =
      ok ? Status::ok : (engine.exhausted() ? Status::limit_exceeded : Status::degenerate_input);
  return out;
}

}  // namespace

template <Real T>
MinCircleResult<T> MinCircle2<T>::compute(std::span<const Vec2<T>> points,
                                          const MinBallOptions& options) {
  MinCircleResult<T> r;
  Vec2<double> center{};
  double radius = 0.0;
  const Solved s = solve<T, 2>(points, options, next_, prev_, order_, points_, center, radius);
  r.status = s.status;
  r.tests = s.tests;
  if (s.status != Status::ok && s.status != Status::limit_exceeded) return r;
  r.support_count = s.support_count;
  for (int i = 0; i < s.support_count; ++i) r.support[static_cast<std::size_t>(i)] = s.support[i];
  r.circle = {vec_cast<T>(center), static_cast<T>(radius)};
  return r;
}

template <Real T>
MinSphereResult<T> MinSphere3<T>::compute(std::span<const Vec3<T>> points,
                                          const MinBallOptions& options) {
  MinSphereResult<T> r;
  Vec3<double> center{};
  double radius = 0.0;
  const Solved s = solve<T, 3>(points, options, next_, prev_, order_, points_, center, radius);
  r.status = s.status;
  r.tests = s.tests;
  if (s.status != Status::ok && s.status != Status::limit_exceeded) return r;
  r.support_count = s.support_count;
  for (int i = 0; i < s.support_count; ++i) r.support[static_cast<std::size_t>(i)] = s.support[i];
  r.sphere = {vec_cast<T>(center), static_cast<T>(radius)};
  return r;
}

template class MinCircle2<float>;
template class MinCircle2<double>;
template class MinSphere3<float>;
template class MinSphere3<double>;

}  // namespace locus
