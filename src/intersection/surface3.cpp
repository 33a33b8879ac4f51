// SPDX-License-Identifier: BSL-1.0
// Intersections with parametric surfaces (include/locus/intersection/detail/surface3.hpp): a
// linear component (Bézier hierarchy refinement, then Newton), a plane (grid contouring with
// bisected edge roots) and a second surface (subdivision seeds, then predictor-corrector
// tracing); rows int3.linear-surface, int3.plane-surface, int3.surface-surface, book sections
// 11.6-11.8. Derivation and bounds: docs/notes/surface_intersection.md.

#include <locus/intersection/detail/surface3.hpp>
#include <locus/primitives/plane.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <utility>
#include <vector>

namespace locus::detail::surface3 {
namespace {

using V4 = Vec<double, 4>;
using HP = BezierPatch<double, 4>;
using V2 = Vec2<double>;

constexpr double eps = 0x1p-52;
constexpr int max_depth = 8;  // leaves of 2^-8 of a Bézier span in each direction
constexpr std::size_t node_budget = 1u << 18;
constexpr double accept_residual = 0x1p-36;         // relative to the scaled surface size O(1)
constexpr double merge_distance = 0x1p-24;          // relative, hits closer than this are one hit
constexpr double merge_distance_tangent = 0x1p-17;  // about sqrt(accept_residual)
constexpr double tangent_sine = 0x1p-20;

[[nodiscard]] std::size_t z(int i) noexcept { return static_cast<std::size_t>(i); }

[[nodiscard]] double pow2_inv(double m) noexcept {
  return m > 0.0 && std::isfinite(m) ? std::ldexp(1.0, -std::ilogb(m)) : 1.0;
}

[[nodiscard]] V xyz(const V4& a) noexcept { return {a.x, a.y, a.z}; }

/// The homogeneous Bézier grid of a NURBS surface (every span a polynomial patch in (w P, w)).
struct Grid {
  Status status = Status::empty_input;
  int count_u = 0, count_v = 0;
  std::vector<HP> patches;
  std::vector<double> breaks_u, breaks_v;
};

Grid homogeneous_grid(const NS& s) {
  Grid g;
  g.status = validate(s);
  if (g.status != Status::ok) return g;
  BezierPatchGrid<double, 4> h = to_bezier(to_homogeneous(s));
  g.status = h.status;
  if (g.status != Status::ok || h.patches.empty()) {
    if (g.status == Status::ok) g.status = Status::degenerate_input;
    return g;
  }
  g.count_u = h.count_u;
  g.count_v = h.count_v;
  g.patches = std::move(h.patches);
  g.breaks_u = std::move(h.breaks_u);
  g.breaks_v = std::move(h.breaks_v);
  return g;
}

/// Rational partials of a homogeneous patch at local (u, v): S, S_u, S_v, S_uv.
SurfaceDerivatives<double, 3> rational_partials(const HP& h, double u, double v) noexcept {
  const SurfaceDerivatives<double, 4> a = partials(h, u, v);
  const double w = a.point.w;
  SurfaceDerivatives<double, 3> s;
  s.point = xyz(a.point) / w;
  s.du = (xyz(a.du) - a.du.w * s.point) / w;
  s.dv = (xyz(a.dv) - a.dv.w * s.point) / w;
  s.duv = (xyz(a.duv) - a.duv.w * s.point - a.du.w * s.dv - a.dv.w * s.du) / w;
  return s;
}

[[nodiscard]] double lerp(double a, double b, double t) noexcept { return a + t * (b - a); }

// ---------------------------------------------------------------------------------------------
// Linear component against a surface.

struct Candidate {
  double tau;   // scaled distance along the unit direction from the origin
  double u, v;  // local parameters on patch k
  int k;
  double residual;
};

/// Newton (Levenberg-damped, so it also converges, linearly, at a tangency) on the first two
/// coordinates of the line-frame patch: (x(u, v), y(u, v)) = 0.
bool newton_line(const HP& p, double& u, double& v, double& residual, double& tau) noexcept {
  for (int it = 0; it < 100; ++it) {
    const SurfaceDerivatives<double, 4> a = partials(p, u, v);
    const double w = a.point.w;
    if (!(w > 0.0)) return false;
    const double x = a.point.x / w, y = a.point.y / w;
    const double xu = (a.du.x - a.du.w * x) / w, xv = (a.dv.x - a.dv.w * x) / w;
    const double yu = (a.du.y - a.du.w * y) / w, yv = (a.dv.y - a.dv.w * y) / w;
    residual = std::hypot(x, y);
    tau = a.point.z / w;
    // (J^T J + mu I) delta = -J^T F
    const double a11 = xu * xu + yu * yu, a12 = xu * xv + yu * yv, a22 = xv * xv + yv * yv;
    const double mu = 0x1p-40 * (a11 + a22) + 1e-300;
    const double g1 = xu * x + yu * y, g2 = xv * x + yv * y;
    const double b11 = a11 + mu, b22 = a22 + mu;
    const double det = b11 * b22 - a12 * a12;
    if (!(det > 0.0) || !std::isfinite(det)) return false;
    const double du = -(b22 * g1 - a12 * g2) / det, dv = -(b11 * g2 - a12 * g1) / det;
    const double nu = std::clamp(u + du, 0.0, 1.0), nv = std::clamp(v + dv, 0.0, 1.0);
    const double step = std::max(std::fabs(nu - u), std::fabs(nv - v));
    u = nu;
    v = nv;
    if (residual == 0.0 || step < 0x1p-50) break;
  }
  const V4 p4 = point_at(p, u, v);
  if (!(p4.w > 0.0)) return false;
  residual = std::hypot(p4.x / p4.w, p4.y / p4.w);
  tau = p4.z / p4.w;
  return std::isfinite(residual) && residual <= accept_residual;
}

/// Whether the point q (line frame) lies on the patch: Gauss-Newton from (u, v) on S - q.
bool project_onto(const HP& p, const V& q, double& u, double& v) noexcept {
  for (int it = 0; it < 40; ++it) {
    const SurfaceDerivatives<double, 3> s = rational_partials(p, u, v);
    const V g = s.point - q;
    if (max_abs(g) <= accept_residual) return true;
    const double a11 = dot(s.du, s.du), a12 = dot(s.du, s.dv), a22 = dot(s.dv, s.dv);
    const double mu = 0x1p-40 * (a11 + a22) + 1e-300;
    const double g1 = dot(s.du, g), g2 = dot(s.dv, g);
    const double b11 = a11 + mu, b22 = a22 + mu, det = b11 * b22 - a12 * a12;
    if (!(det > 0.0) || !std::isfinite(det)) return false;
    const double nu = std::clamp(u - (b22 * g1 - a12 * g2) / det, 0.0, 1.0);
    const double nv = std::clamp(v - (b11 * g2 - a12 * g1) / det, 0.0, 1.0);
    if (nu == u && nv == v) break;
    u = nu;
    v = nv;
  }
  return max_abs(rational_partials(p, u, v).point - q) <= accept_residual;
}

struct Node {
  HP patch;
  double u0, u1, v0, v1;
  int depth;
};

}  // namespace

LinearSurfaceHits<double> linear_hits(const linear3::Lin& l, const NS& s) {
  LinearSurfaceHits<double> r;
  if (!linear3::finite(l.o) || !linear3::finite(l.d) || (l.hi && !linear3::finite(l.q))) {
    r.status = Status::non_finite_input;
    return r;
  }
  const Grid g = homogeneous_grid(s);
  if (g.status != Status::ok) {
    r.status = g.status;
    return r;
  }
  const V d = l.hi ? l.q - l.o : l.d;
  if (d == V{} || !linear3::finite(d)) {
    r.status = Status::degenerate_input;
    return r;
  }
  const V e3 = normalize(d);
  const auto basis = perpendicular_basis(e3);
  const V e1 = basis.u, e2 = basis.v;
  double m = 0.0;
  for (const auto& c : s.control) m = std::max(m, max_abs(c - l.o));
  const double sc = pow2_inv(m);
  const double seg_len = l.hi ? sc * dot(e3, l.q - l.o) : 0.0;
  r.status = Status::ok;

  std::vector<Candidate> cands;
  std::vector<HP> local(g.patches.size());
  std::vector<Node> stack;
  std::size_t nodes = 0;
  for (std::size_t k = 0; k < g.patches.size(); ++k) {
    const HP& hp = g.patches[k];
    HP lp{hp.rows, hp.cols, {}};
    lp.control.reserve(hp.control.size());
    double big = 0.0;
    for (const V4& h : hp.control) {
      const V rel = sc * (xyz(h) - h.w * l.o);
      const V4 q{dot(e1, rel), dot(e2, rel), dot(e3, rel), h.w};
      big = std::max(big, max_abs(q));
      lp.control.push_back(q);
    }
    local[k] = lp;
    const double tol = 256.0 * eps * big;
    stack.clear();
    stack.push_back({lp, 0.0, 1.0, 0.0, 1.0, 0});
    while (!stack.empty()) {
      Node n = std::move(stack.back());
      stack.pop_back();
      if (++nodes > node_budget) {
        r.status = Status::limit_exceeded;
        break;
      }
      double lo1 = INFINITY, hi1 = -INFINITY, lo2 = INFINITY, hi2 = -INFINITY;
      for (const V4& c : n.patch.control) {
        lo1 = std::min(lo1, c.x);
        hi1 = std::max(hi1, c.x);
        lo2 = std::min(lo2, c.y);
        hi2 = std::max(hi2, c.y);
      }
      // Convex-hull property (w > 0): no root where a coordinate keeps one strict sign.
      if (lo1 > tol || hi1 < -tol || lo2 > tol || hi2 < -tol) continue;
      bool behind = l.lo;
      for (const V4& c : n.patch.control) behind = behind && c.z < -tol;
      if (behind) continue;
      if (l.hi) {
        bool beyond = true;
        for (const V4& c : n.patch.control) beyond = beyond && c.z - seg_len * c.w > tol;
        if (beyond) continue;
      }
      if (n.depth == max_depth) {
        // A leaf: either the component lies in this (flat) piece, or Newton from its centre.
        V2 far{};
        double fl = 0.0;
        for (const V4& c : n.patch.control) {
          const double len = std::hypot(c.x, c.y);
          if (len > fl) {
            fl = len;
            far = {c.x / len, c.y / len};
          }
        }
        bool flat = true;
        for (const V4& c : n.patch.control)
          flat = flat && std::fabs(far.x * c.y - far.y * c.x) <= 4.0 * tol;
        if (flat) {
          r.on_surface = true;
          continue;
        }
        double u = 0.5 * (n.u0 + n.u1), v = 0.5 * (n.v0 + n.v1), res = 0.0, tau = 0.0;
        if (newton_line(lp, u, v, res, tau)) cands.push_back({tau, u, v, static_cast<int>(k), res});
        continue;
      }
      const PatchSplit<double, 4> a = subdivide_u(n.patch, 0.5);
      const double um = 0.5 * (n.u0 + n.u1), vm = 0.5 * (n.v0 + n.v1);
      PatchSplit<double, 4> b0 = subdivide_v(a.first, 0.5);
      PatchSplit<double, 4> b1 = subdivide_v(a.second, 0.5);
      stack.push_back({std::move(b0.first), n.u0, um, n.v0, vm, n.depth + 1});
      stack.push_back({std::move(b0.second), n.u0, um, vm, n.v1, n.depth + 1});
      stack.push_back({std::move(b1.first), um, n.u1, n.v0, vm, n.depth + 1});
      stack.push_back({std::move(b1.second), um, n.u1, vm, n.v1, n.depth + 1});
    }
    if (r.status != Status::ok) break;
  }

  // Range of the component, merge duplicates (the same root from neighbouring leaves or
  // patches), then express each hit in the caller's coordinates.
  const double tau_tol = accept_residual;
  std::vector<Candidate> kept;
  for (const Candidate& c : cands) {
    if (l.lo && c.tau < -tau_tol) continue;
    if (l.hi && c.tau > seg_len + tau_tol) continue;
    kept.push_back(c);
  }
  std::sort(kept.begin(), kept.end(),
            [](const Candidate& a, const Candidate& b) { return a.tau < b.tau; });
  struct Merged {
    Candidate c;
    V p;
    bool tangent;
  };
  std::vector<Merged> merged;
  for (const Candidate& c : kept) {
    const SurfaceDerivatives<double, 3> sl = rational_partials(local[z(c.k)], c.u, c.v);
    const V nl = detail::surface_normal(sl, !(c.u > 0.5), !(c.v > 0.5));
    const bool tan = nl == V{} || std::fabs(nl.z) <= tangent_sine;
    bool dup = false;
    for (auto& m2 : merged) {
      // A tangential root is only determined to about the square root of the residual.
      const double near = tan || m2.tangent ? merge_distance_tangent : merge_distance;
      if (max_abs(m2.p - sl.point) <= near) {
        if (c.residual < m2.c.residual) m2 = {c, sl.point, tan || m2.tangent};
        m2.tangent = m2.tangent || tan;
        dup = true;
        break;
      }
    }
    if (!dup) merged.push_back({c, sl.point, tan});
  }
  // A piece of the line lying on a curved surface (a ruling) shows up as a run of tangential
  // roots, one per leaf: two neighbours whose midpoint is on the surface belong to such a
  // piece; they are dropped and on_surface set.
  std::sort(merged.begin(), merged.end(),
            [](const Merged& a, const Merged& b) { return a.c.tau < b.c.tau; });
  std::vector<char> on_piece(merged.size(), 0);
  for (std::size_t i = 0; i + 1 < merged.size(); ++i) {
    if (!merged[i].tangent || !merged[i + 1].tangent) continue;
    const double mid = 0.5 * (merged[i].c.tau + merged[i + 1].c.tau);
    bool on = false;
    for (std::size_t e = i; e <= i + 1 && !on; ++e) {
      double u = merged[e].c.u, v = merged[e].c.v;
      on = project_onto(local[z(merged[e].c.k)], {0.0, 0.0, mid}, u, v);
    }
    if (on) {
      on_piece[i] = on_piece[i + 1] = 1;
      r.on_surface = true;
    }
  }
  const double dd = dot(d, d);
  for (std::size_t mi = 0; mi < merged.size(); ++mi) {
    if (on_piece[mi]) continue;
    const Merged& mc = merged[mi];
    const Candidate& c = mc.c;
    const auto ku = c.k / g.count_v, kv = c.k % g.count_v;
    const SurfaceDerivatives<double, 3> sd = rational_partials(g.patches[z(c.k)], c.u, c.v);
    SurfaceHit<double> h;
    h.point = sd.point;
    h.uv = {lerp(g.breaks_u[z(ku)], g.breaks_u[z(ku + 1)], c.u),
            lerp(g.breaks_v[z(kv)], g.breaks_v[z(kv + 1)], c.v)};
    h.t = dot(d, sd.point - l.o) / dd;
    if (l.lo) h.t = std::max(h.t, 0.0);
    if (l.hi) h.t = std::min(h.t, 1.0);
    h.normal = detail::surface_normal(sd, !(c.u > 0.5), !(c.v > 0.5));
    h.tangent = mc.tangent;
    r.hits.push_back(h);
  }
  std::sort(r.hits.begin(), r.hits.end(),
            [](const SurfaceHit<double>& a, const SurfaceHit<double>& b) { return a.t < b.t; });
  return r;
}

// ---------------------------------------------------------------------------------------------
// Plane against a surface: contouring of the signed distance on a grid of every Bézier span.

namespace {

struct PlaneGrid {
  const Grid* g;
  V n;
  double k;
  int cells;  // per span

