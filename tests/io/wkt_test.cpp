// SPDX-License-Identifier: BSL-1.0
// Tests of io/wkt.hpp and io/geometry.hpp. Round trips write -> read compare bit for bit on
// random awkward coordinates (subnormals, huge, -0, random bit patterns). Texts in other tools'
// conventions (keyword case, white space, CRLF, Z/M/ZM, MULTIPOINT without parentheses,
// GEOMETRYCOLLECTION) are produced here by an independent writer (printf with max_digits10)
// from random geometries, which the reader must give back. Every malformed-input class has its
// expected status and position. The WKT of the JTS and Boost.Geometry suites in tests/data
// must parse. orient_rings() is checked against the exact (GMP) shoelace sign.

#include <locus/io/wkt.hpp>

#include "geo_support.hpp"
#include "support/corpus.hpp"
#include "support/files.hpp"
#include "support/sanitizer.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace {

using geo_test::all_types;
using geo_test::number;
using locus::Geometry2;
using locus::GeometryType;
using locus::Status;
using locus::Vec2;

template <class T>
class WktTest : public ::testing::Test {};
TYPED_TEST_SUITE(WktTest, locus_test::RealTypes);

using locus_test::slurp;

TYPED_TEST(WktTest, RoundTripIsBitExact) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int iter = 0; iter < 300; ++iter) {
    std::vector<Geometry2<T>> list;
    for (const GeometryType t : all_types) list.push_back(geo_test::random_geometry<T>(rng, t));
    std::string text;
    for (const auto& g : list) {
      const auto w = locus::write_wkt_string(g);
      ASSERT_EQ(w.status, Status::ok) << w.message;
      text += w.data + (iter % 2 ? "\r\n" : "\n");
    }
    const auto r = locus::parse_wkt<T>(text);
    ASSERT_EQ(r.status, Status::ok) << r.message << "\n" << text;
    ASSERT_EQ(locus_fuzz::same_geometries(list, r.geometries), "") << text;
  }
}

TYPED_TEST(WktTest, CanonicalText) {
  using T = TypeParam;
  Geometry2<T> g;
  g.type = GeometryType::polygon;
  g.polygons.push_back({{{0, 0}, {4, 0}, {0, 4}, {1, 1}, {1, 2}, {2, 1}}, {3, 6}});
  EXPECT_EQ(locus::write_wkt_string(g).data,
            "POLYGON ((0 0, 4 0, 0 4, 0 0), (1 1, 1 2, 2 1, 1 1))");
  g.type = GeometryType::multi_point;
  g.points = {{T(0.5), -T(0)}, {T(-1.25), T(3)}};
  EXPECT_EQ(locus::write_wkt_string(g).data, "MULTIPOINT ((0.5 -0), (-1.25 3))");
  for (const GeometryType t : all_types) {
    Geometry2<T> e;
    e.type = t;
    EXPECT_EQ(locus::write_wkt_string(e).data, std::string(locus::wkt_name(t)) + " EMPTY");
  }
}

// ---- an independent writer in other tools' styles -------------------------------------------

struct Style {
  int dims = 2;            // numbers per point written
  const char* tag = "";    // "", "Z", "M", "ZM"
  bool attached = false;   // POINTZ instead of POINT Z
  bool unwrapped = false;  // MULTIPOINT (1 2, 3 4)
};

