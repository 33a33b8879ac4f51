// SPDX-License-Identifier: BSL-1.0
// Row mesh.vet: VetMesh against a brute-force model (a list of live faces and explicit edges,
// every adjacency recomputed by scanning it) under seeded random insertions and removals;
// one-ring fans (closed on solids, open on boundaries, two on a bow-tie, counter-clockwise
// order checked against the faces); flipping; compaction maps; conversion from and to
// PolygonMesh with its statuses.

#include <locus/mesh/platonic.hpp>
#include <locus/mesh/polygon_mesh.hpp>
#include <locus/mesh/vet_mesh.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

namespace {

using locus::Status;
using locus::VetMesh;
using locus_test::Rng;
constexpr std::uint32_t npos = VetMesh::npos;

using Edge = std::pair<std::uint32_t, std::uint32_t>;
Edge key(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

struct Model {
  std::map<std::uint32_t, std::vector<std::uint32_t>> faces;  // live faces by id
  std::set<Edge> explicit_edges;
  std::set<std::uint32_t> vertices;

  std::map<Edge, std::multiset<std::uint32_t>> edge_faces() const {
    std::map<Edge, std::multiset<std::uint32_t>> r;
    for (const Edge& e : explicit_edges) r[e];
    for (const auto& [f, c] : faces) {
      for (std::size_t i = 0; i < c.size(); ++i) r[key(c[i], c[(i + 1) % c.size()])].insert(f);
    }
    return r;
  }
};

void expect_matches(const VetMesh& m, const Model& model) {
  const auto ef = model.edge_faces();
  ASSERT_EQ(m.face_count(), model.faces.size());
  ASSERT_EQ(m.edge_count(), ef.size());
  ASSERT_EQ(m.vertex_count(), model.vertices.size());
  for (const auto& [f, c] : model.faces) {
    ASSERT_TRUE(m.has_face(f));
    const auto got = m.face_vertices(f);
    ASSERT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()), c);
    const auto edges = m.face_edges(f);
    for (std::size_t i = 0; i < c.size(); ++i) {
      ASSERT_EQ(edges[i], m.find_edge(c[i], c[(i + 1) % c.size()]));
    }
  }
  std::vector<std::uint32_t> boundary;
  for (const auto& [e, fs] : ef) {
    const std::uint32_t id = m.find_edge(e.first, e.second);
    ASSERT_NE(id, npos);
    ASSERT_EQ(m.find_edge(e.second, e.first), id);
    ASSERT_EQ((std::array<std::uint32_t, 2>{e.first, e.second}), m.edge_vertices(id));
    ASSERT_EQ(m.edge_face_count(id), fs.size());
    const auto got = m.edge_faces(id);
    ASSERT_EQ(std::multiset<std::uint32_t>(got.begin(), got.end()), fs);
    if (fs.size() == 1) boundary.push_back(id);
  }
  std::sort(boundary.begin(), boundary.end());
  ASSERT_EQ(m.boundary_edges(), boundary);
  for (const std::uint32_t v : model.vertices) {
    ASSERT_TRUE(m.has_vertex(v));
    std::multiset<std::uint32_t> faces, nb;
    for (const auto& [f, c] : model.faces) {
      if (std::find(c.begin(), c.end(), v) != c.end()) faces.insert(f);
    }
    for (const auto& [e, fs] : ef) {
      if (e.first == v) nb.insert(e.second);
      if (e.second == v) nb.insert(e.first);
    }
    const auto gf = m.vertex_faces(v);
    ASSERT_EQ(std::multiset<std::uint32_t>(gf.begin(), gf.end()), faces);
    const auto gn = m.vertex_neighbours(v);
    ASSERT_EQ(std::multiset<std::uint32_t>(gn.begin(), gn.end()), nb);
    ASSERT_EQ(m.vertex_edge_count(v), nb.size());
  }
}