  /// Patch index and local parameter of grid coordinate (U, V) (U in [0, count_u * cells]).
  void locate(double uu, double vv, int& pk, double& lu, double& lv) const noexcept {
    const int a = std::min(static_cast<int>(uu / cells), g->count_u - 1);
    const int b = std::min(static_cast<int>(vv / cells), g->count_v - 1);
    lu = std::clamp(uu / cells - a, 0.0, 1.0);
    lv = std::clamp(vv / cells - b, 0.0, 1.0);
    pk = a * g->count_v + b;
  }
  [[nodiscard]] double value(double uu, double vv) const noexcept {
    int pk = 0;
    double lu = 0.0, lv = 0.0;
    locate(uu, vv, pk, lu, lv);
    const V4 h = point_at(g->patches[z(pk)], lu, lv);
    return dot(n, xyz(h)) - k * h.w;
  }
  [[nodiscard]] V point(double uu, double vv) const noexcept {
    int pk = 0;
    double lu = 0.0, lv = 0.0;
    locate(uu, vv, pk, lu, lv);
    const V4 h = point_at(g->patches[z(pk)], lu, lv);
    return xyz(h) / h.w;
  }
  [[nodiscard]] V2 param(double uu, double vv) const noexcept {
    const int a = std::min(static_cast<int>(uu / cells), g->count_u - 1);
    const int b = std::min(static_cast<int>(vv / cells), g->count_v - 1);
    const double lu = uu / cells - a, lv = vv / cells - b;
    return {lerp(g->breaks_u[z(a)], g->breaks_u[z(a + 1)], lu),
            lerp(g->breaks_v[z(b)], g->breaks_v[z(b + 1)], lv)};
  }
};

/// Chains segments (pairs of point indices) into open chains (from degree-1 points) and loops.
void link_segments(const std::vector<std::array<int, 2>>& segs, int npoints,
                   std::vector<std::pair<bool, std::vector<int>>>& out) {
  std::vector<std::array<int, 2>> adj(z(npoints), {-1, -1});
  for (std::size_t s = 0; s < segs.size(); ++s)
    for (int e : segs[s]) {
      auto& a = adj[z(e)];
      (a[0] < 0 ? a[0] : a[1]) = static_cast<int>(s);
    }
  std::vector<char> used(segs.size(), 0);
  const auto walk = [&](int start, int first_seg, std::vector<int>& chain) {
    int p = start, sidx = first_seg;
    chain.push_back(p);
    while (sidx >= 0 && !used[z(sidx)]) {
      used[z(sidx)] = 1;
      const auto& sg = segs[z(sidx)];
      p = sg[0] == p ? sg[1] : sg[0];
      chain.push_back(p);
      const auto& a = adj[z(p)];
      sidx = a[0] == sidx ? a[1] : a[0];
    }
  };
  for (int p = 0; p < npoints; ++p) {
    const auto& a = adj[z(p)];
    if (a[0] >= 0 && a[1] < 0 && !used[z(a[0])]) {
      std::vector<int> chain;
      walk(p, a[0], chain);
      out.push_back({false, std::move(chain)});
    }
  }
  for (std::size_t s = 0; s < segs.size(); ++s) {
    if (used[s]) continue;
    std::vector<int> chain;
    walk(segs[s][0], static_cast<int>(s), chain);
    if (chain.size() > 1 && chain.front() == chain.back()) chain.pop_back();
    out.push_back({true, std::move(chain)});
  }
}

/// The plane's signed distance (homogeneous) at every control point of a patch: min and max.
void plane_range(const HP& p, const V& n, double k, double& lo, double& hi) noexcept {
  lo = INFINITY;
  hi = -INFINITY;
  for (const V4& c : p.control) {
    const double f = dot(n, xyz(c)) - k * c.w;
    lo = std::min(lo, f);
    hi = std::max(hi, f);
  }
}

/// Whether a cell whose four grid corners share the sign `s` holds a point of the other sign
/// (a loop or a double crossing the grid misses): subdivision to `depth` levels, exact-hull
/// rejection, the subpatch corners (surface values) as witnesses; `tol` absorbs rounding.
bool hidden_in_cell(const HP& p, const V& n, double k, int s, double tol, int depth) {
  double lo = 0.0, hi = 0.0;
  plane_range(p, n, k, lo, hi);
  if (s > 0 ? lo >= -tol : hi < tol) return false;  // one-signed hull
  const int rows = p.rows, cols = p.cols;
  const std::size_t corner[4] = {0, z(cols - 1), z((rows - 1) * cols), z(rows * cols - 1)};
  for (std::size_t c : corner) {
    const double f = dot(n, xyz(p.control[c])) - k * p.control[c].w;
    if (s > 0 ? f < -tol : f > tol) return true;
  }
  if (depth == 0) return false;
  const PatchSplit<double, 4> a = subdivide_u(p, 0.5);
  for (const HP* h : {&a.first, &a.second}) {
    const PatchSplit<double, 4> b = subdivide_v(*h, 0.5);
    if (hidden_in_cell(b.first, n, k, s, tol, depth - 1) ||
        hidden_in_cell(b.second, n, k, s, tol, depth - 1))
      return true;
  }
  return false;
}

/// Walks a span's cells [i0, i1) x [j0, j1) (grid units) by subdivision, skipping one-signed
/// hulls, and checks every cell with four equal corner signs for a hidden sign region.
template <class Sign>
bool hidden_in_span(const HP& p, const V& n, double k, int i0, int i1, int j0, int j1,
                    const Sign& sgn, double tol) {
  double lo = 0.0, hi = 0.0;
  plane_range(p, n, k, lo, hi);
  if (lo >= -tol || hi < tol) return false;
  if (i1 - i0 > 1) {
    const int im = (i0 + i1) / 2;
    const PatchSplit<double, 4> a = subdivide_u(p, double(im - i0) / double(i1 - i0));
    return hidden_in_span(a.first, n, k, i0, im, j0, j1, sgn, tol) ||
           hidden_in_span(a.second, n, k, im, i1, j0, j1, sgn, tol);
  }
  if (j1 - j0 > 1) {
    const int jm = (j0 + j1) / 2;
    const PatchSplit<double, 4> a = subdivide_v(p, double(jm - j0) / double(j1 - j0));
    return hidden_in_span(a.first, n, k, i0, i1, j0, jm, sgn, tol) ||
           hidden_in_span(a.second, n, k, i0, i1, jm, j1, sgn, tol);
  }
  const int s0 = sgn(i0, j0);
  if (sgn(i0 + 1, j0) != s0 || sgn(i0 + 1, j0 + 1) != s0 || sgn(i0, j0 + 1) != s0) return false;
  return hidden_in_cell(p, n, k, s0, tol, 5);
}

/// The checks shared by the plane-surface tracer and its Hermite tangents: a finite, nonzero
/// plane and a valid surface (whose Bézier grid is returned in g); ok or the failure status.
Status plane_input(const V& normal, double constant, const NS& s, Grid& g) {
  if (!linear3::finite(normal) || !std::isfinite(constant)) return Status::non_finite_input;
  if (normal == V{}) return Status::degenerate_input;
  g = homogeneous_grid(s);
  return g.status;
}

}  // namespace

SurfaceCurves<double> plane_curves(const V& normal, double constant, const NS& s,
                                   const SurfaceCurveOptions& opt) {
  SurfaceCurves<double> r;
  Grid g;
  r.status = plane_input(normal, constant, s, g);
  if (r.status != Status::ok) return r;
  // Scale the plane to a unit-size normal by a power of two (exact).
  const double ns = pow2_inv(max_abs(normal));
  const V nn = ns * normal;
  const double kk = ns * constant;
  // The grid, refined (doubled, up to 256 cells per span) while some cell hides a sign region.
  int cells = std::clamp(opt.grid, 1, 1024);
  bool hidden = false;
  int nu = 0, nv = 0;
  std::vector<signed char> sign;
  const auto sgn = [&](int i, int j) { return int(sign[z(j) * z(nu) + z(i)]); };
  for (;;) {
    const PlaneGrid pgrid{&g, nn, kk, cells};
    nu = g.count_u * cells + 1;
    nv = g.count_v * cells + 1;
    sign.assign(z(nu) * z(nv), 1);
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        sign[z(j) * z(nu) + z(i)] = pgrid.value(i, j) < 0.0 ? -1 : 1;  // zero counts as positive
    hidden = false;
    for (int a = 0; a < g.count_u && !hidden; ++a)
      for (int b = 0; b < g.count_v && !hidden; ++b) {
        const HP& p = g.patches[z(a * g.count_v + b)];
        double big = 0.0;
        for (const V4& c : p.control) big = std::max(big, std::fabs(dot(nn, xyz(c)) - kk * c.w));
        const auto span_sign = [&](int i, int j) { return sgn(a * cells + i, b * cells + j); };
        hidden = hidden_in_span(p, nn, kk, 0, cells, 0, cells, span_sign, 1024.0 * eps * big);
      }
    if (!hidden || cells >= 256) break;
    cells = std::min(2 * cells, 256);
  }
  const PlaneGrid pg{&g, nn, kk, cells};

  std::vector<V> pts;
  std::vector<V2> prm;
  std::unordered_map<std::int64_t, int> edge_point;
  // Edge (i, j) -> (i + 1, j) (dir 0) or (i, j) -> (i, j + 1) (dir 1): its root by bisection.
  const auto crossing = [&](int i, int j, int dir) {
    const std::int64_t key = (static_cast<std::int64_t>(j) * nu + i) * 2 + dir;
    const auto it = edge_point.find(key);
    if (it != edge_point.end()) return it->second;
    const int i1 = dir == 0 ? i + 1 : i, j1 = dir == 0 ? j : j + 1;
    // Parameter along the edge, bisected on the sign of the evaluated distance.
    double lo = 0.0, hi = 1.0;
    const bool neg_lo = sgn(i, j) < 0;
    (void)i1;
    (void)j1;
    for (int it2 = 0; it2 < 64; ++it2) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const double uu = dir == 0 ? i + mid : i, vv = dir == 0 ? j : j + mid;
      const bool neg = pg.value(uu, vv) < 0.0;
      (neg == neg_lo ? lo : hi) = mid;
    }
    const double t = 0.5 * (lo + hi);
    const double uu = dir == 0 ? i + t : i, vv = dir == 0 ? j : j + t;
    pts.push_back(pg.point(uu, vv));
    prm.push_back(pg.param(uu, vv));
    const int idx = static_cast<int>(pts.size()) - 1;
    edge_point.emplace(key, idx);
    return idx;
  };
  std::vector<std::array<int, 2>> segs;
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      const int s0 = sgn(i, j), s1 = sgn(i + 1, j), s2 = sgn(i + 1, j + 1), s3 = sgn(i, j + 1);
      const bool c0 = s0 != s1, c1 = s1 != s2, c2 = s3 != s2, c3 = s0 != s3;
      const int count = int(c0) + int(c1) + int(c2) + int(c3);
      if (count == 0) continue;
      // Edges: 0 bottom (i,j)-(i+1,j), 1 right (i+1,j)-(i+1,j+1), 2 top (i,j+1)-(i+1,j+1),
      // 3 left (i,j)-(i,j+1).
      const auto edge = [&](int e) {
        switch (e) {
          case 0:
            return crossing(i, j, 0);
          case 1:
            return crossing(i + 1, j, 1);
          case 2:
            return crossing(i, j + 1, 0);
          default:
            return crossing(i, j, 1);
        }
      };
      if (count == 2) {
        int e[2], n = 0;
        const bool c[4] = {c0, c1, c2, c3};
        for (int q = 0; q < 4; ++q)
          if (c[q]) e[n++] = q;
        segs.push_back({edge(e[0]), edge(e[1])});
      } else {
        // Saddle: the centre's sign tells which diagonal pair of corners is connected.
        const int sc = pg.value(i + 0.5, j + 0.5) < 0.0 ? -1 : 1;
        if (sc == s0) {
          segs.push_back({edge(0), edge(1)});  // cuts off corner 1
          segs.push_back({edge(2), edge(3)});  // cuts off corner 3
        } else {
          segs.push_back({edge(0), edge(3)});  // cuts off corner 0
          segs.push_back({edge(1), edge(2)});  // cuts off corner 2
        }
      }
    }
  std::vector<std::pair<bool, std::vector<int>>> chains;
  link_segments(segs, static_cast<int>(pts.size()), chains);
  r.status = hidden ? Status::limit_exceeded : Status::ok;
  for (const auto& ch : chains) {
    SurfaceCurve<double> c;
    c.closed = ch.first;
    for (int p : ch.second) {
      c.points.push_back(pts[z(p)]);
      c.param_b.push_back(prm[z(p)]);
    }
    r.curves.push_back(std::move(c));
  }
  return r;
}

