// SPDX-License-Identifier: BSL-1.0
// GJK distance (signed-volumes subalgorithm) and EPA penetration depth; see
// include/locus/distance/gjk.hpp for the conventions, the method and the references.
// Everything is computed in double (float shapes are promoted); instantiated for float and
// double in 2D and 3D.

#include <locus/core/predicates.hpp>
#include <locus/distance/gjk.hpp>
#include <locus/primitives/triangle.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace locus::detail {
namespace {

template <int N>
using V = Vec<double, N>;

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// A point of the Minkowski difference y = a - b with its two support points.
template <int N>
struct Pt {
  V<N> a, b, y;
};

template <int N>
[[nodiscard]] bool same_point(const Pt<N>& p, const Pt<N>& q) noexcept {
  return p.a == q.a && p.b == q.b;
}

/// The support mapping of A - B (cores only), tracking the coordinate scale and finiteness.
template <class T, int N>
class Minkowski {
 public:
  Minkowski(const SupportMap<T, N>& a, const SupportMap<T, N>& b) noexcept : a_(a), b_(b) {}

  /// The support point of A - B farthest along d (d != 0).
  Pt<N> operator()(V<N> d) noexcept {
    // Normalise by the largest component so that float shapes see neither under- nor overflow.
    const double m = max_abs(d);
    if (m >= std::numeric_limits<double>::min()) {
      d *= 1.0 / m;  // one division (1 / m is finite for a normal m)
    } else if (m > 0.0) {
      d = d / m;
    }
    const Vec<T, N> dt = vec_cast<T>(d);
    Pt<N> p;
    p.a = vec_cast<double>(a_.core(a_.shape, dt));
    p.b = vec_cast<double>(b_.core(b_.shape, -dt));
    p.y = p.a - p.b;
    if (!is_finite(p.y)) {  // also catches a non-finite a or b (inf - inf is NaN)
      finite_ = false;
    } else {
      scale_ = std::max(scale_, std::max(max_abs(p.a), max_abs(p.b)));
    }
    return p;
  }
  [[nodiscard]] bool finite() const noexcept { return finite_; }
  [[nodiscard]] double scale() const noexcept { return scale_; }

 private:
  const SupportMap<T, N>& a_;
  const SupportMap<T, N>& b_;
  double scale_ = 0.0;
  bool finite_ = true;
};

// ---- signed-volumes subalgorithm --------------------------------------------------------------
//
// Every function takes the caller's points y and `must`, the index of the point just added
// (W_k), or -1. The nearest point of conv(S_k + {W_k}) beats V_k = the nearest point of
// conv(S_k) (otherwise GJK has already stopped), so a face without W_k cannot be the answer:
// such faces are skipped, which halves the work of the triangle and tetrahedron cases. (Were
// rounding to make a skipped face win, the "no progress" test of run_gjk keeps S_k.)

/// The point of a sub-simplex nearest to the origin: indices into the caller's points, weights.
template <int N>
struct Sub {
  int n = 0;
  int idx[N + 1] = {};
  double w[N + 1] = {};
  V<N> v{};
  double vv = kInf;
  bool enclosed = false;  // the origin is strictly inside a full-dimensional simplex
};

template <int N>
[[nodiscard]] Sub<N> vertex_sub(const V<N>* y, int i) noexcept {
  Sub<N> s;
  s.n = 1;
  s.idx[0] = i;
  s.w[0] = 1.0;
  s.v = y[i];
  s.vv = sqr_length(y[i]);
  return s;
}

template <int N>
void keep_better(Sub<N>& best, const Sub<N>& c) noexcept {
  if (c.vv < best.vv) best = c;
}

/// Segment y[i] y[j].
template <int N>
[[nodiscard]] Sub<N> sub1(const V<N>* y, int i, int j) noexcept {
  // Base the projection at the endpoint nearer the origin: less cancellation in y_i + t (y_j -
  // y_i).
  if (sqr_length(y[j]) < sqr_length(y[i])) std::swap(i, j);
  const V<N> t = y[j] - y[i];
  const double tt = sqr_length(t);
  if (!(tt > 0.0)) return vertex_sub(y, i);
  const double num = -dot(y[i], t);
  if (!(num > 0.0)) return vertex_sub(y, i);
  if (num >= tt) return vertex_sub(y, j);
  const double lj = num / tt;
  Sub<N> s;
  s.n = 2;
  s.idx[0] = i;
  s.idx[1] = j;
  s.w[0] = 1.0 - lj;
  s.w[1] = lj;
  s.v = y[i] + lj * t;
  s.vv = sqr_length(s.v);
  return s;
}

/// Best of the edges of the face ids[0..k) (k = 3: a triangle) that contain `must`: the edge
/// opposite ids[q] is taken when beyond[q] (the origin lies beyond it).
template <int N>
[[nodiscard]] Sub<N> edges_beyond(const V<N>* y, const int* ids, const bool* beyond,
                                  int must) noexcept {
  Sub<N> best;
  for (int q = 0; q < 3; ++q)
    if (beyond[q] && ids[q] != must) keep_better(best, sub1(y, ids[(q + 1) % 3], ids[(q + 2) % 3]));
  return best;
}

/// Triangle y[i] y[j] y[k] in 3D (not full-dimensional): project the origin onto its plane,
/// then barycentric signs from signed areas in the coordinate plane where the triangle's
/// projection is largest.
[[nodiscard]] Sub<3> sub2_3d(const V<3>* y, int i, int j, int k, int must) noexcept {
  const int ids[3] = {i, j, k};
  const V<3> e1 = y[j] - y[i], e2 = y[k] - y[i];
  const V<3> n = cross(e1, e2);
  const double nn = sqr_length(n), l1 = sqr_length(e1), l2 = sqr_length(e2);
  // Needle or collinear (sine of the angle below 8 eps): the plane is ill-defined and the edges
  // are as close as the interior. Squares within 1e-100 .. 1e100 (no under- or overflow of
  // their products); lengths otherwise, so that 1e-80 or 1e80 scales work too.
  const bool moderate = l1 > 1e-100 && l2 > 1e-100 && l1 < 1e100 && l2 < 1e100;
  const double len = moderate ? std::sqrt(nn) : length(n);  // length() rescales when needed
  const bool needle = moderate ? !(nn > 64.0 * kEps * kEps * l1 * l2)
                               : !(len > 8.0 * kEps * length(e1) * length(e2));
  if (needle) {
    const bool all[3] = {true, true, true};
    return edges_beyond(y, ids, all, must);
  }
  const V<3> nu = n / len;
  const V<3> p = (dot(y[i] + y[j] + y[k], nu) / 3.0) * nu;
  const V<3> an = cwise_abs(n);
  const int m = an.x >= an.y ? (an.x >= an.z ? 0 : 2) : (an.y >= an.z ? 1 : 2);
  const int u = (m + 1) % 3, w = (m + 2) % 3;
  const auto area = [u, w](const V<3>& a, const V<3>& b, const V<3>& c) {
    return (b[u] - a[u]) * (c[w] - a[w]) - (b[w] - a[w]) * (c[u] - a[u]);
  };
  const double mu = area(y[i], y[j], y[k]);
  const double c[3] = {area(p, y[j], y[k]), area(y[i], p, y[k]), area(y[i], y[j], p)};
  bool beyond[3], inside = true;
  for (int q = 0; q < 3; ++q) {
    beyond[q] = !(mu > 0.0 ? c[q] > 0.0 : c[q] < 0.0);
    inside = inside && !beyond[q];
  }
  if (!inside) return edges_beyond(y, ids, beyond, must);
  Sub<3> s;
  s.n = 3;
  const double sum = c[0] + c[1] + c[2];
  for (int q = 0; q < 3; ++q) {
    s.idx[q] = ids[q];
    s.w[q] = c[q] / sum;
  }
  s.v = p;
  s.vv = sqr_length(p);
  return s;
}

/// The exact sign of det[b - a; c - a; ...] (orient2d / orient3d) and its floating value.
[[nodiscard]] Sign orient(const V<2>* p) noexcept { return orient2d(p[0], p[1], p[2]); }
[[nodiscard]] Sign orient(const V<3>* p) noexcept { return orient3d(p[0], p[1], p[2], p[3]); }
[[nodiscard]] double det(const V<2>* p) noexcept { return perp_dot(p[1] - p[0], p[2] - p[0]); }
[[nodiscard]] double det(const V<3>* p) noexcept {
  return dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0]));
}

