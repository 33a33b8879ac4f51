// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus sat3` (tools/locus/cmd_sat3.cpp, docs/cli.md): the command's output on
// two 3D point files equals the library's sat_test / first_contact over their hulls bit for bit
// (numbers print in the shortest form that reads back exactly).

#include <locus/hull/hull3.hpp>
#include <locus/intersection/sat.hpp>
#include <locus/io/point_list.hpp>

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
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using locus::Vec3d;

std::vector<std::vector<std::string>> lines(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
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

TEST(CliSat3, StationaryAndMovingMatchTheLibrary) {
  const fs::path dir = fs::temp_directory_path() / ("locus_cli_sat3_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<Vec3d> a{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1.2}};
  std::vector<Vec3d> b{{0.5, 0.5, 0.5}, {2, 0.3, 0.1}, {1.1, 2, 0.2}, {0.9, 0.8, 2}};
  const std::string fa = (dir / "a.csv").string(), fb = (dir / "b.csv").string();
  ASSERT_EQ((locus::write_points<double, 3>(fa, a).status), locus::Status::ok);
  ASSERT_EQ((locus::write_points<double, 3>(fb, b).status), locus::Status::ok);
  const auto run = [&](const std::string& args, int code = 0) {
    const std::string out = (dir / "out.txt").string();
    const std::string cmd = std::string("'") + LOCUS_CLI_PATH + "' sat3 '" + fa + "' --other '" +
                            fb + "' " + args + " >'" + out + "' 2>/dev/null";
    const int s = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(s) && WEXITSTATUS(s) == code) << cmd;
    return lines(locus_test::slurp(out));
  };
  const auto st = run("");
  ASSERT_EQ(st.size(), 1u);
  EXPECT_EQ(st[0][1], "yes");
  for (Vec3d& p : b) p += Vec3d{6, 0, 0};
  ASSERT_EQ((locus::write_points<double, 3>(fb, b).status), locus::Status::ok);
  EXPECT_EQ(run("")[0][1], "no");
  const auto ha = locus::convex_hull(a), hb = locus::convex_hull(b);
  const locus::ConvexMesh3<double> pa{a, ha.triangles}, pb{b, hb.triangles};
  const auto c = locus::first_contact(pa, Vec3d{0.5, 0, 0}, pb, Vec3d{-1, 0, 0}, 10.0);
  ASSERT_TRUE(static_cast<bool>(c));
  const auto mv = run("--va 0.5 0 0 --vb -1 0 0 --tmax 10");
  ASSERT_EQ(mv.size(), 2u + c.points.size());
  EXPECT_EQ(mv[0][1], std::string(locus::to_string(c.kind)));
  EXPECT_EQ(to_double(mv[1][1]), c.time);
  for (std::size_t i = 0; i < c.points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(to_double(mv[2 + i][1 + static_cast<std::size_t>(k)]), c.points[i][k]);
  // A collinear point set is not a polyhedron: exit 1.
  ASSERT_EQ((locus::write_points<double, 3>(fb, std::vector<Vec3d>{{0, 0, 0}, {1, 1, 1}}).status),
            locus::Status::ok);
  run("", 1);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
