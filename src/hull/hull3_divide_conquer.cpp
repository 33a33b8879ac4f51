// SPDX-License-Identifier: BSL-1.0
// 3D convex hull by divide and conquer (cg.hull3; book section 13.7.2, figures 13.40-13.41):
// Hull3Method::divide_and_conquer of include/locus/hull/hull3.hpp. The points are sorted
// lexicographically (exact duplicates dropped), cut into halves down to a few points (hulled
// by the incremental method), and two linearly separated hulls are merged by Preparata and
// Hong's wrap: a first bridge edge from the lower tangent of the xy projections, then the band
// of new triangles is wrapped around both hulls (each step an exact orient3d "gift wrapping"
// choice among the neighbours of the bridge's ends) and the faces it hides are deleted by a
// flood fill bounded by the two horizons. Every step of a merge is verified exactly; a merge
// that meets a tie (four coplanar points) or a half whose hull is flat is replaced by the
// incremental hull of the two halves' extreme points. Derivation: docs/notes/hull.md.

#include <locus/hull/hull3.hpp>

#include <locus/config.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace locus {

namespace {

constexpr std::uint32_t kNil = 0xFFFFFFFFu;
constexpr std::size_t kLeaf = 16;  // sub-problems this small are hulled directly

struct DcFace {
  std::uint32_t v[3];
  std::uint32_t adj[3];  // across edge (v[e], v[(e + 1) % 3])
  std::uint32_t mark;
  bool alive;
};

// A sub-hull: its extreme points; `full` when it is 3D (its faces are then live in the pool and
// every vertex's `vface_` names one of them).
struct Sub {
  std::vector<std::uint32_t> verts;
  bool full = false;
};

// A neighbour w of vertex v on a hull: face `face` holds the directed edge v -> w as its edge
// `edge`.
struct Nbr {
  std::uint32_t w, face;
  int edge;
};

// One band triangle (a, b, c), outward counter-clockwise, a in the left hull, b in the right
// one; c is a neighbour of a (in_a) or of b. `face`/`edge`: the hull face holding a -> c
// (in_a) or b -> c (otherwise).
struct Step {
  std::uint32_t a, b, c, face;
  int edge;
  bool in_a;
};

template <Real T, class Leaf>
class DivideConquer3 {
 public:
  DivideConquer3(const Vec3<T>* p, std::size_t n, Leaf& leaf)
      : p_(p), leaf_(leaf), vface_(n, kNil), vmark_(n, 0), vdead_(n, 0) {}

  void run(std::span<const std::uint32_t> ids, Hull3Result& out) {
    std::vector<std::uint32_t> s(ids.begin(), ids.end());
    std::sort(s.begin(), s.end(), [this](std::uint32_t i, std::uint32_t j) {
      const Sign c = lexicographic_compare(p_[i], p_[j]);
      return c == Sign::negative || (c == Sign::zero && i < j);
    });
    // Exact duplicates: the smallest index stays.
    std::size_t m = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (m == 0 || !(p_[s[i]] == p_[s[m - 1]])) s[m++] = s[i];
    s.resize(m);
    const Sub root = recurse(s.data(), s.size());
    out.triangles.clear();
    out.adjacency.clear();
    // The caller found four non-coplanar points, so the root's hull is 3D.
    LOCUS_ASSERT(root.full, "divide_and_conquer: a 3D set gave a flat hull");
    if (!root.full) return;
    // Collect the root's faces (a flood over the adjacency) and renumber them.
    std::vector<std::uint32_t> map(faces_.size(), kNil), stack{vface_[root.verts[0]]};
    map[stack[0]] = 0;
    std::vector<std::uint32_t> order{stack[0]};
    while (!stack.empty()) {
      const std::uint32_t g = stack.back();
      stack.pop_back();
      for (const std::uint32_t h : faces_[g].adj)
        if (map[h] == kNil) {
          map[h] = static_cast<std::uint32_t>(order.size());
          order.push_back(h);
          stack.push_back(h);
        }
    }
    for (const std::uint32_t g : order) {
      const DcFace& F = faces_[g];
      out.triangles.push_back({F.v[0], F.v[1], F.v[2]});
      out.adjacency.push_back({map[F.adj[0]], map[F.adj[1]], map[F.adj[2]]});
    }
  }

