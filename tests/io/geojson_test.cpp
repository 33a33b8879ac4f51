// SPDX-License-Identifier: BSL-1.0
// Tests of io/geojson.hpp. Round trips write -> read compare bit for bit on random awkward
// coordinates. Files in other tools' conventions (members in any order, properties, bbox, crs,
// id and foreign members, 3D positions, white space, CRLF, Feature, FeatureCollection and
// GeometryCollection wrappers) are produced here by an independent writer (printf with
// max_digits10) from random geometries, which the reader must give back. Every malformed-input
// class (bad JSON, wrong structure, unclosed rings, hostile nesting) has its expected status and
// position.

#include <locus/io/geojson.hpp>

#include "geo_support.hpp"
#include "support/files.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
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
class GeoJsonTest : public ::testing::Test {};
TYPED_TEST_SUITE(GeoJsonTest, locus_test::RealTypes);

using locus_test::slurp;

TYPED_TEST(GeoJsonTest, RoundTripIsBitExact) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int iter = 0; iter < 300; ++iter) {
    std::vector<Geometry2<T>> list;
    for (const GeometryType t : all_types) list.push_back(geo_test::random_geometry<T>(rng, t));
    const auto w = locus::write_geojson_string(list);
    ASSERT_EQ(w.status, Status::ok) << w.message;
    const auto r = locus::parse_geojson<T>(w.data);
    ASSERT_EQ(r.status, Status::ok) << r.message << "\n" << w.data;
    ASSERT_EQ(locus_fuzz::same_geometries(list, r.geometries), "") << w.data;
    // A single geometry object too.
    const auto one = locus::write_geojson_string(list[2]);
    ASSERT_EQ(one.status, Status::ok);
    const auto r1 = locus::parse_geojson<T>(one.data);
    ASSERT_EQ(r1.status, Status::ok) << r1.message;
    ASSERT_EQ(locus_fuzz::same_geometries({list[2]}, r1.geometries), "");
  }
}

TYPED_TEST(GeoJsonTest, CanonicalText) {
  using T = TypeParam;
  Geometry2<T> g;
  g.type = GeometryType::polygon;
  g.polygons.push_back({{{0, 0}, {4, 0}, {0, 4}}, {3}});
  EXPECT_EQ(locus::write_geojson_string(g).data,
            R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[0,4],[0,0]]]})");
  g.type = GeometryType::point;
  g.polygons.clear();
  EXPECT_EQ(locus::write_geojson_string(g).data, R"({"type":"Point","coordinates":[]})");
}

// ---- an independent writer in other tools' styles -------------------------------------------

class Writer {
 public:
  explicit Writer(locus_test::Rng& rng) : rng_(rng) {}
  std::string ws() {
    static const char* const pieces[] = {"", " ", "\n  ", "\t", "\r\n", "\r\n    "};
    return pieces[rng_.uniform_int(0, 5)];
  }
  template <class T>
  std::string position(const Vec2<T>& p) {
    std::string out = "[" + ws() + number(p.x) + "," + ws() + number(p.y);
    if (three_d_) out += ", " + number(T(rng_.uniform_int(-9, 9)));
    return out + ws() + "]";
  }
  template <class T>
  std::string list(const std::vector<Vec2<T>>& v, bool close) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? "," + ws() : "") + position(v[i]);
    if (close) out += "," + position(v[0]);
    return out + "]";
  }
  template <class T>
  std::string polygon(const locus::RingPolygon2<T>& p) {
    std::string out = "[";
    std::size_t begin = 0;
    for (std::size_t k = 0; k < p.ring_ends.size(); ++k) {
      const std::vector<Vec2<T>> ring(p.points.begin() + std::ptrdiff_t(begin),
                                      p.points.begin() + std::ptrdiff_t(p.ring_ends[k]));
      out += (k ? "," + ws() : "") + list(ring, true);
      begin = p.ring_ends[k];
    }
    return out + "]";
  }
  template <class T>
  std::string coordinates(const Geometry2<T>& g) {
    std::string out = "[";
    switch (g.type) {
      case GeometryType::point:
        return g.points.empty() ? "[]" : position(g.points[0]);
      case GeometryType::line_string:
        return g.lines.empty() ? "[]" : list(g.lines[0], false);
      case GeometryType::polygon:
        return g.polygons.empty() ? "[]" : polygon(g.polygons[0]);
      case GeometryType::multi_point:
        return list(g.points, false);
      case GeometryType::multi_line_string:
        for (std::size_t i = 0; i < g.lines.size(); ++i)
          out += (i ? "," : "") + list(g.lines[i], false);
        break;
      case GeometryType::multi_polygon:
        for (std::size_t i = 0; i < g.polygons.size(); ++i)
          out += (i ? "," : "") + polygon(g.polygons[i]);
        break;
    }
    return out + "]";
  }
  /// An object from members given in a random order, with ignorable extras.
  std::string object(std::vector<std::string> members) {
    static const char* const extras[] = {
        R"("bbox": [-180.0, -90.0, 180.0, 90.0])",
        R"("crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:OGC:1.3:CRS84"}})",
        R"("id": "f\u00e9\"1\\")",
        R"("foreign": {"coordinates": "not ours", "nested": [[[{"a": null}]], true, false]})",
        R"("title": "Ünïcödé ✓ 𝄞")"};
    if (rng_.uniform_int(0, 1)) members.push_back(extras[rng_.uniform_int(0, 4)]);
    std::shuffle(members.begin(), members.end(), rng_.engine());
    std::string out = "{" + ws();
    for (std::size_t i = 0; i < members.size(); ++i) out += (i ? "," + ws() : "") + members[i];
    return out + ws() + "}";
  }
  template <class T>
  std::string geometry(const Geometry2<T>& g) {
    static const char* const names[] = {"Point",      "LineString",      "Polygon",
                                        "MultiPoint", "MultiLineString", "MultiPolygon"};
    three_d_ = rng_.uniform_int(0, 3) == 0;
    return object({std::string(R"("type":)") + ws() + "\"" + names[static_cast<int>(g.type)] + "\"",
                   "\"coordinates\"" + ws() + ":" + ws() + coordinates(g)});
  }
  std::string feature(const std::string& geometry) {
    return object({R"("type": "Feature")",
                   R"("properties": {"name": "x", "type": "Polygon", "coordinates": [1]})",
                   "\"geometry\": " + geometry});
  }

 private:
  locus_test::Rng& rng_;
  bool three_d_ = false;
};

