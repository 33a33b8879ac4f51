// SPDX-License-Identifier: BSL-1.0
// A plane slicing a triangle mesh (include/locus/intersection/plane_mesh.hpp); derivation and
// the vertex-on-plane rule: docs/notes/intersection3.md ("Plane and mesh").

#include <locus/core/plane_side.hpp>
#include <locus/intersection/plane_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace locus {

namespace {

using V = Vec3<double>;

constexpr std::uint32_t none = 0xffffffffu;

// A crossed mesh edge: its point and the (at most two, in the manifold case) segments using it.
struct Node {
  V point;
  std::vector<std::uint32_t> segs;
};

// One triangle's piece: from node a to node b (along cross(plane normal, triangle normal)).
struct Seg {
  std::uint32_t a, b;
  bool used = false;
};

template <Real T>
class Slicer {
 public:
  Slicer(std::span<const Vec3<T>> v, const Plane3<T>& pl)
      : v_(v), n_(vec_cast<double>(pl.normal)), c_(double(pl.constant)) {
    side_.assign(v.size(), 2);
    on_plane_.assign(v.size(), false);
  }

  // Exact side of vertex i, zero counted as positive (+1 / -1); 0 for a non-finite vertex.
  int side(std::uint32_t i) {
    if (side_[i] == 2) {
      const V p = vec_cast<double>(v_[i]);
      if (!is_finite(p)) {
        side_[i] = 0;
      } else {
        const int s = to_int(side_of_plane(n_, c_, p));
        if (s == 0) on_plane_[i] = true;
        side_[i] = s < 0 ? -1 : 1;
      }
    }
    return side_[i];
  }

  // The node of edge {i, j} (its point computed once, from the lower-numbered vertex).
  std::uint32_t node(std::uint32_t i, std::uint32_t j) {
    if (j < i) std::swap(i, j);
    const std::uint64_t key = (std::uint64_t(i) << 32) | j;
    const auto [it, fresh] = index_.try_emplace(key, static_cast<std::uint32_t>(nodes_.size()));
    if (fresh) {
      const V p = vec_cast<double>(v_[i]), q = vec_cast<double>(v_[j]);
      V x;
      if (on_plane_[i]) {
        x = p;
      } else if (on_plane_[j]) {
        x = q;
      } else {
        const double fp = plane_value(n_, c_, p), fq = plane_value(n_, c_, q);
        const double t = std::clamp(fp / (fp - fq), 0.0, 1.0);
        x = t == 0.0 ? p : (t == 1.0 ? q : p + t * (q - p));
      }
      nodes_.push_back({x, {}});
    }
    return it->second;
  }

  // Adds triangle (i0, i1, i2); false when a vertex is not finite.
  bool add(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) {
    if (i0 == i1 || i1 == i2 || i0 == i2) return true;
    const std::uint32_t id[3] = {i0, i1, i2};
    int s[3];
    for (int k = 0; k < 3; ++k) {
      s[k] = side(id[k]);
      if (s[k] == 0) return false;
    }
    if (s[0] == s[1] && s[1] == s[2]) return true;
    // The lone vertex a (signs are +-1 here): the one differing from the other two.
    const int a = s[0] != s[1] && s[0] != s[2] ? 0 : (s[1] != s[0] ? 1 : 2);
    const std::uint32_t nb = node(id[a], id[(a + 1) % 3]), nc = node(id[a], id[(a + 2) % 3]);
    // Along cross(plane normal, triangle normal) the crossing on edge (a, a + 1) comes first
    // iff vertex a is on the positive side (docs/notes/intersection3.md).
    const std::uint32_t first = s[a] > 0 ? nb : nc, second = s[a] > 0 ? nc : nb;
    const auto k = static_cast<std::uint32_t>(segs_.size());
    segs_.push_back({first, second});
    nodes_[first].segs.push_back(k);
    nodes_[second].segs.push_back(k);
    return true;
  }

  std::vector<Polyline3<T>> chain() {
    std::vector<Polyline3<T>> out;
    // Open chains first: from a node with one segment, preferring segment tails.
    for (int pass = 0; pass < 2; ++pass) {
      for (std::uint32_t n = 0; n < nodes_.size(); ++n) {
        if (nodes_[n].segs.size() != 1) continue;
        const std::uint32_t k = nodes_[n].segs[0];
        if (segs_[k].used || (pass == 0 && segs_[k].a != n)) continue;
        out.push_back(walk(n, k));
      }
    }
    // The rest are loops (or chains through non-manifold edges).
    for (std::uint32_t k = 0; k < segs_.size(); ++k) {
      if (!segs_[k].used) out.push_back(walk(segs_[k].a, k));
    }
    return out;
  }

