// SPDX-License-Identifier: BSL-1.0
// Loading a 10^6-triangle mesh from a file (row mesh.io; issue 18 item 9): locus read_mesh<float>
// against Assimp::Importer::ReadFile (Debian libassimp-dev, when found), in one run, for OBJ,
// OFF, PLY ASCII, PLY binary, STL ASCII and STL binary.
// Input: a closed torus grid of 1000 x 500 quads split into 10^6 triangles (500 000 vertices,
// coordinates from sin/cos, so every number has its full digits), written once per format by
// locus::write_mesh into a temporary directory at start-up (STL stores 3 corners per triangle;
// both readers get the same files).
// Assimp runs with no post-processing step (flags 0: its cheapest load, which leaves STL as
// 3 unshared corners per triangle) and, for STL, also with aiProcess_JoinIdenticalVertices
// (assimp_join: the same indexed mesh locus returns, equal corners merged). Counters: Mtri/s (10^6
// triangles per second), peak_MB (largest heap growth during the load, every malloc of the process
// counted: support/heap_peak.hpp) and mesh_MB (the loaded PolygonMesh<float>'s own arrays: 12 bytes
// per vertex, 4 per index and per face offset), so peak_MB / mesh_MB is the memory overhead of a
// load.
//
// Build and run:
//   cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DLOCUS_BENCH_PEERS=ON
//   cmake --build build/bench -j1 --target locus_bench_io
//   build/bench/bench/locus_bench_io --benchmark_counters_tabular=true
// Results: bench/results/io.md.

#include <locus/io/mesh_io.hpp>

#include <benchmark/benchmark.h>

#include "support/heap_peak.hpp"

#include <unistd.h>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>

#if defined(LOCUS_HAVE_ASSIMP)
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>
#endif

namespace {

constexpr std::uint32_t nu = 1000, nv = 500;  // 2 * nu * nv = 10^6 triangles

locus::PolygonMesh<float> torus() {
  locus::PolygonMesh<float> m;
  m.vertices.reserve(std::size_t(nu) * nv);
  for (std::uint32_t i = 0; i < nu; ++i) {
    const double a = 2 * std::numbers::pi * i / nu;
    for (std::uint32_t j = 0; j < nv; ++j) {
      const double b = 2 * std::numbers::pi * j / nv;
      const double r = 3.0 + std::cos(b);
      m.vertices.push_back({float(r * std::cos(a)), float(r * std::sin(a)), float(std::sin(b))});
    }
  }
  const auto at = [](std::uint32_t i, std::uint32_t j) { return (i % nu) * nv + (j % nv); };
  m.face_indices.reserve(std::size_t(6) * nu * nv);
  m.face_offsets.reserve(std::size_t(2) * nu * nv + 1);
  for (std::uint32_t i = 0; i < nu; ++i) {
    for (std::uint32_t j = 0; j < nv; ++j) {
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      for (const std::uint32_t k : {a, b, c, a, c, d}) m.face_indices.push_back(k);
      m.face_offsets.push_back(std::uint32_t(m.face_indices.size() - 3));
      m.face_offsets.push_back(std::uint32_t(m.face_indices.size()));
    }
  }
  return m;
}

struct Files {
  std::filesystem::path dir;
  double mesh_mb = 0;
  Files() {
    dir = std::filesystem::temp_directory_path() /
          ("locus_bench_io_" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::create_directories(dir);
    const locus::PolygonMesh<float> m = torus();
    mesh_mb = double(m.vertices.size() * sizeof(m.vertices[0]) + m.face_indices.size() * 4 +
                     m.face_offsets.size() * 4) /
              (1024.0 * 1024.0);
    using F = locus::MeshFormat;
    const std::pair<const char*, F> out[] = {
        {"mesh.obj", F::obj},        {"mesh.off", F::off},
        {"ascii.ply", F::ply_ascii}, {"binary.ply", F::ply_binary_le},
        {"ascii.stl", F::stl_ascii}, {"binary.stl", F::stl_binary}};
    for (const auto& [name, format] : out) {
      const auto w = locus::write_mesh(dir / name, m, format);
      if (w.status != locus::Status::ok) {
        std::fprintf(stderr, "cannot write %s: %s\n", name, w.message.c_str());
        std::abort();
      }
    }
  }
  ~Files() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

const Files& files() {
  static const Files f;
  return f;
}

constexpr const char* names[] = {"mesh.obj",   "mesh.off",  "ascii.ply",
                                 "binary.ply", "ascii.stl", "binary.stl"};

void set_counters(benchmark::State& state, const locus::bench::HeapPeak& peak, std::size_t tris) {
  state.counters["Mtri/s"] = benchmark::Counter(double(tris) * double(state.iterations()) * 1e-6,
                                                benchmark::Counter::kIsRate);
  state.counters["mesh_MB"] = files().mesh_mb;
  state.counters["file_MB"] =
      double(std::filesystem::file_size(files().dir / names[state.range(0)])) / (1024.0 * 1024.0);
  locus::bench::report_heap_peak(state, peak);
}

void BM_locus_read(benchmark::State& state) {
  const std::filesystem::path path = files().dir / names[state.range(0)];
  std::size_t tris = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    const auto r = locus::read_mesh<float>(path);
    if (r.status != locus::Status::ok) {
      state.SkipWithError(r.message.c_str());
      return;
    }
    tris = locus::face_count(r.mesh);
    benchmark::DoNotOptimize(r.mesh.vertices.data());
  }
  set_counters(state, peak, tris);
}

#if defined(LOCUS_HAVE_ASSIMP)
void BM_assimp_read(benchmark::State& state) {
  const std::filesystem::path path = files().dir / names[state.range(0)];
  const unsigned flags = state.range(1) ? unsigned(aiProcess_JoinIdenticalVertices) : 0u;
  std::size_t tris = 0;
  locus::bench::HeapPeak peak;
  for (auto _ : state) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path.string(), flags);
    if (scene == nullptr) {
      state.SkipWithError(importer.GetErrorString());
      return;
    }
    tris = 0;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) tris += scene->mMeshes[k]->mNumFaces;
    benchmark::DoNotOptimize(scene);
  }
  set_counters(state, peak, tris);
}
#endif

// Names area/implementation/case (scripts/bench_table's convention): load/locus/mesh.obj, ...
const int registered = [] {
  for (int k = 0; k < 6; ++k) {
    benchmark::RegisterBenchmark((std::string("load/locus/") + names[k]).c_str(), BM_locus_read)
        ->Arg(k)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(3);
#if defined(LOCUS_HAVE_ASSIMP)
    benchmark::RegisterBenchmark((std::string("load/assimp/") + names[k]).c_str(), BM_assimp_read)
        ->Args({k, 0})
        ->Unit(benchmark::kMillisecond)
        ->Iterations(3);
    // STL stores corners: locus merges equal ones; Assimp does with JoinIdenticalVertices.
    if (k >= 4) {
      benchmark::RegisterBenchmark((std::string("load/assimp_join/") + names[k]).c_str(),
                                   BM_assimp_read)
          ->Args({k, 1})
          ->Unit(benchmark::kMillisecond)
          ->Iterations(3);
    }
#endif
  }
  return 0;
}();

}  // namespace