CurveTangents plane_curve_tangents(const V& normal, const NS& s, const std::vector<V>& points,
                                   const std::vector<V2>& params, bool closed) {
  CurveTangents r;
  const std::size_t n = points.size();
  if (n == 0 || params.size() != n) {
    r.status = n == 0 ? Status::empty_input : Status::invalid_input;
    return r;
  }
  Grid g;
  r.status = plane_input(normal, 0.0, s, g);
  if (r.status != Status::ok) return r;
  const V nn = pow2_inv(max_abs(normal)) * normal;
  // The span of a parameter: the last break <= x (clamped to the spans).
  const auto span = [](const std::vector<double>& br, double x, double& local) {
    const auto it = std::upper_bound(br.begin() + 1, br.end() - 1, x);
    const std::size_t a = static_cast<std::size_t>(it - br.begin()) - 1;
    local = std::clamp((x - br[a]) / (br[a + 1] - br[a]), 0.0, 1.0);
    return a;
  };
  r.tangent.resize(n);
  r.param_tangent.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    // The chord through the neighbours orients the tangent (and replaces it where it vanishes).
    const std::size_t prev = i > 0 ? i - 1 : (closed ? n - 1 : 0);
    const std::size_t next = i + 1 < n ? i + 1 : (closed ? 0 : n - 1);
    const V chord = points[next] - points[prev];
    const V2 pchord = params[next] - params[prev];
    double lu = 0.0, lv = 0.0;
    const std::size_t a = span(g.breaks_u, params[i].x, lu);
    const std::size_t b = span(g.breaks_v, params[i].y, lv);
    const SurfaceDerivatives<double, 3> d =
        rational_partials(g.patches[a * z(g.count_v) + b], lu, lv);
    // Global partials: the span maps [break_a, break_a+1] onto the local [0, 1].
    const V su = d.du / (g.breaks_u[a + 1] - g.breaks_u[a]);
    const V sv = d.dv / (g.breaks_v[b + 1] - g.breaks_v[b]);
    // N x (S_u x S_v) = S_u (N.S_v) - S_v (N.S_u): the (u, v) velocity (N.S_v, -N.S_u).
    V t = cross(nn, cross(su, sv));
    V2 q{dot(nn, sv), -dot(nn, su)};
    const double len = length(t);
    const double scale = length(su) * length(sv);
    if (!(len > 0x1p-30 * scale) || !std::isfinite(len)) {
      const double cl = length(chord);
      if (!(cl > 0.0)) {
        t = V{};
        q = V2{};
      } else {
        t = chord / cl;
        q = pchord / cl;
      }
    } else {
      t = t / len;
      q = q / len;
      if (dot(t, chord) < 0.0) {
        t = -t;
        q = -q;
      }
    }
    r.tangent[i] = t;
    r.param_tangent[i] = q;
  }
  r.status = Status::ok;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Surface against surface: seeds from subdivision, then predictor-corrector tracing.

