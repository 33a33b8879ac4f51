// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus surfacehit --bezier` (tools/locus/cmd_surfacehit.cpp, docs/cli.md):
// the hit parameters of rays on a Bézier patch equal the library's intersection(Ray3,
// BezierPatch) bit for bit (numbers print in the shortest form that reads back exactly); a ray in
// the planar patch prints on_surface; a malformed net is a usage error (exit 2).

#include <locus/intersection/ray_surface.hpp>

#ifndef LOCUS_CLI_PATH
#error "LOCUS_CLI_PATH (the locus tool) is not defined"
#endif
#include "support/files.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<std::vector<std::string>> lines(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '#') continue;
    std::istringstream w(line);
    std::vector<std::string> ws;
    for (std::string s; w >> s;) ws.push_back(s);
    if (!ws.empty()) out.push_back(ws);
  }
  return out;
}

double to_double(const std::string& s) {
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  EXPECT_TRUE(r.ec == std::errc() && r.ptr == s.data() + s.size()) << "not a number: " << s;
  return v;
}

TEST(CliSurfacehit, BezierPatchMatchesTheLibrary) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_cli_surfacehit_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string rays = (dir / "rays.csv").string(), out = (dir / "out.txt").string();
  {
    std::ofstream f(rays);
    f << "ox,oy,oz,dx,dy,dz\n0.3,0.4,2,0,0,-1\n0.5,-1,0,0,1,0\n5,5,2,0,0,-1\n0.2,0.9,-1,0.3,-0.5,"
         "1\n";
  }
  // A biquadratic bump over the unit square, control net row-major.
  const locus::BezierPatch<double, 3> bump{3,
                                           3,
                                           {{0, 0, 0},
                                            {0, 0.5, 0},
                                            {0, 1, 0},
                                            {0.5, 0, 0},
                                            {0.5, 0.5, 1},
                                            {0.5, 1, 0},
                                            {1, 0, 0},
                                            {1, 0.5, 0},
                                            {1, 1, 0}}};
  std::ostringstream nets;
  nets.precision(17);
  nets << "3,3";
  for (const auto& c : bump.control) nets << ',' << c.x << ',' << c.y << ',' << c.z;
  const std::string net = nets.str();
  const auto run = [&](const std::string& args) {
    const std::string cmd = std::string("'") + LOCUS_CLI_PATH + "' surfacehit '" + rays + "' " +
                            args + " >'" + out + "' 2>/dev/null";
    const int s = std::system(cmd.c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  };
  ASSERT_EQ(run("--bezier " + net), 0);
  const auto got = lines(locus_test::slurp(out));
  ASSERT_EQ(got.size(), 4u);
  const locus::Ray3d r[4] = {{{0.3, 0.4, 2}, {0, 0, -1}},
                             {{0.5, -1, 0}, {0, 1, 0}},
                             {{5, 5, 2}, {0, 0, -1}},
                             {{0.2, 0.9, -1}, {0.3, -0.5, 1}}};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto h = locus::intersection(r[i], bump);
    ASSERT_EQ(to_double(got[i][0]), double(h.hits.size())) << i;
    for (std::size_t k = 0; k < h.hits.size(); ++k) {
      EXPECT_EQ(to_double(got[i][1 + 2 * k]), h.hits[k].t);
      EXPECT_EQ(got[i][2 + 2 * k], h.hits[k].tangent ? "2" : "1");
    }
  }
  EXPECT_EQ(got[0][0], "1");  // straight down onto the bump
  EXPECT_EQ(got[1][0], "2");  // along y at height 0: crosses the bump at its two boundary edges
  EXPECT_EQ(got[2][0], "0");  // misses
  // A ray in a planar patch.
  ASSERT_EQ(run("--bezier 2,2,0,-2,0,0,2,0,1,-2,0,1,2,0"), 0);
  const auto flat = lines(locus_test::slurp(out));
  ASSERT_EQ(flat.size(), 4u);
  EXPECT_EQ(flat[1][0], "on_surface");
  // Malformed nets.
  EXPECT_EQ(run("--bezier 2,2,0,0,0"), 2);
  EXPECT_EQ(run("--bezier 0,2"), 2);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
