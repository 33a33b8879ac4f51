// SPDX-License-Identifier: BSL-1.0
// Separating axes for convex polyhedra, stationary and moving (include/locus/intersection/sat.hpp;
// derivation in docs/notes/sat3.md). Everything is computed in double (float input is exact in it).

#include <locus/core/crossing.hpp>
#include <locus/core/error_free.hpp>
#include <locus/core/exact_sum.hpp>
#include <locus/core/predicates.hpp>
#include <locus/intersection/convex_polygon2.hpp>
#include <locus/intersection/sat.hpp>
#include <locus/intersection/segment_triangle.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace locus::detail::sat3 {

namespace {

using V = Vec3<double>;
using V2 = Vec2<double>;

/// Exact sign of det[p1 - p0, q1 - q0, x - y]: orient3d's stage-A filter (the same three rounded
/// differences per product), then the 48 monomials of the expanded determinant, summed exactly.
}  // namespace

int sign_det_diff(const V& p0, const V& p1, const V& q0, const V& q1, const V& x,
                  const V& y) noexcept {
  const double ux = p1.x - p0.x, uy = p1.y - p0.y, uz = p1.z - p0.z;
  const double wx = q1.x - q0.x, wy = q1.y - q0.y, wz = q1.z - q0.z;
  const double dx = x.x - y.x, dy = x.y - y.y, dz = x.z - y.z;
  const double det = ux * (wy * dz - wz * dy) + uy * (wz * dx - wx * dz) + uz * (wx * dy - wy * dx);
  const double perm = std::abs(ux) * (std::abs(wy * dz) + std::abs(wz * dy)) +
                      std::abs(uy) * (std::abs(wz * dx) + std::abs(wx * dz)) +
                      std::abs(uz) * (std::abs(wx * dy) + std::abs(wy * dx));
  // (7 + 56 eps) eps perm bounds the error of the rounded evaluation (Shewchuk's orient3d
  // stage A); 8 eps is a safe round-up. Below 2^-900 underflow could void it: go exact.
  const double bound = 8.0 * (std::numeric_limits<double>::epsilon() / 2) * perm;
  if (perm > 0x1p-900 && std::abs(det) > bound) return det > 0 ? 1 : -1;
  if (det == 0.0 && perm == 0.0 &&
      ((ux == 0 && uy == 0 && uz == 0) || (wx == 0 && wy == 0 && wz == 0) ||
       (dx == 0 && dy == 0 && dz == 0)))
    return 0;  // a zero vector (differences of equal doubles are exactly zero)
  // Structural zeros (x - y along p1 - p0 or q1 - q0 by construction: the axis' own edge or face
  // vertices) are frequent and would all reach the exact stage.
  const auto in2 = [](const V& a, const V& b, const V& c) { return a == b || a == c; };
  if ((in2(x, p0, p1) && in2(y, p0, p1)) || (in2(x, q0, q1) && in2(y, q0, q1))) return 0;
  if (p0 == q0 && (in2(x, p0, p1) || x == q1) && (in2(y, p0, p1) || y == q1)) return 0;
  // Stage B: the differences split exactly (two_sum) into h + l; the 6 leading products h h h
  // are formed exactly (two_product twice, the second error rounded) and summed with TwoSum; the
  // terms with an l (at most about 3 eps of their product) are rounded. The error is below
  // 120 u^2 perm (u = 2^-53), so 512 u^2 perm decides every case but near-zero determinants.
  if (perm > 0x1p-600 && perm < 0x1p600) {
    double uh[3], ul[3], wh[3], wl[3], dh[3], dl[3];
    for (int k = 0; k < 3; ++k) {
      two_sum(p1[k], -p0[k], uh[k], ul[k]);
      two_sum(q1[k], -q0[k], wh[k], wl[k]);
      two_sum(x[k], -y[k], dh[k], dl[k]);
    }
    static constexpr int order[6][4] = {{0, 1, 2, 1},  {1, 2, 0, 1},  {2, 0, 1, 1},
                                        {0, 2, 1, -1}, {1, 0, 2, -1}, {2, 1, 0, -1}};
    double hi = 0, err = 0, small = 0;
    bool all_exact = true;  // no tail anywhere: hi is the exact value (small integers, ties)
    for (int k = 0; k < 3; ++k) all_exact = all_exact && ul[k] == 0 && wl[k] == 0 && dl[k] == 0;
    for (const auto& o : order) {
      const double a = uh[o[0]], al = ul[o[0]], b = wh[o[1]], bl = wl[o[1]], c = dh[o[2]],
                   cl = dl[o[2]], sg = o[3];
      double pr, pe, q, qe, t, te;
      two_product(a, b, pr, pe);
      two_product(pr, c, q, qe);
      two_sum(hi, sg * q, t, te);
      hi = t;
      err += te;
      small += sg * ((qe + pe * c) + (al * (b + bl) + a * bl) * (c + cl) + a * b * cl);
      all_exact = all_exact && pe == 0 && qe == 0 && te == 0;
    }
    if (all_exact) return hi > 0 ? 1 : (hi < 0 ? -1 : 0);
    const double v = hi + (err + small);
    const double bound_b = 512 * 0x1p-106 * perm;
    if (std::abs(v) > bound_b) return v > 0 ? 1 : -1;
  }
  const double pu[3][2] = {{p1.x, p0.x}, {p1.y, p0.y}, {p1.z, p0.z}};
  const double pw[3][2] = {{q1.x, q0.x}, {q1.y, q0.y}, {q1.z, q0.z}};
  const double pd[3][2] = {{x.x, y.x}, {x.y, y.y}, {x.z, y.z}};
  static constexpr int perms[6][4] = {{0, 1, 2, 1},  {1, 2, 0, 1},  {2, 0, 1, 1},
                                      {0, 2, 1, -1}, {1, 0, 2, -1}, {2, 1, 0, -1}};
  ExactMonomial terms[48];
  int n = 0;
  for (const auto& p : perms)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        for (int c = 0; c < 2; ++c) {
          const int s = p[3] * (a ? -1 : 1) * (b ? -1 : 1) * (c ? -1 : 1);
          terms[n++] = ExactMonomial{s, 0, 3, {pu[p[0]][a], pw[p[1]][b], pd[p[2]][c], 0.0}};
        }
  return exact_sign_of_sum(std::span<const ExactMonomial>(terms, 48));
}