class Writer {
 public:
  explicit Writer(locus_test::Rng& rng) : rng_(rng) {}
  std::string ws() {
    static const char* const pieces[] = {"", " ", "  ", "\t", "\r\n", "\n", " \r\n\t"};
    return pieces[rng_.uniform_int(0, 6)];
  }
  std::string keyword(std::string k) {
    for (char& c : k) {
      if (rng_.uniform_int(0, 1))
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return k;
  }
  template <class T>
  std::string point(const Vec2<T>& p, const Style& s) {
    std::string out = number(p.x) + " " + ws() + number(p.y);
    for (int k = 2; k < s.dims; ++k) out += " " + number(T(rng_.uniform_int(-9, 9)) / T(4));
    return out;
  }
  template <class T>
  std::string list(const std::vector<Vec2<T>>& v, const Style& s, bool close) {
    std::string out = "(" + ws();
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ws() + "," + ws() : "") + point(v[i], s);
    if (close) out += ws() + "," + ws() + point(v[0], s);
    return out + ws() + ")";
  }
  template <class T>
  std::string polygon(const locus::RingPolygon2<T>& p, const Style& s) {
    std::string out = "(" + ws();
    std::size_t begin = 0;
    for (std::size_t k = 0; k < p.ring_ends.size(); ++k) {
      const std::vector<Vec2<T>> ring(p.points.begin() + std::ptrdiff_t(begin),
                                      p.points.begin() + std::ptrdiff_t(p.ring_ends[k]));
      out += (k ? "," + ws() : "") + list(ring, s, true);
      begin = p.ring_ends[k];
    }
    return out + ws() + ")";
  }
  template <class T>
  std::string geometry(const Geometry2<T>& g, const Style& s) {
    std::string out = keyword(locus::wkt_name(g.type));
    if (*s.tag) out += (s.attached ? "" : " ") + keyword(s.tag);
    out += ws() + " ";
    if (g.empty()) return out + keyword("EMPTY");
    std::string body = "(" + ws();
    switch (g.type) {
      case GeometryType::point:
        return out + "(" + point(g.points[0], s) + ")";
      case GeometryType::line_string:
        return out + list(g.lines[0], s, false);
      case GeometryType::polygon:
        return out + polygon(g.polygons[0], s);
      case GeometryType::multi_point:
        for (std::size_t i = 0; i < g.points.size(); ++i) {
          body += (i ? "," + ws() : "") +
                  (s.unwrapped ? point(g.points[i], s) : "(" + point(g.points[i], s) + ")");
        }
        break;
      case GeometryType::multi_line_string:
        for (std::size_t i = 0; i < g.lines.size(); ++i)
          body += (i ? "," + ws() : "") + list(g.lines[i], s, false);
        break;
      case GeometryType::multi_polygon:
        for (std::size_t i = 0; i < g.polygons.size(); ++i)
          body += (i ? "," + ws() : "") + polygon(g.polygons[i], s);
        break;
    }
    return out + body + ws() + ")";
  }
  Style style() {
    Style s;
    switch (rng_.uniform_int(0, 5)) {
      case 1:
        s.dims = 3, s.tag = "Z";
        break;
      case 2:
        s.dims = 3, s.tag = "M";
        break;
      case 3:
        s.dims = 4, s.tag = "ZM";
        break;
      case 4:
        s.dims = 3;  // no keyword, three numbers throughout (PostGIS)
        break;
      default:
        break;
    }
    s.attached = rng_.uniform_int(0, 1) == 1;
    s.unwrapped = rng_.uniform_int(0, 1) == 1;
    return s;
  }

 private:
  locus_test::Rng& rng_;
};

TYPED_TEST(WktTest, ReadsOtherToolsConventions) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  Writer w(rng);
  for (int iter = 0; iter < 400; ++iter) {
    std::vector<Geometry2<T>> list;
    std::string text = w.ws();
    const bool collection = iter % 3 == 0;
    if (collection) text += w.keyword("GEOMETRYCOLLECTION") + w.ws() + "(";
    for (const GeometryType t : all_types) {
      list.push_back(geo_test::random_geometry<T>(rng, t));
      if (collection && t != all_types[0]) text += ",";
      text += w.ws() + w.geometry(list.back(), w.style()) + w.ws() + (collection ? "" : "\r\n");
    }
    if (collection) text += ")" + w.ws();
    // Empty members of multi- geometries are dropped; an empty text member stays empty.
    const auto r = locus::parse_wkt<T>(text);
    ASSERT_EQ(r.status, Status::ok) << r.message << "\n" << text;
    ASSERT_EQ(locus_fuzz::same_geometries(list, r.geometries), "") << text;
  }
}