TEST(VetMesh, RandomInsertRemoveMatchesModel) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 12; ++trial) {
    VetMesh m;
    Model model;
    const int nv = rng.uniform_int(4, 30);
    for (int step = 0; step < 300; ++step) {
      const int op = rng.uniform_int(0, 9);
      if (op < 6) {
        std::vector<std::uint32_t> c(static_cast<std::size_t>(rng.uniform_int(3, 6)));
        for (auto& v : c) v = static_cast<std::uint32_t>(rng.uniform_int(0, nv - 1));
        const std::set<std::uint32_t> distinct(c.begin(), c.end());
        const std::uint32_t f = m.insert_face(c);
        if (distinct.size() != c.size()) {
          ASSERT_EQ(f, npos);
          continue;
        }
        ASSERT_EQ(f, m.face_capacity() - 1);
        model.faces[f] = c;
        model.vertices.insert(c.begin(), c.end());
      } else if (op < 8 && !model.faces.empty()) {
        auto it = model.faces.begin();
        std::advance(it, rng.uniform_int(0, static_cast<int>(model.faces.size()) - 1));
        ASSERT_TRUE(m.remove_face(it->first));
        ASSERT_FALSE(m.remove_face(it->first));
        model.faces.erase(it);
      } else if (op == 8) {
        const auto a = static_cast<std::uint32_t>(rng.uniform_int(0, nv - 1));
        const auto b = static_cast<std::uint32_t>(rng.uniform_int(0, nv - 1));
        const std::uint32_t e = m.insert_edge(a, b);
        if (a == b) {
          ASSERT_EQ(e, npos);
          continue;
        }
        ASSERT_TRUE(m.is_explicit_edge(e));
        model.explicit_edges.insert(key(a, b));
        model.vertices.insert(a);
        model.vertices.insert(b);
      } else if (!model.explicit_edges.empty()) {
        // Remove an explicit edge: refused while a face uses it.
        auto it = model.explicit_edges.begin();
        std::advance(it, rng.uniform_int(0, static_cast<int>(model.explicit_edges.size()) - 1));
        const auto ef = model.edge_faces();
        const bool used = !ef.at(*it).empty();
        ASSERT_EQ(m.remove_edge(m.find_edge(it->first, it->second)), !used);
        if (!used) model.explicit_edges.erase(it);
      }
      expect_matches(m, model);
      if (HasFatalFailure()) return;
    }
    // Compaction keeps everything, renumbered densely in order.
    const std::size_t faces = m.face_count(), edges = m.edge_count();
    const locus::VetCompaction maps = m.compact();
    EXPECT_EQ(m.face_capacity(), faces);
    EXPECT_EQ(m.edge_capacity(), edges);
    Model renamed;
    for (const std::uint32_t v : model.vertices) renamed.vertices.insert(maps.vertex_map[v]);
    for (const auto& [f, c] : model.faces) {
      auto& nc = renamed.faces[maps.face_map[f]];
      for (const std::uint32_t v : c) nc.push_back(maps.vertex_map[v]);
    }
    for (const Edge& e : model.explicit_edges) {
      renamed.explicit_edges.insert(key(maps.vertex_map[e.first], maps.vertex_map[e.second]));
    }
    expect_matches(m, renamed);
    std::uint32_t next = 0;  // live faces keep their order and fill 0, 1, 2, ...
    for (const std::uint32_t g : maps.face_map) {
      if (g != npos) {
        EXPECT_EQ(g, next++);
      }
    }
  }
}

// The ordered one-ring: every fan face i goes v -> rim[i] -> rim[i + 1] (counter-clockwise seen
// from outside) on a consistently oriented mesh.
void expect_ccw_fan(const VetMesh& m, std::uint32_t v, const locus::VertexFan& fan) {
  const std::size_t k = fan.faces.size();
  ASSERT_EQ(fan.rim.size(), fan.closed ? k : k + 1);
  for (std::size_t i = 0; i < k; ++i) {
    const auto c = m.face_vertices(fan.faces[i]);
    const std::size_t n = c.size();
    const std::size_t at = static_cast<std::size_t>(std::find(c.begin(), c.end(), v) - c.begin());
    ASSERT_LT(at, n);
    EXPECT_EQ(c[(at + 1) % n], fan.rim[i]);
    EXPECT_EQ(c[(at + n - 1) % n], fan.rim[(i + 1) % fan.rim.size()]);
  }
}

TEST(VetMesh, FansOfClosedSolidsAreSingleClosedRings) {
  for (const auto& mesh : {locus::icosahedron_mesh<double>(), locus::dodecahedron_mesh<double>(),
                           locus::hexahedron_mesh<double>(), locus::torus_mesh(3.0, 1.0, 8, 5)}) {
    const locus::VetMeshBuild b = locus::make_vet_mesh(mesh);
    ASSERT_EQ(b.status, Status::ok);
    for (std::uint32_t v = 0; v < b.mesh.vertex_capacity(); ++v) {
      const auto fans = b.mesh.vertex_fans(v);
      ASSERT_EQ(fans.size(), 1u);
      EXPECT_TRUE(fans[0].closed);
      EXPECT_EQ(fans[0].faces.size(), b.mesh.vertex_faces(v).size());
      expect_ccw_fan(b.mesh, v, fans[0]);
    }
  }
}

