// SPDX-License-Identifier: BSL-1.0
#pragma once
// Test support for io/svg.hpp and the gallery: a strict little XML parser (balanced tags, quoted
// attributes, known entities only, no control characters), helpers that read the numbers the
// writer prints, and an independent model of the world-to-pixel mapping of a fixed view.

#include <locus/io/svg.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace svg_test {

using locus::SvgOptions;
using locus::Vec2d;

constexpr double kPi = 3.14159265358979323846;

// ---- a strict little XML parser ----------------------------------------------------------------

struct Node {
  std::string tag;
  std::map<std::string, std::string> attrs;
  std::vector<Node> kids;
  std::string text;
  bool has(const std::string& a) const { return attrs.count(a) != 0; }
  const std::string& at(const std::string& a) const { return attrs.at(a); }
};

class XmlParser {
 public:
  explicit XmlParser(const std::string& s) : s_(s) {}
  std::optional<Node> parse() {
    if (s_.compare(0, 5, "<?xml") != 0) return fail("no XML declaration");
    const auto e = s_.find("?>");
    if (e == std::string::npos) return fail("unterminated declaration");
    i_ = e + 2;
    ws();
    Node root;
    if (!element(root)) return std::nullopt;
    ws();
    if (i_ != s_.size()) return fail("content after the root element");
    return root;
  }
  const std::string& error() const { return err_; }

 private:
  std::optional<Node> fail(const std::string& m) {
    if (err_.empty()) err_ = m + " at offset " + std::to_string(i_);
    return std::nullopt;
  }
  bool failb(const std::string& m) {
    fail(m);
    return false;
  }
  void ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool name(std::string& out) {
    const std::size_t b = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' ||
                              s_[i_] == '_' || s_[i_] == ':'))
      ++i_;
    if (i_ == b || std::isdigit(static_cast<unsigned char>(s_[b])) || s_[b] == '-')
      return failb("bad name");
    out = s_.substr(b, i_ - b);
    return true;
  }
  bool decode(std::size_t b, std::size_t e, std::string& out) {
    for (std::size_t k = b; k < e; ++k) {
      const char c = s_[k];
      if (c == '<') return failb("'<' in text");
      const auto u = static_cast<unsigned char>(c);
      if (u < 0x20 && c != '\t' && c != '\n' && c != '\r') return failb("control character");
      if (c != '&') {
        out += c;
        continue;
      }
      const auto semi = s_.find(';', k);
      if (semi == std::string::npos || semi > e) return failb("unterminated entity");
      const std::string ent = s_.substr(k + 1, semi - k - 1);
      if (ent == "amp")
        out += '&';
      else if (ent == "lt")
        out += '<';
      else if (ent == "gt")
        out += '>';
      else if (ent == "quot")
        out += '"';
      else if (ent == "apos")
        out += '\'';
      else
        return failb("unknown entity &" + ent + ";");
      k = semi;
    }
    return true;
  }
  bool element(Node& n) {
    if (i_ >= s_.size() || s_[i_] != '<') return failb("expected '<'");
    ++i_;
    if (!name(n.tag)) return false;
    for (;;) {
      const std::size_t before = i_;
      ws();
      if (i_ >= s_.size()) return failb("unterminated tag");
      if (s_[i_] == '/') {
        if (s_.compare(i_, 2, "/>") != 0) return failb("bad '/'");
        i_ += 2;
        return true;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      if (i_ == before) return failb("attributes must be separated by space");
      std::string an;
      if (!name(an)) return false;
      if (i_ >= s_.size() || s_[i_] != '=') return failb("expected '='");
      ++i_;
      if (i_ >= s_.size() || s_[i_] != '"') return failb("expected quote");
      const auto close = s_.find('"', i_ + 1);
      if (close == std::string::npos) return failb("unterminated attribute");
      std::string val;
      if (!decode(i_ + 1, close, val)) return false;
      if (n.attrs.count(an)) return failb("duplicate attribute " + an);
      n.attrs[an] = val;
      i_ = close + 1;
    }
    // content
    for (;;) {
      const auto lt = s_.find('<', i_);
      if (lt == std::string::npos) return failb("unterminated element " + n.tag);
      if (!decode(i_, lt, n.text)) return false;
      i_ = lt;
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        std::string closing;
        if (!name(closing)) return false;
        if (closing != n.tag) return failb("mismatched </" + closing + "> for <" + n.tag + ">");
        ws();
        if (i_ >= s_.size() || s_[i_] != '>') return failb("expected '>'");
        ++i_;
        return true;
      }
      Node kid;
      if (!element(kid)) return false;
      n.kids.push_back(std::move(kid));
    }
  }

  const std::string& s_;
  std::size_t i_ = 0;
  std::string err_;
};

// Parses or fails the calling test.
inline Node parse_or_fail(const std::string& doc) {
  XmlParser p(doc);
  std::optional<Node> n = p.parse();
  EXPECT_TRUE(n.has_value()) << p.error() << "\n" << doc.substr(0, 2000);
  if (!n) return Node{};
  EXPECT_EQ(n->tag, "svg");
  return *n;
}

inline void flatten(const Node& n, std::vector<const Node*>& out) {
  for (const Node& k : n.kids) {
    out.push_back(&k);
    flatten(k, out);
  }
}
inline std::vector<const Node*> elements(const Node& root, const std::string& tag = "") {
  std::vector<const Node*> all, out;
  flatten(root, all);
  for (const Node* n : all)
    if (tag.empty() || n->tag == tag) out.push_back(n);
  return out;
}