 private:
  Sub recurse(const std::uint32_t* ids, std::size_t m) {
    if (m <= kLeaf) return hull_of(std::span<const std::uint32_t>(ids, m));
    const std::size_t h = m / 2;
    Sub left = recurse(ids, h);
    Sub right = recurse(ids + h, m - h);
    if (left.full && right.full) {
      Sub merged;
      if (merge(left, right, merged)) return merged;
    }
    // A flat half or a degenerate merge: the incremental hull of both halves' extreme points
    // (the hull of the union is the hull of those).
    kill(left);
    kill(right);
    left.verts.insert(left.verts.end(), right.verts.begin(), right.verts.end());
    return hull_of(left.verts);
  }

  // The hull of a few points (or of two halves' extreme points) by the incremental method.
  Sub hull_of(std::span<const std::uint32_t> ids) {
    const int dim = leaf_(ids, tmp_);
    Sub s;
    s.verts = tmp_.vertices;
    if (dim < 3) return s;
    s.full = true;
    std::vector<std::uint32_t> id(tmp_.triangles.size());
    for (std::size_t t = 0; t < id.size(); ++t) id[t] = alloc();
    for (std::size_t t = 0; t < id.size(); ++t) {
      DcFace& F = faces_[id[t]];
      for (int e = 0; e < 3; ++e) {
        F.v[e] = tmp_.triangles[t][static_cast<std::size_t>(e)];
        F.adj[e] = id[tmp_.adjacency[t][static_cast<std::size_t>(e)]];
        vface_[F.v[e]] = id[t];
      }
    }
    return s;
  }

  std::uint32_t alloc() {
    std::uint32_t g;
    if (!free_.empty()) {
      g = free_.back();
      free_.pop_back();
    } else {
      g = static_cast<std::uint32_t>(faces_.size());
      faces_.emplace_back();
    }
    faces_[g].mark = 0;
    faces_[g].alive = true;
    return g;
  }

  void release(std::uint32_t g) {
    faces_[g].alive = false;
    free_.push_back(g);
  }

  // Deletes every face of a 3D sub-hull (a flood from one of its faces).
  void kill(const Sub& s) {
    if (!s.full) return;
    const std::uint32_t st = ++stamp_;
    stack_.assign(1, vface_[s.verts[0]]);
    faces_[stack_[0]].mark = st;
    while (!stack_.empty()) {
      const std::uint32_t g = stack_.back();
      stack_.pop_back();
      for (const std::uint32_t h : faces_[g].adj)
        if (faces_[h].mark != st) {
          faces_[h].mark = st;
          stack_.push_back(h);
        }
      release(g);
    }
  }

  [[nodiscard]] static int slot(const DcFace& F, std::uint32_t v) noexcept {
    return F.v[0] == v ? 0 : (F.v[1] == v ? 1 : 2);
  }

  // The neighbours of v on its hull, one per incident face (the fan around v).
  void fan(std::uint32_t v, std::vector<Nbr>& out) const {
    out.clear();
    const std::uint32_t g0 = vface_[v];
    std::uint32_t g = g0;
    do {
      const int i = slot(faces_[g], v);
      out.push_back({faces_[g].v[(i + 1) % 3], g, i});
      g = faces_[g].adj[i];
    } while (g != g0 && out.size() <= faces_.size());
  }

  // The lower tangent of the xy projections of two hulls, the left one lexicographically
  // before the right one: indices into L.verts and R.verts, or false when a projection is flat.
  bool lower_tangent(const Sub& L, const Sub& R, std::uint32_t& a0, std::uint32_t& b0) {
    const auto project = [this](const Sub& s, std::vector<Vec2<T>>& q, Hull2Result& r) {
      q.resize(s.verts.size());
      for (std::size_t k = 0; k < q.size(); ++k) q[k] = Vec2<T>{p_[s.verts[k]].x, p_[s.verts[k]].y};
      hull2_.compute(std::span<const Vec2<T>>(q), Hull2Options{}, r);
      return r.status == Status::ok && r.dimension == 2;
    };
    if (!project(L, qa_, ra_) || !project(R, qb_, rb_)) return false;
    const std::vector<std::uint32_t>& A = ra_.indices;
    const std::vector<std::uint32_t>& B = rb_.indices;
    const std::size_t na = A.size(), nb = B.size();
    const auto xy_less = [](const Vec2<T>& u, const Vec2<T>& w) {
      return u.x < w.x || (u.x == w.x && u.y < w.y);
    };
    std::size_t i = 0, j = 0;
    for (std::size_t k = 1; k < na; ++k)
      if (xy_less(qa_[A[i]], qa_[A[k]])) i = k;
    for (std::size_t k = 1; k < nb; ++k)
      if (xy_less(qb_[B[k]], qb_[B[j]])) j = k;
    // Walk down the lower chains: a clockwise on the left polygon, b counter-clockwise on the
    // right one, while the next vertex is right of a -> b.
    for (std::size_t guard = 0; guard <= 2 * (na + nb); ++guard) {
      bool moved = false;
      for (std::size_t k = 0; k < na; ++k) {
        const std::size_t i2 = (i + na - 1) % na;
        if (orient2d(qa_[A[i]], qb_[B[j]], qa_[A[i2]]) != Sign::negative) break;
        i = i2;
        moved = true;
      }
      for (std::size_t k = 0; k < nb; ++k) {
        const std::size_t j2 = (j + 1) % nb;
        if (orient2d(qa_[A[i]], qb_[B[j]], qb_[B[j2]]) != Sign::negative) break;
        j = j2;
        moved = true;
      }
      if (!moved) {
        a0 = L.verts[A[i]];
        b0 = R.verts[B[j]];
        return true;
      }
    }
    return false;
  }

