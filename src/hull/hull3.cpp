// SPDX-License-Identifier: BSL-1.0
// 3D convex hull (cg.hull3): QuickHull and the book's incremental method with exact predicates
// (include/locus/hull/hull3.hpp), compiled once for float and double.

#include <locus/hull/hull3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace locus {

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

template <Real T>
[[nodiscard]] Vec2<T> drop_axis(const Vec3<T>& p, int k) noexcept {
  return Vec2<T>{p[(k + 1) % 3], p[(k + 2) % 3]};
}

// Three points are collinear iff their three coordinate projections are (the components of
// (b - a) x (c - a) are those 2D determinants).
template <Real T>
[[nodiscard]] bool collinear3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) noexcept {
  for (int k = 0; k < 3; ++k)
    if (orient2d(drop_axis(a, k), drop_axis(b, k), drop_axis(c, k)) != Sign::zero) return false;
  return true;
}

template <Real T>
[[nodiscard]] bool lex_less(const Vec3<T>& a, const Vec3<T>& b) noexcept {
  return lexicographic_compare(a, b) == Sign::negative;
}

template <Real T>
[[nodiscard]] Sign side(const Vec3<T>* p, const std::uint32_t v[3], std::uint32_t q) noexcept {
  return orient3d(p[v[0]], p[v[1]], p[v[2]], p[q]);
}

// Bit pattern of a coordinate with -0 folded into +0 (equal values, equal keys).
template <Real T>
[[nodiscard]] std::uint64_t coord_bits(T x) noexcept {
  x = x + T(0);
  if constexpr (sizeof(T) == 8) {
    std::uint64_t b;
    std::memcpy(&b, &x, 8);
    return b;
  } else {
    std::uint32_t b;
    std::memcpy(&b, &x, 4);
    return b;
  }
}

template <Real T>
[[nodiscard]] std::uint64_t point_hash(const Vec3<T>& p) noexcept {
  std::uint64_t h = coord_bits(p.x) * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 29) ^ coord_bits(p.y)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 31) ^ coord_bits(p.z)) * 0x94D049BB133111EBull;
  return h ^ (h >> 32);
}

}  // namespace

template <Real T>
Hull3Result ConvexHull3<T>::compute(std::span<const Vec3<T>> points, const Hull3Options& options) {
  Hull3Result r;
  compute(points, options, r);
  return r;
}

