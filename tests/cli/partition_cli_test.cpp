// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus partition` (tools/locus/cmd_partition.cpp, docs/cli.md): the built
// binary on a WKT file written here must print the library's convex pieces (one piece per line,
// indices in file order), for both methods; a self-crossing ring exits 1 with a message.

#include <locus/triangulate/convex_partition.hpp>

#include "support/cli_run.hpp"
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using locus_test::CliRun;
using locus_test::run_locus;

std::vector<std::vector<std::uint32_t>> rows(const std::string& text) {
  std::vector<std::vector<std::uint32_t>> r;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream l(line);
    r.emplace_back();
    for (std::uint32_t v; l >> v;) r.back().push_back(v);
  }
  return r;
}

TEST(PartitionCli, PiecesMatchTheLibrary) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_partition_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Two polygons: a comb without holes, then a square with a square hole (hm only).
  const std::vector<locus::Vec2d> comb{{0, 0}, {6, 0}, {6, 3}, {5, 3}, {4, 1},
                                       {3, 3}, {2, 1}, {1, 3}, {0, 3}};
  {
    std::ofstream f(dir / "comb.wkt");
    f << "POLYGON ((0 0, 6 0, 6 3, 5 3, 4 1, 3 3, 2 1, 1 3, 0 3, 0 0))\n";
  }
  const std::uint32_t ends[] = {9};
  for (const std::string method : {"hm", "min"}) {
    const auto lib = method == "min" ? locus::min_convex_partition(comb, ends)
                                     : locus::convex_partition(comb, ends);
    ASSERT_EQ(lib.status, locus::Status::ok);
    std::vector<std::vector<std::uint32_t>> expected;
    std::uint32_t b = 0;
    for (const std::uint32_t e : lib.piece_ends) {
      expected.emplace_back(lib.vertices.begin() + b, lib.vertices.begin() + e);
      b = e;
    }
    const CliRun r = run_locus(dir, "partition " + (dir / "comb.wkt").string() + " --method " +
                                        method + " --svg " + (dir / "p.svg").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(rows(r.out), expected) << method;
    EXPECT_NE(locus_test::slurp((dir / "p.svg").string()).find("<svg"), std::string::npos);
  }
  {
    std::ofstream f(dir / "bow.wkt");
    f << "POLYGON ((0 0, 2 2, 2 0, 1 0.5, 0 2, 0 0))\n";
  }
  const CliRun bad = run_locus(dir, "partition " + (dir / "bow.wkt").string() + " --method min");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("invalid_topology"), std::string::npos) << bad.err;
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