/// The nearest point of facet f (the points other than y[f]) of a full-dimensional simplex.
[[nodiscard]] Sub<2> facet_nearest(const V<2>* y, int f, int) noexcept {
  return sub1(y, (f + 1) % 3, (f + 2) % 3);
}
[[nodiscard]] Sub<3> facet_nearest(const V<3>* y, int f, int must) noexcept {
  static constexpr int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  return sub2_3d(y, face[f][0], face[f][1], face[f][2], must);
}

/// Full-dimensional simplex y[0..N] (a triangle in 2D, a tetrahedron in 3D): the exact signs
/// of the N + 1 simplices with one vertex replaced by the origin decide containment (the origin
/// is inside iff all agree with the simplex's own sign); inside, those determinants are the
/// barycentric weights; outside, the facets the origin lies beyond are searched.
template <int N>
[[nodiscard]] Sub<N> full_simplex(const V<N>* y, int must) noexcept {
  const Sign s = orient(y);
  Sign si[N + 1];
  bool inside = s != Sign::zero;
  for (int q = 0; q <= N; ++q) {
    V<N> t[N + 1];
    for (int r = 0; r <= N; ++r) t[r] = r == q ? V<N>{} : y[r];
    si[q] = s == Sign::zero ? Sign::zero : orient(t);
    inside = inside && si[q] == s;
  }
  if (inside) {
    Sub<N> r;
    double c[N + 1], sum = 0.0;
    for (int q = 0; q <= N; ++q) {
      V<N> t[N + 1];
      for (int k = 0; k <= N; ++k) t[k] = k == q ? V<N>{} : y[k];
      c[q] = s == Sign::positive ? std::max(det(t), 0.0) : std::max(-det(t), 0.0);
      sum += c[q];
    }
    r.n = N + 1;
    for (int q = 0; q <= N; ++q) {
      r.idx[q] = q;
      r.w[q] = sum > 0.0 ? c[q] / sum : 1.0 / (N + 1);
    }
    r.v = V<N>{};
    r.vv = 0.0;
    r.enclosed = true;
    return r;
  }
  // A flat simplex (s = 0): every facet with `must`; otherwise those the origin lies beyond.
  Sub<N> best;
  for (int q = 0; q <= N; ++q)
    if (q != must && (s == Sign::zero || si[q] != s)) keep_better(best, facet_nearest(y, q, must));
  return best;
}

/// The point of conv(y[0..n-1]) nearest to the origin; y[n-1] is the point just added.
template <int N>
[[nodiscard]] Sub<N> nearest(const V<N>* y, int n) noexcept {
  if (n == 1) return vertex_sub(y, 0);
  if (n == 2) return sub1(y, 0, 1);
  if (n == N + 1) return full_simplex<N>(y, n - 1);
  if constexpr (N == 3) return sub2_3d(y, 0, 1, 2, 2);
  return vertex_sub(y, n - 1);  // unreachable: n <= N + 1
}

// ---- GJK ----------------------------------------------------------------------------------