template <Real T>
void ConvexHull3<T>::compute(std::span<const Vec3<T>> points, const Hull3Options& options,
                             Hull3Result& out) {
  out.status = Status::ok;
  out.dimension = -1;
  out.triangles.clear();
  out.adjacency.clear();
  out.polygon.clear();
  out.plane_axis = -1;
  out.vertices.clear();
  const std::size_t n = points.size();
  if (n == 0) {
    out.status = Status::empty_input;
    return;
  }
  if (n >= kNone) {
    out.status = Status::invalid_input;
    return;
  }
  pts_ = points.data();
  n_ = n;
  constexpr T big = std::numeric_limits<T>::max();
  const bool filter = options.method == Hull3Method::quickhull && n >= 2000;
  // Extremes along x, y, z and the four body diagonals (heuristic values in double).
  double ext_min[7], ext_max[7];
  std::uint32_t arg_min[7] = {}, arg_max[7] = {};
  for (int k = 0; k < 7; ++k) {
    ext_min[k] = std::numeric_limits<double>::infinity();
    ext_max[k] = -std::numeric_limits<double>::infinity();
  }
  bool finite = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<T> p = points[i];
    finite &= std::abs(p.x) <= big && std::abs(p.y) <= big && std::abs(p.z) <= big;
    if (!filter) continue;
    const double x = static_cast<double>(p.x), y = static_cast<double>(p.y),
                 z = static_cast<double>(p.z);
    const double v[7] = {x + y + z, x + y - z, x - y + z, x - y - z, x, y, z};
    for (int k = 0; k < 7; ++k) {
      if (v[k] < ext_min[k]) {
        ext_min[k] = v[k];
        arg_min[k] = static_cast<std::uint32_t>(i);
      }
      if (v[k] > ext_max[k]) {
        ext_max[k] = v[k];
        arg_max[k] = static_cast<std::uint32_t>(i);
      }
    }
  }
  if (!finite) {
    out.status = Status::non_finite_input;
    return;
  }
  ids_.clear();
  bool filtered = false;
  if (filter) {
    std::vector<std::uint32_t> cand;
    for (int k = 0; k < 7; ++k) {
      cand.push_back(arg_min[k]);
      cand.push_back(arg_max[k]);
    }
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    Hull3Result small;
    if (build(cand, Hull3Method::quickhull, small, false) == 3) {
      // The box from the diagonal extremes: a point extreme in direction (sx, sy, sz) bounds the
      // box from below on the axes where s is negative and from above where it is positive.
      static constexpr int sgn[4][3] = {{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}};
      T lo[3], hi[3];
      for (int a = 0; a < 3; ++a) lo[a] = -big, hi[a] = big;
      for (int k = 0; k < 4; ++k) {
        for (int which = 0; which < 2; ++which) {
          const Vec3<T> e = points[which == 0 ? arg_max[k] : arg_min[k]];
          for (int a = 0; a < 3; ++a) {
            const int s = which == 0 ? sgn[k][a] : -sgn[k][a];
            if (s < 0)
              lo[a] = std::max(lo[a], e[a]);
            else
              hi[a] = std::min(hi[a], e[a]);
          }
        }
      }
      bool ok = lo[0] < hi[0] && lo[1] < hi[1] && lo[2] < hi[2];
      if (ok) {
        ok = false;
        T c[3];
        for (int a = 0; a < 3; ++a) c[a] = lo[a] / T(2) + hi[a] / T(2);
        for (const T f :
             {T(1), T(1) - T(0x1p-20), T(1) - T(0x1p-12), T(1) - T(0x1p-6), T(0.9), T(0.5)}) {
          T l[3], h[3];
          for (int a = 0; a < 3; ++a) {
            l[a] = c[a] + f * (lo[a] - c[a]);
            h[a] = c[a] + f * (hi[a] - c[a]);
          }
          bool inside = true;
          for (int corner = 0; corner < 8 && inside; ++corner) {
            const Vec3<T> q{(corner & 1) ? h[0] : l[0], (corner & 2) ? h[1] : l[1],
                            (corner & 4) ? h[2] : l[2]};
            for (const auto& t : small.triangles) {
              if (orient3d(points[t[0]], points[t[1]], points[t[2]], q) != Sign::negative) {
                inside = false;
                break;
              }
            }
          }
          if (inside) {
            for (int a = 0; a < 3; ++a) lo[a] = l[a], hi[a] = h[a];
            ok = true;
            break;
          }
        }
      }
      if (ok) {
        // The closed box lies strictly inside the hull of input points: nothing in it is on the
        // hull's boundary.
        filtered = true;
        ids_.reserve(n / 8);
        for (std::size_t i = 0; i < n; ++i) {
          const Vec3<T> p = points[i];
          const bool in = (p.x >= lo[0]) & (p.x <= hi[0]) & (p.y >= lo[1]) & (p.y <= hi[1]) &
                          (p.z >= lo[2]) & (p.z <= hi[2]);
          if (!in) ids_.push_back(static_cast<std::uint32_t>(i));
        }
      }
    }
  }
  if (!filtered) {
    ids_.resize(n);
    for (std::size_t i = 0; i < n; ++i) ids_[i] = static_cast<std::uint32_t>(i);
  }
  const int dim = build(ids_, options.method, out, true);
  out.dimension = dim;
  if (dim == 3) {
    // Smallest index among duplicates: hash the hull vertices, look every candidate up.
    std::vector<std::uint32_t>& v = out.vertices;
    std::size_t cap = 16;
    while (cap < 2 * v.size()) cap *= 2;
    map_.assign(cap, kNone);
    for (std::uint32_t k = 0; k < v.size(); ++k) {
      std::size_t slot = point_hash(points[v[k]]) & (cap - 1);
      while (map_[slot] != kNone) slot = (slot + 1) & (cap - 1);
      map_[slot] = k;
    }
    std::vector<std::uint32_t> rep(v);
    bool changed = false;
    for (const std::uint32_t q : ids_) {
      std::size_t slot = point_hash(points[q]) & (cap - 1);
      while (map_[slot] != kNone) {
        const std::uint32_t k = map_[slot];
        if (points[v[k]] == points[q]) {
          if (q < rep[k]) {
            rep[k] = q;
            changed = true;
          }
          break;
        }
        slot = (slot + 1) & (cap - 1);
      }
    }
    if (changed) {
      // v is sorted; translate each triangle corner through it.
      for (auto& t : out.triangles)
        for (auto& x : t) x = rep[std::lower_bound(v.begin(), v.end(), x) - v.begin()];
      v = rep;
      std::sort(v.begin(), v.end());
    }
  }
}