TYPED_TEST(WktTest, FlattensCollectionsAndDropsEmptyMembers) {
  using T = TypeParam;
  const auto r = locus::parse_wkt<T>(
      "GeometryCollection (POINT (1 2), GEOMETRYCOLLECTION EMPTY, geometrycollection (\n"
      "  LINESTRING (0 0, 1 1)), MULTIPOLYGON (EMPTY, ((0 0, 1 0, 0 1, 0 0))),\n"
      "  MULTIPOINT (EMPTY, 3 4, (5 6)))  POINT EMPTY");
  ASSERT_EQ(r.status, Status::ok) << r.message;
  ASSERT_EQ(r.geometries.size(), 5u);
  EXPECT_EQ(r.geometries[0].type, GeometryType::point);
  EXPECT_EQ(r.geometries[1].type, GeometryType::line_string);
  EXPECT_EQ(r.geometries[2].polygons.size(), 1u);
  EXPECT_EQ(r.geometries[3].points.size(), 2u);
  EXPECT_TRUE(r.geometries[4].empty());
  EXPECT_EQ(locus::parse_wkt<T>("GEOMETRYCOLLECTION EMPTY").geometries.size(), 0u);
  const auto bom = locus::parse_wkt<T>("\xEF\xBB\xBFPOINT (1 2)\r\n");
  ASSERT_EQ(bom.status, Status::ok) << bom.message;
  EXPECT_EQ(bom.geometries[0].points[0], (Vec2<T>{1, 2}));
}

// ---- malformed input: status and position ---------------------------------------------------

struct Bad {
  const char* text;
  Status status;
  std::size_t line, column;
  const char* reason;  // a part of the message
};

TYPED_TEST(WktTest, MalformedInputHasStatusAndPosition) {
  using T = TypeParam;
  const Bad cases[] = {
      {"", Status::empty_input, 1, 1, "no geometry"},
      {" \r\n\t", Status::empty_input, 1, 1, "no geometry"},
      {"POINT (1 2", Status::parse_error, 1, 11, "end of text"},
      {"POINT (1 2) x", Status::parse_error, 1, 13, "unknown or unsupported"},
      {"POINT (1)", Status::parse_error, 1, 8, "at least 2 numbers"},
      {"POINT (1 2 3 4 5)", Status::parse_error, 1, 16, "more than 4"},
      {"POINT Z (1 2)", Status::parse_error, 1, 10, "expected 3"},
      {"POINT ZM (1 2 3)", Status::parse_error, 1, 11, "expected 4"},
      {"LINESTRING (0 0, 1 1 1)", Status::parse_error, 1, 18, "expected 2"},
      {"POINT (1 nan)", Status::non_finite_input, 1, 10, "not finite"},
      {"POINT (inf 2)", Status::non_finite_input, 1, 8, "not finite"},
      {"POINT (1e400 2)", Status::non_finite_input, 1, 8, "not finite"},
      {"POINT (1 2x)", Status::parse_error, 1, 10, "expected a number"},
      {"POINT (1 , 2)", Status::parse_error, 1, 8, "at least 2"},
      {"CIRCULARSTRING (0 0, 1 1, 2 0)", Status::parse_error, 1, 1, "CIRCULARSTRING"},
      {"SRID=4326;POINT (1 2)", Status::parse_error, 1, 1, "SRID"},
      {"POINT", Status::parse_error, 1, 6, "end of text"},
      {"POINT [1 2]", Status::parse_error, 1, 7, "'[1'"},
      {"LINESTRING (0 0)", Status::parse_error, 1, 12, "at least 2 points"},
      {"POLYGON ((0 0, 1 0, 1 1, 0 1))", Status::parse_error, 1, 10, "not closed"},
      {"POLYGON ((0 0, 1 0, 0 0))", Status::parse_error, 1, 10, "at least 4"},
      {"POLYGON ((0 0, 1 0, 1 0, 0 0))", Status::parse_error, 1, 10, "3 distinct"},
      {"POLYGON\r\n((0 0, 1 0, 0 1, 0 0),\r\n (5 5, 6 6, 5 5, 5 5))", Status::parse_error, 3, 2,
       "3 distinct"},
      {"POLYGON (EMPTY, (0 0, 1 0, 0 1, 0 0))", Status::parse_error, 1, 17, "EMPTY outer"},
      {"MULTIPOLYGON ((0 0, 1 0, 0 1, 0 0))", Status::parse_error, 1, 16, "'('"},
      {"MULTIPOINT ((1 2), (3 4)", Status::parse_error, 1, 25, "end of text"},
      {"GEOMETRYCOLLECTION (POINT (1 2) POINT (3 4))", Status::parse_error, 1, 33,
       "GEOMETRYCOLLECTION"},
      {"GEOMETRYCOLLECTION ()", Status::parse_error, 1, 21, "geometry keyword"},
  };
  for (const Bad& b : cases) {
    SCOPED_TRACE(b.text);
    const auto r = locus::parse_wkt<T>(b.text, "in.wkt");
    EXPECT_EQ(r.status, b.status) << r.message;
    EXPECT_EQ(r.line, b.line) << r.message;
    EXPECT_EQ(r.column, b.column) << r.message;
    EXPECT_NE(r.message.find(b.reason), std::string::npos) << r.message;
    EXPECT_EQ(r.message.rfind(
                  "in.wkt:" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": ", 0),
              0u)
        << r.message;
  }
  // A number finite in double but not in float.
  const auto big = locus::parse_wkt<T>("POINT (1e39 0)");
  EXPECT_EQ(big.status, sizeof(T) == 4 ? Status::non_finite_input : Status::ok) << big.message;
}

