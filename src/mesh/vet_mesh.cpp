// SPDX-License-Identifier: BSL-1.0
// VetMesh (mesh/vet_mesh.hpp): flat records, corner pool, edge lists around vertices and an
// open-addressing edge table with backward-shift deletion (no tombstones in the table).

#include <locus/mesh/vet_mesh.hpp>

#include <algorithm>
#include <utility>

namespace locus {

namespace {

constexpr std::uint64_t empty_key = ~std::uint64_t{0};

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) noexcept {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

std::size_t slot_of(std::uint64_t key, std::size_t mask) noexcept {
  return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 17) & mask;
}

}  // namespace

// ---- edge table

std::uint32_t VetMesh::map_find(std::uint64_t key) const noexcept {
  if (map_keys_.empty()) return npos;
  const std::size_t mask = map_keys_.size() - 1;
  for (std::size_t i = slot_of(key, mask);; i = (i + 1) & mask) {
    if (map_keys_[i] == key) return map_values_[i];
    if (map_keys_[i] == empty_key) return npos;
  }
}

void VetMesh::map_insert(std::uint64_t key, std::uint32_t e) {
  if (2 * (map_used_ + 1) > map_keys_.size()) {  // keep the load at most 1/2
    std::vector<std::uint64_t> keys(std::max<std::size_t>(16, 2 * map_keys_.size()), empty_key);
    std::vector<std::uint32_t> values(keys.size(), npos);
    const std::size_t mask = keys.size() - 1;
    for (std::size_t j = 0; j < map_keys_.size(); ++j) {
      if (map_keys_[j] == empty_key) continue;
      std::size_t i = slot_of(map_keys_[j], mask);
      while (keys[i] != empty_key) i = (i + 1) & mask;
      keys[i] = map_keys_[j];
      values[i] = map_values_[j];
    }
    map_keys_ = std::move(keys);
    map_values_ = std::move(values);
  }
  const std::size_t mask = map_keys_.size() - 1;
  std::size_t i = slot_of(key, mask);
  while (map_keys_[i] != empty_key) i = (i + 1) & mask;
  map_keys_[i] = key;
  map_values_[i] = e;
  ++map_used_;
}

void VetMesh::map_erase(std::uint64_t key) {
  const std::size_t mask = map_keys_.size() - 1;
  std::size_t i = slot_of(key, mask);
  while (map_keys_[i] != key) {
    LOCUS_ASSERT(map_keys_[i] != empty_key, "edge key missing from the table");
    i = (i + 1) & mask;
  }
  // Backward shift: move later entries of the probe run into the hole when their home slot
  // does not lie cyclically in (hole, entry].
  for (std::size_t j = (i + 1) & mask; map_keys_[j] != empty_key; j = (j + 1) & mask) {
    const std::size_t home = slot_of(map_keys_[j], mask);
    const bool stays = i <= j ? (i < home && home <= j) : (i < home || home <= j);
    if (stays) continue;
    map_keys_[i] = map_keys_[j];
    map_values_[i] = map_values_[j];
    i = j;
  }
  map_keys_[i] = empty_key;
  map_values_[i] = npos;
  --map_used_;
}

// ---- building

std::uint32_t VetMesh::insert_vertex() {
  vertices_.push_back({npos, 0, true});
  ++live_vertices_;
  return size32(vertices_) - 1;
}

void VetMesh::ensure_vertex(std::uint32_t v) {
  LOCUS_ASSERT(v != npos, "vertex id npos");
  if (v >= vertices_.size()) vertices_.resize(std::size_t{v} + 1);
  if (!vertices_[v].alive) {
    vertices_[v] = {npos, 0, true};
    ++live_vertices_;
  }
}

std::uint32_t VetMesh::get_edge(std::uint32_t a, std::uint32_t b) {
  const std::uint64_t key = edge_key(a, b);
  if (const std::uint32_t e = map_find(key); e != npos) return e;
  ensure_vertex(a);
  ensure_vertex(b);
  const std::uint32_t e = size32(edges_);
  EdgeRec r{};
  r.v[0] = std::min(a, b);
  r.v[1] = std::max(a, b);
  r.first_corner = npos;
  r.face_count = 0;
  r.alive = true;
  r.explicit_edge = false;
  for (int s = 0; s < 2; ++s) {  // push at the front of both vertex lists
    VertexRec& vr = vertices_[r.v[s]];
    r.prev[s] = npos;
    r.next[s] = vr.first_edge;
    if (vr.first_edge != npos) {
      EdgeRec& n = edges_[vr.first_edge];
      n.prev[n.v[0] == r.v[s] ? 0 : 1] = e;
    }
    vr.first_edge = e;
    ++vr.edge_count;
  }
  edges_.push_back(r);
  map_insert(key, e);
  ++live_edges_;
  return e;
}