// Picks an initial simplex and returns the dimension of the set (0..3).
template <Real T>
int ConvexHull3<T>::simplex(std::span<const std::uint32_t> ids, std::uint32_t s[4]) {
  const Vec3<T>* p = pts_;
  std::uint32_t i0 = ids[0], i1 = ids[0];
  for (const std::uint32_t q : ids) {
    if (lex_less(p[q], p[i0])) i0 = q;
    if (lex_less(p[i1], p[q])) i1 = q;
  }
  s[0] = i0;
  s[1] = i1;
  if (p[i0] == p[i1]) return 0;
  const Vec3<double> a = detail::to_double(p[i0]);
  const Vec3<double> ab = detail::to_double(p[i1]) - a;
  double best = -1.0;
  std::uint32_t i2 = kNone;
  for (const std::uint32_t q : ids) {
    const Vec3<double> aq = detail::to_double(p[q]) - a;
    const Vec3<double> c{ab.y * aq.z - ab.z * aq.y, ab.z * aq.x - ab.x * aq.z,
                         ab.x * aq.y - ab.y * aq.x};
    const double l = c.x * c.x + c.y * c.y + c.z * c.z;
    if (l > best) best = l, i2 = q;
  }
  if (i2 == kNone || collinear3(p[i0], p[i1], p[i2])) {
    i2 = kNone;
    for (const std::uint32_t q : ids)
      if (!collinear3(p[i0], p[i1], p[q])) {
        i2 = q;
        break;
      }
    if (i2 == kNone) return 1;
  }
  s[2] = i2;
  best = -1.0;
  std::uint32_t i3 = kNone;
  for (const std::uint32_t q : ids) {
    const double v = std::abs(orient3d_value(p[i0], p[i1], p[i2], p[q]));
    if (v > best) best = v, i3 = q;
  }
  if (i3 == kNone || orient3d(p[i0], p[i1], p[i2], p[i3]) == Sign::zero) {
    i3 = kNone;
    for (const std::uint32_t q : ids)
      if (orient3d(p[i0], p[i1], p[i2], p[q]) != Sign::zero) {
        i3 = q;
        break;
      }
    if (i3 == kNone) return 2;
  }
  s[3] = i3;
  return 3;
}

template <Real T>
void ConvexHull3<T>::planar(std::span<const std::uint32_t> ids, const std::uint32_t s[3],
                            Hull3Result& out) {
  const Vec3<T>* p = pts_;
  const Vec3<double> a = detail::to_double(p[s[0]]);
  const Vec3<double> u = detail::to_double(p[s[1]]) - a, w = detail::to_double(p[s[2]]) - a;
  const double nrm[3] = {std::abs(u.y * w.z - u.z * w.y), std::abs(u.z * w.x - u.x * w.z),
                         std::abs(u.x * w.y - u.y * w.x)};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return nrm[i] > nrm[j]; });
  int axis = order[0];
  for (const int k : order) {
    if (orient2d(drop_axis(p[s[0]], k), drop_axis(p[s[1]], k), drop_axis(p[s[2]], k)) !=
        Sign::zero) {
      axis = k;
      break;
    }
  }
  proj_.resize(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) proj_[i] = drop_axis(p[ids[i]], axis);
  hull2_.compute(std::span<const Vec2<T>>(proj_), Hull2Options{}, r2_);
  out.plane_axis = axis;
  for (const std::uint32_t k : r2_.indices) out.polygon.push_back(ids[k]);
  out.vertices = out.polygon;
  std::sort(out.vertices.begin(), out.vertices.end());
}

template <Real T>
std::uint32_t ConvexHull3<T>::new_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::uint32_t f;
  if (!free_.empty()) {
    f = free_.back();
    free_.pop_back();
  } else {
    f = static_cast<std::uint32_t>(faces_.size());
    faces_.emplace_back();
  }
  Face& F = faces_[f];
  F.v[0] = a, F.v[1] = b, F.v[2] = c;
  F.adj[0] = F.adj[1] = F.adj[2] = kNone;
  F.head = kNone;
  F.furthest = kNone;
  F.fdist = -std::numeric_limits<double>::infinity();
  const Vec3<double> pa = detail::to_double(pts_[a]);
  const Vec3<double> u = detail::to_double(pts_[b]) - pa, w = detail::to_double(pts_[c]) - pa;
  F.n[0] = u.y * w.z - u.z * w.y;
  F.n[1] = u.z * w.x - u.x * w.z;
  F.n[2] = u.x * w.y - u.y * w.x;
  F.off = F.n[0] * pa.x + F.n[1] * pa.y + F.n[2] * pa.z;
  F.vis = F.seen = 0;
  F.alive = true;
  return f;
}