TYPED_TEST(WktTest, TruncationAtEveryByteNeverSucceedsSilently) {
  using T = TypeParam;
  const std::string full =
      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), "
      "((20 20, 30 20, 20 30, 20 20)))";
  for (std::size_t n = 0; n < full.size(); ++n) {
    const auto r = locus::parse_wkt<T>(std::string_view(full).substr(0, n));
    EXPECT_NE(r.status, Status::ok) << n;
    EXPECT_LE(r.byte_offset, n);
    EXPECT_FALSE(r.message.empty());
  }
  EXPECT_EQ(locus::parse_wkt<T>(full).status, Status::ok);
}

TYPED_TEST(WktTest, HostileNestingAndSizes) {
  using T = TypeParam;
  // Nesting far beyond the bound: an error at the 33rd level, no deep recursion.
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "GEOMETRYCOLLECTION (";
  auto r = locus::parse_wkt<T>(deep);
  EXPECT_EQ(r.status, Status::parse_error);
  EXPECT_EQ(r.byte_offset, 32 * std::string("GEOMETRYCOLLECTION (").size());
  std::string ok_deep;
  for (int i = 0; i < 32; ++i) ok_deep += "GEOMETRYCOLLECTION (";
  ok_deep += "POINT (1 2)" + std::string(32, ')');
  r = locus::parse_wkt<T>(ok_deep);
  EXPECT_EQ(r.status, Status::ok) << r.message;
  EXPECT_EQ(r.geometries.size(), 1u);
  // Many parentheses where a number belongs, a megabyte of digits, a long keyword.
  EXPECT_EQ(locus::parse_wkt<T>("MULTIPOLYGON " + std::string(1 << 20, '(')).status,
            Status::parse_error);
  EXPECT_EQ(locus::parse_wkt<T>("POINT (1" + std::string(1 << 20, '0') + " 2)").status,
            Status::non_finite_input);
  EXPECT_EQ(locus::parse_wkt<T>(std::string(1 << 20, 'P')).status, Status::parse_error);
  // A long list reads in linear time.
  std::string line = "LINESTRING (";
  for (int i = 0; i < 200000; ++i) line += (i ? ", " : "") + std::to_string(i) + " 1";
  r = locus::parse_wkt<T>(line + ")");
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_EQ(r.geometries[0].lines[0].size(), 200000u);
}