namespace {

[[nodiscard]] V2 drop(const V& p, int k) noexcept {
  return k == 0 ? V2{p.y, p.z} : (k == 1 ? V2{p.z, p.x} : V2{p.x, p.y});
}

/// A candidate axis. Spatial: projections compare by det[p1 - p0, q1 - q0, x - y]. Planar (two
/// flat polyhedra in one plane): drop coordinate k and compare det2[p1' - p0', x' - y'].
struct Axis {
  bool planar;
  int k;
  V p0, p1, q0, q1;
};

/// Exact sign of proj(x) - proj(y).
int axis_sign(const Axis& ax, const V& x, const V& y) noexcept {
  if (ax.planar)
    return to_int(turn2d(drop(ax.p0, ax.k), drop(ax.p1, ax.k), drop(y, ax.k), drop(x, ax.k)));
  return sign_det_diff(ax.p0, ax.p1, ax.q0, ax.q1, x, y);
}

/// proj(x) - proj(y), rounded.
double axis_value(const Axis& ax, const V& x, const V& y) noexcept {
  if (ax.planar)
    return turn2d_value(drop(ax.p0, ax.k), drop(ax.p1, ax.k), drop(y, ax.k), drop(x, ax.k));
  const V u = ax.p1 - ax.p0, w = ax.q1 - ax.q0, d = x - y;
  return dot(cross(u, w), d);
}

/// A polyhedron promoted to double with its edges (parallel ones dropped) and a reference
/// non-degenerate triangle.
struct Poly {
  std::vector<V> v;
  std::vector<std::array<std::uint32_t, 3>> tri;   // non-degenerate triangles only
  std::vector<std::array<std::uint32_t, 2>> edge;  // one per direction
  bool flat = false;
};

[[nodiscard]] bool parallel(const V& a0, const V& a1, const V& b0, const V& b1) noexcept {
  // (a1 - a0) x (b1 - b0) = 0 iff its three coordinate-plane components vanish (exact).
  for (int k = 0; k < 3; ++k)
    if (turn2d(drop(a0, k), drop(a1, k), drop(b0, k), drop(b1, k)) != Sign::zero) return false;
  return true;
}

template <Real T>
Status load(const ConvexMesh3<T>& in, Poly& out) {
  for (const Vec3<T>& p : in.vertices)
    if (!is_finite(p)) return Status::non_finite_input;
  const std::size_t n = in.vertices.size();
  out.v.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.v[i] = vec_cast<double>(in.vertices[i]);
  for (const auto& t : in.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n) return Status::invalid_input;
    if (!parallel(out.v[t[0]], out.v[t[1]], out.v[t[0]], out.v[t[2]])) out.tri.push_back(t);
  }
  if (out.tri.empty()) return Status::degenerate_input;
  std::vector<std::array<std::uint32_t, 2>> all;
  if (!in.edges.empty()) {
    for (const auto& e : in.edges) {
      if (e[0] >= n || e[1] >= n) return Status::invalid_input;
      if (e[0] != e[1]) all.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
    }
  } else {
    for (const auto& t : in.triangles)
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = t[static_cast<std::size_t>(i)],
                            b = t[static_cast<std::size_t>((i + 1) % 3)];
        if (a != b) all.push_back({std::min(a, b), std::max(a, b)});
      }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
  }
  for (const auto& e : all) {
    const V &a0 = out.v[e[0]], &a1 = out.v[e[1]];
    if (a0 == a1) continue;
    bool dup = false;
    for (const auto& f : out.edge)
      if (parallel(a0, a1, out.v[f[0]], out.v[f[1]])) {
        dup = true;
        break;
      }
    if (!dup) out.edge.push_back(e);
  }
  const auto& r = out.tri.front();
  out.flat = true;
  for (const V& p : out.v)
    if (orient3d(out.v[r[0]], out.v[r[1]], out.v[r[2]], p) != Sign::zero) {
      out.flat = false;
      break;
    }
  return Status::ok;
}