template <Real T>
void ConvexHull3<T>::add_outside(std::uint32_t f, std::uint32_t q) {
  Face& F = faces_[f];
  const Vec3<T>& p = pts_[q];
  const double d = F.n[0] * static_cast<double>(p.x) + F.n[1] * static_cast<double>(p.y) +
                   F.n[2] * static_cast<double>(p.z) - F.off;
  next_[q] = F.head;
  F.head = q;
  // Ties (duplicates) go to the smaller index.
  if (d > F.fdist || (d == F.fdist && q < F.furthest) || F.furthest == kNone) {
    F.fdist = d;
    F.furthest = q;
  }
}

// Links the faces of the initial tetrahedron (their edges are matched by vertex pairs).
template <Real T>
void ConvexHull3<T>::quickhull(std::span<const std::uint32_t> ids, const std::uint32_t s[4]) {
  const Vec3<T>* p = pts_;
  next_.resize(n_);
  start_.resize(n_);
  end_.resize(n_);
  std::uint32_t f[4];
  f[0] = new_face(s[0], s[1], s[2]);
  f[1] = new_face(s[1], s[0], s[3]);
  f[2] = new_face(s[2], s[1], s[3]);
  f[3] = new_face(s[0], s[2], s[3]);
  for (int i = 0; i < 4; ++i)
    for (int e = 0; e < 3; ++e) {
      Face& F = faces_[f[i]];
      const std::uint32_t a = F.v[e], b = F.v[(e + 1) % 3];
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 3; ++k)
          if (faces_[f[j]].v[k] == b && faces_[f[j]].v[(k + 1) % 3] == a) F.adj[e] = f[j];
    }
  for (const std::uint32_t q : ids) {
    if (q == s[0] || q == s[1] || q == s[2] || q == s[3]) continue;
    for (int i = 0; i < 4; ++i)
      if (side(p, faces_[f[i]].v, q) == Sign::positive) {
        add_outside(f[i], q);
        break;
      }
  }
  stack_.clear();
  for (int i = 0; i < 4; ++i)
    if (faces_[f[i]].head != kNone) stack_.push_back(f[i]);
  const std::size_t budget = 8 * ids.size() + 64;
  for (std::size_t iter = 0; !stack_.empty() && iter < budget; ++iter) {
    const std::uint32_t f0 = stack_.back();
    stack_.pop_back();
    if (!faces_[f0].alive || faces_[f0].head == kNone) continue;
    const std::uint32_t apex = faces_[f0].furthest;
    // The faces that see the apex: a walk over the adjacency from f0 (the visible region of a
    // convex polytope is connected), exact orient3d on each face reached.
    ++stamp_;
    visible_.clear();
    horizon_.clear();
    faces_[f0].vis = stamp_;
    visible_.push_back(f0);
    for (std::size_t i = 0; i < visible_.size(); ++i) {
      const std::uint32_t g = visible_[i];
      for (std::uint32_t e = 0; e < 3; ++e) {
        const std::uint32_t h = faces_[g].adj[e];
        Face& H = faces_[h];
        if (H.vis == stamp_) continue;
        if (H.seen != stamp_) {
          if (side(p, H.v, apex) == Sign::positive) {
            H.vis = stamp_;
            visible_.push_back(h);
            continue;
          }
          H.seen = stamp_;
        }
        horizon_.push_back(g * 3 + e);
      }
    }
    // Cone the horizon to the apex.
    newf_.clear();
    for (const std::uint32_t ge : horizon_) {
      const std::uint32_t g = ge / 3, e = ge % 3;
      const std::uint32_t a = faces_[g].v[e], b = faces_[g].v[(e + 1) % 3];
      const std::uint32_t h = faces_[g].adj[e];
      const std::uint32_t nf = new_face(a, b, apex);
      faces_[nf].adj[0] = h;
      Face& H = faces_[h];
      for (int k = 0; k < 3; ++k)
        if (H.v[k] == b && H.v[(k + 1) % 3] == a) H.adj[k] = nf;
      start_[a] = nf;
      end_[b] = nf;
      newf_.push_back(nf);
    }
    for (const std::uint32_t nf : newf_) {
      Face& F = faces_[nf];
      F.adj[1] = start_[F.v[1]];
      F.adj[2] = end_[F.v[0]];
    }
    // Orphaned outside points go to the first new face they see; the others are inside.
    const std::size_t nn = newf_.size();
    std::size_t last = 0;
    for (const std::uint32_t g : visible_) {
      for (std::uint32_t q = faces_[g].head; q != kNone;) {
        const std::uint32_t nq = next_[q];
        if (q != apex) {
          for (std::size_t j = 0; j < nn; ++j) {
            const std::size_t k = last + j < nn ? last + j : last + j - nn;
            if (side(p, faces_[newf_[k]].v, q) == Sign::positive) {
              add_outside(newf_[k], q);
              last = k;
              break;
            }
          }
        }
        q = nq;
      }
      faces_[g].alive = false;
      faces_[g].head = kNone;
      free_.push_back(g);
    }
    for (const std::uint32_t nf : newf_)
      if (faces_[nf].head != kNone) stack_.push_back(nf);
  }
}