namespace {

struct Eval {
  V p, su, sv;
};
Eval eval(const NS& s, double u, double v) noexcept {
  const SurfaceDerivatives<double, 3> d = partials(s, u, v);
  return {d.point, d.du, d.dv};
}

struct Box {
  V lo, hi;
  double u0, u1, v0, v1;
  V axis;         // unit normal at the leaf centre (zero where undefined)
  double spread;  // largest angle (radians) from axis to a sampled normal (pi: unknown)
  int gi, gj;     // position in the surface's global leaf grid
};

/// Control-net boxes of the leaves of every span split `n` times in each direction, with an
/// estimated normal cone (the normals at the centre and the 3 x 3 grid of corner, edge and
/// centre points; used only to decide where to look harder, never to reject).
std::vector<Box> leaf_boxes(const Grid& g, int n) {
  std::vector<Box> out;
  for (int a = 0; a < g.count_u; ++a)
    for (int b = 0; b < g.count_v; ++b) {
      const HP& p = g.patches[z(a * g.count_v + b)];
      for (int i = 0; i < n; ++i) {
        // Column strip [i/n, (i+1)/n] along u.
        const double ua = double(i) / n, ub = double(i + 1) / n;
        HP strip = subdivide_u(subdivide_u(p, ub).first, ub > 0.0 ? ua / ub : 0.0).second;
        for (int j = 0; j < n; ++j) {
          const double va = double(j) / n, vb = double(j + 1) / n;
          const HP cell =
              subdivide_v(subdivide_v(strip, vb).first, vb > 0.0 ? va / vb : 0.0).second;
          Box bx{{INFINITY, INFINITY, INFINITY},
                 {-INFINITY, -INFINITY, -INFINITY},
                 0,
                 0,
                 0,
                 0,
                 V{},
                 std::numbers::pi,
                 a * n + i,
                 b * n + j};
          for (const V4& c : cell.control) {
            const V q = xyz(c) / c.w;
            for (int k = 0; k < 3; ++k) {
              bx.lo[k] = std::min(bx.lo[k], q[k]);
              bx.hi[k] = std::max(bx.hi[k], q[k]);
            }
          }
          bx.u0 = lerp(g.breaks_u[z(a)], g.breaks_u[z(a + 1)], ua);
          bx.u1 = lerp(g.breaks_u[z(a)], g.breaks_u[z(a + 1)], ub);
          bx.v0 = lerp(g.breaks_v[z(b)], g.breaks_v[z(b + 1)], va);
          bx.v1 = lerp(g.breaks_v[z(b)], g.breaks_v[z(b + 1)], vb);
          const auto normal_at = [&](double su, double sv) {
            const SurfaceDerivatives<double, 3> d = rational_partials(cell, su, sv);
            const V nv = cross(d.du, d.dv);
            const double ln = length(nv);
            return ln > 0.0 && std::isfinite(ln) ? nv / ln : V{};
          };
          const V axis = normal_at(0.5, 0.5);
          if (axis == V{}) {
            out.push_back(bx);
            continue;
          }
          double spread = 0.0;
          for (int si = 0; si <= 2 && spread < std::numbers::pi; ++si)
            for (int sj = 0; sj <= 2; ++sj) {
              const V nq = normal_at(0.5 * si, 0.5 * sj);
              if (nq == V{}) {
                spread = std::numbers::pi;
                break;
              }
              spread = std::max(spread, std::acos(std::clamp(dot(axis, nq), -1.0, 1.0)));
            }
          bx.axis = axis;
          // Widened: the sampled normals underestimate the cone between the samples.
          bx.spread = std::min(2.0 * spread + 0x1p-10, std::numbers::pi);
          out.push_back(bx);
        }
      }
    }
  return out;
}

/// Whether two leaves may hold a pair of parallel normals (Sederberg's loop criterion: without
/// one, the leaves' intersection has no closed loop and no tangential contact).
[[nodiscard]] bool cones_overlap(const Box& x, const Box& y) noexcept {
  if (x.axis == V{} || y.axis == V{}) return true;
  const double angle = std::acos(std::clamp(std::fabs(dot(x.axis, y.axis)), 0.0, 1.0));
  return angle <= x.spread + y.spread;
}

/// Solves the n x n system m x = b by Gaussian elimination with partial pivoting.
template <int N>
bool solve(std::array<std::array<double, N + 1>, N> m, std::array<double, N>& x) noexcept {
  for (int c = 0; c < N; ++c) {
    int piv = c;
    for (int r = c + 1; r < N; ++r)
      if (std::fabs(m[z(r)][z(c)]) > std::fabs(m[z(piv)][z(c)])) piv = r;
    if (!(std::fabs(m[z(piv)][z(c)]) > 1e-300)) return false;
    std::swap(m[z(piv)], m[z(c)]);
    for (int r = c + 1; r < N; ++r) {
      const double f = m[z(r)][z(c)] / m[z(c)][z(c)];
      for (int k = c; k <= N; ++k) m[z(r)][z(k)] -= f * m[z(c)][z(k)];
    }
  }
  for (int c = N - 1; c >= 0; --c) {
    double s = m[z(c)][z(N)];
    for (int k = c + 1; k < N; ++k) s -= m[z(c)][z(k)] * x[z(k)];
    x[z(c)] = s / m[z(c)][z(c)];
  }
  for (double q : x)
    if (!std::isfinite(q)) return false;
  return true;
}

/// How a traced branch ends.
enum class End { closed, boundary, tangent, stalled };

struct Pair {
  const NS* a;
  const NS* b;
  ParamDomain<double> ua, va, ub, vb;
  double scale;  // the size of the problem (box diagonal)