template <int N>
struct GjkState {
  Pt<N> s[N + 1];
  double w[N + 1] = {};
  int n = 0;
  V<N> v{};
  double vv = kInf;
  bool enclosed = false;
  bool limit = false;
  int iterations = 0;
};

template <class T, int N>
void trace_simplex(GjkSimplex<T, N>& out, const GjkState<N>& st) noexcept {
  out.size = st.n;
  for (int i = 0; i < st.n; ++i) {
    out.a[static_cast<std::size_t>(i)] = vec_cast<T>(st.s[i].a);
    out.b[static_cast<std::size_t>(i)] = vec_cast<T>(st.s[i].b);
    out.weight[static_cast<std::size_t>(i)] = static_cast<T>(st.w[i]);
  }
}

template <class T, int N>
[[nodiscard]] GjkState<N> run_gjk(Minkowski<T, N>& mk, const GjkOptions<T, N>& opt) {
  GjkState<N> st;
  V<N> d0 = vec_cast<double>(opt.initial_direction);
  if (!is_finite(d0) || !(max_abs(d0) > 0.0)) d0 = unit_vec<double, N>(0);
  st.s[0] = mk(d0);
  st.w[0] = 1.0;
  st.n = 1;
  st.v = st.s[0].y;
  st.vv = sqr_length(st.v);
  GjkTrace<T, N>* trace = opt.trace;
  if (trace) {
    trace->steps.clear();
    trace->v0 = vec_cast<T>(st.v);
  }
  if (!mk.finite()) return st;
  const double rel = std::max(static_cast<double>(opt.relative_tolerance), 0.0);
  for (;;) {
    // |V| at the rounding floor of the coordinates: the origin is on the simplex.
    const double floor = 8.0 * kEps * mk.scale();
    if (st.vv <= floor * floor) break;
    if (st.iterations >= opt.max_iterations) {
      st.limit = true;
      break;
    }
    ++st.iterations;
    const Pt<N> w = mk(-st.v);
    if (!mk.finite()) break;
    bool repeat = false;
    for (int i = 0; i < st.n; ++i) repeat = repeat || same_point(st.s[i], w);
    GjkStep<T, N>* step = nullptr;
    if (trace) {
      trace->steps.emplace_back();
      step = &trace->steps.back();
      step->v = vec_cast<T>(st.v);
      step->w = vec_cast<T>(w.y);
    }
    // The gap |V|^2 - V.W bounds |V|^2 - dist^2: stop when the distance is accurate enough.
    if (repeat || st.vv - dot(st.v, w.y) <= rel * st.vv) {
      if (step) {
        trace_simplex(step->simplex, st);
        step->v_next = step->v;
      }
      break;
    }
    // S_k + {W_k}: W_k goes to the free slot (st.n <= N here: a full simplex encloses the
    // origin and ends the loop), so S_k stays intact if no progress is made.
    st.s[st.n] = w;
    const int m = st.n + 1;
    V<N> y[N + 1];
    for (int i = 0; i < m; ++i) y[i] = st.s[i].y;
    const Sub<N> sub = nearest<N>(y, m);
    if (!(sub.vv < st.vv) && !sub.enclosed) {
      // No progress: rounding has taken over; keep the previous (better) simplex.
      if (step) {
        trace_simplex(step->simplex, st);
        step->v_next = step->v;
      }
      break;
    }
    Pt<N> kept[N + 1];
    for (int i = 0; i < sub.n; ++i) kept[i] = st.s[sub.idx[i]];
    for (int i = 0; i < sub.n; ++i) {
      st.s[i] = kept[i];
      st.w[i] = sub.w[i];
    }
    st.n = sub.n;
    st.v = sub.v;
    st.vv = sub.vv;
    st.enclosed = sub.enclosed;
    if (step) {
      trace_simplex(step->simplex, st);
      step->v_next = vec_cast<T>(st.v);
    }
    if (st.enclosed) break;
  }
  return st;
}

template <int N>
void witnesses(const GjkState<N>& st, V<N>& pa, V<N>& pb) noexcept {
  pa = V<N>{};
  pb = V<N>{};
  for (int i = 0; i < st.n; ++i) {
    pa += st.w[i] * st.s[i].a;
    pb += st.w[i] * st.s[i].b;
  }
}

template <Real T>
[[nodiscard]] double contact_tol(T option, double scale) noexcept {
  if (option >= T(0)) return static_cast<double>(option);
  return 64.0 * static_cast<double>(eps_v<T>) * scale;
}

// ---- EPA ----------------------------------------------------------------------------------

/// EPA outcome for the cores: depth >= 0 along unit normal (from A towards B), witnesses.
template <int N>
struct EpaOut {
  Status status = Status::ok;
  bool touching = false;  // the origin is on the boundary (a support plane through it)
  double depth = 0.0;
  V<N> normal{};
  V<N> wa{}, wb{};
  int iterations = 0;
};

/// Gram-Schmidt: adds the component of r orthogonal to basis[0..dim) when longer than tol.
template <int N>
bool extend_basis(V<N>* basis, int& dim, V<N> r, double tol) noexcept {
  for (int i = 0; i < dim; ++i) r -= dot(r, basis[i]) * basis[i];
  for (int i = 0; i < dim; ++i) r -= dot(r, basis[i]) * basis[i];  // second pass: orthogonality
  const double len = length(r);
  if (!(len > tol) || dim >= N) return false;
  basis[dim++] = r / len;
  return true;
}

/// A unit vector orthogonal to basis[0..dim) (dim < N).
template <int N>
[[nodiscard]] V<N> orthogonal_direction(const V<N>* basis, int dim) noexcept {
  V<N> best{};
  double best_len = -1.0;
  for (int axis = 0; axis < N; ++axis) {
    V<N> r = unit_vec<double, N>(axis);
    for (int i = 0; i < dim; ++i) r -= dot(r, basis[i]) * basis[i];
    for (int i = 0; i < dim; ++i) r -= dot(r, basis[i]) * basis[i];
    const double len = length(r);
    if (len > best_len) {
      best_len = len;
      best = r / len;
    }
  }
  return best;
}