TYPED_TEST(GeoJsonTest, ReadsOtherToolsConventions) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  Writer w(rng);
  for (int iter = 0; iter < 300; ++iter) {
    std::vector<Geometry2<T>> list;
    std::vector<std::string> texts;
    for (const GeometryType t : all_types) {
      list.push_back(geo_test::random_geometry<T>(rng, t));
      texts.push_back(w.geometry(list.back()));
    }
    std::string text;
    switch (iter % 3) {
      case 0: {  // FeatureCollection, one with a null geometry, one GeometryCollection
        std::string features;
        for (std::size_t i = 0; i < 3; ++i) features += w.feature(texts[i]) + ",";
        features += w.feature("null") + ",";
        std::string members;
        for (std::size_t i = 3; i < texts.size(); ++i) members += (i > 3 ? "," : "") + texts[i];
        features += w.feature(
            w.object({R"("type": "GeometryCollection")", "\"geometries\": [" + members + "]"}));
        text = w.object({R"("type": "FeatureCollection")", "\"features\": [" + features + "]"});
        break;
      }
      case 1: {  // a nested GeometryCollection
        std::string inner, outer;
        for (std::size_t i = 0; i < texts.size(); ++i) {
          if (i < 2) outer += texts[i] + ",";
          if (i >= 2) inner += (i > 2 ? "," : "") + texts[i];
        }
        outer += w.object({R"("type":"GeometryCollection")", "\"geometries\":[" + inner + "]"});
        text = w.object({R"("type":"GeometryCollection")", "\"geometries\":[" + outer + "]"});
        break;
      }
      default: {  // one Feature, the others dropped
        list.resize(1);
        text = w.feature(texts[0]);
        break;
      }
    }
    text = "\xEF\xBB\xBF" + w.ws() + text + w.ws();
    const auto r = locus::parse_geojson<T>(text);
    ASSERT_EQ(r.status, Status::ok) << r.message << "\n" << text;
    ASSERT_EQ(locus_fuzz::same_geometries(list, r.geometries), "") << text;
  }
}

// ---- malformed input: status and position ---------------------------------------------------

struct Bad {
  const char* text;
  Status status;
  std::size_t line, column;
  const char* reason;
};