TYPED_TEST(WktTest, WriterRefusesWhatItCannotWrite) {
  using T = TypeParam;
  Geometry2<T> g;
  g.type = GeometryType::polygon;
  g.polygons.push_back({{{0, 0}, {1, 0}, {0, 1}}, {3}});
  EXPECT_EQ(locus::write_wkt_string(g).status, Status::ok);
  g.polygons[0].points[1].x = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::write_wkt_string(g).status, Status::non_finite_input);
  g.polygons[0] = {{{0, 0}, {1, 0}, {1, 0}}, {3}};
  EXPECT_EQ(locus::write_wkt_string(g).status, Status::invalid_input);
  g.polygons[0] = {{{0, 0}, {1, 0}, {0, 1}}, {4}};
  EXPECT_EQ(locus::write_wkt_string(g).status, Status::invalid_input);
  g.polygons.push_back(g.polygons[0]);
  g.polygons[0].ring_ends = {3};
  g.polygons[1].ring_ends = {3};
  EXPECT_EQ(locus::write_wkt_string(g).status, Status::invalid_input);  // two in a POLYGON
  g.type = GeometryType::multi_polygon;
  EXPECT_EQ(locus::write_wkt_string(g).status, Status::ok);
  Geometry2<T> l;
  l.type = GeometryType::line_string;
  l.lines.push_back({{1, 1}});
  EXPECT_EQ(locus::write_wkt_string(l).status, Status::invalid_input);
}

TYPED_TEST(WktTest, Files) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Geometry2<T>> list;
  for (const GeometryType t : all_types) list.push_back(geo_test::random_geometry<T>(rng, t));
  const auto dir = std::filesystem::temp_directory_path() /
                   ("locus_wkt_" + std::to_string(sizeof(T)) + "_" +
                    std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  ASSERT_EQ(locus::write_wkt(dir / "a.wkt", list).status, Status::ok);
  const auto r = locus::read_wkt<T>(dir / "a.wkt");
  ASSERT_EQ(r.status, Status::ok) << r.message;
  EXPECT_EQ(locus_fuzz::same_geometries(list, r.geometries), "");
  EXPECT_EQ(locus::read_wkt<T>(dir / "missing.wkt").status, Status::io_error);
  EXPECT_EQ(locus::read_wkt<T>(dir).status, Status::io_error);
  EXPECT_EQ(locus::write_wkt(dir / "no" / "such" / "dir.wkt", list).status, Status::io_error);
  std::filesystem::remove_all(dir);
}

// ---- orientation helper and conversions -----------------------------------------------------

template <class T>
int exact_area_sign(const std::vector<Vec2<T>>& v) {
  mpq_class twice = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % v.size()];
    twice += mpq_class(double(a.x)) * mpq_class(double(b.y)) -
             mpq_class(double(b.x)) * mpq_class(double(a.y));
  }
  return sgn(twice);
}