/// Raises the GJK simplex (which contains the origin, up to the rounding floor) to a
/// full-dimensional point set with support points along +-n, n orthogonal to its span.
/// Returns false when a support plane through the origin was found (out holds the touching
/// answer) or the input went non-finite.
template <class T, int N>
[[nodiscard]] bool raise_simplex(Minkowski<T, N>& mk, const GjkState<N>& st, double tol, Pt<N>* pts,
                                 int& npts, EpaOut<N>& out) {
  npts = 0;
  for (int i = 0; i < st.n; ++i)
    if (st.w[i] > 0.0 || st.n == 1) pts[npts++] = st.s[i];
  if (npts == 0) pts[npts++] = st.s[0];
  V<N> basis[N];
  int dim = 0;
  const double dim_tol = 16.0 * kEps * std::max(mk.scale(), std::numeric_limits<double>::min());
  for (int i = 1; i < npts; ++i) extend_basis(basis, dim, pts[i].y - pts[0].y, dim_tol);
  while (dim < N) {
    const V<N> n = orthogonal_direction(basis, dim);
    const Pt<N> sp = mk(n), sm = mk(-n);
    if (!mk.finite()) {
      out.status = Status::non_finite_input;
      return false;
    }
    const double hp = dot(sp.y, n), hm = -dot(sm.y, n);
    if (std::min(hp, hm) <= tol) {
      // A support plane (almost) through the origin: the origin is on the boundary.
      out.touching = true;
      out.status = std::max(hp, hm) <= tol ? Status::degenerate_input : Status::ok;
      out.depth = std::max(std::min(hp, hm), 0.0);
      out.normal = hp <= hm ? n : -n;
      witnesses(st, out.wa, out.wb);
      return false;
    }
    pts[npts++] = sp;
    pts[npts++] = sm;
    const int before = dim;
    extend_basis(basis, dim, sp.y - pts[0].y, dim_tol);
    extend_basis(basis, dim, sm.y - pts[0].y, dim_tol);
    if (dim == before) {  // cannot happen with hp, hm > tol >= dim_tol; be safe anyway
      out.touching = true;
      out.status = Status::degenerate_input;
      out.normal = n;
      witnesses(st, out.wa, out.wb);
      return false;
    }
  }
  return true;
}

/// EPA in 3D over a fixed-capacity triangle mesh with exact orient3d visibility.
template <Real T>
class Epa3 {
 public:
  static constexpr int max_v = epa_max_vertices;
  static constexpr int max_f = 2 * epa_max_vertices + 8;

  EpaOut<3> run(Minkowski<T, 3>& mk, const GjkState<3>& st, double tol, double rel,
                int max_iterations) {
    EpaOut<3> out;
    Pt<3> pts[2 * 3 + 4];
    int npts = 0;
    if (!raise_simplex(mk, st, tol, pts, npts, out)) return out;
    if (!init(pts, npts)) {
      out.touching = true;
      out.status = Status::degenerate_input;
      witnesses(st, out.wa, out.wb);
      return out;
    }
    int best = -1;
    Face f{};
    for (int it = 0;; ++it) {
      const int c = closest_face();
      if (c < 0) {
        out.status = Status::limit_exceeded;
        break;
      }
      best = c;
      f = face_[c];  // a copy: insert() may recycle the slot
      if (it >= max_iterations) {
        out.status = Status::limit_exceeded;
        break;
      }
      ++out.iterations;
      const Pt<3> w = mk(f.n);
      if (!mk.finite()) {
        out.status = Status::non_finite_input;
        return out;
      }
      const double h = dot(w.y, f.n);
      const double floor = 8.0 * kEps * mk.scale();
      if (h - f.dist <= rel * std::fabs(h) || h - f.dist <= floor) break;
      bool repeat = false;
      for (int i = 0; i < nv_; ++i) repeat = repeat || same_point(vert_[i], w);
      if (repeat || !visible(f, w.y)) break;
      if (!insert(w, best)) {
        out.status = Status::limit_exceeded;
        break;
      }
    }
    if (best < 0) {
      witnesses(st, out.wa, out.wb);
      return out;
    }
    out.depth = std::max(f.dist, 0.0);
    out.normal = f.n;
    out.touching = out.depth <= tol;
    // Barycentric coordinates of the origin's projection onto the face.
    const V<3> p = out.depth * f.n;
    const V<3>& a = vert_[f.v[0]].y;
    const V<3>& b = vert_[f.v[1]].y;
    const V<3>& c = vert_[f.v[2]].y;
    double l[3] = {dot(f.n, cross(b - p, c - p)), dot(f.n, cross(c - p, a - p)),
                   dot(f.n, cross(a - p, b - p))};
    double sum = 0.0;
    for (double& li : l) {
      li = std::max(li, 0.0);
      sum += li;
    }
    if (!(sum > 0.0)) l[0] = l[1] = l[2] = sum = 1.0;
    for (int i = 0; i < 3; ++i) {
      out.wa += (l[i] / sum) * vert_[f.v[i]].a;
      out.wb += (l[i] / sum) * vert_[f.v[i]].b;
    }
    return out;
  }

 private:
  struct Face {
    int v[3];
    int adj[3];    // face across edge (v[e], v[e+1])
    int adj_e[3];  // that edge's index in the neighbour
    V<3> n;
    double dist;
    bool alive;
  };
  struct HorizonEdge {
    int face, edge;
  };

  [[nodiscard]] bool visible(const Face& f, const V<3>& p) const noexcept {
    return orient3d(vert_[f.v[0]].y, vert_[f.v[1]].y, vert_[f.v[2]].y, p) == Sign::positive;
  }