std::uint32_t VetMesh::insert_edge(std::uint32_t a, std::uint32_t b) {
  if (a == b || a == npos || b == npos) return npos;
  const std::uint32_t e = get_edge(a, b);
  edges_[e].explicit_edge = true;
  return e;
}

void VetMesh::link_corner(std::uint32_t c) {
  EdgeRec& r = edges_[corner_edge_[c]];
  corner_next_[c] = r.first_corner;
  r.first_corner = c;
  ++r.face_count;
}

void VetMesh::unlink_corner(std::uint32_t c) {
  EdgeRec& r = edges_[corner_edge_[c]];
  std::uint32_t* link = &r.first_corner;
  while (*link != c) {
    LOCUS_ASSERT(*link != npos, "corner missing from its edge");
    link = &corner_next_[*link];
  }
  *link = corner_next_[c];
  corner_next_[c] = npos;
  --r.face_count;
}

std::uint32_t VetMesh::insert_face(std::span<const std::uint32_t> cycle) {
  const std::size_t k = cycle.size();
  if (k < 3 || k >= npos) return npos;
  for (std::size_t i = 0; i < k; ++i) {
    if (cycle[i] == npos) return npos;
  }
  if (k <= 16) {
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = i + 1; j < k; ++j) {
        if (cycle[i] == cycle[j]) return npos;
      }
    }
  } else {
    std::vector<std::uint32_t> s(cycle.begin(), cycle.end());
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end()) return npos;
  }
  const std::uint32_t f = size32(faces_);
  const std::uint32_t first = size32(corner_vertex_);
  faces_.push_back({first, static_cast<std::uint32_t>(k)});
  for (std::size_t i = 0; i < k; ++i) {
    const std::uint32_t e = get_edge(cycle[i], cycle[(i + 1) % k]);
    corner_vertex_.push_back(cycle[i]);
    corner_edge_.push_back(e);
    corner_next_.push_back(npos);
    corner_face_.push_back(f);
    link_corner(first + static_cast<std::uint32_t>(i));
  }
  ++live_faces_;
  return f;
}

void VetMesh::unlink_edge(std::uint32_t e) {
  EdgeRec& r = edges_[e];
  for (int s = 0; s < 2; ++s) {
    VertexRec& vr = vertices_[r.v[s]];
    if (r.prev[s] == npos) {
      vr.first_edge = r.next[s];
    } else {
      EdgeRec& p = edges_[r.prev[s]];
      p.next[p.v[0] == r.v[s] ? 0 : 1] = r.next[s];
    }
    if (r.next[s] != npos) {
      EdgeRec& n = edges_[r.next[s]];
      n.prev[n.v[0] == r.v[s] ? 0 : 1] = r.prev[s];
    }
    --vr.edge_count;
  }
  map_erase(edge_key(r.v[0], r.v[1]));
  r.alive = false;
  --live_edges_;
}

bool VetMesh::remove_face(std::uint32_t f) {
  if (!has_face(f)) return false;
  const FaceRec fr = faces_[f];
  for (std::uint32_t c = fr.first; c < fr.first + fr.size; ++c) {
    unlink_corner(c);
    const std::uint32_t e = corner_edge_[c];
    if (edges_[e].face_count == 0 && !edges_[e].explicit_edge) unlink_edge(e);
  }
  faces_[f].size = 0;
  --live_faces_;
  return true;
}

bool VetMesh::remove_edge(std::uint32_t e) {
  if (!has_edge(e) || edges_[e].face_count != 0) return false;
  unlink_edge(e);
  return true;
}

bool VetMesh::remove_vertex(std::uint32_t v) {
  if (!has_vertex(v) || vertices_[v].edge_count != 0) return false;
  vertices_[v].alive = false;
  --live_vertices_;
  return true;
}