  // Merges two 3D hulls, L lexicographically before R, into out; false (nothing changed) when a
  // decision meets a tie.
  bool merge(const Sub& L, const Sub& R, Sub& out) {
    std::uint32_t a0, b0;
    if (!lower_tangent(L, R, a0, b0)) return false;
    // Wrap the band. The vertical plane through a0 b0 supports both hulls, so the candidates of
    // the first step lie in a half-space bounded by a plane through the bridge, where "c' lies
    // outside plane (a, b, c)" orders them; later steps rotate about the new bridge from the
    // previous band triangle, again a supporting plane.
    band_.clear();
    std::uint32_t a = a0, b = b0, prev = kNil;
    const std::size_t limit = L.verts.size() + R.verts.size() + 3;
    std::uint32_t fan_a = kNil, fan_b = kNil;  // whose neighbours na_ and nb_ hold
    for (;;) {
      if (band_.size() > limit) return false;
      if (fan_a != a) fan(fan_a = a, na_);
      if (fan_b != b) fan(fan_b = b, nb_);
      const Nbr* best = nullptr;
      bool best_a = true;
      for (int side = 0; side < 2; ++side)
        for (const Nbr& c : side == 0 ? na_ : nb_) {
          if (c.w == prev) continue;
          if (best == nullptr) {
            best = &c;
            best_a = side == 0;
            continue;
          }
          const Sign s = orient3d(p_[a], p_[b], p_[best->w], p_[c.w]);
          if (s == Sign::zero) return false;
          if (s == Sign::positive) {
            best = &c;
            best_a = side == 0;
          }
        }
      if (best == nullptr) return false;
      // Verify: every neighbour of a and b strictly inside the plane (a, b, c) makes it a face of
      // the merged hull (a convex polytope lies in the cone of a vertex's edges), touching the
      // hulls only along a -> c or b -> c.
      for (int side = 0; side < 2; ++side)
        for (const Nbr& c : side == 0 ? na_ : nb_)
          if (&c != best && orient3d(p_[a], p_[b], p_[best->w], p_[c.w]) != Sign::negative)
            return false;
      band_.push_back({a, b, best->w, best->face, best->edge, best_a});
      if (best_a) {
        prev = a;
        a = best->w;
      } else {
        prev = b;
        b = best->w;
      }
      if (a == a0 && b == b0) break;
    }
    // The hull faces along both horizons: kept (outside the band) and hidden (inside). A hull
    // edge that the band walks both ways (the chains need not be simple: figure 13.41's
    // terminator is two cycles) has both its faces hidden and joins two band triangles.
    const std::size_t nband = band_.size();
    twin_.assign(nband, kNil);
    keys_.clear();
    for (std::size_t k = 0; k < nband; ++k) {
      const Step& s = band_[k];
      keys_.push_back(
          {std::uint64_t(s.in_a ? s.a : s.b) << 32 | s.c, static_cast<std::uint32_t>(k)});
    }
    std::sort(keys_.begin(), keys_.end());
    for (std::size_t k = 0; k < nband; ++k) {
      const Step& s = band_[k];
      const std::uint64_t rev = std::uint64_t(s.c) << 32 | (s.in_a ? s.a : s.b);
      const auto it =
          std::lower_bound(keys_.begin(), keys_.end(), std::make_pair(rev, std::uint32_t(0)));
      if (it != keys_.end() && it->first == rev) twin_[k] = it->second;
    }
    const std::uint32_t kept = ++stamp_;
    seeds_.clear();
    keep_.assign(nband, {kNil, 0});
    bool any_a = false, any_b = false;
    for (std::size_t k = 0; k < nband; ++k) {
      const Step& s = band_[k];
      (s.in_a ? any_a : any_b) = true;
      if (twin_[k] != kNil) {
        seeds_.push_back(s.face);
        continue;
      }
      std::uint32_t kf, h;
      int e;
      if (s.in_a) {  // the face with a -> c is kept, the one across (holding c -> a) hidden
        kf = s.face;
        e = s.edge;
        h = faces_[kf].adj[e];
      } else {  // the face with b -> c is hidden, the one across (holding c -> b) kept
        h = s.face;
        kf = faces_[h].adj[s.edge];
        e = slot(faces_[kf], s.c);
      }
      faces_[kf].mark = kept;
      keep_[k] = {kf, static_cast<std::uint32_t>(e)};
      seeds_.push_back(h);
    }
    // A hull the band touches in one vertex only is hidden entirely.
    if (!any_a) seeds_.push_back(vface_[a0]);
    if (!any_b) seeds_.push_back(vface_[b0]);
    for (const std::uint32_t h : seeds_)
      if (faces_[h].mark == kept) return false;  // a face both kept and hidden: not a band
    // Commit: the band faces, linked to each other and to the kept faces.
    const std::uint32_t horizon = ++stamp_;
    newf_.resize(nband);
    for (std::size_t k = 0; k < nband; ++k) {
      const Step& s = band_[k];
      const std::uint32_t g = alloc();
      newf_[k] = g;
      DcFace& F = faces_[g];
      F.v[0] = s.a, F.v[1] = s.b, F.v[2] = s.c;
      for (const std::uint32_t v : F.v) {
        vface_[v] = g;
        vmark_[v] = horizon;
      }
    }
    for (std::size_t k = 0; k < nband; ++k) {
      const std::uint32_t g = newf_[k], h = newf_[(k + 1) % nband];
      const int side = band_[k].in_a ? 2 : 1;  // the edge on the hull, a -> c reversed or b -> c
      if (twin_[k] != kNil) {
        faces_[g].adj[side] = newf_[twin_[k]];
      } else {
        const auto [kf, ke] = keep_[k];
        faces_[g].adj[side] = kf;
        faces_[kf].adj[ke] = g;
      }
      faces_[g].adj[band_[k].in_a ? 1 : 2] = h;
      faces_[h].adj[0] = g;
    }
    // Delete the hidden faces: a flood from the seeds that never enters a kept face. Their
    // vertices off the horizons leave the hull.
    const std::uint32_t hidden = ++stamp_;
    stack_.clear();
    for (const std::uint32_t h : seeds_)
      if (faces_[h].mark != hidden) {
        faces_[h].mark = hidden;
        stack_.push_back(h);
      }
    while (!stack_.empty()) {
      const std::uint32_t g = stack_.back();
      stack_.pop_back();
      for (const std::uint32_t v : faces_[g].v)
        if (vmark_[v] != horizon) vdead_[v] = hidden;
      for (const std::uint32_t h : faces_[g].adj)
        if (faces_[h].mark != hidden && faces_[h].mark != kept) {
          faces_[h].mark = hidden;
          stack_.push_back(h);
        }
      release(g);
    }
    out.full = true;
    out.verts.clear();
    for (const Sub* s : {&L, &R})
      for (const std::uint32_t v : s->verts)
        if (vdead_[v] != hidden) out.verts.push_back(v);
    return true;
  }

