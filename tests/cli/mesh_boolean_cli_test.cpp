// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus mesh boolean` (tools/locus/cmd_mesh_boolean.cpp, docs/cli.md): the
// built binary on two OFF boxes written here (quad faces, fanned by the tool) must write the
// library's result bit for bit, whose volume is the known exact one; a bad --op exits 2, a
// NaN coordinate exits 1.

#include <locus/bsp/bsp3_boolean.hpp>
#include <locus/io/mesh_io.hpp>

#include "support/cli_run.hpp"
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using locus_test::CliRun;
using locus_test::run_locus;

/// The box [lo, lo + size] as an OFF file of six quads, outward.
void write_box(const fs::path& p, double lo, double size, bool nan = false) {
  std::ofstream f(p);
  f << "OFF\n8 6 0\n";
  for (int i = 0; i < 8; ++i) {
    f << ((i & 1) ? lo + size : lo) << ' ' << ((i & 2) ? lo + size : lo) << ' ';
    if (nan && i == 7)
      f << "nan\n";
    else
      f << ((i & 4) ? lo + size : lo) << '\n';
  }
  f << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
}

std::vector<std::array<std::uint32_t, 3>> fan(const locus::PolygonMesh<double>& m) {
  std::vector<std::array<std::uint32_t, 3>> t;
  for (std::size_t f = 0; f + 1 < m.face_offsets.size(); ++f)
    for (std::uint32_t k = m.face_offsets[f] + 1; k + 1 < m.face_offsets[f + 1]; ++k)
      t.push_back({m.face_indices[m.face_offsets[f]], m.face_indices[k], m.face_indices[k + 1]});
  return t;
}

TEST(MeshBooleanCli, WritesTheLibraryResult) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_mesh_boolean_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_box(dir / "a.off", 0, 2);
  write_box(dir / "b.off", 1, 2);
  const auto a = locus::read_mesh<double>(dir / "a.off"),
             b = locus::read_mesh<double>(dir / "b.off");
  ASSERT_EQ(a.status, locus::Status::ok);
  const auto ta = fan(a.mesh), tb = fan(b.mesh);
  const std::pair<const char*, locus::MeshBooleanOp> ops[] = {
      {"union", locus::MeshBooleanOp::union_},
      {"intersection", locus::MeshBooleanOp::intersection},
      {"difference", locus::MeshBooleanOp::difference},
      {"xor", locus::MeshBooleanOp::symmetric_difference}};
  const char* volumes[] = {"volume 15\n", "volume 1\n", "volume 7\n", "volume 14\n"};
  for (int i = 0; i < 4; ++i) {
    const fs::path out = dir / (std::string(ops[i].first) + ".off");
    const CliRun r = run_locus(dir, std::string("mesh boolean --op ") + ops[i].first + " '" +
                                        (dir / "a.off").string() + "' '" +
                                        (dir / "b.off").string() + "' -o '" + out.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find(volumes[i]), std::string::npos) << r.out;
    const auto got = locus::read_mesh<double>(out);
    ASSERT_EQ(got.status, locus::Status::ok);
    const auto want =
        locus::mesh_boolean<double>(ops[i].second, a.mesh.vertices, ta, b.mesh.vertices, tb);
    EXPECT_EQ(got.mesh.vertices, want.vertices);
    EXPECT_EQ(fan(got.mesh), want.triangles);
  }
  const CliRun bad =
      run_locus(dir, "mesh boolean --op nand '" + (dir / "a.off").string() + "' '" +
                         (dir / "b.off").string() + "' -o '" + (dir / "x.off").string() + "'");
  EXPECT_EQ(bad.code, 2);
  write_box(dir / "nan.off", 0, 1, true);
  const CliRun nan =
      run_locus(dir, "mesh boolean --op union '" + (dir / "a.off").string() + "' '" +
                         (dir / "nan.off").string() + "' -o '" + (dir / "y.off").string() + "'");
  EXPECT_EQ(nan.code, 1);
  EXPECT_FALSE(nan.err.empty());
  fs::remove_all(dir);
}

}  // namespace