  [[nodiscard]] bool inside(const std::array<double, 4>& x, double slack) const noexcept {
    return x[0] >= ua.min - slack && x[0] <= ua.max + slack && x[1] >= va.min - slack &&
           x[1] <= va.max + slack && x[2] >= ub.min - slack && x[2] <= ub.max + slack &&
           x[3] >= vb.min - slack && x[3] <= vb.max + slack;
  }
  void clamp(std::array<double, 4>& x) const noexcept {
    x[0] = std::clamp(x[0], ua.min, ua.max);
    x[1] = std::clamp(x[1], va.min, va.max);
    x[2] = std::clamp(x[2], ub.min, ub.max);
    x[3] = std::clamp(x[3], vb.min, vb.max);
  }
  [[nodiscard]] double lo(int k) const noexcept {
    return k == 0 ? ua.min : k == 1 ? va.min : k == 2 ? ub.min : vb.min;
  }
  [[nodiscard]] double hi(int k) const noexcept {
    return k == 0 ? ua.max : k == 1 ? va.max : k == 2 ? ub.max : vb.max;
  }

  /// Minimum-norm Gauss-Newton onto Sa = Sb (a seed), parameters kept in the domains.
  bool seed(std::array<double, 4>& x) const noexcept {
    for (int it = 0; it < 40; ++it) {
      const Eval ea = eval(*a, x[0], x[1]), eb = eval(*b, x[2], x[3]);
      const V f = ea.p - eb.p;
      if (max_abs(f) <= accept_residual * 0x1p-8 * scale) return true;
      const std::array<V, 4> col{ea.su, ea.sv, -eb.su, -eb.sv};
      // (J J^T + mu I) y = f, delta = -J^T y
      std::array<std::array<double, 4>, 3> m{};
      double tr = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double s = 0.0;
          for (int k = 0; k < 4; ++k) s += col[z(k)][i] * col[z(k)][j];
          m[z(i)][z(j)] = s;
          if (i == j) tr += s;
        }
      for (int i = 0; i < 3; ++i) {
        m[z(i)][z(i)] += 1e-14 * tr + 1e-300;
        m[z(i)][3] = f[i];
      }
      std::array<double, 3> y{};
      if (!solve<3>(m, y)) return false;
      for (int k = 0; k < 4; ++k)
        x[z(k)] -= col[z(k)].x * y[0] + col[z(k)].y * y[1] + col[z(k)].z * y[2];
      clamp(x);
    }
    const V f = eval(*a, x[0], x[1]).p - eval(*b, x[2], x[3]).p;
    return max_abs(f) <= accept_residual * scale;
  }