TYPED_TEST(WktTest, OrientRingsMatchesExactArea) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int iter = 0; iter < 200; ++iter) {
    // Star-shaped (hence simple) rings around random centres, in a random winding.
    locus::RingPolygon2<T> p;
    for (int k = 0; k < 3; ++k) {
      const int n = rng.uniform_int(3, 12);
      const T cx = rng.uniform<T>(-100, 100), cy = rng.uniform<T>(-100, 100);
      const bool cw = rng.uniform_int(0, 1) == 1;
      for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * (cw ? n - i : i) / n;
        const T r = rng.uniform<T>(1, 5);
        p.points.push_back({cx + r * T(std::cos(a)), cy + r * T(std::sin(a))});
      }
      p.ring_ends.push_back(static_cast<std::uint32_t>(p.points.size()));
    }
    const auto before = p;
    locus::orient_rings(p);
    const auto rings = locus::to_polygon_with_holes(p);
    ASSERT_EQ(rings.holes.size(), 2u);
    EXPECT_EQ(exact_area_sign(rings.outer.vertices), 1);
    for (const auto& h : rings.holes) EXPECT_EQ(exact_area_sign(h.vertices), -1);
    // Same rings as sets, and lossless conversions.
    EXPECT_EQ(p.ring_ends, before.ring_ends);
    auto a = p.points, b = before.points;
    const auto less = [](const Vec2<T>& u, const Vec2<T>& v) {
      return u.x < v.x || (u.x == v.x && u.y < v.y);
    };
    std::sort(a.begin(), a.end(), less);
    std::sort(b.begin(), b.end(), less);
    EXPECT_EQ(a, b);
    const auto back = locus::to_ring_polygon(rings);
    EXPECT_EQ(back.points, p.points);
    EXPECT_EQ(back.ring_ends, p.ring_ends);
  }
}

// ---- the corpus: JTS test XML and Boost.Geometry overlay cases ------------------------------

std::string first_word(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  std::size_t j = i;
  while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
  std::string w = s.substr(i, j - i);
  for (char& c : w) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return w;
}

/// What is wrong with the ring whose '(' is at text[at], by a reading independent of the
/// reader: "at least 4", "not closed", "3 distinct", or "" when nothing is.
std::string ring_defect(const std::string& text, std::size_t at) {
  if (at >= text.size() || text[at] != '(') return "";
  const std::size_t end = text.find(')', at);
  if (end == std::string::npos) return "";
  std::vector<std::pair<double, double>> pts;
  std::size_t i = at + 1;
  while (i < end) {
    const std::size_t comma = std::min(text.find(',', i), end);
    const std::string item = text.substr(i, comma - i);
    char* next = nullptr;
    const double x = std::strtod(item.c_str(), &next);
    const double y = std::strtod(next, nullptr);
    pts.emplace_back(x, y);
    i = comma + 1;
  }
  if (pts.size() < 4) return "at least 4";
  if (pts.front() != pts.back()) return "not closed";
  pts.pop_back();
  std::sort(pts.begin(), pts.end());
  if (std::unique(pts.begin(), pts.end()) - pts.begin() < 3) return "3 distinct";
  return "";
}