 private:
  Polyline3<T> walk(std::uint32_t start, std::uint32_t k) {
    Polyline3<T> line;
    std::vector<V> pts{nodes_[start].point};
    std::uint32_t n = start;
    while (k != none) {
      segs_[k].used = true;
      n = segs_[k].a == n ? segs_[k].b : segs_[k].a;
      pts.push_back(nodes_[n].point);
      k = none;
      for (const std::uint32_t j : nodes_[n].segs) {
        if (!segs_[j].used) {
          k = j;
          break;
        }
      }
    }
    line.closed = n == start && pts.size() > 1;
    if (line.closed) pts.pop_back();
    for (const V& p : pts) {
      const Vec3<T> q = vec_cast<T>(p);
      if (line.vertices.empty() || !(line.vertices.back() == q)) line.vertices.push_back(q);
    }
    while (line.closed && line.vertices.size() > 1 && line.vertices.back() == line.vertices[0]) {
      line.vertices.pop_back();
    }
    return line;
  }

  std::span<const Vec3<T>> v_;
  V n_;
  double c_;
  std::vector<signed char> side_;
  std::vector<bool> on_plane_;
  std::vector<Node> nodes_;
  std::vector<Seg> segs_;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
};

template <Real T>
Status check_plane(const Plane3<T>& pl) noexcept {
  if (!is_finite(pl.normal) || !std::isfinite(pl.constant)) return Status::non_finite_input;
  if (pl.normal == Vec3<T>{}) return Status::degenerate_input;
  return Status::ok;
}

}  // namespace

template <Real T>
MeshSlice<T> slice_mesh(std::span<const Vec3<T>> vertices,
                        std::span<const std::array<std::uint32_t, 3>> triangles,
                        const Plane3<T>& plane) {
  MeshSlice<T> r;
  if (triangles.empty()) return r;
  for (const std::array<std::uint32_t, 3>& t : triangles) {
    if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size()) {
      r.status = Status::invalid_input;
      return r;
    }
  }
  r.status = check_plane(plane);
  if (r.status != Status::ok) return r;
  Slicer<T> s(vertices, plane);
  for (const std::array<std::uint32_t, 3>& t : triangles) {
    if (!s.add(t[0], t[1], t[2])) {
      r.status = Status::non_finite_input;
      return r;
    }
  }
  r.polylines = s.chain();
  return r;
}

template <Real T>
MeshSlice<T> slice_mesh(std::span<const Vec3<T>> vertices,
                        std::span<const std::uint32_t> face_offsets,
                        std::span<const std::uint32_t> face_indices, const Plane3<T>& plane) {
  MeshSlice<T> r;
  if (face_offsets.size() < 2) return r;
  if (face_offsets[0] != 0 || face_offsets.back() != face_indices.size()) {
    r.status = Status::invalid_input;
    return r;
  }
  std::vector<std::array<std::uint32_t, 3>> tris;
  for (std::size_t f = 0; f + 1 < face_offsets.size(); ++f) {
    const std::uint32_t b = face_offsets[f], e = face_offsets[f + 1];
    if (e < b + 3) {
      r.status = Status::invalid_input;
      return r;
    }
    for (std::uint32_t i = b + 1; i + 1 < e; ++i) {
      tris.push_back({face_indices[b], face_indices[i], face_indices[i + 1]});
    }
  }
  return slice_mesh(vertices, std::span<const std::array<std::uint32_t, 3>>(tris), plane);
}

template MeshSlice<float> slice_mesh(std::span<const Vec3<float>>,
                                     std::span<const std::array<std::uint32_t, 3>>,
                                     const Plane3<float>&);
template MeshSlice<double> slice_mesh(std::span<const Vec3<double>>,
                                      std::span<const std::array<std::uint32_t, 3>>,
                                      const Plane3<double>&);
template MeshSlice<float> slice_mesh(std::span<const Vec3<float>>, std::span<const std::uint32_t>,
                                     std::span<const std::uint32_t>, const Plane3<float>&);
template MeshSlice<double> slice_mesh(std::span<const Vec3<double>>, std::span<const std::uint32_t>,
                                      std::span<const std::uint32_t>, const Plane3<double>&);

}  // namespace locus