/// The coordinate whose drop keeps the reference triangle of a flat polyhedron non-degenerate.
int planar_drop(const Poly& a) noexcept {
  const auto& r = a.tri.front();
  for (int k = 2; k >= 0; --k)
    if (orient2d(drop(a.v[r[0]], k), drop(a.v[r[1]], k), drop(a.v[r[2]], k)) != Sign::zero)
      return k;
  return 2;
}

/// Every candidate axis of the pair.
std::vector<Axis> axes_of(const Poly& a, const Poly& b) {
  std::vector<Axis> ax;
  ax.reserve(a.tri.size() + b.tri.size() + a.edge.size() * b.edge.size());
  for (const Poly* p : {&a, &b})
    for (const auto& t : p->tri)
      ax.push_back({false, 0, p->v[t[0]], p->v[t[1]], p->v[t[0]], p->v[t[2]]});
  for (const auto& ea : a.edge)
    for (const auto& eb : b.edge) {
      const V &a0 = a.v[ea[0]], &a1 = a.v[ea[1]], &b0 = b.v[eb[0]], &b1 = b.v[eb[1]];
      if (!parallel(a0, a1, b0, b1)) ax.push_back({false, 0, a0, a1, b0, b1});
    }
  if (a.flat && b.flat) {
    // Two flat polyhedra in parallel planes (the same plane included): a - b is flat, and its
    // facets are in-plane edges, whose normals the axes above miss. Parallel: every vertex of b
    // is at the same height over a's plane (exact). Dropping coordinate k maps both planes
    // bijectively, so the in-plane edge normals there complete the set (for moving polyhedra
    // too, at the moment the planes coincide).
    const auto& r = a.tri.front();
    bool parallel_planes = true;
    for (const V& p : b.v)
      if (sign_det_diff(a.v[r[0]], a.v[r[1]], a.v[r[0]], a.v[r[2]], p, b.v.front()) != 0) {
        parallel_planes = false;
        break;
      }
    if (parallel_planes) {
      const int k = planar_drop(a);
      for (const Poly* p : {&a, &b})
        for (const auto& e : p->edge) ax.push_back({true, k, p->v[e[0]], p->v[e[1]], V{}, V{}});
    }
  }
  return ax;
}

