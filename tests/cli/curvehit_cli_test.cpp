// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus curvehit` (tools/locus/cmd_curvehit.cpp, docs/cli.md): the command's
// hits for a line, a segment, a B-spline and a second curve equal the library's intersection()
// bit for bit (numbers print in the shortest form that reads back exactly); bad input fails.

#include <locus/intersection/curve_curve.hpp>
#include <locus/intersection/curve_self.hpp>
#include <locus/intersection/line_curve.hpp>
#include <locus/intersection/segment_curve.hpp>
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
using locus::Vec2d;

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

void expect_same(const std::vector<std::vector<std::string>>& out,
                 const locus::CurveHits2<double>& r) {
  ASSERT_EQ(out.size(), 1 + r.hits.size());
  EXPECT_EQ(out[0][1], std::string(locus::to_string(r.kind)));
  for (std::size_t i = 0; i < r.hits.size(); ++i) {
    const auto& w = out[1 + i];
    ASSERT_EQ(w.size(), 6u);
    EXPECT_EQ(to_double(w[1]), r.hits[i].point.x);
    EXPECT_EQ(to_double(w[2]), r.hits[i].point.y);
    EXPECT_EQ(to_double(w[3]), r.hits[i].param_a);
    EXPECT_EQ(to_double(w[4]), r.hits[i].param_b);
    EXPECT_EQ(std::stoi(w[5]), r.hits[i].multiplicity);
  }
}

TEST(CliCurvehit, MatchesTheLibrary) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_cli_curvehit_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<Vec2d> a{{-3, -1}, {-1, 3}, {1, -3}, {3, 1}};
  const std::vector<Vec2d> b{{-3, 2}, {-1, -4}, {2, 4}, {3, -2}};
  const std::string fa = (dir / "a.csv").string(), fb = (dir / "b.csv").string();
  ASSERT_EQ((locus::write_points<double, 2>(fa, a).status), locus::Status::ok);
  ASSERT_EQ((locus::write_points<double, 2>(fb, b).status), locus::Status::ok);
  int status = 0;
  const auto run = [&](const std::string& args) {
    const std::string out = (dir / "out.txt").string();
    const std::string cmd = std::string("'") + LOCUS_CLI_PATH + "' curvehit '" + fa + "' " + args +
                            " >'" + out + "' 2>/dev/null";
    status = std::system(cmd.c_str());
    return lines(locus_test::slurp(out));
  };
  const locus::BezierCurve2<double> ca{a}, cb{b};
  const auto l = run("--line -3.5 -0.35 1 0.1");
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  expect_same(l, locus::intersection(locus::Line2d{{-3.5, -0.35}, {1, 0.1}}, ca));
  locus::CurveHitOptions raster;
  raster.method = locus::CurveMethod::raster;
  raster.raster_cells = 64;
  expect_same(run("--segment -3.5 -0.35 1 0.1 --method raster --cells 64"),
              locus::intersection(locus::Segment2d{{-3.5, -0.35}, {1, 0.1}}, ca, raster));
  expect_same(run("--other '" + fb + "'"), locus::intersection(ca, cb));
  // The same points as a clamped cubic B-spline with one span (knots 0 0 0 0 1 1 1 1).
  const locus::BSplineCurve2<double> spline{3, a, {0, 0, 0, 0, 1, 1, 1, 1}};
  expect_same(run("--degree 3 --knots 0 0 0 0 1 1 1 1 --line 0 -4 0.1 1"),
              locus::intersection(locus::Line2d{{0, -4}, {0.1, 1}}, spline));
  locus::CurveHitOptions resultant;
  resultant.method = locus::CurveMethod::resultant;
  const auto rl = run("--other '" + fb + "' --method resultant");
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  expect_same(rl, locus::intersection(ca, cb, resultant));
  // A cubic with a loop: its double point.
  const std::vector<Vec2d> loop{{0, 0}, {4, 3}, {-1, 3}, {3, 0}};
  const std::string fl = (dir / "loop.csv").string();
  ASSERT_EQ((locus::write_points<double, 2>(fl, loop).status), locus::Status::ok);
  const std::string out = (dir / "self.txt").string();
  status = std::system((std::string("'") + LOCUS_CLI_PATH + "' curvehit '" + fl + "' --self >'" +
                        out + "' 2>/dev/null")
                           .c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const auto self = locus::self_intersection(locus::BezierCurve2<double>{loop});
  ASSERT_EQ(self.hits.size(), 1u);
  expect_same(lines(locus_test::slurp(out)), self);
  // Bad input: no second object, a bad method, knots without a degree, --self with another.
  run("");
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  run("--line 0 0 1 0 --method guess");
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  run("--knots 0 1 --line 0 0 1 0");
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  run("--self --line 0 0 1 0");
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