void VetMesh::flip_face(std::uint32_t f) {
  LOCUS_ASSERT(has_face(f), "face id not live");
  const FaceRec fr = faces_[f];
  const std::uint32_t end = fr.first + fr.size;
  for (std::uint32_t c = fr.first; c < end; ++c) unlink_corner(c);
  std::reverse(corner_vertex_.begin() + fr.first, corner_vertex_.begin() + end);
  for (std::uint32_t c = fr.first; c < end; ++c) {
    const std::uint32_t next = c + 1 == end ? fr.first : c + 1;
    corner_edge_[c] = map_find(edge_key(corner_vertex_[c], corner_vertex_[next]));
    link_corner(c);
  }
}

VetCompaction VetMesh::compact() {
  VetCompaction maps;
  maps.vertex_map.assign(vertices_.size(), npos);
  maps.edge_map.assign(edges_.size(), npos);
  maps.face_map.assign(faces_.size(), npos);
  VetMesh n;
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    if (vertices_[v].alive) maps.vertex_map[v] = n.insert_vertex();
  }
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    if (!edges_[e].alive) continue;
    maps.edge_map[e] = n.get_edge(maps.vertex_map[edges_[e].v[0]], maps.vertex_map[edges_[e].v[1]]);
    n.edges_[maps.edge_map[e]].explicit_edge = edges_[e].explicit_edge;
  }
  std::vector<std::uint32_t> cycle;
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    if (!has_face(f)) continue;
    cycle.clear();
    for (const std::uint32_t v : face_vertices(f)) cycle.push_back(maps.vertex_map[v]);
    maps.face_map[f] = n.insert_face(cycle);
  }
  *this = std::move(n);
  return maps;
}

// ---- queries

std::uint32_t VetMesh::find_edge(std::uint32_t a, std::uint32_t b) const noexcept {
  if (a == b) return npos;
  return map_find(edge_key(a, b));
}

bool VetMesh::face_uses_edge_forward(std::uint32_t f, std::uint32_t e) const noexcept {
  const FaceRec fr = faces_[f];
  for (std::uint32_t c = fr.first; c < fr.first + fr.size; ++c) {
    if (corner_edge_[c] == e) return corner_vertex_[c] == edges_[e].v[0];
  }
  LOCUS_ASSERT(false, "face does not use the edge");
  return false;
}

std::vector<std::uint32_t> VetMesh::edge_faces(std::uint32_t e) const {
  LOCUS_ASSERT(has_edge(e), "edge id not live");
  std::vector<std::uint32_t> out;
  for_each_edge_face(e, [&](std::uint32_t f) { out.push_back(f); });
  return out;
}

std::vector<std::uint32_t> VetMesh::vertex_edges(std::uint32_t v) const {
  LOCUS_ASSERT(has_vertex(v), "vertex id not live");
  std::vector<std::uint32_t> out;
  for_each_vertex_edge(v, [&](std::uint32_t e) { out.push_back(e); });
  return out;
}

std::vector<std::uint32_t> VetMesh::vertex_neighbours(std::uint32_t v) const {
  LOCUS_ASSERT(has_vertex(v), "vertex id not live");
  std::vector<std::uint32_t> out;
  for_each_vertex_edge(v, [&](std::uint32_t e) {
    out.push_back(edges_[e].v[0] == v ? edges_[e].v[1] : edges_[e].v[0]);
  });
  return out;
}

std::vector<std::uint32_t> VetMesh::vertex_faces(std::uint32_t v) const {
  LOCUS_ASSERT(has_vertex(v), "vertex id not live");
  // Each face through v has exactly one corner at v, on the edge leaving v in face order.
  std::vector<std::uint32_t> out;
  for_each_vertex_edge(v, [&](std::uint32_t e) {
    for (std::uint32_t c = edges_[e].first_corner; c != npos; c = corner_next_[c]) {
      if (corner_vertex_[c] == v) out.push_back(corner_face_[c]);
    }
  });
  return out;
}

std::vector<std::uint32_t> VetMesh::boundary_edges() const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t e = 0; e < edges_.size(); ++e) {
    if (edges_[e].alive && edges_[e].face_count == 1) out.push_back(e);
  }
  return out;
}