/// Indices of the smallest and largest projections. Rounded projections n . (x_i - x_0) with a
/// generous error bound B (32 eps |u|_1 |w|_1 max |x_i - x_0|_1: the normal's and the dot's
/// roundings) leave as candidates only the vertices within 2B of the rounded extreme; exact
/// comparisons pick among those (any vertex truly beyond the rounded pick is a candidate).
void extremes(const Axis& ax, const std::vector<V>& p, std::size_t& lo, std::size_t& hi,
              std::vector<double>& val) noexcept {
  lo = hi = 0;
  const std::size_t m = p.size();
  V n;
  double scale;
  if (ax.planar) {
    const V2 e = drop(ax.p1, ax.k) - drop(ax.p0, ax.k);
    n = V{};
    const int i = (ax.k + 1) % 3, j = (ax.k + 2) % 3;
    n[i] = -e.y;  // det2[e, d] = e.x d.y - e.y d.x
    n[j] = e.x;
    scale = std::abs(e.x) + std::abs(e.y);
  } else {
    const V u = ax.p1 - ax.p0, w = ax.q1 - ax.q0;
    n = cross(u, w);
    scale = (std::abs(u.x) + std::abs(u.y) + std::abs(u.z)) *
            (std::abs(w.x) + std::abs(w.y) + std::abs(w.z));
  }
  val.resize(m);
  double reach = 0;
  for (std::size_t i = 0; i < m; ++i) {
    const V d = p[i] - p[0];
    val[i] = dot(n, d);
    reach = std::max(reach, std::abs(d.x) + std::abs(d.y) + std::abs(d.z));
  }
  const double bound = 32 * std::numeric_limits<double>::epsilon() * scale * reach;
  const bool filtered = scale * reach > 0x1p-800 && std::isfinite(bound);
  double vmin = val[0], vmax = val[0];
  for (std::size_t i = 1; i < m; ++i) {
    vmin = std::min(vmin, val[i]);
    vmax = std::max(vmax, val[i]);
  }
  bool lo_set = false, hi_set = false;
  for (std::size_t i = 0; i < m; ++i) {
    if (!filtered || val[i] <= vmin + 2 * bound) {
      if (!lo_set || axis_sign(ax, p[i], p[lo]) < 0) lo = i;
      lo_set = true;
    }
    if (!filtered || val[i] >= vmax - 2 * bound) {
      if (!hi_set || axis_sign(ax, p[i], p[hi]) > 0) hi = i;
      hi_set = true;
    }
  }
}