  /// Newton on Sa = Sb plus one more equation: tan . (Sa - q) = 0 (fixed < 0) or
  /// x[fixed] = value (fixed >= 0).
  bool correct(std::array<double, 4>& x, const V& tan, const V& q, int fixed,
               double value) const noexcept {
    for (int it = 0; it < 16; ++it) {
      const Eval ea = eval(*a, x[0], x[1]), eb = eval(*b, x[2], x[3]);
      const V f = ea.p - eb.p;
      std::array<std::array<double, 5>, 4> m{};
      const std::array<V, 4> col{ea.su, ea.sv, -eb.su, -eb.sv};
      for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 4; ++k) m[z(i)][z(k)] = col[z(k)][i];
        m[z(i)][4] = -f[i];
      }
      if (fixed < 0) {
        m[3] = {dot(tan, ea.su), dot(tan, ea.sv), 0.0, 0.0, -dot(tan, ea.p - q)};
      } else {
        m[3] = {0.0, 0.0, 0.0, 0.0, value - x[z(fixed)]};
        m[3][z(fixed)] = 1.0;
      }
      std::array<double, 4> dx{};
      if (!solve<4>(m, dx)) return false;
      double step = 0.0;
      for (int k = 0; k < 4; ++k) {
        x[z(k)] += dx[z(k)];
        step = std::max(step, std::fabs(dx[z(k)]) / std::max(1.0, hi(k) - lo(k)));
      }
      if (!inside(x, 0.5 * (ua.max - ua.min + va.max - va.min + ub.max - ub.min + vb.max - vb.min)))
        return false;
      if (step < 0x1p-44) {
        const V g = eval(*a, x[0], x[1]).p - eval(*b, x[2], x[3]).p;
        return max_abs(g) <= accept_residual * scale;
      }
    }
    const V g = eval(*a, x[0], x[1]).p - eval(*b, x[2], x[3]).p;
    return max_abs(g) <= accept_residual * scale;
  }

  /// The unit tangent of the intersection curve at x (zero where the surfaces touch).
  [[nodiscard]] V tangent(const std::array<double, 4>& x) const noexcept {
    const Eval ea = eval(*a, x[0], x[1]), eb = eval(*b, x[2], x[3]);
    const V na = cross(ea.su, ea.sv), nb = cross(eb.su, eb.sv);
    const V t = cross(na, nb);
    const double ln = length(na) * length(nb);
    if (!(length(t) > 0x1p-26 * ln)) return V{};
    return normalize(t);
  }

  /// The sine of the angle between the normals at x (1 where a normal is undefined).
  [[nodiscard]] double normal_sine(const std::array<double, 4>& x) const noexcept {
    const Eval ea = eval(*a, x[0], x[1]), eb = eval(*b, x[2], x[3]);
    const V na = cross(ea.su, ea.sv), nb = cross(eb.su, eb.sv);
    const double ln = length(na) * length(nb);
    if (!(ln > 0.0) || !std::isfinite(ln)) return 1.0;
    return length(cross(na, nb)) / ln;
  }

  /// One branch from x along +-tangent (points appended to out) and how it ends.
  End trace(std::array<double, 4> x, double dir, double h0,
            std::vector<std::array<double, 4>>& out) const {
    const V start = eval(*a, x[0], x[1]).p;
    V prev_t = dir * tangent(x);
    if (prev_t == V{}) return End::tangent;
    double h = h0;
    const int max_points = 100000;
    for (int n = 0; n < max_points; ++n) {
      const Eval ea = eval(*a, x[0], x[1]), eb = eval(*b, x[2], x[3]);
      V t = tangent(x);
      if (t == V{}) return End::tangent;
      if (dot(t, prev_t) < 0.0) t = -t;
      const V q = ea.p + h * t;
      // Predictor in parameters: least-squares steps on each surface.
      std::array<double, 4> y = x;
      const auto lsq = [&](const V& su, const V& sv, double& du, double& dv) {
        const double a11 = dot(su, su), a12 = dot(su, sv), a22 = dot(sv, sv);
        const double b1 = h * dot(su, t), b2 = h * dot(sv, t);
        const double det = a11 * a22 - a12 * a12;
        if (!(std::fabs(det) > 0.0)) return;
        du = (a22 * b1 - a12 * b2) / det;
        dv = (a11 * b2 - a12 * b1) / det;
      };
      double d0 = 0.0, d1 = 0.0, d2 = 0.0, d3 = 0.0;
      lsq(ea.su, ea.sv, d0, d1);
      lsq(eb.su, eb.sv, d2, d3);
      y[0] += d0;
      y[1] += d1;
      y[2] += d2;
      y[3] += d3;
      // The end point on the domain bound that a step to y crosses (false: none crossed).
      const auto exit_at_bound = [&](const std::array<double, 4>& yo, bool must) {
        int k_out = -1;
        double worst = 0.0;
        for (int k = 0; k < 4; ++k) {
          const double ex = std::max(lo(k) - yo[z(k)], yo[z(k)] - hi(k)) / (hi(k) - lo(k));
          if (ex > worst) {
            worst = ex;
            k_out = k;
          }
        }
        if (k_out < 0) return false;
        std::array<double, 4> e = x;
        const double bound = yo[z(k_out)] < lo(k_out) ? lo(k_out) : hi(k_out);
        const bool hit =
            correct(e, t, q, k_out, bound) && length(eval(*a, e[0], e[1]).p - ea.p) <= 2.0 * h;
        if (hit) {
          clamp(e);
          out.push_back(e);
        }
        return hit || must;
      };
      const std::array<double, 4> predicted = y;
      const bool ok = correct(y, t, q, -1, 0.0);
      const V ty = ok ? tangent(y) : V{};
      if (!ok || ty == V{} || std::fabs(dot(ty, t)) < 0.9 ||
          length(eval(*a, y[0], y[1]).p - ea.p) > 2.0 * h) {
        // A corrector failing on a step out of a domain (a corner): end on the bound.
        if (!inside(predicted, 0.0) && exit_at_bound(predicted, false)) return End::boundary;
        h *= 0.5;
        // Stuck: near a touching point the normals turn parallel (the caller locates it).
        if (h < h0 * 0x1p-20) return normal_sine(x) <= 0x1p-6 ? End::tangent : End::stalled;
        --n;
        continue;
      }
      // Leaving a domain: the end point on the boundary the step crossed.
      if (!inside(y, 0.0) && exit_at_bound(y, true)) return End::boundary;
      const V py = eval(*a, y[0], y[1]).p;
      if (out.size() >= 3 && length(py - start) <= h && dot(start - ea.p, t) > 0.0)
        return End::closed;
      out.push_back(y);
      prev_t = t;
      x = y;
      h = std::min(h0, 1.5 * h);
    }
    return End::stalled;
  }

  // ---- Tangential contact: critical points of |Sa - Sb|^2 with parallel normals. ----

  /// The contact system at x: the projections of Sa - Sb on Sb's unit partials (Sb(s, t) is
  /// the foot of Sa(u, v)) and of Sa's unit normal on them (parallel normals), in length units.
  [[nodiscard]] std::array<double, 4> contact_system(const std::array<double, 4>& x) const {
    const Eval ea = eval(*a, x[0], x[1]), eb = eval(*b, x[2], x[3]);
    const V na = cross(ea.su, ea.sv);
    const double ln = length(na), ls = length(eb.su), lt = length(eb.sv);
    if (!(ln > 0.0) || !(ls > 0.0) || !(lt > 0.0)) return {NAN, NAN, NAN, NAN};
    const V d = ea.p - eb.p, n = na / ln, es = eb.su / ls, et = eb.sv / lt;
    return {dot(d, es), dot(d, et), scale * dot(n, es), scale * dot(n, et)};
  }

  /// The Jacobian of contact_system by central differences (one-sided on a domain bound), its
  /// columns per unit of the relative parameter (the parameter divided by its domain width).
  bool contact_jacobian(const std::array<double, 4>& x,
                        std::array<std::array<double, 4>, 4>& j) const {
    for (int k = 0; k < 4; ++k) {
      const double w = hi(k) - lo(k), eta = 0x1p-20 * w;
      std::array<double, 4> xp = x, xm = x;
      xp[z(k)] = std::min(x[z(k)] + eta, hi(k));
      xm[z(k)] = std::max(x[z(k)] - eta, lo(k));
      const double span = (xp[z(k)] - xm[z(k)]) / w;
      if (!(span > 0.0)) return false;
      const std::array<double, 4> gp = contact_system(xp), gm = contact_system(xm);
      for (int i = 0; i < 4; ++i) j[z(i)][z(k)] = (gp[z(i)] - gm[z(i)]) / span;
    }
    for (const auto& row : j)
      for (double q : row)
        if (!std::isfinite(q)) return false;
    return true;
  }

  /// Minimum-norm Newton on the contact system (it converges onto a curve of contact too, where
  /// the system has rank 3); coordinate `frozen` (>= 0) is kept. True when it converged.
  bool contact(std::array<double, 4>& x, int frozen = -1) const {
    for (int it = 0; it < 40; ++it) {
      const std::array<double, 4> g = contact_system(x);
      std::array<std::array<double, 4>, 4> j{};
      if (!std::isfinite(g[0]) || !contact_jacobian(x, j)) return false;
      if (frozen >= 0)
        for (auto& row : j) row[z(frozen)] = 0.0;
      // (J J^T + mu I) y = g, delta = -J^T y (relative parameters).
      std::array<std::array<double, 5>, 4> m{};
      double tr = 0.0;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          double sum = 0.0;
          for (int k = 0; k < 4; ++k) sum += j[z(r)][z(k)] * j[z(c)][z(k)];
          m[z(r)][z(c)] = sum;
          if (r == c) tr += sum;
        }
      for (int r = 0; r < 4; ++r) {
        m[z(r)][z(r)] += 1e-14 * tr + 1e-300;
        m[z(r)][4] = g[z(r)];
      }
      std::array<double, 4> y{};
      if (!solve<4>(m, y)) return false;
      double step = 0.0;
      for (int k = 0; k < 4; ++k) {
        double dk = 0.0;
        for (int r = 0; r < 4; ++r) dk -= j[z(r)][z(k)] * y[z(r)];
        step = std::max(step, std::fabs(dk));
        x[z(k)] += dk * (hi(k) - lo(k));
      }
      clamp(x);
      if (step < 0x1p-40) break;
    }
    const std::array<double, 4> g = contact_system(x);
    double worst = 0.0;
    for (double q : g) worst = std::max(worst, std::fabs(q));
    return worst <= 0x1p-30 * scale;
  }

  /// The gap |Sa - Sb| at x relative to the size of the problem.
  [[nodiscard]] double gap(const std::array<double, 4>& x) const {
    return max_abs(eval(*a, x[0], x[1]).p - eval(*b, x[2], x[3]).p) / scale;
  }

  /// The rank (up to 4) of the contact system at x, and for rank 3 the direction of the curve
  /// of contact (in parameters, unit 3D speed on the first surface).
  int contact_rank(const std::array<double, 4>& x, std::array<double, 4>& kernel) const {
    std::array<std::array<double, 4>, 4> m{};
    if (!contact_jacobian(x, m)) return 0;
    // Gaussian elimination with complete pivoting.
    std::array<int, 4> col{0, 1, 2, 3};
    double first = 0.0;
    int rank = 0;
    for (int c = 0; c < 4; ++c) {
      int pr = c, pc = c;
      for (int r = c; r < 4; ++r)
        for (int k = c; k < 4; ++k)
          if (std::fabs(m[z(r)][z(k)]) > std::fabs(m[z(pr)][z(pc)])) {
            pr = r;
            pc = k;
          }
      const double pivot = std::fabs(m[z(pr)][z(pc)]);
      if (c == 0) first = pivot;
      if (!(pivot > 0x1p-20 * first) || !(first > 0.0)) break;
      std::swap(m[z(pr)], m[z(c)]);
      for (auto& row : m) std::swap(row[z(pc)], row[z(c)]);
      std::swap(col[z(pc)], col[z(c)]);
      for (int r = c + 1; r < 4; ++r) {
        const double f = m[z(r)][z(c)] / m[z(c)][z(c)];
        for (int k = c; k < 4; ++k) m[z(r)][z(k)] -= f * m[z(c)][z(k)];
      }
      ++rank;
    }
    if (rank != 3) return rank;
    std::array<double, 4> yv{0.0, 0.0, 0.0, 1.0};
    for (int c = 2; c >= 0; --c) {
      double sum = -m[z(c)][3];
      for (int k = c + 1; k < 3; ++k) sum -= m[z(c)][z(k)] * yv[z(k)];
      yv[z(c)] = sum / m[z(c)][z(c)];
    }
    for (int c = 0; c < 4; ++c) kernel[z(col[z(c)])] = yv[z(c)] * (hi(col[z(c)]) - lo(col[z(c)]));
    const Eval ea = eval(*a, x[0], x[1]);
    const double speed = length(kernel[0] * ea.su + kernel[1] * ea.sv);
    if (!(speed > 0.0) || !std::isfinite(speed)) return 2;
    for (double& q : kernel) q /= speed;
    return 3;
  }

  /// One branch of a curve of contact from x (rank 3) along +-kernel, as trace() does.
  End trace_contact(std::array<double, 4> x, double dir, double h0,
                    std::vector<std::array<double, 4>>& out) const {
    const V start = eval(*a, x[0], x[1]).p;
    std::array<double, 4> prev{};
    if (contact_rank(x, prev) != 3) return End::tangent;
    for (double& q : prev) q *= dir;
    double h = h0;
    for (int n = 0; n < 20000; ++n) {
      std::array<double, 4> k{};
      if (contact_rank(x, k) != 3) return End::tangent;
      double along = 0.0;
      for (int i = 0; i < 4; ++i) along += k[z(i)] * prev[z(i)] / std::pow(hi(i) - lo(i), 2.0);
      if (along < 0.0)
        for (double& q : k) q = -q;
      const V pa = eval(*a, x[0], x[1]).p;
      std::array<double, 4> y = x;
      for (int i = 0; i < 4; ++i) y[z(i)] += h * k[z(i)];
      int k_out = -1;
      double worst = 0.0;
      for (int i = 0; i < 4; ++i) {
        const double ex = std::max(lo(i) - y[z(i)], y[z(i)] - hi(i)) / (hi(i) - lo(i));
        if (ex > worst) {
          worst = ex;
          k_out = i;
        }
      }
      clamp(y);
      const bool ok = contact(y, k_out) && gap(y) <= accept_residual;
      const double moved = ok ? length(eval(*a, y[0], y[1]).p - pa) : 0.0;
      if (!ok || moved > 2.0 * h || moved < 0.25 * h) {
        if (ok && k_out >= 0 && moved <= 2.0 * h) {
          out.push_back(y);  // the last, short step onto a domain bound
          return End::boundary;
        }
        h *= 0.5;
        if (h < h0 * 0x1p-10) return End::stalled;
        --n;
        continue;
      }
      if (k_out >= 0) {
        out.push_back(y);
        return End::boundary;
      }
      const V py = eval(*a, y[0], y[1]).p;
      if (out.size() >= 3 && length(py - start) <= h) return End::closed;
      out.push_back(y);
      prev = k;
      x = y;
      h = std::min(h0, 1.5 * h);
    }
    return End::stalled;
  }
};

/// Gauss-Newton projection of q onto s from (u, v) (kept in the domain): whether the foot is
/// within `tol` of q and the unit normal there (zero where undefined); stops within `stop`.
bool project_point(const NS& s, const V& q, double& u, double& v, double tol, double stop,
                   V& normal) {
  const ParamDomain<double> du = domain_u(s), dv = domain_v(s);
  for (int it = 0; it < 30; ++it) {
    const Eval e = eval(s, u, v);
    const V g = e.p - q;
    if (max_abs(g) <= stop) break;
    const double a11 = dot(e.su, e.su), a12 = dot(e.su, e.sv), a22 = dot(e.sv, e.sv);
    const double mu = 0x1p-40 * (a11 + a22) + 1e-300;
    const double g1 = dot(e.su, g), g2 = dot(e.sv, g);
    const double b11 = a11 + mu, b22 = a22 + mu, det = b11 * b22 - a12 * a12;
    if (!(det > 0.0) || !std::isfinite(det)) return false;
    const double nu = std::clamp(u - (b22 * g1 - a12 * g2) / det, du.min, du.max);
    const double nv = std::clamp(v - (b11 * g2 - a12 * g1) / det, dv.min, dv.max);
    if (nu == u && nv == v) break;
    u = nu;
    v = nv;
  }
  const Eval e = eval(s, u, v);
  const V nn = cross(e.su, e.sv);
  const double ln = length(nn);
  normal = ln > 0.0 && std::isfinite(ln) ? nn / ln : V{};
  return max_abs(e.p - q) <= tol;
}

}  // namespace