  const Vec3<T>* p_;
  Leaf& leaf_;
  std::vector<DcFace> faces_;
  std::vector<std::uint32_t> free_, vface_, vmark_, vdead_, stack_, seeds_, newf_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keep_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys_;
  std::vector<std::uint32_t> twin_;
  std::vector<Nbr> na_, nb_;
  std::vector<Step> band_;
  std::uint32_t stamp_ = 0;
  Hull3Result tmp_;
  ConvexHull2<T> hull2_;
  std::vector<Vec2<T>> qa_, qb_;
  Hull2Result ra_, rb_;
};

}  // namespace

template <Real T>
void ConvexHull3<T>::divide_conquer(std::span<const std::uint32_t> ids, Hull3Result& out) {
  // Leaves and fallbacks: the incremental method (ConvexHull3::build, which also drops the
  // non-extreme points it meets).
  auto leaf = [this](std::span<const std::uint32_t> s, Hull3Result& r) {
    return build(s, Hull3Method::incremental, r, true);
  };
  DivideConquer3<T, decltype(leaf)> dc(pts_, n_, leaf);
  dc.run(ids, out);
}

template void ConvexHull3<float>::divide_conquer(std::span<const std::uint32_t>, Hull3Result&);
template void ConvexHull3<double>::divide_conquer(std::span<const std::uint32_t>, Hull3Result&);

}  // namespace locus
