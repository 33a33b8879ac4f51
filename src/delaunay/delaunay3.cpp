// SPDX-License-Identifier: BSL-1.0
// 3D Delaunay tetrahedralization (see include/locus/delaunay/delaunay3.hpp for the contract).
//
// Internal representation: a closed triangulated 3-sphere. Real cells are positively oriented;
// every hull face is matched by a ghost cell (a, b, c, kGhost) with the ghost vertex always at
// corner 3 and face 3 = (a, b, c) oriented with the outside on its positive side, so "is ghost"
// is one load and the adjacency has no boundary: the cavity code has no hull special case.
// neighbors[i] holds 4 * cell + face (the face index of this face in the neighbouring cell).

#include <locus/config.hpp>
#include <locus/delaunay/delaunay3.hpp>

#include <locus/core/detail/spatial_sort.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <utility>

namespace locus {

namespace {

constexpr std::uint32_t kGhost = 0xFFFFFFFFu;
constexpr std::uint32_t kDead = 0xFFFFFFFEu;  // vertices[3] of a free slot
constexpr std::uint32_t kNone = 0xFFFFFFFFu;
constexpr std::size_t kMaxPoints = std::size_t(1) << 26;  // 4 * cells + 3 fits in int32

constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

template <Real T>
[[nodiscard]] bool same_point(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

// a, b, c on one line (exactly): every coordinate projection is degenerate.
template <Real T>
[[nodiscard]] bool collinear(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) noexcept {
  return orient2d(Vec2<T>{a.x, a.y}, Vec2<T>{b.x, b.y}, Vec2<T>{c.x, c.y}) == Sign::zero &&
         orient2d(Vec2<T>{a.y, a.z}, Vec2<T>{b.y, b.z}, Vec2<T>{c.y, c.z}) == Sign::zero &&
         orient2d(Vec2<T>{a.x, a.z}, Vec2<T>{b.x, b.z}, Vec2<T>{c.x, c.z}) == Sign::zero;
}

// The synthetic apex of a coplanar input (see the header): `a` with its coordinate along the
// first axis not parallel to the plane of a, b, c (non-collinear) changed, so it is off the
// plane exactly. The faces opposite the apex are oriented toward it; `flip` says to reverse
// them so that their normals have a positive component along that axis.
template <Real T>
struct PlanarApex {
  Vec3<T> point;
  bool flip;
};

template <Real T>
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

// The zero case of insphere_perturbed: point q's lift |q|^2 is raised by eps_q, larger for
// lexicographically larger q. The perturbed determinant is insphere + sum eps_q * C_q with
// C_e = -orient3d(a, b, c, d) (raising e moves it outside) and, by antisymmetry, C_q for a
// vertex q = orient3d of (a, b, c, d) with q replaced by e. The largest eps with a nonzero
// cofactor decides.
// order[] = 0 .. 4 sorted so that p[order[0]] is the lexicographically largest (insertion
// sort: five points).
template <Real T>
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

template <Real T>
LOCUS_NOINLINE Sign perturbed_zero_case(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c,
                                        const Vec3<T>& d, const Vec3<T>& e) noexcept {
  const Vec3<T>* const p[5] = {&a, &b, &c, &d, &e};
  int order[5];
  lexicographic_descending(p, order);
  for (const int k : order) {
    Sign s;
    if (k == 4) {
      s = -orient3d(a, b, c, d);
    } else {
      const Vec3<T>* q[4] = {&a, &b, &c, &d};
      q[k] = &e;
      s = orient3d(*q[0], *q[1], *q[2], *q[3]);
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

// The perturbed sign of an exactly cospherical a, b, c, d, e from the exact minors
// {bcd, cda, dab, abc} of the differences p - e (detail::InsphereTerms): with e at the origin,
// the cofactors of perturbed_zero_case are orient3d(e, b, c, d) = minor[0], orient3d(a, e, c, d)
// = -minor[1], orient3d(a, b, e, d) = minor[2], orient3d(a, b, c, e) = -minor[3] and
// orient3d(a, b, c, d) = minor[0] - minor[1] + minor[2] - minor[3] (row operations), all exact
// in double on the insphere lattice (below 4 * 6 * 2^27 q^3). The lexicographically largest
// point with a nonzero cofactor decides.
LOCUS_NOINLINE Sign perturbed_from_minors(const Vec3<double>& a, const Vec3<double>& b,
                                          const Vec3<double>& c, const Vec3<double>& d,
                                          const Vec3<double>& e, const double minor[4]) noexcept {
  const double cofactor[5] = {minor[0], -minor[1], minor[2], -minor[3],
                              -((minor[0] - minor[1]) + (minor[2] - minor[3]))};
  const Vec3<double>* const pts[5] = {&a, &b, &c, &d, &e};
  int top = -1;
  for (int k = 0; k < 5; ++k)
    if (cofactor[k] != 0.0 && (top < 0 || lexicographically_greater(*pts[k], *pts[top]))) top = k;
  return top < 0 ? Sign::zero  // a, b, c, d coplanar and e on their plane
                 : detail::nonzero_sign(cofactor[top]);
}

// After the semi-static filter failed: the insphere lattice shortcut of core (exact terms, and
// an exact zero perturbed from their minors), else core's full stage A and adaptive stages, and
// perturbed_zero_case for an exact zero.
LOCUS_NOINLINE Sign insphere_perturbed_slow(const Vec3<double>& a, const Vec3<double>& b,
                                            const Vec3<double>& c, const Vec3<double>& d,
                                            const Vec3<double>& e) noexcept {
  if (const std::optional<detail::InsphereTerms> t = detail::insphere_lattice(a, b, c, d, e)) {
    if (t->det != 0.0) return -detail::nonzero_sign(t->det);
    return perturbed_from_minors(a, b, c, d, e, t->minor);
  }
  const detail::StageA<double> f = detail::insphere_stage_a(a, b, c, d, e);
  const Sign s =
      detail::certain(f) ? detail::nonzero_sign(f.det) : detail::insphere_adaptive(a, b, c, d, e);
  if (s != Sign::zero) return s;
  return perturbed_zero_case(a, b, c, d, e);
}

// The perturbed insphere (float input is promoted exactly; the perturbation only compares and
// takes orientations, so deciding it on the doubles is the same): core's semi-static filter
// (the cavity's cells have similar spreads in BRIO order), then the slow path.
template <Real T>
LOCUS_ALWAYS_INLINE inline Sign insphere_perturbed_inline(const Vec3<T>& pa, const Vec3<T>& pb,
                                                          const Vec3<T>& pc, const Vec3<T>& pd,
                                                          const Vec3<T>& pe) noexcept {
  const Vec3<double> a = detail::to_double(pa), b = detail::to_double(pb),
                     c = detail::to_double(pc), d = detail::to_double(pd),
                     e = detail::to_double(pe);
  const detail::StageA<double> f =
      detail::insphere_stage_a_semi_static(detail::insphere_terms(a, b, c, d, e));
  if (detail::certain(f)) [[likely]]
    return detail::nonzero_sign(f.det);
  return insphere_perturbed_slow(a, b, c, d, e);
}

// Every point on core's insphere lattice (detail::points_on_insphere_lattice: integer grids,
// voxels): the double evaluation of the determinants is exact, so no filter is needed, and an
// exact zero is perturbed from the same minors.
template <Real T>
LOCUS_ALWAYS_INLINE inline Sign insphere_perturbed_lattice(const Vec3<T>& pa, const Vec3<T>& pb,
                                                           const Vec3<T>& pc, const Vec3<T>& pd,
                                                           const Vec3<T>& pe) noexcept {
  const Vec3<double> a = detail::to_double(pa), b = detail::to_double(pb),
                     c = detail::to_double(pc), d = detail::to_double(pd),
                     e = detail::to_double(pe);
  const detail::InsphereTerms q = detail::insphere_terms(a, b, c, d, e);
  if (q.det != 0.0) [[likely]]
    return -detail::nonzero_sign(q.det);
  return perturbed_from_minors(a, b, c, d, e, q.minor);
}

// orient3d on the insphere lattice: the double determinant is exact.
template <Real T>
LOCUS_ALWAYS_INLINE inline Sign orient3d_on_lattice(const Vec3<T>& pa, const Vec3<T>& pb,
                                                    const Vec3<T>& pc, const Vec3<T>& pd) noexcept {
  return sign_of(detail::orient3d_stage_a(detail::to_double(pa), detail::to_double(pb),
                                          detail::to_double(pc), detail::to_double(pd))
                     .det);
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
Delaunay3Result Delaunay3<T>::take_result() {
  if (dirty_) compact(false);
  Delaunay3Result r = std::move(result_);
  result_ = Delaunay3Result{};
  points_.clear();
  sorted_.clear();
  orig_.clear();
  cell_v_.clear();
  cell_n_.clear();
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
  std::vector<std::uint32_t> order;
  detail::brio_order(points, order, keys_, keys_tmp_);
  for (const std::uint32_t k : order) {
    const std::uint32_t i = static_cast<std::uint32_t>(n0) + k;
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
LOCUS_ALWAYS_INLINE inline std::uint32_t Delaunay3<T>::edge_match(std::uint32_t u, std::uint32_t v,
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
LOCUS_ALWAYS_INLINE inline void Delaunay3<T>::glue(std::uint32_t code,
                                                   std::uint32_t other) noexcept {
  if (other == kNone) return;
  cell_n_[code >> 2][code & 3u] = static_cast<std::int32_t>(other);
  cell_n_[other >> 2][other & 3u] = static_cast<std::int32_t>(code);
}

// Links the faces through `apex` of the given cells: the face through apex and edge x -> y
// (in the face's orientation) meets the face of another cell with the edge y -> x.
template <Real T>
void Delaunay3<T>::link_around(std::span<const std::uint32_t> cells, std::uint32_t apex) {
  edges_begin(3 * cells.size());
  for (const std::uint32_t t : cells) {
    const auto& v = cell_v_[t];
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
LOCUS_ALWAYS_INLINE inline bool Delaunay3<T>::in_conflict(std::uint32_t t,
                                                          std::uint32_t v) const noexcept {
  const auto& c_v = cell_v_[t];
  const auto& c_n = cell_n_[t];
  const Vec3<T>* pts = sorted_.data();
  const Vec3<T>& p = pts[v];
  if (c_v[3] == kGhost) [[unlikely]] {
    const Vec3<T>&a = pts[c_v[0]], &b = pts[c_v[1]], &cc = pts[c_v[2]];
    const Sign s = lattice_ ? orient3d_on_lattice(a, b, cc, p) : orient3d(a, b, cc, p);
    if (s != Sign::zero) return s == Sign::positive;
    // On the hull plane: the ghost goes with the real cell under the face, so the face is
    // either inside the cavity or not on its boundary (never a flat new cell).
    const auto& r_v = cell_v_[std::uint32_t(c_n[3]) >> 2];
    const Vec3<T>&ra = pts[r_v[0]], &rb = pts[r_v[1]], &rc = pts[r_v[2]], &rd = pts[r_v[3]];
    return (lattice_ ? insphere_perturbed_lattice(ra, rb, rc, rd, p)
                     : insphere_perturbed_inline(ra, rb, rc, rd, p)) == Sign::positive;
  }
  const Vec3<T>&a = pts[c_v[0]], &b = pts[c_v[1]], &cc = pts[c_v[2]], &d = pts[c_v[3]];
  if (lattice_) return insphere_perturbed_lattice(a, b, cc, d, p) == Sign::positive;
  return insphere_perturbed_inline(a, b, cc, d, p) == Sign::positive;
}

template <Real T>
std::uint32_t Delaunay3<T>::scan(std::uint32_t v, std::uint32_t* duplicate) noexcept {
  const Vec3<T>* pts = sorted_.data();
  const Vec3<T>& p = pts[v];
  const std::uint32_t nc = static_cast<std::uint32_t>(cell_v_.size());
  for (std::uint32_t t = 0; t < nc; ++t) {
    const auto& c_v = cell_v_[t];
    if (c_v[3] >= kDead) continue;
    bool inside = true;
    for (int i = 0; i < 4 && inside; ++i)
      inside = orient3d(pts[c_v[std::size_t(kFace[i][0])]], pts[c_v[std::size_t(kFace[i][1])]],
                        pts[c_v[std::size_t(kFace[i][2])]], p) != Sign::negative;
    if (!inside) continue;
    for (int i = 0; i < 4; ++i)
      if (same_point(pts[c_v[std::size_t(i)]], p)) *duplicate = c_v[std::size_t(i)];
    return t;
  }
  for (std::uint32_t t = 0; t < nc; ++t)
    if (cell_v_[t][3] == kGhost && in_conflict(t, v)) return t;
  return kNone;
}

template <Real T>
std::uint32_t Delaunay3<T>::walk(std::uint32_t v, std::uint32_t t,
                                 std::uint32_t* duplicate) noexcept {
  // A visibility walk in a Delaunay tetrahedralization visits no cell twice (Edelsbrunner's
  // acyclicity of the in-front relation), so it ends within the cell count; the budget guards
  // a corrupted structure. The face order is varied per step (a remembering stochastic walk).
  const std::size_t budget = cell_v_.size() + 64;
  const Vec3<T>* pts = sorted_.data();
  const Vec3<T> p = pts[v];
  std::uint32_t came = kNone;
  std::uint32_t rng = walk_rng_;
  for (std::size_t step = 0; step < budget; ++step) {
    const auto& c_v = cell_v_[t];
    const auto& c_n = cell_n_[t];
    if (c_v[3] == kGhost) {
      const Vec3<T>&a = pts[c_v[0]], &b = pts[c_v[1]], &cc = pts[c_v[2]];
      if ((lattice_ ? orient3d_on_lattice(a, b, cc, p) : orient3d(a, b, cc, p)) == Sign::positive) {
        walk_rng_ = rng;
        return t;
      }
      // p is on the real side of the hull face or on its plane: test every face from inside.
      came = kNone;
      t = std::uint32_t(c_n[3]) >> 2;
      continue;
    }
    rng = rng * 1664525u + 1013904223u;
    const int start = static_cast<int>(rng >> 30);
    int zeros = 0;
    bool moved = false;
    for (int j = 0; j < 4; ++j) {
      const int i = (start + j) & 3;
      const std::uint32_t nb = std::uint32_t(c_n[std::size_t(i)]) >> 2;
      if (nb == came) continue;
      const Vec3<T>& a = pts[c_v[std::size_t(kFace[i][0])]];
      const Vec3<T>& b = pts[c_v[std::size_t(kFace[i][1])]];
      const Vec3<T>& cc = pts[c_v[std::size_t(kFace[i][2])]];
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
        if (same_point(pts[c_v[std::size_t(i)]], p)) *duplicate = c_v[std::size_t(i)];
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
  std::size_t budget = cell_v_.size() + 16;
  while (!stack_.empty()) {
    if (budget-- == 0) return false;
    const std::uint32_t c = stack_.back();
    stack_.pop_back();
    for (int i = 0; i < 4; ++i) {
      const std::int32_t code = cell_n_[c][std::size_t(i)];
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
      const auto& cc_v = cell_v_[c];
      boundary_.push_back({cc_v[std::size_t(kFace[i][0])], cc_v[std::size_t(kFace[i][1])],
                           cc_v[std::size_t(kFace[i][2])], code});
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
      s = static_cast<std::uint32_t>(cell_v_.size());
      cell_v_.push_back({});
      cell_n_.push_back({});
      mark_.push_back(0);
      mark = mark_.data();
    }
    fresh_.push_back(s);
  }
  for (std::size_t k = nb_faces; k < cavity_.size(); ++k) {
    cell_v_[cavity_[k]] = {kNone, kNone, kNone, kDead};
    free_.push_back(cavity_[k]);
  }
  for (std::size_t k = 0; k < nb_faces; ++k) {
    const Boundary& f = boundary_[k];
    const std::uint32_t s = fresh_[k];
    std::array<std::uint32_t, 4>& cell_v = cell_v_[s];
    std::array<std::uint32_t, 4>& cell_n = cell_n_[s];
    // (a, b, c, v) is positive: v sees the face from the cavity side. A ghost vertex is moved
    // to corner 3 by an even permutation.
    int apex_corner = 3;
    if (f.a == kGhost) {
      cell_v = {v, f.c, f.b, kGhost};
      apex_corner = 0;
    } else if (f.b == kGhost) {
      cell_v = {f.c, v, f.a, kGhost};
      apex_corner = 1;
    } else if (f.c == kGhost) {
      cell_v = {f.b, f.a, v, kGhost};
      apex_corner = 2;
    } else {
      cell_v = {f.a, f.b, f.c, v};
    }
    cell_n[std::size_t(apex_corner)] = f.outside;
    cell_n_[std::uint32_t(f.outside) >> 2][std::uint32_t(f.outside) & 3u] =
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
  cell_v_.clear();
  cell_n_.clear();
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

  // BRIO rounds in Hilbert order (core/detail/spatial_sort.hpp).
  detail::brio_order(std::span<const Vec3<T>>(points_), orig_, keys_, keys_tmp_);
  sorted_.resize(n);
  for (std::size_t k = 0; k < n; ++k) sorted_[k] = points_[orig_[k]];
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
  lattice_ = detail::points_on_insphere_lattice(std::span<const Vec3<T>>(sorted_));
  std::uint32_t a = 0, b = static_cast<std::uint32_t>(k1), c = static_cast<std::uint32_t>(k2),
                d = static_cast<std::uint32_t>(k3);
  if (orient3d(pts[a], pts[b], pts[c], pts[d]) == Sign::negative) std::swap(c, d);

  cell_v_.reserve(7 * n + 64);

  cell_n_.reserve(7 * n + 64);
  mark_.reserve(7 * n + 64);
  cell_v_.resize(5);
  cell_n_.resize(5);
  mark_.assign(5, 0);
  cell_v_[0] = {a, b, c, d};
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t f0 = cell_v_[0][std::size_t(kFace[i][0])];
    const std::uint32_t f1 = cell_v_[0][std::size_t(kFace[i][1])];
    const std::uint32_t f2 = cell_v_[0][std::size_t(kFace[i][2])];
    const std::uint32_t g = 1 + std::uint32_t(i);
    cell_v_[g] = {f0, f2, f1, kGhost};  // the outside on the positive side
    cell_n_[g][3] = static_cast<std::int32_t>(4 * 0 + std::uint32_t(i));
    cell_n_[0][std::size_t(i)] = static_cast<std::int32_t>(4 * g + 3);
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
  r.adjacency.clear();
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
  // New index of each real cell (mark_ is reused as the map); ghosts and free slots map to
  // kNoTetrahedron, building codes 4 * cell + face to the neighbour's new index.
  const std::uint32_t nc = static_cast<std::uint32_t>(cell_v_.size());
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < nc; ++t)
    mark_[t] = cell_v_[t][3] >= kDead ? kNoTetrahedron : count++;
  const std::uint32_t* map = mark_.data();
  const std::uint32_t* orig = orig_.data();
  std::array<std::uint32_t, 4>* tets = cell_v_.data();
  std::array<std::uint32_t, 4>* adjacency = cell_n_.data();
  if (!in_place) {
    r.tetrahedra.resize(count);
    r.adjacency.resize(count);
    tets = r.tetrahedra.data();
    adjacency = r.adjacency.data();
  }
  // In place, slot map[t] <= t, so a forward pass packs the arrays (already in the result's
  // type) without overwriting unread cells, and they are handed over: no second copy of 32 bytes
  // per cell is allocated or touched.
  for (std::uint32_t t = 0; t < nc; ++t) {
    const std::array<std::uint32_t, 4> v = cell_v_[t];
    if (v[3] == kGhost) {
      r.hull.push_back({orig[v[0]], orig[v[1]], orig[v[2]]});
      continue;
    }
    if (v[3] == kDead) continue;
    const std::array<std::uint32_t, 4> n = cell_n_[t];
    const std::uint32_t k = map[t];
    for (std::size_t i = 0; i < 4; ++i) {
      tets[k][i] = orig[v[i]];
      adjacency[k][i] = map[n[i] >> 2];
    }
  }
  if (in_place) {
    cell_v_.resize(count);
    cell_n_.resize(count);
    r.tetrahedra.swap(cell_v_);
    r.adjacency.swap(cell_n_);
    cell_v_.clear();
    cell_n_.clear();
    mark_.clear();
    mark_.shrink_to_fit();
    sorted_.clear();
    sorted_.shrink_to_fit();
    orig_.clear();
    orig_.shrink_to_fit();
    dimension_ = -1;
    return;
  }
  // The query start: a real cell of the last inserted point (under it when last_ is a ghost).
  std::uint32_t last = last_;
  if (cell_v_[last][3] == kGhost) last = std::uint32_t(cell_n_[last][3]) >> 2;
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
  for (const std::array<std::uint32_t, 4>& c_v : cell_v_) {
    if (c_v[3] >= kDead) continue;
    int j = 0;
    while (j < 3 && c_v[std::size_t(j)] != apex_) ++j;
    std::array<std::uint32_t, 3> t;
    for (int k = 0; k < 3; ++k) t[std::size_t(k)] = orig_[c_v[std::size_t(kFace[j][k])]];
    if (apex_flip_) std::swap(t[1], t[2]);
    r.triangles.push_back(t);
  }
  if (in_place) {
    cell_v_.clear();
    cell_n_.clear();
    cell_v_.shrink_to_fit();
    cell_n_.shrink_to_fit();
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
template <Real T>
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

template <Real T>
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
template <Real T>
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

template <Real T>
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
  std::vector<std::uint32_t> index(hull.facets.size(), kNoTetrahedron);
  std::uint32_t count = 0;
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
    std::array<std::uint32_t, 4> v, nb;
    for (std::size_t i = 0; i < 4; ++i) {
      v[i] = kept[F.v[i]];
      nb[i] = index[F.nb[i]];
    }
    r.tetrahedra.push_back(v);
    r.adjacency.push_back(nb);
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

// Tetrahedron t of dt has vertices below np and neighbours below nt (or none).
[[nodiscard]] bool valid_tetrahedron(const Delaunay3Result& dt, std::size_t t, std::size_t np,
                                     std::size_t nt) noexcept {
  if (t >= dt.adjacency.size()) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint32_t nb = dt.adjacency[t][i];
    if (dt.tetrahedra[t][i] >= np || (nb != kNoTetrahedron && nb >= nt)) return false;
  }
  return true;
}

template <Real T>
[[nodiscard]] Sign face_side(std::span<const Vec3<T>> pts, const std::array<std::uint32_t, 4>& v,
                             int i, const Vec3<T>& p) noexcept {
  return orient3d(pts[v[std::size_t(kFace[i][0])]], pts[v[std::size_t(kFace[i][1])]],
                  pts[v[std::size_t(kFace[i][2])]], p);
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
    if (!valid_tetrahedron(dt, t, np, nt)) {
      r.status = Status::invalid_input;
      return r;
    }
    const std::array<std::uint32_t, 4>& v = dt.tetrahedra[t];
    unsigned zero_mask = 0;
    bool moved = false;
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t nb = dt.adjacency[t][std::size_t(i)];
      if (nb != kNoTetrahedron && std::size_t(nb) == came) continue;  // p is strictly this side
      const Sign s = face_side(points, v, i, p);
      if (s == Sign::negative) {
        if (nb == kNoTetrahedron) {  // beyond a hull face: outside the convex hull
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
    if (!valid_tetrahedron(dt, u, np, nt)) {
      r.status = Status::invalid_input;
      return r;
    }
    unsigned zero_mask = 0;
    bool in = true;
    for (int i = 0; i < 4 && in; ++i) {
      const Sign s = face_side(points, dt.tetrahedra[u], i, p);
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
      if (dt.adjacency[u][std::size_t(i)] == kNoTetrahedron &&
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
  std::uint32_t best = dt.tetrahedra[t][0];
  for (const std::uint32_t v : dt.tetrahedra[t])
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
      if (!valid_tetrahedron(dt, s, np, dt.tetrahedra.size())) {
        r.status = Status::invalid_input;
        return r;
      }
      for (std::size_t i = 0; i < 4 && !moved; ++i) {
        const std::uint32_t w = dt.tetrahedra[s][i];
        if (w == best) continue;
        if (compare_sqr_distance(p, points[w], points[best]) == Sign::negative) {
          best = w;
          t = s;
          moved = true;
          break;
        }
        // Face i contains `best` (it is opposite another corner): its neighbour is in the star.
        const std::uint32_t nb = dt.adjacency[s][i];
        if (nb == kNoTetrahedron) continue;
        bool seen = false;
        for (std::size_t k = 0; k < count && !seen; ++k) seen = star[k] == nb;
        if (seen) continue;
        if (count == kStar) {  // an unusually large star: decide by scanning
          scan();
          return r;
        }
        star[count++] = nb;
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