  int new_face(int a, int b, int c) noexcept {
    int id;
    if (nfree_ > 0) {
      id = free_[--nfree_];
    } else {
      if (nf_ >= max_f) return -1;
      id = nf_++;
    }
    Face& f = face_[id];
    f.v[0] = a;
    f.v[1] = b;
    f.v[2] = c;
    f.adj[0] = f.adj[1] = f.adj[2] = -1;
    f.adj_e[0] = f.adj_e[1] = f.adj_e[2] = -1;
    f.alive = true;
    const V<3> n = normal(Triangle3<double>{vert_[a].y, vert_[b].y, vert_[c].y});
    const double len = length(n);
    if (len > 0.0 && is_finite(n)) {
      f.n = n / len;
      f.dist = (dot(f.n, vert_[a].y) + dot(f.n, vert_[b].y) + dot(f.n, vert_[c].y)) / 3.0;
    } else {
      f.n = V<3>{};
      f.dist = kInf;  // a zero-area face never bounds the depth
    }
    ++gen_[id];
    if (f.dist < kInf) heap_push(f.dist, id);
    return id;
  }

  void link(int f, int e, int g, int ge) noexcept {
    face_[f].adj[e] = g;
    face_[f].adj_e[e] = ge;
    face_[g].adj[ge] = f;
    face_[g].adj_e[ge] = e;
  }

  bool init(const Pt<3>* pts, int npts) {
    nv_ = nf_ = nfree_ = nheap_ = 0;
    heap_overflow_ = false;
    // Initial tetrahedron: far point, far from the line, far from the plane.
    int i0 = 0, i1 = -1, i2 = -1, i3 = -1;
    double best = -1.0;
    for (int i = 1; i < npts; ++i) {
      const double d = sqr_length(pts[i].y - pts[i0].y);
      if (d > best) {
        best = d;
        i1 = i;
      }
    }
    if (i1 < 0) return false;
    best = -1.0;
    const V<3> e = pts[i1].y - pts[i0].y;
    for (int i = 0; i < npts; ++i) {
      const double d = sqr_length(cross(e, pts[i].y - pts[i0].y));
      if (d > best) {
        best = d;
        i2 = i;
      }
    }
    best = -1.0;
    const V<3> n = cross(e, pts[i2].y - pts[i0].y);
    for (int i = 0; i < npts; ++i) {
      const double d = std::fabs(dot(n, pts[i].y - pts[i0].y));
      if (d > best) {
        best = d;
        i3 = i;
      }
    }
    Sign s = orient3d(pts[i0].y, pts[i1].y, pts[i2].y, pts[i3].y);
    if (s == Sign::zero) return false;
    if (s == Sign::positive) std::swap(i1, i2);
    const int id[4] = {i0, i1, i2, i3};
    for (int k = 0; k < 4; ++k) vert_[nv_++] = pts[id[k]];
    // Faces with outward normals (orient3d(face, opposite vertex) < 0): abc, adb, bdc, cda.
    const int fv[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    for (const auto& t : fv) new_face(t[0], t[1], t[2]);
    for (int f = 0; f < 4; ++f)
      for (int fe = 0; fe < 3; ++fe) {
        if (face_[f].adj[fe] >= 0) continue;
        const int u = face_[f].v[fe], w = face_[f].v[(fe + 1) % 3];
        for (int g = 0; g < 4; ++g)
          for (int ge = 0; ge < 3; ++ge)
            if (g != f && face_[g].v[ge] == w && face_[g].v[(ge + 1) % 3] == u) link(f, fe, g, ge);
      }
    // The remaining points (they contain the origin together with the tetrahedron).
    for (int i = 0; i < npts; ++i) {
      if (i == i0 || i == i1 || i == i2 || i == i3) continue;
      for (int f = 0; f < nf_; ++f) {
        if (face_[f].alive && visible(face_[f], pts[i].y)) {
          if (!insert(pts[i], f)) return false;
          break;
        }
      }
    }
    return true;
  }

  [[nodiscard]] int closest_face() noexcept {
    if (!heap_overflow_) {
      while (nheap_ > 0) {
        const HeapEntry& top = heap_[0];
        if (face_[top.face].alive && gen_[top.face] == top.gen) return top.face;
        heap_pop();
      }
      return -1;
    }
    int best = -1;
    double d = kInf;
    for (int f = 0; f < nf_; ++f)
      if (face_[f].alive && face_[f].dist < d) {
        d = face_[f].dist;
        best = f;
      }
    return best;
  }

  // Depth-first walk over the faces visible from p starting across edge `e` of a removed face;
  // collects the horizon in order (van den Bergen's silhouette).
  void silhouette(int f, int e, const V<3>& p) noexcept {
    if (f < 0 || !face_[f].alive) return;
    if (!visible(face_[f], p)) {
      if (nhorizon_ < max_f) horizon_[nhorizon_++] = {f, e};
      return;
    }
    face_[f].alive = false;
    removed_[nremoved_++] = f;
    const int e1 = (e + 1) % 3, e2 = (e + 2) % 3;
    silhouette(face_[f].adj[e1], face_[f].adj_e[e1], p);
    silhouette(face_[f].adj[e2], face_[f].adj_e[e2], p);
  }

  /// Adds vertex w, which sees face f0; false when a capacity is exhausted or the horizon is
  /// not a simple cycle (then the polytope is left as it was before the call... as far as the
  /// caller is concerned: EPA stops).
  bool insert(const Pt<3>& w, int f0) {
    if (nv_ >= max_v) return false;
    nhorizon_ = nremoved_ = 0;
    face_[f0].alive = false;
    removed_[nremoved_++] = f0;
    for (int e = 0; e < 3; ++e) silhouette(face_[f0].adj[e], face_[f0].adj_e[e], w.y);
    if (nhorizon_ < 3) return false;
    for (int i = 0; i < nremoved_; ++i) free_[nfree_++] = removed_[i];
    const int wi = nv_;
    vert_[nv_++] = w;
    int first = -1;
    for (int i = 0; i < nhorizon_; ++i) {
      const HorizonEdge h = horizon_[i];
      const int s = face_[h.face].v[h.edge], t = face_[h.face].v[(h.edge + 1) % 3];
      const int id = new_face(t, s, wi);
      if (id < 0) return false;
      link(id, 0, h.face, h.edge);
      created_[i] = id;
      if (first < 0) first = id;
    }
    // Link the cone: edge 1 (s -> w) of a new face meets edge 2 (w -> t) of the face with t = s.
    for (int i = 0; i < nhorizon_; ++i) {
      const int fi = created_[i];
      int match = -1;
      for (int j = 0; j < nhorizon_; ++j)
        if (face_[created_[j]].v[0] == face_[fi].v[1]) {
          if (match >= 0) return false;
          match = created_[j];
        }
      if (match < 0) return false;
      link(fi, 1, match, 2);
    }
    return true;
  }

  // Min-heap of (distance, face, generation) with lazy deletion: entries of removed or
  // recycled faces are skipped when they reach the top.
  static constexpr int max_heap = 8 * epa_max_vertices;
  struct HeapEntry {
    double dist;
    int face;
    unsigned gen;
  };
  void heap_push(double dist, int f) noexcept {
    if (nheap_ >= max_heap) {
      heap_overflow_ = true;  // closest_face() falls back to a scan
      return;
    }
    int i = nheap_++;
    heap_[i] = {dist, f, gen_[f]};
    while (i > 0 && heap_[(i - 1) / 2].dist > heap_[i].dist) {
      std::swap(heap_[(i - 1) / 2], heap_[i]);
      i = (i - 1) / 2;
    }
  }
  void heap_pop() noexcept {
    heap_[0] = heap_[--nheap_];
    int i = 0;
    for (;;) {
      const int l = 2 * i + 1, r = l + 1;
      int m = i;
      if (l < nheap_ && heap_[l].dist < heap_[m].dist) m = l;
      if (r < nheap_ && heap_[r].dist < heap_[m].dist) m = r;
      if (m == i) break;
      std::swap(heap_[i], heap_[m]);
      i = m;
    }
  }
  HeapEntry heap_[max_heap];
  int nheap_ = 0;
  bool heap_overflow_ = false;
  unsigned gen_[max_f] = {};

  Pt<3> vert_[max_v];
  int nv_ = 0;
  Face face_[max_f];
  int nf_ = 0;
  int free_[max_f];
  int nfree_ = 0;
  HorizonEdge horizon_[max_f];
  int nhorizon_ = 0;
  int removed_[max_f];
  int nremoved_ = 0;
  int created_[max_f];
};

/// EPA in 2D over a counter-clockwise polygon with exact orient2d visibility.
template <Real T>
class Epa2 {
 public:
  static constexpr int max_v = epa_max_vertices;