TEST(VetMesh, OpenFanAndBowTie) {
  VetMesh m;
  // A fan of three triangles around 0 (open), then a second fan touching only at 0.
  m.insert_face({0, 1, 2});
  m.insert_face({0, 2, 3});
  m.insert_face({0, 3, 4});
  auto fans = m.vertex_fans(0);
  ASSERT_EQ(fans.size(), 1u);
  EXPECT_FALSE(fans[0].closed);
  EXPECT_EQ(fans[0].rim, (std::vector<std::uint32_t>{1, 2, 3, 4}));
  expect_ccw_fan(m, 0, fans[0]);
  m.insert_face({0, 5, 6});
  fans = m.vertex_fans(0);
  ASSERT_EQ(fans.size(), 2u);
  for (const auto& f : fans) expect_ccw_fan(m, 0, f);
  // Closing the first fan: the ring 1 2 3 4 and back to 1.
  m.insert_face({0, 4, 1});
  fans = m.vertex_fans(0);
  ASSERT_EQ(fans.size(), 2u);
  EXPECT_TRUE(fans[0].closed != fans[1].closed);
  // Isolated vertex: no fans.
  const std::uint32_t lone = m.insert_vertex();
  EXPECT_TRUE(m.vertex_fans(lone).empty());
  EXPECT_TRUE(m.remove_vertex(lone));
  EXPECT_FALSE(m.has_vertex(lone));
  EXPECT_FALSE(m.remove_vertex(0));  // has edges
}

TEST(VetMesh, FlipFaceReversesAndKeepsAdjacency) {
  VetMesh m;
  const std::uint32_t f = m.insert_face({0, 1, 2, 3});
  m.insert_face({1, 0, 4});
  const std::uint32_t e = m.find_edge(0, 1);
  EXPECT_TRUE(m.face_uses_edge_forward(f, e));
  m.flip_face(f);
  const auto c = m.face_vertices(f);
  EXPECT_EQ(std::vector<std::uint32_t>(c.begin(), c.end()),
            (std::vector<std::uint32_t>{3, 2, 1, 0}));
  EXPECT_FALSE(m.face_uses_edge_forward(f, e));
  EXPECT_EQ(m.edge_face_count(e), 2u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(m.face_edges(f)[i], m.find_edge(c[i], c[(i + 1) % 4]));
}

template <class T>
class VetMeshConvert : public ::testing::Test {};
TYPED_TEST_SUITE(VetMeshConvert, locus_test::RealTypes);

TYPED_TEST(VetMeshConvert, RoundTripAndStatuses) {
  using T = TypeParam;
  locus::PolygonMesh<T> pm = locus::dodecahedron_mesh<T>();
  pm.vertices.push_back({5, 5, 5});  // an isolated vertex
  locus::VetMeshBuild b = locus::make_vet_mesh(pm);
  ASSERT_EQ(b.status, Status::ok);
  EXPECT_EQ(b.mesh.vertex_count(), 21u);
  EXPECT_EQ(b.mesh.vertex_edge_count(20), 0u);
  EXPECT_EQ(b.mesh.edge_count(), 30u);
  const locus::PolygonMesh<T> back =
      locus::to_polygon_mesh(b.mesh, std::span<const locus::Vec3<T>>(pm.vertices));
  EXPECT_EQ(back.face_offsets, pm.face_offsets);
  EXPECT_EQ(back.face_indices, pm.face_indices);
  // Empty, repeated index (face skipped), out of range, too short, bad offsets.
  EXPECT_EQ(locus::make_vet_mesh(locus::PolygonMesh<T>{}).status, Status::empty_input);
  locus::PolygonMesh<T> rep = pm;
  const std::array<std::uint32_t, 3> bad{0, 1, 0};
  locus::add_face(rep, std::span<const std::uint32_t>(bad));
  locus::add_face(rep, std::span<const std::uint32_t>(pm.face_indices).subspan(0, 5));
  b = locus::make_vet_mesh(rep);
  EXPECT_EQ(b.status, Status::degenerate_input);
  EXPECT_EQ(b.face_ids[12], npos);
  EXPECT_EQ(b.face_ids[13], 12u);
  locus::PolygonMesh<T> out = pm;
  out.face_indices[3] = 99;
  EXPECT_EQ(locus::make_vet_mesh(out).status, Status::invalid_input);
  locus::PolygonMesh<T> shortf = pm;
  const std::array<std::uint32_t, 2> two{0, 1};
  locus::add_face(shortf, std::span<const std::uint32_t>(two));
  EXPECT_EQ(locus::make_vet_mesh(shortf).status, Status::invalid_input);
  locus::PolygonMesh<T> offs = pm;
  offs.face_offsets.back() += 1;
  EXPECT_EQ(locus::make_vet_mesh(offs).status, Status::invalid_input);
}

}  // namespace