// The book's incremental method: every face is tested against each point in turn; the visible
// faces are replaced by the cone from the point over their boundary (the terminator).
template <Real T>
void ConvexHull3<T>::incremental(std::span<const std::uint32_t> ids, const std::uint32_t s[4]) {
  const Vec3<T>* p = pts_;
  new_face(s[0], s[1], s[2]);
  new_face(s[1], s[0], s[3]);
  new_face(s[2], s[1], s[3]);
  new_face(s[0], s[2], s[3]);
  std::vector<std::uint64_t> edges;
  for (const std::uint32_t q : ids) {
    if (q == s[0] || q == s[1] || q == s[2] || q == s[3]) continue;
    visible_.clear();
    for (std::uint32_t f = 0; f < faces_.size(); ++f)
      if (faces_[f].alive && side(p, faces_[f].v, q) == Sign::positive) visible_.push_back(f);
    if (visible_.empty()) continue;
    edges.clear();
    for (const std::uint32_t f : visible_)
      for (int e = 0; e < 3; ++e)
        edges.push_back(std::uint64_t(faces_[f].v[e]) << 32 | faces_[f].v[(e + 1) % 3]);
    std::sort(edges.begin(), edges.end());
    horizon_.clear();
    for (const std::uint64_t ed : edges) {
      const std::uint64_t rev = (ed << 32) | (ed >> 32);
      if (!std::binary_search(edges.begin(), edges.end(), rev)) {
        horizon_.push_back(static_cast<std::uint32_t>(ed >> 32));
        horizon_.push_back(static_cast<std::uint32_t>(ed & 0xFFFFFFFFu));
      }
    }
    for (const std::uint32_t f : visible_) {
      faces_[f].alive = false;
      free_.push_back(f);
    }
    for (std::size_t i = 0; i < horizon_.size(); i += 2) new_face(horizon_[i], horizon_[i + 1], q);
  }
  // Adjacency by matching each directed edge with its reverse.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> de;
  for (std::uint32_t f = 0; f < faces_.size(); ++f)
    if (faces_[f].alive)
      for (std::uint32_t e = 0; e < 3; ++e)
        de.push_back({std::uint64_t(faces_[f].v[e]) << 32 | faces_[f].v[(e + 1) % 3], f * 3 + e});
  std::sort(de.begin(), de.end());
  for (const auto& [ed, fe] : de) {
    const std::uint64_t rev = (ed << 32) | (ed >> 32);
    const auto it = std::lower_bound(de.begin(), de.end(), std::make_pair(rev, std::uint32_t(0)));
    if (it != de.end() && it->first == rev) faces_[fe / 3].adj[fe % 3] = it->second / 3;
  }
}

