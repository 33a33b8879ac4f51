// SPDX-License-Identifier: BSL-1.0
// Tests for core/status.hpp: every Status has its own lower-case name (the messages of results
// and the CLI print them), out-of-range values are named "unknown" rather than read past the
// switch, and Side orders outside < boundary < inside (callers compare sides by sign).
#include <locus/core/side.hpp>
#include <locus/core/status.hpp>

#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>

using namespace locus;

TEST(Status, EveryValueHasADistinctLowerCaseName) {
  // The enumerators are contiguous from ok to limit_exceeded: walk them all by value so that a
  // new enumerator without a name shows up here as "unknown".
  std::set<std::string> names;
  const int last = int(Status::limit_exceeded);
  for (int v = 0; v <= last; ++v) {
    const std::string_view name = to_string(Status(v));
    EXPECT_NE(name, "unknown") << v;
    EXPECT_FALSE(name.empty()) << v;
    for (char c : name)
      EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || c == '_') << name;
    names.insert(std::string(name));
  }
  EXPECT_EQ(int(names.size()), last + 1);
  EXPECT_EQ(to_string(Status::ok), "ok");
  EXPECT_EQ(to_string(Status::non_finite_input), "non_finite_input");
  EXPECT_EQ(to_string(Status(last + 1)), "unknown");
  EXPECT_EQ(to_string(Status(255)), "unknown");
  static_assert(to_string(Status::parse_error) == "parse_error");  // usable at compile time
}

TEST(Status, SideIsOrderedBySign) {
  EXPECT_LT(int(Side::outside), int(Side::boundary));
  EXPECT_LT(int(Side::boundary), int(Side::inside));
  EXPECT_EQ(int(Side::boundary), 0);
  EXPECT_EQ(-int(Side::inside), int(Side::outside));
}