namespace {

using X = std::array<double, 4>;

/// The distance from p to a polyline (closed: with its closing segment).
double polyline_distance(const V& p, const std::vector<V>& pts, bool closed,
                         std::size_t* seg = nullptr, double* at = nullptr) {
  double best = INFINITY;
  const std::size_t n = pts.size();
  if (seg) *seg = 0;
  if (at) *at = 0.0;
  if (n == 1) return length(p - pts[0]);
  for (std::size_t q = 0; q + (closed ? 0 : 1) < n; ++q) {
    const V& e0 = pts[q];
    const V& e1 = pts[(q + 1) % n];
    const V ed = e1 - e0;
    const double el = dot(ed, ed);
    const double tt = el > 0.0 ? std::clamp(dot(p - e0, ed) / el, 0.0, 1.0) : 0.0;
    const double d = length(p - (e0 + tt * ed));
    if (d < best) {
      best = d;
      if (seg) *seg = q;
      if (at) *at = tt;
    }
  }
  return best;
}

/// Parameter rectangles covering the flagged cells of a leaf grid (greedy maximal runs).
std::vector<ParamRect<double>> merge_leaves(const std::vector<Box>& boxes,
                                            const std::vector<char>& flag) {
  std::vector<ParamRect<double>> out;
  int cu = 0, cv = 0;
  for (const Box& b : boxes) {
    cu = std::max(cu, b.gi + 1);
    cv = std::max(cv, b.gj + 1);
  }
  std::vector<int> at(z(cu) * z(cv), -1);
  for (std::size_t k = 0; k < boxes.size(); ++k)
    if (flag[k]) at[z(boxes[k].gi) * z(cv) + z(boxes[k].gj)] = static_cast<int>(k);
  std::vector<char> done(at.size(), 0);
  const auto cell = [&](int i, int j) { return z(i) * z(cv) + z(j); };
  for (int i = 0; i < cu; ++i)
    for (int j = 0; j < cv; ++j) {
      if (at[cell(i, j)] < 0 || done[cell(i, j)]) continue;
      int j1 = j + 1;
      while (j1 < cv && at[cell(i, j1)] >= 0 && !done[cell(i, j1)]) ++j1;
      int i1 = i + 1;
      for (;; ++i1) {
        bool full = i1 < cu;
        for (int jj = j; jj < j1 && full; ++jj) full = at[cell(i1, jj)] >= 0 && !done[cell(i1, jj)];
        if (!full) break;
      }
      for (int ii = i; ii < i1; ++ii)
        for (int jj = j; jj < j1; ++jj) done[cell(ii, jj)] = 1;
      const Box& lo = boxes[z(at[cell(i, j)])];
      const Box& hi = boxes[z(at[cell(i1 - 1, j1 - 1)])];
      out.push_back({{lo.u0, lo.v0}, {hi.u1, hi.v1}});
    }
  return out;
}

[[nodiscard]] SurfaceCurveEnd end_kind(End e) noexcept {
  return e == End::tangent   ? SurfaceCurveEnd::tangent_point
         : e == End::stalled ? SurfaceCurveEnd::stalled
                             : SurfaceCurveEnd::boundary;
}

}  // namespace