  EpaOut<2> run(Minkowski<T, 2>& mk, const GjkState<2>& st, double tol, double rel,
                int max_iterations) {
    EpaOut<2> out;
    Pt<2> pts[2 * 2 + 3];
    int npts = 0;
    if (!raise_simplex(mk, st, tol, pts, npts, out)) return out;
    if (!init(pts, npts)) {
      out.touching = true;
      out.status = Status::degenerate_input;
      witnesses(st, out.wa, out.wb);
      return out;
    }
    int best = 0;
    for (int it = 0;; ++it) {
      best = closest_edge();
      if (it >= max_iterations) {
        out.status = Status::limit_exceeded;
        break;
      }
      ++out.iterations;
      const V<2> n = edge_normal(best);
      const double dist = edge_dist(best, n);
      const Pt<2> w = mk(n);
      if (!mk.finite()) {
        out.status = Status::non_finite_input;
        return out;
      }
      const double h = dot(w.y, n);
      const double floor = 8.0 * kEps * mk.scale();
      if (h - dist <= rel * std::fabs(h) || h - dist <= floor) break;
      bool repeat = false;
      for (int i = 0; i < nv_; ++i) repeat = repeat || same_point(poly_[i], w);
      if (repeat || !sees(best, w.y)) break;
      if (!insert(w, best)) {
        out.status = Status::limit_exceeded;
        break;
      }
    }
    const V<2> n = edge_normal(best);
    const double dist = edge_dist(best, n);
    out.depth = std::max(dist, 0.0);
    out.normal = n;
    out.touching = out.depth <= tol;
    const Pt<2>& p = poly_[best];
    const Pt<2>& q = poly_[(best + 1) % nv_];
    const V<2> e = q.y - p.y;
    const double ee = sqr_length(e);
    const double t = ee > 0.0 ? clamp(dot(out.depth * n - p.y, e) / ee, 0.0, 1.0) : 0.0;
    out.wa = lerp(p.a, q.a, t);
    out.wb = lerp(p.b, q.b, t);
    return out;
  }

 private:
  [[nodiscard]] V<2> edge_normal(int i) const noexcept {
    const V<2> e = poly_[(i + 1) % nv_].y - poly_[i].y;
    return normalize(V<2>{e.y, -e.x});  // outward for a counter-clockwise polygon
  }
  [[nodiscard]] double edge_dist(int i, const V<2>& n) const noexcept {
    return 0.5 * (dot(n, poly_[i].y) + dot(n, poly_[(i + 1) % nv_].y));
  }
  [[nodiscard]] bool sees(int i, const V<2>& p) const noexcept {
    return orient2d(poly_[i].y, poly_[(i + 1) % nv_].y, p) == Sign::negative;
  }
  [[nodiscard]] int closest_edge() const noexcept {
    int best = 0;
    double d = kInf;
    for (int i = 0; i < nv_; ++i) {
      const double di = edge_dist(i, edge_normal(i));
      if (di < d) {
        d = di;
        best = i;
      }
    }
    return best;
  }

