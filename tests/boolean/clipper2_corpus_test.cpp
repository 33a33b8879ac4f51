// SPDX-License-Identifier: BSL-1.0
// The 195 boolean cases of Clipper2's Tests/Polygons.txt (tests/data/corpus/clipper2): every
// output must pass the independent validity checker, and its area must match SOL_AREA within the
// tolerance Clipper2's own test (TestPolygons.cpp) gives: 1% by default, 50% for cases 19, 22,
// 23, 24, 20% for 193, 10% for 63, 7.5% for 16, 5% for 26, 2% for 15, 52, 53, 54, 59, 60, 64,
// 117, 119, 184 (case 44 is checked against the exact area instead; see below). Ring counts are
// reported, not asserted: Clipper2 counts its own output convention (it keeps touching rings joined
// where locus splits them).

#include <locus/boolean/polygon_boolean.hpp>

#include <support/files.hpp>
#include <support/polygon_validity.hpp>

#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using locus::BooleanOp;
using locus::FillRule;
using locus::Polygon2;

struct Case {
  int id = 0;
  std::string clip_type, fill_rule;
  double sol_area = 0;
  long sol_count = 0;
  std::vector<Polygon2<double>> subjects, clips;
};

std::vector<Case> read_cases(const std::string& text) {
  std::vector<Case> cases;
  std::istringstream in(text);
  std::string line;
  std::vector<Polygon2<double>>* target = nullptr;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto value = [&](const char* key) { return line.substr(std::string(key).size()); };
    if (line.rfind("CAPTION:", 0) == 0) {
      cases.emplace_back();
      cases.back().id = std::atoi(value("CAPTION:").c_str());
      target = nullptr;
    } else if (cases.empty()) {
      continue;
    } else if (line.rfind("CLIPTYPE:", 0) == 0) {
      std::istringstream(value("CLIPTYPE:")) >> cases.back().clip_type;
    } else if (line.rfind("FILLRULE:", 0) == 0) {
      std::istringstream(value("FILLRULE:")) >> cases.back().fill_rule;
    } else if (line.rfind("SOL_AREA:", 0) == 0) {
      cases.back().sol_area = std::atof(value("SOL_AREA:").c_str());
    } else if (line.rfind("SOL_COUNT:", 0) == 0) {
      cases.back().sol_count = std::atol(value("SOL_COUNT:").c_str());
    } else if (line == "SUBJECTS") {
      target = &cases.back().subjects;
    } else if (line == "CLIPS") {
      target = &cases.back().clips;
    } else if (line.rfind("SUBJECTS_OPEN", 0) == 0) {
      target = nullptr;  // open paths: not part of polygon booleans
    } else if (target && !line.empty()) {
      for (char& c : line)
        if (c == ',') c = ' ';
      std::istringstream nums(line);
      Polygon2<double> ring;
      double x = 0, y = 0;
      while (nums >> x >> y) ring.vertices.push_back({x, y});
      if (!ring.vertices.empty()) target->push_back(ring);
    }
  }
  return cases;
}

double tolerance(int id) {
  static const std::map<int, double> loose = {
      {19, 0.5},   {22, 0.5},  {23, 0.5},  {24, 0.5},   {193, 0.2},  {63, 0.1},
      {16, 0.075}, {26, 0.05}, {15, 0.02}, {52, 0.02},  {53, 0.02},  {54, 0.02},
      {59, 0.02},  {60, 0.02}, {64, 0.02}, {117, 0.02}, {119, 0.02}, {184, 0.02}};
  const auto it = loose.find(id);
  return it == loose.end() ? 0.01 : it->second;
}

TEST(PolygonBooleanCorpus, Clipper2PolygonsAreValidWithExpectedAreas) {
  const std::string text =
      locus_test::slurp(std::string(LOCUS_SHARED_DIR) + "/corpus/clipper2/tests/Polygons.txt");
  ASSERT_FALSE(text.empty());
  const std::vector<Case> cases = read_cases(text);
  ASSERT_EQ(cases.size(), 195u);
  int valid = 0, area_checked = 0, area_ok = 0, count_checked = 0, count_equal = 0;
  // The sanitized build checks every 20th case; the optimised run covers every case.
#if defined(__SANITIZE_ADDRESS__)
  const std::size_t stride = 20;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  const std::size_t stride = 20;
#else
  const std::size_t stride = 1;
#endif
#else
  const std::size_t stride = 1;
#endif
  for (std::size_t k = 0; k < cases.size(); k += stride) {
    const Case& c = cases[k];
    SCOPED_TRACE("case " + std::to_string(c.id));
    const BooleanOp op = c.clip_type == "UNION"          ? BooleanOp::union_
                         : c.clip_type == "INTERSECTION" ? BooleanOp::intersection
                         : c.clip_type == "DIFFERENCE"   ? BooleanOp::difference
                                                         : BooleanOp::symmetric_difference;
    std::vector<Polygon2<double>> subjects = c.subjects, clips = c.clips;
    FillRule rule = FillRule::even_odd;
    if (c.fill_rule == "NONZERO") rule = FillRule::non_zero;
    if (c.fill_rule == "POSITIVE") rule = FillRule::positive;
    if (c.fill_rule == "NEGATIVE") {  // negative winding = positive winding of reversed rings
      rule = FillRule::positive;
      for (auto* set : {&subjects, &clips})
        for (auto& r : *set) std::reverse(r.vertices.begin(), r.vertices.end());
    }
    const auto res = locus::boolean_op<double>(op, subjects, clips, {rule, 0});
    ASSERT_EQ(res.status, locus::Status::ok) << res.message;
    const std::string why = locus_test::polygon_validity(res.polygons);
    EXPECT_EQ(why, "");
    valid += why.empty();
    const double area = locus_test::exact_area(res.polygons).get_d();
    if (c.sol_area > 0) {
      ++area_checked;
      // Case 44's SOL_AREA (272) is Clipper2's integer-rounded answer, 2.9% above the exact one;
      // the reference here is GEOS's area of the even-odd intersection (shapely, make_valid).
      const bool ok = c.id == 44 ? std::abs(area - 264.3829652753729) <= 1e-9 * area
                                 : std::abs(area - c.sol_area) <= tolerance(c.id) * c.sol_area;
      EXPECT_TRUE(ok) << "area " << area << " expected " << c.sol_area;
      area_ok += ok;
    }
    if (c.sol_count > 0) {
      ++count_checked;
      long rings = 0;
      for (const auto& p : res.polygons) rings += 1 + static_cast<long>(p.holes.size());
      count_equal += rings == c.sol_count;
    }
  }
  std::printf(
      "clipper2 corpus: %d/%zu valid, areas %d/%d within tolerance, ring counts %d/%d "
      "equal\n",
      valid, (cases.size() + stride - 1) / stride, area_ok, area_checked, count_equal,
      count_checked);
}

}  // namespace
