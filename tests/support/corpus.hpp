// SPDX-License-Identifier: BSL-1.0
#pragma once
// Readers for the case files of the overlay corpus (tests/data/corpus), shared by the tests that
// read it (tests/boolean/*_corpus_test.cpp, tests/io/wkt_test.cpp) and the peer comparison in
// bench/boolean/boolean_peer_failures.cpp, so that all of them see the same cases:
//   - Boost.Geometry's overlay_cases.json: named cases, each a "wkt" array of WKT texts (the
//     file puts one value per line, which is all this reader relies on);
//   - a JTS XML test file: the <a> and <b> texts of each <case> (WKT, or WKB hex in a few files)
//     and whether the file declares a fixed precision model;
//   - Clipper2's Tests/Polygons.txt: raw rings with clip type, fill rule and expected area, and
//     Clipper2's own per-case area tolerances (its TestPolygons.cpp).
// Geometry texts are read by the library (read_polygonal: locus::parse_wkt).

#include <locus/boolean/polygon_boolean.hpp>
#include <locus/io/geometry.hpp>
#include <locus/io/wkt.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace locus_test {

// ---- Boost.Geometry overlay_cases.json ----------------------------------------------------

/// The value of a JSON string line `"...",` (no escapes occur in these files but \").
inline std::string json_string_value(const std::string& line) {
  const auto b = line.find('"'), e = line.rfind('"');
  const std::string s = line.substr(b + 1, e - b - 1);
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) ++i;
    out += s[i];
  }
  return out;
}

struct BoostOverlayCase {
  std::string name;
  std::vector<std::string> wkt;  ///< empty for "wkt": [] (a case without data)
};

/// The cases of overlay_cases.json in file order.
inline std::vector<BoostOverlayCase> read_boost_overlay_cases(const std::string& json) {
  std::vector<BoostOverlayCase> cases;
  std::istringstream in(json);
  std::string line, name;
  bool in_wkt = false;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    const std::string t = line.substr(first);
    if (in_wkt) {
      if (t[0] == ']') {
        in_wkt = false;
        continue;
      }
      cases.back().wkt.push_back(json_string_value(t));
    } else if (t.rfind("\"wkt\"", 0) == 0) {
      in_wkt = t.back() == '[';
      cases.push_back({name, {}});
    } else if (t.size() > 3 && t[0] == '"' && t.back() == '{') {
      name = t.substr(1, t.find('"', 1) - 1);
    }
  }
  return cases;
}

// ---- JTS XML test files ---------------------------------------------------------------------

/// The text of the first <tag> or <tag ...> element in s, "" when there is none.
inline std::string xml_element(std::string_view s, const char* tag) {
  const std::string open = std::string("<") + tag, close = std::string("</") + tag + ">";
  std::size_t b = s.find(open);
  while (b != std::string_view::npos && b + open.size() < s.size() && s[b + open.size()] != '>' &&
         s[b + open.size()] != ' ')
    b = s.find(open, b + 1);
  if (b == std::string_view::npos || b + open.size() >= s.size()) return "";
  b = s.find('>', b) + 1;
  const std::size_t e = s.find(close, b);
  return e == std::string_view::npos ? "" : std::string(s.substr(b, e - b));
}

struct JtsCase {
  std::string a, b;  ///< the geometry texts, "" where the case has no such element
};

/// The <a>, <b> texts of every <case> of a JTS XML file, in file order.
inline std::vector<JtsCase> read_jts_cases(const std::string& xml) {
  std::vector<JtsCase> cases;
  for (std::size_t at = xml.find("<case"); at != std::string::npos;
       at = xml.find("<case", at + 1)) {
    const std::size_t end = xml.find("</case>", at);
    if (end == std::string::npos) break;
    // Searched within the case only: many files' cases have no <b>.
    const std::string_view body = std::string_view(xml).substr(at, end - at);
    cases.push_back({xml_element(body, "a"), xml_element(body, "b")});
  }
  return cases;
}