  /// Convex hull (counter-clockwise, strictly convex) of the few starting points.
  bool init(const Pt<2>* pts, int npts) {
    const auto less = [&](int i, int j) {
      return pts[i].y.x < pts[j].y.x || (pts[i].y.x == pts[j].y.x && pts[i].y.y < pts[j].y.y);
    };
    int order[8];
    for (int i = 0; i < npts && i < 8; ++i) {  // insertion sort of at most 7 points
      int k = i;
      for (; k > 0 && less(i, order[k - 1]); --k) order[k] = order[k - 1];
      order[k] = i;
    }
    // Andrew's monotone chain: lower hull left to right, then upper hull right to left.
    int hull[16];
    int h = 0;
    const auto left_turn = [&](int i) {
      return orient2d(pts[hull[h - 2]].y, pts[hull[h - 1]].y, pts[i].y) == Sign::positive;
    };
    for (int k = 0; k < npts; ++k) {
      while (h >= 2 && !left_turn(order[k])) --h;
      hull[h++] = order[k];
    }
    const int lower = h + 1;
    for (int k = npts - 2; k >= 0; --k) {
      while (h >= lower && !left_turn(order[k])) --h;
      hull[h++] = order[k];
    }
    --h;  // the first point closes the chain
    if (h < 3) return false;
    nv_ = 0;
    for (int k = 0; k < h; ++k) poly_[nv_++] = pts[hull[k]];
    return true;
  }

  bool insert(const Pt<2>& w, int i) {
    if (nv_ >= max_v) return false;
    // The visible chain of edges around edge i: vertices strictly inside it are removed.
    int first = i, last = (i + 1) % nv_;
    int guard = 0;
    while (guard++ < nv_ && sees((first - 1 + nv_) % nv_, w.y)) first = (first - 1 + nv_) % nv_;
    while (guard++ < 2 * nv_ && sees(last, w.y)) last = (last + 1) % nv_;
    Pt<2> tmp[max_v];
    int n = 0;
    for (int k = last;; k = (k + 1) % nv_) {
      tmp[n++] = poly_[k];
      if (k == first) break;
    }
    tmp[n++] = w;
    if (n < 3) return false;
    for (int k = 0; k < n; ++k) poly_[k] = tmp[k];
    nv_ = n;
    return true;
  }

  Pt<2> poly_[max_v];
  int nv_ = 0;
};

template <class T, int N>
[[nodiscard]] EpaOut<N> run_epa(Minkowski<T, N>& mk, const GjkState<N>& st, double tol,
                                const GjkOptions<T, N>& opt) {
  const double rel = std::max(static_cast<double>(opt.relative_tolerance), 0.0);
  if constexpr (N == 3) {
    Epa3<T> epa;
    return epa.run(mk, st, tol, rel, opt.max_iterations);
  } else {
    Epa2<T> epa;
    return epa.run(mk, st, tol, rel, opt.max_iterations);
  }
}

/// Lower bound on the depth of the origin in the enclosing simplex: its distance to the
/// nearest facet plane.
template <int N>
[[nodiscard]] double simplex_depth(const GjkState<N>& st) noexcept {
  double best = kInf;
  for (int skip = 0; skip <= N; ++skip) {
    V<N> f[N];
    int k = 0;
    for (int i = 0; i <= N; ++i)
      if (i != skip) f[k++] = st.s[i].y;
    double d;
    if constexpr (N == 2) {
      const V<2> e = f[1] - f[0];
      const double len = length(e);
      d = len > 0.0 ? std::fabs(perp_dot(e, f[0])) / len : 0.0;
    } else {
      const V<3> n = normal(Triangle3<double>{f[0], f[1], f[2]});
      const double len = length(n);
      d = len > 0.0 ? std::fabs(dot(n, f[0])) / len : 0.0;
    }
    best = std::min(best, d);
  }
  return best;
}

template <class T, int N>
[[nodiscard]] bool bad_margin(const SupportMap<T, N>& m) noexcept {
  return !is_finite(m.margin);
}

}  // namespace

template <Real T, int N>
GjkDistance<T, N> gjk_distance(const SupportMap<T, N>& a, const SupportMap<T, N>& b,
                               const GjkOptions<T, N>& opt) noexcept {
  GjkDistance<T, N> r;
  r.status = Status::ok;
  static constexpr T nan = std::numeric_limits<T>::quiet_NaN();
  const auto non_finite = [&r](Status s) {
    r.status = s;
    r.distance = r.sqr_distance = nan;
    r.closest = {splat<T, N>(nan), splat<T, N>(nan)};
    r.normal = splat<T, N>(nan);
    return r;
  };
  if (bad_margin(a) || bad_margin(b)) return non_finite(Status::non_finite_input);
  if (a.margin < T(0) || b.margin < T(0)) return non_finite(Status::invalid_input);
  Minkowski<T, N> mk(a, b);
  const GjkState<N> st = run_gjk(mk, opt);
  r.iterations = st.iterations;
  if (!mk.finite()) return non_finite(Status::non_finite_input);
  r.status = st.limit ? Status::limit_exceeded : Status::ok;
  trace_simplex(r.simplex, st);
  const double tol = contact_tol(opt.contact_tolerance, mk.scale());
  const double ma = static_cast<double>(a.margin), mb = static_cast<double>(b.margin);
  const double margin = ma + mb;
  V<N> pa, pb;
  witnesses(st, pa, pb);
  const double floor = 8.0 * kEps * mk.scale();
  const double dc = st.enclosed ? 0.0 : length(st.v);
  if (dc > floor) {
    const V<N> n = -st.v / dc;
    const double signed_dist = dc - margin;
    r.contact = signed_dist > tol     ? Contact::separated
                : signed_dist >= -tol ? Contact::touching
                                      : Contact::intersecting;
    r.normal = vec_cast<T>(n);
    if (signed_dist >= 0.0) {
      r.distance = static_cast<T>(signed_dist);
      r.sqr_distance =
          margin == 0.0 ? static_cast<T>(st.vv) : static_cast<T>(signed_dist * signed_dist);
      r.closest = {vec_cast<T>(pa + ma * n), vec_cast<T>(pb - mb * n)};
    } else {
      // The round parts overlap: a common point on the segment between the core points.
      const V<N> common = pa + (ma * dc / margin) * n;
      r.closest = {vec_cast<T>(common), vec_cast<T>(common)};
    }
    return r;
  }
  // The cores touch or overlap.
  r.closest = {vec_cast<T>(pa), vec_cast<T>(pb)};
  if (margin > tol || (st.enclosed && simplex_depth(st) > tol)) {
    r.contact = Contact::intersecting;
    return r;
  }
  const EpaOut<N> e = run_epa(mk, st, tol, opt);
  if (!mk.finite()) return non_finite(Status::non_finite_input);
  r.normal = vec_cast<T>(e.normal);
  r.contact = e.depth + margin > tol ? Contact::intersecting : Contact::touching;
  if (e.status == Status::limit_exceeded) r.status = Status::limit_exceeded;
  return r;
}