TEST(WktCorpus, JtsAndBoostGeometriesParse) {
  const std::filesystem::path root = std::filesystem::path(LOCUS_SHARED_DIR) / "corpus";
  std::size_t files = 0, read = 0, skipped = 0, open_rings = 0, bad_rings = 0, nan_texts = 0,
              typos = 0;
  std::map<std::string, std::size_t> kinds;
  const auto check = [&](const std::string& origin, const std::string& wkt) {
    const std::string word = first_word(wkt);
    if (word.empty()) {  // WKB hex (a few JTS files) or a file reference
      ++skipped;
      return;
    }
    const auto r = locus::parse_wkt<double>(wkt, origin);
    if (r.status == Status::ok) {
      ++read;
      for (const auto& g : r.geometries) ++kinds[locus::wkt_name(g.type)];
      // Every geometry read also survives the round trip (float too, when in range). The
      // sanitizer build (-O0) round-trips every 4th text: the round trip (six reads, four
      // writes) was three quarters of this test's 1.3 s there; every text is still read, and
      // the writers' round trips are also checked there by RoundTripIsBitExact (WKT, GeoJSON).
      if (!locus_test::kSanitizerBuild || read % 4 == 1) {
        EXPECT_EQ(locus_fuzz::check_geo(true, reinterpret_cast<const std::uint8_t*>(wkt.data()),
                                        wkt.size()),
                  "")
            << origin;
      }
      return;
    }
    // Refusals the suites provoke on purpose (validity and degenerate-input tests): a ring
    // the reader calls too short, unclosed or degenerate is re-read here at the reported
    // position by a plain strtod split, which must agree.
    const std::string why = ring_defect(wkt, r.byte_offset);
    if (!why.empty() && r.message.find(why) != std::string::npos) {
      ++(origin.find(":open_") != std::string::npos ? open_rings : bad_rings);
      return;
    }
    if (r.status == Status::non_finite_input && wkt.find("NaN") != std::string::npos) {
      ++nan_texts;
      return;
    }
    // Known texts that are not WKT: a stray ')' after a JTS geometry (TestCentroid.xml),
    // Boost's own BOX keyword, a missing comma in a Boost case.
    const bool typo =
        (wkt.find("120 0))") != std::string::npos &&
         r.message.find("found ')'") != std::string::npos) ||
        (origin == "boost:ticket_17" && r.message.find("'BOX'") != std::string::npos) ||
        (origin == "boost:issue_1138" &&
         r.message.find("more than 4 numbers") != std::string::npos);
    if (typo) {
      ++typos;
      return;
    }
    ADD_FAILURE() << r.message << "\n" << wkt.substr(0, 200);
  };
  for (const auto& e : std::filesystem::recursive_directory_iterator(root / "jts-testxml")) {
    if (e.path().extension() != ".xml") continue;
    ++files;
    for (const auto& c : locus_test::read_jts_cases(slurp(e.path())))
      for (const std::string* wkt : {&c.a, &c.b})
        if (!wkt->empty()) check(e.path().string(), *wkt);
  }
  ++files;
  for (const auto& c :
       locus_test::read_boost_overlay_cases(slurp(root / "boost-geometry" / "overlay_cases.json")))
    for (const std::string& wkt : c.wkt)
      // issue_1183's one text is a stray separator (",\n    "), not a geometry.
      if (wkt.find('(') != std::string::npos || wkt.find("EMPTY") != std::string::npos)
        check("boost:" + c.name, wkt);
  std::string summary;
  for (const auto& [k, n] : kinds) summary += k + "=" + std::to_string(n) + " ";
  std::printf(
      "[ corpus   ] %zu files, %zu WKT texts read (geometries: %s); refused as "
      "documented: %zu Boost open rings, %zu degenerate rings, %zu NaN texts, %zu not WKT; "
      "%zu non-WKT skipped\n",
      files, read, summary.c_str(), open_rings, bad_rings, nan_texts, typos, skipped);
  EXPECT_LE(typos, 3u);
  // Counts at the time of writing; a drop means texts stopped parsing.
  EXPECT_GE(files, 104u);
  EXPECT_GE(read, 3310u);
  EXPECT_GE(kinds["POLYGON"], 1523u);
  EXPECT_GE(kinds["MULTIPOLYGON"], 903u);
  EXPECT_GE(kinds["LINESTRING"], 650u);
  EXPECT_GE(kinds["MULTILINESTRING"], 159u);
  EXPECT_GE(kinds["MULTIPOINT"], 201u);
  EXPECT_GE(kinds["POINT"], 236u);
  EXPECT_LE(skipped, 75u);
}

// ---- committed fuzz inputs ------------------------------------------------------------------

TEST(WktFuzzCorpus, EveryCommittedInputKeepsTheReaderProperty) {
  const std::filesystem::path root = std::filesystem::path(LOCUS_SOURCE_DIR) / "tests" / "fuzz";
  int seeds = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const auto dir = root / kind / "wkt";
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      SCOPED_TRACE(entry.path().string());
      const std::string bytes = slurp(entry.path());
      EXPECT_EQ(locus_fuzz::check_geo(true, reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                      bytes.size()),
                "");
      if (std::string(kind) == "corpus") {
        ++seeds;
        const auto r = locus::parse_wkt<double>(bytes, entry.path().string());
        EXPECT_EQ(r.status, Status::ok) << r.message;
      }
    }
  }
  EXPECT_GE(seeds, 8);
}

}  // namespace