// Hull of the points ids (a subset of pts_); writes out's triangles/adjacency/polygon/vertices
// and returns the dimension.
template <Real T>
int ConvexHull3<T>::build(std::span<const std::uint32_t> ids, Hull3Method method, Hull3Result& out,
                          bool allow_rebuild) {
  out.triangles.clear();
  out.adjacency.clear();
  out.polygon.clear();
  out.vertices.clear();
  out.plane_axis = -1;
  std::uint32_t s[4];
  const int dim = simplex(ids, s);
  if (dim == 0) {
    out.polygon = {s[0]};
    out.vertices = out.polygon;
    return 0;
  }
  if (dim == 1) {
    out.polygon = {s[0], s[1]};
    out.vertices = {std::min(s[0], s[1]), std::max(s[0], s[1])};
    return 1;
  }
  if (dim == 2) {
    planar(ids, s, out);
    return 2;
  }
  // Orient the simplex so that s[3] is behind face (s0, s1, s2).
  if (orient3d(pts_[s[0]], pts_[s[1]], pts_[s[2]], pts_[s[3]]) == Sign::positive)
    std::swap(s[1], s[2]);
  if (method == Hull3Method::divide_and_conquer) {
    divide_conquer(ids, out);  // src/hull/hull3_divide_conquer.cpp
  } else {
    faces_.clear();
    free_.clear();
    if (method == Hull3Method::quickhull)
      quickhull(ids, s);
    else
      incremental(ids, s);
    // Compact.
    map_.assign(faces_.size(), kNone);
    for (std::uint32_t f = 0; f < faces_.size(); ++f)
      if (faces_[f].alive) {
        map_[f] = static_cast<std::uint32_t>(out.triangles.size());
        out.triangles.push_back({faces_[f].v[0], faces_[f].v[1], faces_[f].v[2]});
      }
    out.adjacency.resize(out.triangles.size());
    for (std::uint32_t f = 0; f < faces_.size(); ++f)
      if (faces_[f].alive)
        for (int e = 0; e < 3; ++e)
          out.adjacency[map_[f]][e] = faces_[f].adj[e] == kNone ? kNone : map_[faces_[f].adj[e]];
  }
  // Extreme-point test: a vertex is a corner of the polytope iff its incident triangles span at
  // least three planes; walking its fan, count the changes of plane between neighbours
  // (coplanarity of neighbouring triangles is one exact orient3d per edge).
  const auto& tri = out.triangles;
  const auto& adj = out.adjacency;
  const std::size_t nt = tri.size();
  std::vector<std::uint8_t> flat(nt * 3, 0);
  for (std::size_t t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = adj[t][e];
      if (u == kNone || u < t) continue;
      std::uint32_t w = tri[u][0];
      for (int k = 0; k < 3; ++k)
        if (tri[u][k] != tri[t][e] && tri[u][k] != tri[t][(e + 1) % 3]) w = tri[u][k];
      const bool f =
          orient3d(pts_[tri[t][0]], pts_[tri[t][1]], pts_[tri[t][2]], pts_[w]) == Sign::zero;
      flat[t * 3 + e] = f;
      for (int k = 0; k < 3; ++k)
        if (adj[u][k] == t) flat[u * 3 + k] = f;
    }
  std::vector<std::uint32_t>& verts = out.vertices;
  for (const auto& t : tri) verts.insert(verts.end(), t.begin(), t.end());
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  // One incident corner per vertex.
  std::vector<std::uint32_t> corner(verts.size(), kNone);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::size_t k = static_cast<std::size_t>(
          std::lower_bound(verts.begin(), verts.end(), tri[t][e]) - verts.begin());
      if (corner[k] == kNone) corner[k] = t * 3 + e;
    }
  ids2_.clear();
  bool all_extreme = true;
  for (std::size_t k = 0; k < verts.size(); ++k) {
    std::uint32_t t = corner[k] / 3, e = corner[k] % 3;
    int changes = 0;
    for (std::size_t guard = 0; guard <= nt; ++guard) {
      changes += flat[t * 3 + e] == 0;
      const std::uint32_t u = adj[t][e];
      if (u == kNone) break;
      std::uint32_t j = 0;
      while (j < 3 && tri[u][j] != verts[k]) ++j;
      if (j == 3) break;
      t = u, e = j;
      if (t * 3 + e == corner[k]) break;
    }
    if (changes >= 3)
      ids2_.push_back(verts[k]);
    else
      all_extreme = false;
  }
  if (!all_extreme && allow_rebuild) {
    std::vector<std::uint32_t> ext(ids2_);
    return build(ext, method, out, false);
  }
  return 3;
}

template class ConvexHull3<float>;
template class ConvexHull3<double>;

}  // namespace locus
