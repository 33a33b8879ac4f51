// SPDX-License-Identifier: BSL-1.0
// End-to-end test of `locus construct` (tools/locus/cmd_construct.cpp, docs/cli.md): the printed
// solutions equal the library's, bit for bit (numbers print in the shortest exact form), and a
// bad radius exits 1 with one stderr line.

#include <locus/construct/circles_of_radius.hpp>
#include <locus/construct/tangent_lines.hpp>

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

struct Outcome {
  int code = -1;
  std::string out, err;
};

Outcome run(const std::string& args) {
  const fs::path dir =
      fs::temp_directory_path() / ("locus_construct_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
  const std::string cmd =
      std::string("'") + LOCUS_CLI_PATH + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int s = std::system(cmd.c_str());
  Outcome r{WIFEXITED(s) ? WEXITSTATUS(s) : -1, locus_test::slurp(out), locus_test::slurp(err)};
  fs::remove_all(dir);
  return r;
}

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::vector<double>> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) {
      double v = 0;
      std::from_chars(c.data(), c.data() + c.size(), v);
      row.push_back(v);
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(CliConstruct, MatchesTheLibrary) {
  const Outcome t = run("construct tangent-2circles 0 0 2 6 8 3");
  ASSERT_EQ(t.code, 0) << t.err;
  const auto lines = locus::tangent_lines(locus::Circle2d{{0, 0}, 2}, locus::Circle2d{{6, 8}, 3});
  const auto rows = csv_rows(t.out);
  ASSERT_EQ(static_cast<int>(rows.size()), lines.count);
  for (int i = 0; i < lines.count; ++i) {
    const auto& l = lines.item[static_cast<std::size_t>(i)];
    EXPECT_EQ(rows[std::size_t(i)],
              (std::vector<double>{l.origin.x, l.origin.y, l.direction.x, l.direction.y}));
  }
  const Outcome c = run("construct circle-pt-circle-r -- -1 4 1 1 1 3");
  ASSERT_EQ(c.code, 0) << c.err;
  const auto circles =
      locus::circles_of_radius(locus::Vec2d{-1, 4}, locus::Circle2d{{1, 1}, 1}, 3.0);
  const auto crow = csv_rows(c.out);
  ASSERT_EQ(static_cast<int>(crow.size()), circles.count);
  for (int i = 0; i < circles.count; ++i) {
    const auto& k = circles.item[static_cast<std::size_t>(i)];
    EXPECT_EQ(crow[std::size_t(i)], (std::vector<double>{k.center.x, k.center.y, k.radius}));
  }
}

TEST(CliConstruct, BadInputExitsOne) {
  const Outcome r = run("construct circle-2pts-r 0 0 1 1 0");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("degenerate_input"), std::string::npos);
  EXPECT_EQ(run("construct circle3pts 0 0 1").code, 2);
}

}  // namespace
