// SPDX-License-Identifier: BSL-1.0
// The gallery: every figure computes successfully, has a caption from the embedded figures.txt,
// and renders to a well-formed SVG (strict XML parse, no nan/inf text, every coordinate inside
// the document, at least a few drawn elements); run() writes every file and an index listing
// each of them.

// gallery.hpp is on the include path only when gallery/CMakeLists.txt links locus_gallery_lib
// into this test (LOCUS_BUILD_GALLERY=ON); otherwise the test reports itself skipped.
#if __has_include("gallery.hpp")
#include "gallery.hpp"
#include "io/svg_xml.hpp"
#define LOCUS_HAVE_GALLERY 1
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#ifndef LOCUS_HAVE_GALLERY
TEST(Gallery, Skipped) { GTEST_SKIP() << "configure with -DLOCUS_BUILD_GALLERY=ON"; }
#else
namespace {

using namespace svg_test;

TEST(Gallery, FiguresAreUniqueCaptionedAndInBookOrder) {
  const auto figs = locus_gallery::all_figures();
  EXPECT_GE(figs.size(), 40u);
  std::set<std::string> ids;
  std::pair<int, int> prev{0, 0};
  for (const auto& f : figs) {
    SCOPED_TRACE(f.id);
    EXPECT_TRUE(ids.insert(f.id).second) << "duplicate figure";
    EXPECT_TRUE(locus_gallery::caption(f.id).has_value()) << "no caption in figures.txt";
    EXPECT_NE(std::string(f.computed_with), "");
    const auto order = locus_gallery::figure_order(f.id);
    ASSERT_GE(order.first, 0) << "malformed figure id";
    EXPECT_LT(prev, order);
    prev = order;
    std::string expected_name = std::string("fig_") + f.id + ".svg";
    std::replace(expected_name.begin(), expected_name.end(), '.', '_');
    expected_name.replace(expected_name.size() - 4, 1, ".");
    EXPECT_EQ(locus_gallery::file_name(f.id), expected_name);
  }
  EXPECT_EQ(locus_gallery::caption("3.15").value_or(""), "Angle between vectors.");
  EXPECT_FALSE(locus_gallery::caption("99.1").has_value());
  EXPECT_LT(locus_gallery::figure_order("15.9"), locus_gallery::figure_order("A.2"));
  EXPECT_LT(locus_gallery::figure_order("3.9"), locus_gallery::figure_order("3.10"));
  EXPECT_EQ(locus_gallery::figure_order("x"), std::make_pair(-1, -1));
  EXPECT_EQ(locus_gallery::figure_order("3."), std::make_pair(-1, -1));
}

TEST(Gallery, EveryFigureRendersAWellFormedSvg) {
  for (const auto& f : locus_gallery::all_figures()) {
    SCOPED_TRACE(f.id);
    const locus_gallery::Rendered r = locus_gallery::render(f);
    EXPECT_TRUE(r.ok) << "a locus computation failed";
    const Node root = parse_or_fail(r.svg);
    const double W = num(root, "width"), H = num(root, "height");
    std::size_t drawn = 0;
    for (const Node* n : elements(root)) {
      // No attribute (coordinates, sizes, transforms) spells a non-finite number; text content
      // may ("infinitely many solutions").
      for (const auto& [key, value] : n->attrs) {
        std::string v = value;
        std::transform(v.begin(), v.end(), v.begin(), [](char ch) {
          return static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        });
        EXPECT_EQ(v.find("nan"), std::string::npos) << n->tag << " " << key << "=" << value;
        EXPECT_EQ(v.find("inf"), std::string::npos) << n->tag << " " << key << "=" << value;
      }
      if (n->tag == "title" || n->tag == "g") continue;
      ++drawn;
      for (const Vec2d& q : covered_points(*n)) {
        EXPECT_GE(q.x, -kPx) << n->tag;
        EXPECT_LE(q.x, W + kPx) << n->tag;
        EXPECT_GE(q.y, -kPx) << n->tag;
        EXPECT_LE(q.y, H + kPx) << n->tag;
      }
    }
    EXPECT_GE(drawn, 4u);  // background plus at least three items
    const auto titles = elements(root, "title");
    ASSERT_EQ(titles.size(), 1u);
    EXPECT_NE(titles[0]->text.find(std::string("Figure ") + f.id + ":"), std::string::npos);
  }
}

TEST(Gallery, RunWritesEveryFileAndTheIndex) {
  std::random_device rd;
  const auto dir =
      std::filesystem::temp_directory_path() / ("locus_gallery_test_" + std::to_string(rd()));
  const locus_gallery::RunResult r = locus_gallery::run(dir.string());
  EXPECT_EQ(r.status, locus::Status::ok);
  EXPECT_TRUE(r.errors.empty());
  const auto figs = locus_gallery::all_figures();
  EXPECT_EQ(r.written, static_cast<int>(figs.size()));
  std::ifstream index(dir / "index.html");
  std::stringstream ss;
  ss << index.rdbuf();
  const std::string html = ss.str();
  for (const auto& f : figs) {
    const std::string name = locus_gallery::file_name(f.id);
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    EXPECT_GT(std::filesystem::file_size(dir / name), 200u) << name;
    EXPECT_NE(html.find("src=\"" + name + "\""), std::string::npos) << name;
  }
  // The index states how many of the book's figures it shows, counted from the figures drawn, and
  // lists the chapters they come from (chapter 13 is among them today).
  EXPECT_NE(html.find("<p>" + std::to_string(figs.size()) + " of the book's "), std::string::npos);
  EXPECT_NE(html.find("figures, from chapters 2, 3"), std::string::npos);
  EXPECT_NE(html.find(", 13"), std::string::npos);
  std::filesystem::remove_all(dir);

  // An output directory that cannot be created is an io_error, not a crash.
  const auto blocker =
      std::filesystem::temp_directory_path() / ("locus_gallery_file_" + std::to_string(rd()));
  std::ofstream(blocker) << "x";
  const locus_gallery::RunResult bad = locus_gallery::run((blocker / "sub").string());
  EXPECT_EQ(bad.status, locus::Status::io_error);
  EXPECT_EQ(bad.written, 0);
  std::filesystem::remove(blocker);
}

}  // namespace
#endif