TYPED_TEST(GeoJsonTest, MalformedInputHasStatusAndPosition) {
  using T = TypeParam;
  const Bad cases[] = {
      {"", Status::empty_input, 1, 1, "no JSON"},
      {"{", Status::parse_error, 1, 2, "end of text"},
      {R"({"type": "Point", "coordinates": [1, 2]} x)", Status::parse_error, 1, 42, "after"},
      {R"({"type": "Point", "coordinates": [1, 2],})", Status::parse_error, 1, 41, "member name"},
      {R"({"type": "Point", "coordinates": [1, 2,]})", Status::parse_error, 1, 40, "not the start"},
      {R"({"type": "Point", "coordinates": [+1, 2]})", Status::parse_error, 1, 35, "not the start"},
      {R"({"type": "Point", "coordinates": [01, 2]})", Status::parse_error, 1, 35, "leading zero"},
      {R"({"type": "Point", "coordinates": [1., 2]})", Status::parse_error, 1, 35, "follow '.'"},
      {R"({"type": "Point", "coordinates": [NaN, 2]})", Status::parse_error, 1, 35,
       "not the start"},
      {R"({"type": "Point", "coordinates": [1e999, 2]})", Status::non_finite_input, 1, 35,
       "overflows"},
      {R"({"type": "Point", 'coordinates': [1, 2]})", Status::parse_error, 1, 19, "member name"},
      {"{\"type\": \"Po\x01int\"}", Status::parse_error, 1, 13, "control character"},
      {"{\"type\": \"\\x\"}", Status::parse_error, 1, 11, "bad escape"},
      {"{\"type\": \"\\u12\"}", Status::parse_error, 1, 11, "\\u escape"},
      {"{\"type\": \"\xC3\x28\"}", Status::parse_error, 1, 11, "UTF-8"},
      {"{\"type\": \"Point", Status::parse_error, 1, 10, "unterminated"},
      {R"([1, 2])", Status::parse_error, 1, 1, "not a GeoJSON object"},
      {R"({"coordinates": [1, 2]})", Status::parse_error, 1, 1, "no \"type\""},
      {R"({"type": "point", "coordinates": [1, 2]})", Status::parse_error, 1, 10, "case-sensitive"},
      {R"({"type": 7, "coordinates": [1, 2]})", Status::parse_error, 1, 10, "not a string"},
      {R"({"type": "Point", "coordinates": [1, 2], "type": "Point"})", Status::parse_error, 1, 42,
       "twice"},
      {R"({"type": "Point"})", Status::parse_error, 1, 1, "\"coordinates\""},
      {R"({"type": "Point", "coordinates": [1]})", Status::parse_error, 1, 34, "2 or 3 numbers"},
      {R"({"type": "Point", "coordinates": [1, 2, 3, 4]})", Status::parse_error, 1, 34, "found 4"},
      {R"({"type": "Point", "coordinates": [1, "2"]})", Status::parse_error, 1, 38, "not a number"},
      {R"({"type": "LineString", "coordinates": [[1, 2]]})", Status::parse_error, 1, 39,
       "at least 2"},
      {"{\"type\": \"Polygon\",\r\n \"coordinates\": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}",
       Status::parse_error, 2, 18, "not closed"},
      {R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 0]]]})", Status::parse_error, 1,
       37, "at least 4"},
      {R"({"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 0], [0, 0]]]})",
       Status::parse_error, 1, 37, "3 distinct"},
      {R"({"type": "Polygon", "coordinates": [[0, 0]]})", Status::parse_error, 1, 38,
       "a position is not an array"},
      {R"({"type": "MultiPolygon", "coordinates": [[[0, 0]]]})", Status::parse_error, 1, 44,
       "a position is not an array"},
      {R"({"type": "Feature", "properties": {}})", Status::parse_error, 1, 1, "\"geometry\""},
      {R"({"type": "Feature", "geometry": 3})", Status::parse_error, 1, 33, "neither"},
      {R"({"type": "FeatureCollection", "features": {}})", Status::parse_error, 1, 43,
       "not an array"},
      {R"({"type": "FeatureCollection", "features": [{"type": "Point", "coordinates": []}]})",
       Status::parse_error, 1, 44, "expected a Feature"},
      {R"({"type": "GeometryCollection", "geometries": [1]})", Status::parse_error, 1, 47,
       "not an object"},
      {R"({"type": "Circle", "coordinates": [1, 2]})", Status::parse_error, 1, 10, "'Circle'"},
  };
  for (const Bad& b : cases) {
    SCOPED_TRACE(b.text);
    const auto r = locus::parse_geojson<T>(b.text, "in.json");
    EXPECT_EQ(r.status, b.status) << r.message;
    EXPECT_EQ(r.line, b.line) << r.message;
    EXPECT_EQ(r.column, b.column) << r.message;
    EXPECT_NE(r.message.find(b.reason), std::string::npos) << r.message;
    EXPECT_EQ(r.message.rfind(
                  "in.json:" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": ", 0),
              0u)
        << r.message;
  }
  const auto big = locus::parse_geojson<T>(R"({"type": "Point", "coordinates": [1e39, 0]})");
  EXPECT_EQ(big.status, sizeof(T) == 4 ? Status::non_finite_input : Status::ok) << big.message;
}