// Every number the writer prints: optional minus, digits, optional fraction. No exponent, no
// nan/inf, no locale-dependent comma.
inline const std::regex& number_re() {
  static const std::regex re("-?[0-9]+(\\.[0-9]+)?");
  return re;
}
inline std::vector<double> numbers_in(const std::string& s) {
  std::vector<double> v;
  static const std::regex tok("-?[0-9]+(\\.[0-9]+)?");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), tok); it != std::sregex_iterator(); ++it)
    v.push_back(std::stod(it->str()));
  return v;
}
inline double num(const Node& n, const std::string& a) {
  EXPECT_TRUE(n.has(a)) << n.tag << " lacks " << a;
  if (!n.has(a)) return std::numeric_limits<double>::quiet_NaN();
  const std::string& s = n.at(a);
  EXPECT_TRUE(std::regex_match(s, number_re())) << a << "=\"" << s << "\"";
  return std::stod(s);
}
inline std::vector<Vec2d> point_list(const std::string& s) {
  const std::vector<double> v = numbers_in(s);
  EXPECT_EQ(v.size() % 2, 0u);
  std::vector<Vec2d> p;
  for (std::size_t i = 0; i + 1 < v.size(); i += 2) p.push_back({v[i], v[i + 1]});
  return p;
}

// A path 'd' as commands with their numbers.
struct PathCmd {
  char op;
  std::vector<double> v;
};
inline std::vector<PathCmd> parse_path(const std::string& d) {
  std::vector<PathCmd> cmds;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const char c = d[i];
    if (std::isalpha(static_cast<unsigned char>(c))) {
      cmds.push_back({c, {}});
      continue;
    }
    if (c == ' ' || c == ',') continue;
    std::size_t j = i;
    while (j < d.size() &&
           (std::isdigit(static_cast<unsigned char>(d[j])) || d[j] == '-' || d[j] == '.'))
      ++j;
    EXPECT_GT(j, i) << "unexpected character '" << c << "' in path " << d;
    if (j == i || cmds.empty()) return cmds;
    const std::string tok = d.substr(i, j - i);
    EXPECT_TRUE(std::regex_match(tok, number_re())) << tok;
    cmds.back().v.push_back(std::stod(tok));
    i = j - 1;
  }
  return cmds;
}

// The pixel points an element covers (for the containment check).
inline std::vector<Vec2d> covered_points(const Node& n) {
  std::vector<Vec2d> p;
  if (n.tag == "line") {
    p.push_back({num(n, "x1"), num(n, "y1")});
    p.push_back({num(n, "x2"), num(n, "y2")});
  } else if (n.tag == "polyline" || n.tag == "polygon") {
    p = point_list(n.at("points"));
  } else if (n.tag == "circle") {
    const double cx = num(n, "cx"), cy = num(n, "cy"), r = num(n, "r");
    p = {{cx - r, cy - r}, {cx + r, cy + r}};
  } else if (n.tag == "rect") {
    const double x = num(n, "x"), y = num(n, "y"), w = num(n, "width"), h = num(n, "height");
    p = {{x, y}, {x + w, y + h}};
  } else if (n.tag == "ellipse") {
    const double cx = num(n, "cx"), cy = num(n, "cy"), rx = num(n, "rx"), ry = num(n, "ry");
    const std::vector<double> t = numbers_in(n.at("transform"));
    const double a = t.at(0) * kPi / 180.0;
    const double hx = std::hypot(rx * std::cos(a), ry * std::sin(a));
    const double hy = std::hypot(rx * std::sin(a), ry * std::cos(a));
    p = {{cx - hx, cy - hy}, {cx + hx, cy + hy}};
  } else if (n.tag == "path") {
    for (const PathCmd& c : parse_path(n.at("d"))) {
      if (c.op == 'M' || c.op == 'L')
        for (std::size_t i = 0; i + 1 < c.v.size(); i += 2) p.push_back({c.v[i], c.v[i + 1]});
      if (c.op == 'A') p.push_back({c.v.at(5), c.v.at(6)});
    }
  } else if (n.tag == "text") {
    p.push_back({num(n, "x"), num(n, "y")});
  }
  return p;
}

// Independent model of the fixed-view mapping (header comment of svg.hpp).
struct Model {
  Vec2d lo, hi;
  double s, m, w, h;
  Model(Vec2d lo_, Vec2d hi_, const SvgOptions& o = {}) : lo(lo_), hi(hi_) {
    s = std::min(o.max_width / (hi.x - lo.x), o.max_height / (hi.y - lo.y));
    m = o.margin;
    w = (hi.x - lo.x) * s + 2 * m;
    h = (hi.y - lo.y) * s + 2 * m;
  }
  Vec2d px(const Vec2d& p) const { return {(p.x - lo.x) * s + m, (hi.y - p.y) * s + m}; }
  Vec2d world(const Vec2d& q) const { return {(q.x - m) / s + lo.x, hi.y - (q.y - m) / s}; }
  Vec2d win_lo() const { return lo - Vec2d{m / s, m / s}; }
  Vec2d win_hi() const { return hi + Vec2d{m / s, m / s}; }
};

// Printed numbers carry 3 decimals: half a unit of the last place, plus a little for the maths.
constexpr double kPx = 1.5e-3;

}  // namespace svg_test