template <Real T, int N>
Penetration<T, N> penetration(const SupportMap<T, N>& a, const SupportMap<T, N>& b,
                              const GjkOptions<T, N>& opt) noexcept {
  Penetration<T, N> r;
  r.status = Status::ok;
  static constexpr T nan = std::numeric_limits<T>::quiet_NaN();
  const auto non_finite = [&r](Status s) {
    r.status = s;
    r.depth = nan;
    r.closest = {splat<T, N>(nan), splat<T, N>(nan)};
    r.normal = splat<T, N>(nan);
    return r;
  };
  if (bad_margin(a) || bad_margin(b)) return non_finite(Status::non_finite_input);
  if (a.margin < T(0) || b.margin < T(0)) return non_finite(Status::invalid_input);
  Minkowski<T, N> mk(a, b);
  const GjkState<N> st = run_gjk(mk, opt);
  r.iterations = st.iterations;
  if (!mk.finite()) return non_finite(Status::non_finite_input);
  r.status = st.limit ? Status::limit_exceeded : Status::ok;
  const double tol = contact_tol(opt.contact_tolerance, mk.scale());
  const double ma = static_cast<double>(a.margin), mb = static_cast<double>(b.margin);
  const double margin = ma + mb;
  const auto classify = [&](double depth) {
    r.contact = depth > tol     ? Contact::intersecting
                : depth >= -tol ? Contact::touching
                                : Contact::separated;
  };
  V<N> pa, pb;
  witnesses(st, pa, pb);
  const double floor = 8.0 * kEps * mk.scale();
  const double dc = st.enclosed ? 0.0 : length(st.v);
  if (dc > floor) {
    // Separated cores: the depth is what the round parts add beyond the gap.
    const V<N> n = -st.v / dc;
    const double depth = margin - dc;
    r.depth = static_cast<T>(depth);
    r.normal = vec_cast<T>(n);
    r.closest = {vec_cast<T>(pa + ma * n), vec_cast<T>(pb - mb * n)};
    classify(depth);
    return r;
  }
  const EpaOut<N> e = run_epa(mk, st, tol, opt);
  r.iterations += e.iterations;
  if (!mk.finite() || e.status == Status::non_finite_input)
    return non_finite(Status::non_finite_input);
  if (e.status != Status::ok) r.status = e.status;
  // Flat differences with margins are ordinary: the depth is the margins.
  if (e.status == Status::degenerate_input && margin > 0.0)
    r.status = st.limit ? Status::limit_exceeded : Status::ok;
  const double depth = e.depth + margin;
  r.depth = static_cast<T>(depth);
  r.normal = vec_cast<T>(e.normal);
  r.closest = {vec_cast<T>(e.wa + ma * e.normal), vec_cast<T>(e.wb - mb * e.normal)};
  classify(depth);
  return r;
}

template GjkDistance<float, 2> gjk_distance(const SupportMap<float, 2>&,
                                            const SupportMap<float, 2>&,
                                            const GjkOptions<float, 2>&) noexcept;
template GjkDistance<float, 3> gjk_distance(const SupportMap<float, 3>&,
                                            const SupportMap<float, 3>&,
                                            const GjkOptions<float, 3>&) noexcept;
template GjkDistance<double, 2> gjk_distance(const SupportMap<double, 2>&,
                                             const SupportMap<double, 2>&,
                                             const GjkOptions<double, 2>&) noexcept;
template GjkDistance<double, 3> gjk_distance(const SupportMap<double, 3>&,
                                             const SupportMap<double, 3>&,
                                             const GjkOptions<double, 3>&) noexcept;
template Penetration<float, 2> penetration(const SupportMap<float, 2>&, const SupportMap<float, 2>&,
                                           const GjkOptions<float, 2>&) noexcept;
template Penetration<float, 3> penetration(const SupportMap<float, 3>&, const SupportMap<float, 3>&,
                                           const GjkOptions<float, 3>&) noexcept;
template Penetration<double, 2> penetration(const SupportMap<double, 2>&,
                                            const SupportMap<double, 2>&,
                                            const GjkOptions<double, 2>&) noexcept;
template Penetration<double, 3> penetration(const SupportMap<double, 3>&,
                                            const SupportMap<double, 3>&,
                                            const GjkOptions<double, 3>&) noexcept;

}  // namespace locus::detail