SurfaceCurves<double> surface_curves(const NS& sa, const NS& sb, const SurfaceCurveOptions& opt) {
  SurfaceCurves<double> r;
  const Grid ga = homogeneous_grid(sa);
  const Grid gb = homogeneous_grid(sb);
  if (ga.status != Status::ok || gb.status != Status::ok) {
    r.status = ga.status != Status::ok ? ga.status : gb.status;
    return r;
  }
  r.status = Status::ok;
  const int n = std::clamp(opt.grid / 2, 2, 64);
  const std::vector<Box> ba = leaf_boxes(ga, n), bb = leaf_boxes(gb, n);
  V lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto* list : {&ba, &bb})
    for (const Box& b : *list)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], b.lo[k]);
        hi[k] = std::max(hi[k], b.hi[k]);
      }
  const double scale = std::max(length(hi - lo), 1e-300);
  const Pair pr{&sa, &sb, domain_u(sa), domain_v(sa), domain_u(sb), domain_v(sb), scale};
  const double slack = 0x1p-30 * scale;

  // The overlapping leaf pairs.
  std::vector<std::pair<int, int>> pairs;
  constexpr std::size_t pair_budget = 1u << 20;
  for (std::size_t i = 0; i < ba.size() && r.status == Status::ok; ++i)
    for (std::size_t j = 0; j < bb.size(); ++j) {
      const Box& x = ba[i];
      const Box& y = bb[j];
      bool overlap = true;
      for (int k = 0; k < 3; ++k)
        overlap = overlap && x.lo[k] <= y.hi[k] + slack && y.lo[k] <= x.hi[k] + slack;
      if (!overlap) continue;
      if (pairs.size() >= pair_budget) {
        r.status = Status::limit_exceeded;
        break;
      }
      pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }

  // Coincidence: a leaf lies on the other surface when each of its 3 x 3 sample points (corners,
  // edge midpoints, centre) projects onto it within accept_residual * scale with parallel
  // normals (sine <= 2^-20). A sample is tried from the centre of each overlapping leaf of the
  // other surface until it succeeds; the first failing sample ends a pair's attempt.
  const double on_tol = accept_residual * scale;
  constexpr unsigned full_mask = (1u << 9) - 1u;
  std::vector<unsigned> mask_a(ba.size(), 0u), mask_b(bb.size(), 0u);
  const auto cover = [&](const Box& leaf, const NS& own, const NS& other, const Box& start,
                         unsigned& mask) {
    while (mask != full_mask) {
      int k = 0;
      while (mask & (1u << k)) ++k;
      const double u = lerp(leaf.u0, leaf.u1, 0.5 * (k / 3)),
                   v = lerp(leaf.v0, leaf.v1, 0.5 * (k % 3));
      const Eval e = eval(own, u, v);
      const V no = cross(e.su, e.sv);
      double s = 0.5 * (start.u0 + start.u1), t = 0.5 * (start.v0 + start.v1);
      V nt{};
      if (!project_point(other, e.p, s, t, on_tol, 0x1p-8 * on_tol, nt)) return;
      const double ln = length(no);
      if (nt != V{} && ln > 0.0 && length(cross(no / ln, nt)) > 0x1p-20) return;
      mask |= 1u << k;
    }
  };
  for (const auto& pq : pairs) {
    cover(ba[z(pq.first)], sa, sb, bb[z(pq.second)], mask_a[z(pq.first)]);
    cover(bb[z(pq.second)], sb, sa, ba[z(pq.first)], mask_b[z(pq.second)]);
  }
  std::vector<char> same_a(ba.size()), same_b(bb.size());
  for (std::size_t i = 0; i < ba.size(); ++i) same_a[i] = mask_a[i] == full_mask;
  for (std::size_t j = 0; j < bb.size(); ++j) same_b[j] = mask_b[j] == full_mask;
  r.coincident_a = merge_leaves(ba, same_a);
  r.coincident_b = merge_leaves(bb, same_b);
  // Whether x lies in (or next to) a coincident leaf of either surface.
  const auto in_coincident = [&](const X& x) {
    for (std::size_t i = 0; i < ba.size(); ++i)
      if (same_a[i]) {
        const Box& b = ba[i];
        const double wu = b.u1 - b.u0, wv = b.v1 - b.v0;
        if (x[0] >= b.u0 - wu && x[0] <= b.u1 + wu && x[1] >= b.v0 - wv && x[1] <= b.v1 + wv)
          return true;
      }
    for (std::size_t j = 0; j < bb.size(); ++j)
      if (same_b[j]) {
        const Box& b = bb[j];
        const double wu = b.u1 - b.u0, wv = b.v1 - b.v0;
        if (x[2] >= b.u0 - wu && x[2] <= b.u1 + wu && x[3] >= b.v0 - wv && x[3] <= b.v1 + wv)
          return true;
      }
    return false;
  };

  // A seed on the loop around the critical point c of the gap (NaN: none): the signed gap g0
  // at c and at a point of the first surface eta away give the relative normal curvature k
  // along that direction; the loop crosses it at the radius sqrt(-2 g0 / k) (g0 k < 0), where
  // Gauss-Newton starts, in the four parameter directions until one lands near that radius.
  const auto loop_seed = [&](const X& c, double eta) {
    const Eval ea = eval(sa, c[0], c[1]), eb = eval(sb, c[2], c[3]);
    const V nb = cross(eb.su, eb.sv);
    const double lb = length(nb);
    X none{NAN, NAN, NAN, NAN};
    if (!(lb > 0.0)) return none;
    const double g0 = dot(ea.p - eb.p, nb / lb);
    for (int d = 0; d < 4; ++d) {
      const V dir = d < 2 ? ea.su : ea.sv;
      const double ld = length(dir);
      if (!(ld > 0.0)) continue;
      const double sign = d % 2 == 0 ? 1.0 : -1.0;
      X t = c;
      t[z(d / 2)] += sign * eta / ld;
      pr.clamp(t);
      const V q = eval(sa, t[0], t[1]).p;
      const double moved = length(q - ea.p);
      double s = c[2], tt = c[3];
      V nf{};
      project_point(sb, q, s, tt, INFINITY, 0x1p-44 * scale, nf);
      if (nf == V{} || !(moved > 0.0)) continue;
      const double g1 = dot(q - eval(sb, s, tt).p, dot(nf, nb) < 0.0 ? -nf : nf);
      const double k = 2.0 * (g1 - g0) / (moved * moved);
      if (!(g0 * k < 0.0)) continue;
      const double radius = std::sqrt(-2.0 * g0 / k);
      for (const double f : {1.0, 0.5, 2.0}) {
        X w = c;
        w[z(d / 2)] += sign * f * radius / ld;
        pr.clamp(w);
        if (!pr.seed(w) || pr.tangent(w) == V{}) continue;
        const double rw = length(eval(sa, w[0], w[1]).p - ea.p);
        if (rw >= 0.5 * radius && rw <= 2.0 * radius) return w;
      }
    }
    return none;
  };

  // Seeds: transversal points from the pair centres; where that fails and the normal cones
  // overlap, a critical point of the distance (a contact, or the centre of a small loop).
  std::vector<X> seeds, contact_starts, searched;
  std::vector<char> explored(ba.size(), 0);
  constexpr std::size_t seed_budget = 1u << 14;
  std::size_t seeded = 0;
  for (const auto& pq : pairs) {
    if (same_a[z(pq.first)] || same_b[z(pq.second)]) continue;  // inside a coincident region
    if (++seeded > seed_budget) {
      r.status = Status::limit_exceeded;
      break;
    }
    const Box& x = ba[z(pq.first)];
    const Box& y = bb[z(pq.second)];
    const X centre{0.5 * (x.u0 + x.u1), 0.5 * (x.v0 + x.v1), 0.5 * (y.u0 + y.u1),
                   0.5 * (y.v0 + y.v1)};
    X s = centre;
    const bool seeded_here = pr.seed(s);
    if (seeded_here) seeds.push_back(s);
    // Parallel normals possible: a contact, or a small loop around a critical point of the
    // distance, may hide here (once per leaf of the first surface).
    if (explored[z(pq.first)] || !cones_overlap(x, y)) continue;
    explored[z(pq.first)] = 1;
    X c = centre;
    if (!pr.contact(c)) continue;
    if (pr.gap(c) <= accept_residual) {
      contact_starts.push_back(c);
      continue;
    }
    // A critical point with a gap: the centre of a possible small loop (the gap function has
    // an extremum inside every closed loop), searched even where this pair seeded another
    // curve (Gauss-Newton from the centres is drawn to the nearer, larger curve).
    const V pc = eval(sa, c[0], c[1]).p;
    const double diag = std::max(length(x.hi - x.lo), length(y.hi - y.lo));
    if (pr.gap(c) * scale > diag) continue;
    bool seen = false;
    for (const X& q : searched)
      seen = seen || length(eval(sa, q[0], q[1]).p - pc) <= 0x1p-17 * scale;
    if (seen) continue;
    searched.push_back(c);
    const X loop = loop_seed(c, 0.125 * diag);
    if (loop[0] == loop[0]) seeds.push_back(loop);
  }

  const double h0 = std::clamp(opt.step, 0x1p-12, 0.25) * scale;
  // Contacts: isolated points (contact system of rank 4) and curves of contact (rank 3, traced
  // along the kernel); rank <= 2 means a coincident piece (reported above).
  std::vector<SurfaceCurve<double>> contact_curves;
  const auto locate_contacts = [&](const std::vector<X>& starts) {
    for (X c : starts) {
      if (!pr.contact(c) || pr.gap(c) > accept_residual || in_coincident(c)) continue;
      const V p = eval(sa, c[0], c[1]).p;
      bool known = false;
      for (const auto& k : r.contacts) known = known || length(k.point - p) <= 0x1p-17 * scale;
      for (const auto& cc : contact_curves)
        known = known || polyline_distance(p, cc.points, cc.closed) <= 0.1 * h0 + 0x1p-17 * scale;
      if (known) continue;
      X kernel{};
      const int rank = pr.contact_rank(c, kernel);
      if (rank == 4) {
        r.contacts.push_back({p, {c[0], c[1]}, {c[2], c[3]}});
        continue;
      }
      if (rank != 3) continue;
      std::vector<X> fwd, bwd;
      const End fe = pr.trace_contact(c, 1.0, h0, fwd);
      End be = End::closed;
      if (fe != End::closed) be = pr.trace_contact(c, -1.0, h0, bwd);
      if (fwd.empty() && bwd.empty()) {
        // A degenerate touching point (rank 3 without a curve through it: a cusp's tip).
        r.contacts.push_back({p, {c[0], c[1]}, {c[2], c[3]}});
        continue;
      }
      std::vector<X> all(bwd.rbegin(), bwd.rend());
      all.push_back(c);
      all.insert(all.end(), fwd.begin(), fwd.end());
      SurfaceCurve<double> cv;
      cv.tangent = true;
      cv.closed = fe == End::closed;
      if (!cv.closed) {
        cv.first_end = end_kind(be);
        cv.last_end = end_kind(fe);
      }
      for (const auto& x : all) {
        cv.points.push_back(eval(sa, x[0], x[1]).p);
        cv.param_a.push_back({x[0], x[1]});
        cv.param_b.push_back({x[2], x[3]});
      }
      contact_curves.push_back(std::move(cv));
    }
  };
  std::vector<char> covered(seeds.size(), 0);
  for (std::size_t si = 0; si < seeds.size(); ++si)
    if (pr.tangent(seeds[si]) == V{}) {
      covered[si] = 1;
      contact_starts.push_back(seeds[si]);
    }
  locate_contacts(contact_starts);
  const double near_contact = 0x1p-14 * scale;
  // Seeds next to a curve of contact belong to it (near it the normals are almost parallel and
  // the transversal tracer would follow a shadow of it).
  for (std::size_t si = 0; si < seeds.size(); ++si) {
    const V p = eval(sa, seeds[si][0], seeds[si][1]).p;
    for (const auto& cc : contact_curves)
      if (polyline_distance(p, cc.points, cc.closed) <= 0.1 * h0 + 0x1p-17 * scale) covered[si] = 1;
    // Near a touching point (seeds there solve Sa = Sb only to the tolerance, within about its
    // square root of the point) no transversal curve can be told apart from the contact.
    for (const auto& k : r.contacts)
      if (length(p - k.point) <= near_contact) covered[si] = 1;
  }
  std::vector<X> branch_ends;
  for (std::size_t si = 0; si < seeds.size(); ++si) {
    if (covered[si]) continue;
    std::vector<X> fwd, bwd;
    const End fe = pr.trace(seeds[si], 1.0, h0, fwd);
    End be = End::closed;
    if (fe != End::closed) be = pr.trace(seeds[si], -1.0, h0, bwd);
    std::vector<X> all(bwd.rbegin(), bwd.rend());
    all.push_back(seeds[si]);
    all.insert(all.end(), fwd.begin(), fwd.end());
    SurfaceCurve<double> c;
    c.closed = fe == End::closed;
    if (!c.closed) {
      c.first_end = end_kind(be);
      c.last_end = end_kind(fe);
      // A branch stopped at a touching point: the contact is located from its last point.
      if (fe == End::tangent) branch_ends.push_back(all.back());
      if (be == End::tangent) branch_ends.push_back(all.front());
    }
    for (const auto& x : all) {
      c.points.push_back(eval(sa, x[0], x[1]).p);
      c.param_a.push_back({x[0], x[1]});
      c.param_b.push_back({x[2], x[3]});
    }
    for (std::size_t sj = 0; sj < seeds.size(); ++sj) {
      if (covered[sj]) continue;
      const V p = eval(sa, seeds[sj][0], seeds[sj][1]).p;
      // The seeds lie on the curve: within a fraction of the step of a chord; or, farther from
      // a chord (the tracer allows turns of ~25 degrees a step), the curve corrected from the
      // nearest chord point onto the plane through the seed lands on the seed.
      std::size_t q = 0;
      double tt = 0.0;
      const double d = polyline_distance(p, c.points, c.closed, &q, &tt);
      if (d <= 0.05 * h0 + 0x1p-20 * scale) {
        covered[sj] = 1;
      } else if (d <= 0.25 * h0) {
        const X& e0 = all[q];
        const X& e1 = all[(q + 1) % all.size()];
        X m{};
        for (int k = 0; k < 4; ++k) m[z(k)] = lerp(e0[z(k)], e1[z(k)], tt);
        const V ts = pr.tangent(seeds[sj]);
        if (ts != V{} && pr.correct(m, ts, p, -1, 0.0) &&
            length(eval(sa, m[0], m[1]).p - p) <= 0x1p-20 * scale)
          covered[sj] = 1;
      }
    }
    covered[si] = 1;
    bool shadow = !r.contacts.empty();  // every point next to one contact: its shadow
    for (const V& p : c.points) {
      bool near = false;
      for (const auto& k : r.contacts) near = near || length(p - k.point) <= near_contact;
      shadow = shadow && near;
    }
    if (c.points.size() >= 2 && !shadow) r.curves.push_back(std::move(c));
  }

  locate_contacts(branch_ends);
  for (auto& cv : contact_curves) r.curves.push_back(std::move(cv));
  return r;
}

}  // namespace locus::detail::surface3