std::vector<VertexFan> VetMesh::vertex_fans(std::uint32_t v) const {
  LOCUS_ASSERT(has_vertex(v), "vertex id not live");
  // One record per face at v: the face goes prev -> v -> next. The rim graph joins prev and
  // next by that face; fans are its paths and cycles, cut at rim vertices met by other than
  // two faces (their edge {v, w} is a boundary or non-manifold edge).
  struct Rec {
    std::uint32_t face, prev, next;
  };
  std::vector<Rec> recs;
  for_each_vertex_edge(v, [&](std::uint32_t e) {
    for (std::uint32_t c = edges_[e].first_corner; c != npos; c = corner_next_[c]) {
      if (corner_vertex_[c] != v) continue;
      const FaceRec fr = faces_[corner_face_[c]];
      const std::uint32_t p = c == fr.first ? fr.first + fr.size - 1 : c - 1;
      const std::uint32_t n = c + 1 == fr.first + fr.size ? fr.first : c + 1;
      recs.push_back({corner_face_[c], corner_vertex_[p], corner_vertex_[n]});
    }
  });
  std::vector<VertexFan> fans;
  if (recs.empty()) return fans;
  // (rim vertex, record) pairs sorted by rim vertex: the records at each rim vertex.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> at;
  for (std::uint32_t r = 0; r < recs.size(); ++r) {
    at.push_back({recs[r].prev, r});
    at.push_back({recs[r].next, r});
  }
  std::sort(at.begin(), at.end());
  const auto range = [&](std::uint32_t w) {
    const auto lo = std::lower_bound(at.begin(), at.end(), std::pair{w, std::uint32_t{0}});
    auto hi = lo;
    while (hi != at.end() && hi->first == w) ++hi;
    return std::pair{lo, hi};
  };
  const auto degree = [&](std::uint32_t w) {
    const auto [lo, hi] = range(w);
    return hi - lo;
  };
  std::vector<char> used(recs.size(), 0);
  // Walks from record r entering through rim vertex `from`.
  const auto walk = [&](std::uint32_t r, std::uint32_t from) {
    VertexFan fan;
    fan.rim.push_back(from);
    const std::uint32_t start = r;
    for (;;) {
      used[r] = 1;
      fan.faces.push_back(recs[r].face);
      const std::uint32_t to = recs[r].prev == from ? recs[r].next : recs[r].prev;
      if (degree(to) != 2) {
        fan.rim.push_back(to);
        break;
      }
      const auto [lo, hi] = range(to);
      const std::uint32_t other = lo->second == r ? (lo + 1)->second : lo->second;
      if (other == start) {
        fan.closed = true;
        break;
      }
      fan.rim.push_back(to);
      if (used[other]) break;  // unreachable for a path; a guard against malformed input
      r = other;
      from = to;
    }
    fans.push_back(std::move(fan));
  };
  // Open fans start at an end; the counter-clockwise direction enters a face through its next
  // vertex, so prefer ends that are a next vertex.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t r = 0; r < recs.size(); ++r) {
      if (used[r]) continue;
      if (degree(recs[r].next) != 2) {
        walk(r, recs[r].next);
      } else if (pass == 1 && degree(recs[r].prev) != 2) {
        walk(r, recs[r].prev);
      }
    }
  }
  for (std::uint32_t r = 0; r < recs.size(); ++r) {
    if (!used[r]) walk(r, recs[r].next);
  }
  return fans;
}

namespace detail {

VetMeshBuild make_vet_mesh(std::size_t vertex_count, std::span<const std::uint32_t> offsets,
                           std::span<const std::uint32_t> indices) {
  VetMeshBuild out;
  if (vertex_count >= VetMesh::npos) {
    out.status = Status::invalid_input;
    return out;
  }
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != indices.size()) {
    out.status = Status::invalid_input;
    return out;
  }
  for (std::size_t f = 0; f + 1 < offsets.size(); ++f) {
    if (offsets[f + 1] < offsets[f] || offsets[f + 1] - offsets[f] < 3) {
      out.status = Status::invalid_input;
      return out;
    }
  }
  for (const std::uint32_t i : indices) {
    if (i >= vertex_count) {
      out.status = Status::invalid_input;
      return out;
    }
  }
  out.status = vertex_count == 0 && offsets.size() == 1 ? Status::empty_input : Status::ok;
  for (std::size_t v = 0; v < vertex_count; ++v) out.mesh.insert_vertex();
  out.face_ids.reserve(offsets.size() - 1);
  std::uint32_t next_id = 0;
  for (std::size_t f = 0; f + 1 < offsets.size(); ++f) {
    const std::uint32_t id =
        out.mesh.insert_face(indices.subspan(offsets[f], offsets[f + 1] - offsets[f]));
    if (id == VetMesh::npos) {
      out.status = Status::degenerate_input;
    } else {
      LOCUS_ASSERT(id == next_id, "face ids are sequential");
      ++next_id;
    }
    out.face_ids.push_back(id);
  }
  return out;
}

}  // namespace detail

}  // namespace locus