/// Whether the file's <precisionModel> is a fixed grid (its expected results assume snapping).
inline bool jts_fixed_precision(const std::string& xml) {
  const auto pm = xml.find("<precisionModel");
  if (pm == std::string::npos) return false;
  const std::string tag = xml.substr(pm, xml.find('>', pm) - pm);
  return tag.find("FIXED") != std::string::npos || tag.find("scale") != std::string::npos;
}

/// Reads a WKT text holding one POLYGON or MULTIPOLYGON into m (rings as written); false when
/// the text does not parse or holds anything else.
inline bool read_polygonal(const std::string& wkt, locus::MultiPolygon2<double>& m) {
  const auto r = locus::parse_wkt<double>(wkt);
  if (r.status != locus::Status::ok || r.geometries.size() != 1) return false;
  const auto& g = r.geometries[0];
  if (g.type != locus::GeometryType::polygon && g.type != locus::GeometryType::multi_polygon)
    return false;
  for (const auto& p : g.polygons) m.push_back(locus::to_polygon_with_holes(p));
  return true;
}

// ---- Clipper2 Tests/Polygons.txt ------------------------------------------------------------

struct Clipper2Case {
  int id = 0;
  std::string clip_type, fill_rule;  ///< as written: UNION, ..., EVENODD, NONZERO, ...
  double sol_area = 0;
  long sol_count = 0;
  std::vector<locus::Polygon2<double>> subjects, clips;  ///< closed rings (open paths dropped)
};

inline std::vector<Clipper2Case> read_clipper2_cases(const std::string& text) {
  std::vector<Clipper2Case> cases;
  std::istringstream in(text);
  std::string line;
  std::vector<locus::Polygon2<double>>* target = nullptr;
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
      locus::Polygon2<double> ring;
      double x = 0, y = 0;
      while (nums >> x >> y) ring.vertices.push_back({x, y});
      if (!ring.vertices.empty()) target->push_back(ring);
    }
  }
  return cases;
}

/// Clipper2's relative area tolerance for a case (TestPolygons.cpp): 1% unless listed.
inline double clipper2_area_tolerance(int id) {
  static const std::map<int, double> loose = {
      {19, 0.5},   {22, 0.5},  {23, 0.5},  {24, 0.5},   {193, 0.2},  {63, 0.1},
      {16, 0.075}, {26, 0.05}, {15, 0.02}, {52, 0.02},  {53, 0.02},  {54, 0.02},
      {59, 0.02},  {60, 0.02}, {64, 0.02}, {117, 0.02}, {119, 0.02}, {184, 0.02}};
  const auto it = loose.find(id);
  return it == loose.end() ? 0.01 : it->second;
}

/// A case as a locus boolean: its operation, fill rule and operands. NEGATIVE (winding < 0)
/// becomes POSITIVE on the reversed rings.
struct Clipper2Boolean {
  locus::BooleanOp op = locus::BooleanOp::intersection;
  locus::FillRule rule = locus::FillRule::even_odd;
  std::vector<locus::Polygon2<double>> subjects, clips;
};

inline Clipper2Boolean clipper2_boolean(const Clipper2Case& c) {
  using locus::BooleanOp;
  using locus::FillRule;
  Clipper2Boolean b;
  b.op = c.clip_type == "UNION"          ? BooleanOp::union_
         : c.clip_type == "INTERSECTION" ? BooleanOp::intersection
         : c.clip_type == "DIFFERENCE"   ? BooleanOp::difference
                                         : BooleanOp::symmetric_difference;
  b.subjects = c.subjects;
  b.clips = c.clips;
  if (c.fill_rule == "NONZERO") b.rule = FillRule::non_zero;
  if (c.fill_rule == "POSITIVE") b.rule = FillRule::positive;
  if (c.fill_rule == "NEGATIVE") {
    b.rule = FillRule::positive;
    for (auto* set : {&b.subjects, &b.clips})
      for (auto& r : *set) std::reverse(r.vertices.begin(), r.vertices.end());
  }
  return b;
}

}  // namespace locus_test
