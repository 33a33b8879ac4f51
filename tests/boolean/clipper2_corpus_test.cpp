// SPDX-License-Identifier: BSL-1.0
// The 195 boolean cases of Clipper2's Tests/Polygons.txt (tests/data/corpus/clipper2): every
// output must pass the independent validity checker, and its area must match SOL_AREA within the
// tolerance Clipper2's own test (TestPolygons.cpp) gives: 1% by default, 50% for cases 19, 22,
// 23, 24, 20% for 193, 10% for 63, 7.5% for 16, 5% for 26, 2% for 15, 52, 53, 54, 59, 60, 64,
// 117, 119, 184 (case 44 is checked against the exact area instead; see below). Ring counts are
// reported, not asserted: Clipper2 counts its own output convention (it keeps touching rings joined
// where locus splits them).

#include <locus/boolean/polygon_boolean.hpp>

#include <support/corpus.hpp>
#include <support/files.hpp>
#include <support/polygon_validity.hpp>
#include <support/sanitizer.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace {

TEST(PolygonBooleanCorpus, Clipper2PolygonsAreValidWithExpectedAreas) {
  const std::string text =
      locus_test::slurp(std::string(LOCUS_SHARED_DIR) + "/corpus/clipper2/tests/Polygons.txt");
  ASSERT_FALSE(text.empty());
  const std::vector<locus_test::Clipper2Case> cases = locus_test::read_clipper2_cases(text);
  ASSERT_EQ(cases.size(), 195u);
  int valid = 0, area_checked = 0, area_ok = 0, count_checked = 0, count_equal = 0;
  // The optimised run checks every case. The sanitizer build (-O0, 20-40 times slower) checks
  // the 132 cases of at most 64 input vertices, which hold every clip type and fill rule, and one
  // of the 63 random cases of 100-200 vertices (case 147: 100 vertices, 1133 output vertices);
  // the others, more of Clipper2's random polygons (other seeds, sizes, clip types and fill rules,
  // all of which the small cases hold), take about a second each there, most of it in the
  // quadratic validity checker.
  int checked = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::size_t input_vertices = 0;
    for (const auto* set : {&cases[k].subjects, &cases[k].clips})
      for (const auto& ring : *set) input_vertices += ring.vertices.size();
    if (locus_test::kSanitizerBuild && input_vertices > 64 && cases[k].id != 147) continue;
    ++checked;
    const locus_test::Clipper2Case& c = cases[k];
    SCOPED_TRACE("case " + std::to_string(c.id));
    const locus_test::Clipper2Boolean b = locus_test::clipper2_boolean(c);
    const auto res = locus::boolean_op<double>(b.op, b.subjects, b.clips, {b.rule, 0});
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
                                 : std::abs(area - c.sol_area) <=
                                       locus_test::clipper2_area_tolerance(c.id) * c.sol_area;
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
      "clipper2 corpus: %d/%d valid, areas %d/%d within tolerance, ring counts %d/%d "
      "equal\n",
      valid, checked, area_ok, area_checked, count_equal, count_checked);
}

}  // namespace