TYPED_TEST(GeoJsonTest, TruncationAtEveryByteNeverSucceedsSilently) {
  using T = TypeParam;
  const std::string full =
      R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"a":[1,{}]},)"
      R"("geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,0]]]}}]})";
  ASSERT_EQ(locus::parse_geojson<T>(full).status, Status::ok);
  for (std::size_t n = 0; n < full.size(); ++n) {
    const auto r = locus::parse_geojson<T>(std::string_view(full).substr(0, n));
    EXPECT_NE(r.status, Status::ok) << n;
    EXPECT_LE(r.byte_offset, n);
    EXPECT_FALSE(r.message.empty());
  }
}

TYPED_TEST(GeoJsonTest, HostileNestingAndSizes) {
  using T = TypeParam;
  // Nesting beyond 64 levels is refused where the 65th opens, without recursion.
  for (const char open : {'[', '{'}) {
    std::string deep;
    for (int i = 0; i < 1000000; ++i) deep += open == '[' ? "[" : "{\"a\":";
    const auto r = locus::parse_geojson<T>(deep);
    EXPECT_EQ(r.status, Status::parse_error);
    EXPECT_EQ(r.byte_offset, open == '[' ? 64u : 64u * 5);
    EXPECT_NE(r.message.find("deeper than 64"), std::string::npos) << r.message;
  }
  // Nested GeometryCollections within the bound.
  std::string gc;
  for (int i = 0; i < 31; ++i) gc += R"({"type":"GeometryCollection","geometries":[)";
  gc += R"({"type":"Point","coordinates":[1,2]})";
  for (int i = 0; i < 31; ++i) gc += "]}";
  const auto r = locus::parse_geojson<T>(gc);
  ASSERT_EQ(r.status, Status::ok) << r.message;
  EXPECT_EQ(r.geometries.size(), 1u);
  // A megabyte of digits; a long string; a long list.
  EXPECT_EQ(locus::parse_geojson<T>(R"({"type":"Point","coordinates":[1)" +
                                    std::string(1 << 20, '0') + ",2]}")
                .status,
            Status::non_finite_input);
  EXPECT_EQ(locus::parse_geojson<T>("\"" + std::string(1 << 20, 'a')).status, Status::parse_error);
  std::string line = R"({"type":"LineString","coordinates":[)";
  for (int i = 0; i < 200000; ++i) line += (i ? ",[" : "[") + std::to_string(i) + ",1]";
  const auto l = locus::parse_geojson<T>(line + "]}");
  ASSERT_EQ(l.status, Status::ok);
  EXPECT_EQ(l.geometries[0].lines[0].size(), 200000u);
}

TYPED_TEST(GeoJsonTest, Files) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  std::vector<Geometry2<T>> list;
  for (const GeometryType t : all_types) list.push_back(geo_test::random_geometry<T>(rng, t));
  const auto dir = std::filesystem::temp_directory_path() /
                   ("locus_geojson_" + std::to_string(sizeof(T)) + "_" +
                    std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  ASSERT_EQ(locus::write_geojson(dir / "a.geojson", list).status, Status::ok);
  const auto r = locus::read_geojson<T>(dir / "a.geojson");
  ASSERT_EQ(r.status, Status::ok) << r.message;
  EXPECT_EQ(locus_fuzz::same_geometries(list, r.geometries), "");
  EXPECT_EQ(locus::read_geojson<T>(dir / "missing.json").status, Status::io_error);
  EXPECT_EQ(locus::write_geojson(dir / "no" / "dir.json", list).status, Status::io_error);
  list[0].type = GeometryType::multi_point;
  list[0].points = {{std::numeric_limits<T>::infinity(), 0}};
  EXPECT_EQ(locus::write_geojson(dir / "b.json", list).status, Status::non_finite_input);
  std::filesystem::remove_all(dir);
}

TEST(GeoJsonFuzzCorpus, EveryCommittedInputKeepsTheReaderProperty) {
  const std::filesystem::path root = std::filesystem::path(LOCUS_SOURCE_DIR) / "tests" / "fuzz";
  int seeds = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const auto dir = root / kind / "geojson";
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      SCOPED_TRACE(entry.path().string());
      const std::string bytes = slurp(entry.path());
      EXPECT_EQ(locus_fuzz::check_geo(false, reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                      bytes.size()),
                "");
      if (std::string(kind) == "corpus") {
        ++seeds;
        const auto r = locus::parse_geojson<double>(bytes, entry.path().string());
        EXPECT_EQ(r.status, Status::ok) << r.message;
      }
    }
  }
  EXPECT_GE(seeds, 6);
}

}  // namespace