/// Convex hull (counter-clockwise, no collinear vertices) of a few points: monotone chain with
/// exact orient2d.
std::vector<V2> small_hull(std::vector<V2> p) {
  std::sort(p.begin(), p.end(),
            [](const V2& a, const V2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<V2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient2d(h[k - 2], h[k - 1], p[i]) != Sign::positive) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient2d(h[k - 2], h[k - 1], p[i]) != Sign::positive) --k;
    h[k++] = p[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

}  // namespace

template <Real T>
SatTest3 test(const ConvexMesh3<T>& a_in, const ConvexMesh3<T>& b_in) {
  Poly a, b;
  SatTest3 r;
  const Status sa = load(a_in, a);
  const Status sb = sa == Status::ok ? load(b_in, b) : sa;
  r.status = sa != Status::ok ? sa : sb;
  if (r.status != Status::ok) return r;
  std::vector<double> scratch;
  for (const Axis& ax : axes_of(a, b)) {
    std::size_t alo, ahi, blo, bhi;
    extremes(ax, a.v, alo, ahi, scratch);
    extremes(ax, b.v, blo, bhi, scratch);
    if (axis_sign(ax, b.v[blo], a.v[ahi]) > 0 || axis_sign(ax, a.v[alo], b.v[bhi]) > 0) return r;
  }
  r.intersects = true;
  return r;
}

template <Real T>
Contact3<T> first_contact(const ConvexMesh3<T>& a_in, const Vec3<T>& va_in,
                          const ConvexMesh3<T>& b_in, const Vec3<T>& vb_in, T tmax_in) {
  Contact3<T> r;
  if (!(tmax_in >= T(0))) {  // negative or NaN
    r.status = Status::invalid_input;
    return r;
  }
  if (!is_finite(va_in) || !is_finite(vb_in)) {
    r.status = Status::non_finite_input;
    return r;
  }
  Poly a, b;
  const Status sa = load(a_in, a);
  const Status sb = sa == Status::ok ? load(b_in, b) : sa;
  r.status = sa != Status::ok ? sa : sb;
  if (r.status != Status::ok) return r;
  const V va = vec_cast<double>(va_in), vb = vec_cast<double>(vb_in);
  const double tmax = double(tmax_in);

  // B relative to A moves with vb - va. Per axis: side at time 0 (exact), speed sign (exact),
  // entry and exit times (rounded); the latest entry and earliest exit over all axes.
  double tfirst = 0.0, tlast = tmax;
  const Axis* best = nullptr;
  bool b_right = true;  // on `best`: B lies on the positive side of A
  const std::vector<Axis> axes = axes_of(a, b);
  std::vector<double> scratch;
  for (const Axis& ax : axes) {
    std::size_t alo, ahi, blo, bhi;
    extremes(ax, a.v, alo, ahi, scratch);
    extremes(ax, b.v, blo, bhi, scratch);
    const int right = axis_sign(ax, b.v[blo], a.v[ahi]);  // > 0: B strictly on the + side
    const int left = axis_sign(ax, a.v[alo], b.v[bhi]);   // > 0: B strictly on the - side
    const int sv = axis_sign(ax, vb, va);
    const double speed = sv == 0 ? 0.0 : axis_value(ax, vb, va);
    double tenter = 0.0, texit = std::numeric_limits<double>::infinity();
    bool entering = false, side_right = true;
    if (right > 0) {
      if (sv >= 0) return r;  // moving apart or parallel: never meet
      tenter = axis_value(ax, b.v[blo], a.v[ahi]) / -speed;
      texit = axis_value(ax, b.v[bhi], a.v[alo]) / -speed;
      entering = true;
    } else if (left > 0) {
      if (sv <= 0) return r;
      tenter = axis_value(ax, a.v[alo], b.v[bhi]) / speed;
      texit = axis_value(ax, a.v[ahi], b.v[blo]) / speed;
      entering = true;
      side_right = false;
    } else {
      // Overlapping or touching at time 0.
      if (sv > 0) texit = axis_value(ax, a.v[ahi], b.v[blo]) / speed;
      if (sv < 0) texit = axis_value(ax, b.v[bhi], a.v[alo]) / -speed;
      if (right == 0 || left == 0) {
        entering = true;  // touching: contact begins (and may end) at 0
        side_right = right == 0;
      }
    }
    if (entering && (best == nullptr || tenter > tfirst)) {
      tfirst = std::max(tfirst, tenter);
      best = &ax;
      b_right = side_right;
    }
    tlast = std::min(tlast, texit);
    if (tfirst > tmax || tfirst > tlast) return r;
  }
  r.time = T(tfirst);
  if (best == nullptr) {
    r.overlap = true;
    return r;
  }
  // Contact set: the extreme features of `best` (chosen exactly at time 0; translation keeps
  // them), moved to tfirst, intersected in the coordinate plane of the axis' largest normal
  // component and lifted back to the plane of A's feature.
  const Axis& ax = *best;
  std::size_t alo, ahi, blo, bhi;
  extremes(ax, a.v, alo, ahi, scratch);
  extremes(ax, b.v, blo, bhi, scratch);
  const std::size_t ia = b_right ? ahi : alo, ib = b_right ? blo : bhi;
  std::vector<V> fa, fb;
  for (const V& p : a.v)
    if (axis_sign(ax, p, a.v[ia]) == 0) fa.push_back(p + tfirst * va);
  for (const V& p : b.v)
    if (axis_sign(ax, p, b.v[ib]) == 0) fb.push_back(p + tfirst * vb);
  V n;
  int k;
  if (ax.planar) {
    const auto& t = a.tri.front();
    n = cross(a.v[t[1]] - a.v[t[0]], a.v[t[2]] - a.v[t[0]]);
    k = ax.k;
  } else {
    n = cross(ax.p1 - ax.p0, ax.q1 - ax.q0);
    k = std::abs(n.x) >= std::abs(n.y) && std::abs(n.x) >= std::abs(n.z)
            ? 0
            : (std::abs(n.y) >= std::abs(n.z) ? 1 : 2);
  }
  std::vector<V2> pa, pb;
  for (const V& p : fa) pa.push_back(drop(p, k));
  for (const V& p : fb) pb.push_back(drop(p, k));
  pa = small_hull(pa);
  pb = small_hull(pb);
  std::vector<V2> out(pa.size() + pb.size());
  std::vector<detail::sat2::Sym> work(detail::sat2::work_size(pa.size(), pb.size()));
  int count = 0;
  Kind kind = detail::sat2::find<double>(pa, pb, out.data(), count, work.data());
  if (kind == Kind::empty || count == 0) {
    // Rounding of the moved features lost a contact the exact sides found: report one feature
    // point (a vertex feature if there is one).
    kind = Kind::point;
    count = 1;
    out.resize(1);
    out[0] = fb.size() == 1 ? drop(fb[0], k) : drop(fa[0], k);
  }
  // Lift onto the plane of A's feature (through fa[0], normal n): coordinate k from the others.
  const V& o = fa.front();
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  r.kind = kind;
  for (int c = 0; c < count; ++c) {
    const V2& q = out[static_cast<std::size_t>(c)];
    V p{};
    p[i] = q.x;
    p[j] = q.y;
    p[k] = o[k] - (n[i] * (q.x - o[i]) + n[j] * (q.y - o[j])) / n[k];
    r.points.push_back(vec_cast<T>(p));
  }
  return r;
}

template <Real T>
ConvexOverlap3<T> overlap(const ConvexMesh3<T>& a_in, const ConvexMesh3<T>& b_in) {
  ConvexOverlap3<T> r;
  const SatTest3 t = test<T>(a_in, b_in);
  r.status = t.status;
  r.intersects = t.intersects;
  if (!t.intersects) return r;
  Poly a, b;
  (void)load(a_in, a);
  (void)load(b_in, b);
  std::vector<V> out;
  // Vertices of one inside the other (a solid only: a flat container's vertices are found as
  // edge-triangle touches). Inside: on the inner side of, or on, every triangle's plane; the
  // inner side is that of a vertex off the plane (exact orient3d).
  const auto inside = [](const Poly& p, std::span<const V> pts, std::vector<V>& dst) {
    if (p.flat) return;
    std::vector<Sign> inner;
    for (const auto& f : p.tri) {
      Sign s = Sign::zero;
      for (const V& q : p.v)
        if ((s = orient3d(p.v[f[0]], p.v[f[1]], p.v[f[2]], q)) != Sign::zero) break;
      inner.push_back(s);
    }
    for (const V& x : pts) {
      bool in = true;
      for (std::size_t i = 0; i < p.tri.size() && in; ++i) {
        const auto& f = p.tri[i];
        const Sign s = orient3d(p.v[f[0]], p.v[f[1]], p.v[f[2]], x);
        in = s == Sign::zero || s == inner[i];
      }
      if (in) dst.push_back(x);
    }
  };
  inside(b, a.v, out);
  inside(a, b.v, out);
  // Every edge of each (all of them: parallel ones are distinct segments here) against every
  // triangle of the other.
  const auto crossings = [](const ConvexMesh3<T>& e_in, const Poly& e, const Poly& f,
                            std::vector<V>& dst) {
    std::vector<std::array<std::uint32_t, 2>> edges;
    if (!e_in.edges.empty()) {
      edges.assign(e_in.edges.begin(), e_in.edges.end());
    } else {
      for (const auto& t3 : e_in.triangles)
        for (int i = 0; i < 3; ++i) {
          const std::uint32_t p = t3[static_cast<std::size_t>(i)],
                              q = t3[static_cast<std::size_t>((i + 1) % 3)];
          if (p != q) edges.push_back({std::min(p, q), std::max(p, q)});
        }
      std::sort(edges.begin(), edges.end());
      edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    }
    for (const auto& ed : edges) {
      const Segment3<double> s{e.v[ed[0]], e.v[ed[1]]};
      for (const auto& t3 : f.tri) {
        const Triangle3<double> tri{f.v[t3[0]], f.v[t3[1]], f.v[t3[2]]};
        const auto x = intersection(s, tri);
        for (int k = 0; k < x.count; ++k) dst.push_back(x.point[static_cast<std::size_t>(k)]);
      }
    }
  };
  crossings(a_in, a, b, out);
  crossings(b_in, b, a, out);
  std::sort(out.begin(), out.end(), [](const V& p, const V& q) {
    return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z)));
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  for (const V& p : out) r.vertices.push_back(vec_cast<T>(p));
  return r;
}

template ConvexOverlap3<float> overlap<float>(const ConvexMesh3<float>&, const ConvexMesh3<float>&);
template ConvexOverlap3<double> overlap<double>(const ConvexMesh3<double>&,
                                                const ConvexMesh3<double>&);
template SatTest3 test<float>(const ConvexMesh3<float>&, const ConvexMesh3<float>&);
template SatTest3 test<double>(const ConvexMesh3<double>&, const ConvexMesh3<double>&);
template Contact3<float> first_contact<float>(const ConvexMesh3<float>&, const Vec3<float>&,
                                              const ConvexMesh3<float>&, const Vec3<float>&, float);
template Contact3<double> first_contact<double>(const ConvexMesh3<double>&, const Vec3<double>&,
                                                const ConvexMesh3<double>&, const Vec3<double>&,
                                                double);

}  // namespace locus::detail::sat3
