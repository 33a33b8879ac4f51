// SPDX-License-Identifier: BSL-1.0
// Tests of io/svg.hpp. The emitted document is parsed by a small, strict XML parser written
// here (balanced tags, quoted attributes, known entities only), and every geometric claim is
// checked against an independent model: the world-to-pixel mapping is recomputed from the fixed
// view, line clipping is compared with dense sampling along the line, arcs are reconstructed
// with the SVG specification's endpoint-to-centre conversion, ellipses are checked through
// their implicit equation, and 3D projections through closed-form pinhole formulas.

#include <locus/io/svg.hpp>

#include "io/svg_xml.hpp"

#include "support/typed.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using locus::SvgAnchor;
using locus::SvgCamera;
using locus::SvgMarker;
using locus::SvgOptions;
using locus::SvgStyle;
using locus::SvgWriter;
using locus::Vec2;
using locus::Vec2d;
using locus::Vec3;
using locus::Vec3d;
using locus_test::Rng;

using namespace svg_test;

template <class T>
class SvgTyped : public ::testing::Test {};
TYPED_TEST_SUITE(SvgTyped, locus_test::RealTypes);

// ---- structure ---------------------------------------------------------------------------------

TEST(Svg, EmptyDrawingIsAValidDocument) {
  for (const char* bg : {"white", "none"}) {
    SvgOptions o;
    o.background = bg;
    SvgWriter w(o);
    const std::string doc = w.to_string();
    const Node root = parse_or_fail(doc);
    EXPECT_EQ(root.at("xmlns"), "http://www.w3.org/2000/svg");
    const double W = num(root, "width"), H = num(root, "height");
    EXPECT_GT(W, 0.0);
    EXPECT_GT(H, 0.0);
    const std::vector<double> vb = numbers_in(root.at("viewBox"));
    ASSERT_EQ(vb.size(), 4u);
    EXPECT_EQ(vb[0], 0.0);
    EXPECT_EQ(vb[1], 0.0);
    EXPECT_EQ(vb[2], W);
    EXPECT_EQ(vb[3], H);
    EXPECT_EQ(root.kids.size(), std::string(bg) == "none" ? 0u : 1u);
  }
}

TEST(Svg, TitleAndTextAreEscaped) {
  SvgOptions o;
  o.title = "a < b & \"c\"";
  SvgWriter w(o);
  const std::string label = "x<y & y>'z' \"q\"";
  w.text(Vec2d{0, 0}, label + "\x01\x7f");
  const Node root = parse_or_fail(w.to_string());
  const auto titles = elements(root, "title");
  ASSERT_EQ(titles.size(), 1u);
  EXPECT_EQ(titles[0]->text, o.title);
  const auto texts = elements(root, "text");
  ASSERT_EQ(texts.size(), 1u);
  EXPECT_EQ(texts[0]->text, label);  // control characters dropped
}

TEST(Svg, StylesAreEmitted) {
  SvgWriter w;
  SvgStyle s;
  s.stroke = "#ff0000";
  s.fill = "blue";
  s.width = 2.5;
  s.dash = {4, 2};
  s.opacity = 0.5;
  s.fill_opacity = 0.25;
  w.polyline(std::vector<Vec2d>{{0, 0}, {1, 0}, {1, 1}}, s, true);
  SvgStyle t;
  t.font_size = 20;
  t.anchor = SvgAnchor::middle;
  w.text(Vec2d{0.5, 0.5}, "label", t);
  SvgStyle bad;
  bad.dash = {1, std::nan("")};
  bad.width = -1;
  w.segment(Vec2d{0, 0}, Vec2d{1, 1}, bad);
  const Node root = parse_or_fail(w.to_string());
  const auto polys = elements(root, "polygon");
  ASSERT_EQ(polys.size(), 1u);
  EXPECT_EQ(polys[0]->at("stroke"), "#ff0000");
  EXPECT_EQ(polys[0]->at("fill"), "blue");
  EXPECT_EQ(num(*polys[0], "stroke-width"), 2.5);
  EXPECT_EQ(numbers_in(polys[0]->at("stroke-dasharray")), (std::vector<double>{4, 2}));
  EXPECT_EQ(num(*polys[0], "opacity"), 0.5);
  EXPECT_EQ(num(*polys[0], "fill-opacity"), 0.25);
  const auto texts = elements(root, "text");
  ASSERT_EQ(texts.size(), 1u);
  EXPECT_EQ(num(*texts[0], "font-size"), 20.0);
  EXPECT_EQ(texts[0]->at("text-anchor"), "middle");
  const auto lines = elements(root, "line");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_FALSE(lines[0]->has("stroke-dasharray"));  // invalid dash pattern dropped
  EXPECT_FALSE(lines[0]->has("stroke-width"));      // negative width dropped
}

TEST(Svg, MarkersHaveTheirShapes) {
  SvgWriter w;
  SvgStyle s;
  s.marker_size = 5;
  for (SvgMarker mk :
       {SvgMarker::circle, SvgMarker::square, SvgMarker::triangle, SvgMarker::cross}) {
    s.marker = mk;
    w.point(Vec2d{0, 0}, s);
  }
  const Node root = parse_or_fail(w.to_string());
  EXPECT_EQ(elements(root, "circle").size(), 1u);
  EXPECT_EQ(elements(root, "rect").size(), 2u);  // background + square
  EXPECT_EQ(elements(root, "polygon").size(), 1u);
  EXPECT_EQ(elements(root, "path").size(), 1u);
  const auto c = elements(root, "circle")[0];
  EXPECT_EQ(num(*c, "r"), 5.0);
}

// ---- non-finite input --------------------------------------------------------------------------

TYPED_TEST(SvgTyped, NonFiniteCoordinatesAreNeverEmitted) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const T big = std::numeric_limits<T>::max();
  SvgWriter w;
  int finite_points = 0;
  for (T x : {T(0), nan, inf, -inf, T(1)}) {
    for (T y : {T(0), nan, T(2)}) {
      w.point(Vec2<T>{x, y});
      if (std::isfinite(x) && std::isfinite(y)) ++finite_points;
    }
  }
  w.segment(Vec2<T>{0, 0}, Vec2<T>{nan, 1});
  w.arrow(Vec2<T>{inf, 0}, Vec2<T>{0, 1});
  w.line(Vec2<T>{0, 0}, Vec2<T>{nan, 1});
  w.line(Vec2<T>{0, 0}, Vec2<T>{0, 0});  // zero direction
  w.ray(Vec2<T>{inf, 0}, Vec2<T>{1, 1});
  w.circle(Vec2<T>{0, 0}, nan);
  w.circle(Vec2<T>{0, 0}, T(-1));
  w.circle(Vec2<T>{nan, 0}, T(1));
  w.ellipse(Vec2<T>{0, 0}, Vec2<T>{0, 0}, T(1), T(1));
  w.ellipse(Vec2<T>{0, 0}, Vec2<T>{1, 0}, inf, T(1));
  w.arc(Vec2<T>{0, 0}, T(1), T(0), nan);
  w.arc(Vec2<T>{0, 0}, T(1), T(1), T(1));  // empty span
  w.text(Vec2<T>{nan, 0}, "nan");
  // A polyline is split at its non-finite vertices; runs of one vertex vanish.
  w.polyline(
      std::vector<Vec2<T>>{{0, 0}, {1, 0}, {nan, 0}, {2, 0}, {nan, nan}, {3, 0}, {3, 1}, {4, 1}});
  // A polygon ring drops them.
  w.polygon(std::vector<Vec2<T>>{{0, 0}, {inf, 0}, {1, 0}, {1, 1}});
  const std::string doc = w.to_string();
  std::string lower = doc;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  });
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  EXPECT_EQ(lower.find("inf"), std::string::npos);
  const Node root = parse_or_fail(doc);
  EXPECT_EQ(static_cast<int>(elements(root, "circle").size()), finite_points);
  EXPECT_TRUE(elements(root, "line").empty());
  EXPECT_TRUE(elements(root, "ellipse").empty());
  EXPECT_TRUE(elements(root, "text").empty());
  const auto polylines = elements(root, "polyline");
  ASSERT_EQ(polylines.size(), 2u);
  EXPECT_EQ(point_list(polylines[0]->at("points")).size(), 2u);
  EXPECT_EQ(point_list(polylines[1]->at("points")).size(), 3u);
  const auto paths = elements(root, "path");
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(parse_path(paths[0]->at("d")).size(), 4u);  // M L L Z

  // Extreme but finite coordinates: the mapping may overflow; the output still never has inf.
  SvgWriter x;
  x.segment(Vec2<T>{-big, -big}, Vec2<T>{big, big});
  x.point(Vec2<T>{big, T(0)});
  x.circle(Vec2<T>{T(0), T(0)}, big);
  x.line(Vec2<T>{T(0), T(0)}, Vec2<T>{T(1), T(2)});
  const std::string doc2 = x.to_string();
  std::string lower2 = doc2;
  std::transform(lower2.begin(), lower2.end(), lower2.begin(), [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  });
  EXPECT_EQ(lower2.find("nan"), std::string::npos);
  EXPECT_EQ(lower2.find("inf"), std::string::npos);
  const Node root2 = parse_or_fail(doc2);
  for (const Node* n : elements(root2))
    for (const auto& [k, v] : n->attrs)
      if (k == "x" || k == "y" || k == "cx" || k == "cy" || k == "r" || k == "x1" || k == "y2") {
        EXPECT_TRUE(std::regex_match(v, number_re())) << k << "=" << v;
      }
}

// ---- mapping and view box ----------------------------------------------------------------------

TYPED_TEST(SvgTyped, YAxisPointsUpAndMappingIsUniform) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int rep = 0; rep < 20; ++rep) {
    const Vec2d lo{rng.uniform(-50.0, 0.0), rng.uniform(-50.0, 0.0)};
    const Vec2d hi = lo + Vec2d{rng.uniform(1.0, 60.0), rng.uniform(1.0, 60.0)};
    SvgOptions o;
    o.max_width = rng.uniform(100.0, 800.0);
    o.max_height = rng.uniform(100.0, 800.0);
    o.margin = rng.uniform(0.0, 30.0);
    o.background = "none";
    SvgWriter w(o);
    w.set_view(lo, hi);
    const Model md(lo, hi, o);
    std::vector<Vec2<T>> pts;
    for (int i = 0; i < 10; ++i) {
      pts.push_back(Vec2<T>{static_cast<T>(rng.uniform(lo.x, hi.x)),
                            static_cast<T>(rng.uniform(lo.y, hi.y))});
      w.point(pts.back());
    }
    const Node root = parse_or_fail(w.to_string());
    EXPECT_NEAR(num(root, "width"), md.w, kPx);
    EXPECT_NEAR(num(root, "height"), md.h, kPx);
    const auto cs = elements(root, "circle");
    ASSERT_EQ(cs.size(), pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec2d q = md.px(locus::vec_cast<double>(pts[i]));
      EXPECT_NEAR(num(*cs[i], "cx"), q.x, kPx);
      EXPECT_NEAR(num(*cs[i], "cy"), q.y, kPx);
      for (std::size_t j = 0; j < pts.size(); ++j)
        if (pts[i].y > pts[j].y + T(1e-2)) {
          EXPECT_LT(num(*cs[i], "cy"), num(*cs[j], "cy"));
        }
    }
  }
}

// Random geometry of every kind with the automatic view: every emitted coordinate lies in the
// document, and the fit is tight (the drawing touches the margin on the limiting axis).
TYPED_TEST(SvgTyped, AutomaticViewContainsEveryEmittedCoordinate) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int rep = 0; rep < 25; ++rep) {
    const double scale = std::pow(10.0, rng.uniform(-3.0, 4.0));
    const Vec2d off{rng.uniform(-1.0, 1.0) * scale * 5, rng.uniform(-1.0, 1.0) * scale * 5};
    auto rp = [&]() {
      return Vec2<T>{static_cast<T>(off.x + rng.uniform(-1.0, 1.0) * scale),
                     static_cast<T>(off.y + rng.uniform(-1.0, 1.0) * scale)};
    };
    auto rr = [&]() { return static_cast<T>(rng.uniform(0.05, 0.5) * scale); };
    // w gets everything; g only the bounded geometry without markers, arrow heads or labels,
    // whose extent the fitted view must match exactly.
    SvgWriter w, g;
    for (int i = 0; i < 3; ++i) {
      w.point(rp());
      w.arrow(rp(), rp());
      w.line(rp(), rp() - rp());
      w.ray(rp(), rp() - rp());
      w.text(rp(), "t");
      const Vec2<T> s0 = rp(), s1 = rp();
      const std::vector<Vec2<T>> pl{rp(), rp(), rp(), rp()};
      const std::vector<Vec2<T>> outer{rp(), rp(), rp()};
      const std::vector<std::vector<Vec2<T>>> holes{{rp(), rp(), rp()}};
      const Vec2<T> cc = rp(), ec = rp(), ea = rp() - rp(), ac = rp();
      const T cr = rr(), e0 = rr(), e1 = rr(), ar = rr();
      const T a0 = static_cast<T>(rng.uniform(-7.0, 7.0)),
              a1 = static_cast<T>(rng.uniform(-7.0, 7.0));
      for (SvgWriter* x : {&w, &g}) {
        x->segment(s0, s1);
        x->polyline(pl);
        x->polygon(outer, holes, SvgStyle{});
        x->circle(cc, cr);
        x->ellipse(ec, ea, e0, e1);
      }
      w.arc(ac, ar, a0, a1);  // covered_points sees only an arc's end points
    }
    const Node root = parse_or_fail(w.to_string());
    const double W = num(root, "width"), H = num(root, "height");
    for (const Node* n : elements(root)) {
      for (const Vec2d& q : covered_points(*n)) {
        EXPECT_GE(q.x, -kPx) << n->tag;
        EXPECT_LE(q.x, W + kPx) << n->tag;
        EXPECT_GE(q.y, -kPx) << n->tag;
        EXPECT_LE(q.y, H + kPx) << n->tag;
      }
    }
    // The bounded geometry alone: inside the inner box [m, W - m] x [m, H - m] and touching
    // both of its sides along the limiting axis (so the view is fitted, not merely enclosing).
    const Node groot = parse_or_fail(g.to_string());
    const double gw = num(groot, "width"), gh = num(groot, "height");
    const double m = g.options().margin;
    double minx = 1e300, maxx = -1e300, miny = 1e300, maxy = -1e300;
    for (const Node* n : elements(groot)) {
      if (n->tag == "rect") continue;  // background
      for (const Vec2d& q : covered_points(*n)) {
        minx = std::min(minx, q.x);
        maxx = std::max(maxx, q.x);
        miny = std::min(miny, q.y);
        maxy = std::max(maxy, q.y);
      }
    }
    // Circles and ellipses cover their exact bounding boxes (from the printed attributes).
    const double tol = 4 * kPx;
    EXPECT_NEAR(minx, m, tol);
    EXPECT_NEAR(maxx, gw - m, tol);
    EXPECT_NEAR(miny, m, tol);
    EXPECT_NEAR(maxy, gh - m, tol);
    const bool x_full = gw - 2 * m >= g.options().max_width - kPx;
    const bool y_full = gh - 2 * m >= g.options().max_height - kPx;
    EXPECT_TRUE(x_full || y_full) << gw << " x " << gh;
  }
}

// A long label at the right edge grows the canvas (the scale stays): its estimated extent,
// 0.6 em per character, fits the document, and the geometry keeps its pixel positions.
TEST(Svg, LabelsGrowTheCanvas) {
  SvgOptions o;
  o.background = "none";
  SvgWriter plain(o), labelled(o);
  for (SvgWriter* w : {&plain, &labelled}) w->segment(Vec2d{0, 0}, Vec2d{4, 2});
  SvgStyle ts;
  ts.font_size = 20;
  ts.text_dx = 0;
  ts.text_dy = 0;
  const std::string text = "a label much longer than the margin";
  labelled.text(Vec2d{4, 2}, text, ts);  // anchored at the top-right corner of the drawing
  ts.anchor = SvgAnchor::end;
  labelled.text(Vec2d{0, 0}, "left\u00b7label", ts);  // the middle dot counts as one character
  const Node a = parse_or_fail(plain.to_string());
  const Node b = parse_or_fail(labelled.to_string());
  const double wa = num(a, "width"), wb = num(b, "width"), hb = num(b, "height");
  EXPECT_GT(wb, wa);
  const auto texts = elements(b, "text");
  ASSERT_EQ(texts.size(), 2u);
  const double x0 = num(*texts[0], "x"), y0 = num(*texts[0], "y");
  EXPECT_LE(x0 + 0.6 * 20 * static_cast<double>(text.size()), wb + kPx);
  EXPECT_GE(y0 - 0.8 * 20, -kPx);
  const double x1 = num(*texts[1], "x");
  EXPECT_GE(x1 - 0.6 * 20 * 10, -kPx);
  EXPECT_LE(num(*texts[1], "y"), hb + kPx);
  // Same scale: the segment has the same pixel length in both documents.
  const auto la = elements(a, "line"), lb = elements(b, "line");
  ASSERT_EQ(la.size(), 1u);
  ASSERT_EQ(lb.size(), 1u);
  EXPECT_NEAR(num(*la[0], "x2") - num(*la[0], "x1"), num(*lb[0], "x2") - num(*lb[0], "x1"), kPx);
  EXPECT_NEAR(num(*la[0], "y2") - num(*la[0], "y1"), num(*lb[0], "y2") - num(*lb[0], "y1"), kPx);
  // The segment's start is pushed right by the left label's extent.
  EXPECT_GT(num(*lb[0], "x1"), num(*la[0], "x1"));
}

TEST(Svg, EllipseBoundsAreExact) {
  Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int rep = 0; rep < 50; ++rep) {
    const double a = rng.uniform(0.0, 2 * kPi), e0 = rng.uniform(0.5, 5.0),
                 e1 = rng.uniform(0.5, 5.0);
    SvgOptions o;
    o.max_width = o.max_height = 400;
    SvgWriter w(o);
    w.ellipse(Vec2d{1, 2}, Vec2d{std::cos(a), std::sin(a)} * 3.0, e0, e1);
    const auto mp = w.mapping();
    // Independent: the extent of c + e0 cos t u + e1 sin t v along x is max over t.
    double hx = 0, hy = 0;
    for (int i = 0; i < 20000; ++i) {
      const double t = 2 * kPi * i / 20000;
      const double x = e0 * std::cos(t) * std::cos(a) - e1 * std::sin(t) * std::sin(a);
      const double y = e0 * std::cos(t) * std::sin(a) + e1 * std::sin(t) * std::cos(a);
      hx = std::max(hx, std::abs(x));
      hy = std::max(hy, std::abs(y));
    }
    // Sampling every 2pi/20000 underestimates a maximum by at most r (1 - cos(pi/20000)).
    const double sample_tol = 5.0 * (1 - std::cos(kPi / 20000)) + 1e-12;
    EXPECT_NEAR(mp.inner_hi.x - mp.inner_lo.x, 2 * hx, 2 * sample_tol + 1e-12);
    EXPECT_NEAR(mp.inner_hi.y - mp.inner_lo.y, 2 * hy, 2 * sample_tol + 1e-12);
  }
}

TEST(Svg, DegenerateExtentsGiveAFiniteView) {
  SvgWriter one;
  one.point(Vec2d{3, 4});
  Node r1 = parse_or_fail(one.to_string());
  EXPECT_GT(num(r1, "width"), 2 * one.options().margin);
  const auto c = elements(r1, "circle");
  ASSERT_EQ(c.size(), 1u);
  // The lone point sits in the middle.
  EXPECT_NEAR(num(*c[0], "cx"), num(r1, "width") / 2, kPx);
  EXPECT_NEAR(num(*c[0], "cy"), num(r1, "height") / 2, kPx);

  SvgWriter flat;  // horizontal segment: zero height
  flat.segment(Vec2d{0, 1}, Vec2d{10, 1});
  Node r2 = parse_or_fail(flat.to_string());
  EXPECT_NEAR(num(r2, "height"), 2 * flat.options().margin, kPx);
  EXPECT_NEAR(num(r2, "width"), flat.options().max_width + 2 * flat.options().margin, kPx);

  SvgWriter only_line;  // nothing bounded but the base point
  only_line.line(Vec2d{0, 0}, Vec2d{1, 1});
  Node r3 = parse_or_fail(only_line.to_string());
  EXPECT_EQ(elements(r3, "line").size(), 1u);
}

// ---- line and ray clipping against a sampling oracle ------------------------------------------

TYPED_TEST(SvgTyped, LinesAndRaysAreClippedToTheView) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-10, -5}, hi{10, 5};
  SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  const Vec2d wl = md.win_lo(), wh = md.win_hi();
  int emitted = 0, missed = 0;
  for (int rep = 0; rep < 120; ++rep) {
    const bool is_ray = rep % 2 == 1;
    const Vec2<T> p{static_cast<T>(rng.uniform(-30.0, 30.0)),
                    static_cast<T>(rng.uniform(-30.0, 30.0))};
    Vec2<T> d = rng.unit<T, 2>() * static_cast<T>(rng.uniform(0.01, 100.0));
    if (rep % 17 == 0) d = Vec2<T>{T(0), T(3)};  // axis-parallel
    if (rep % 19 == 0) d = Vec2<T>{T(-2), T(0)};
    SvgWriter w(o);
    w.set_view(lo, hi);
    if (is_ray)
      w.ray(p, d);
    else
      w.line(p, d);
    const Node root = parse_or_fail(w.to_string());
    const auto lines = elements(root, "line");
    // Oracle: sample the line densely in the unit-direction parameter.
    const Vec2d pd = locus::vec_cast<double>(p);
    const Vec2d u = locus::normalize(locus::vec_cast<double>(d));
    const double reach = locus::length(pd) + locus::length(wh - wl) + 1;
    const int n = 40000;
    const double t_lo = is_ray ? 0.0 : -reach, dt = (reach - t_lo) / n;
    double smin = 1e300, smax = -1e300;
    for (int i = 0; i <= n; ++i) {
      const double t = t_lo + dt * i;
      const Vec2d q = pd + t * u;
      if (q.x >= wl.x && q.x <= wh.x && q.y >= wl.y && q.y <= wh.y) {
        smin = std::min(smin, t);
        smax = std::max(smax, t);
      }
    }
    const double tol = 2 * kPx / md.s;  // printed-pixel rounding in world units
    if (lines.empty()) {
      ++missed;
      EXPECT_GT(smin, smax) << "the line crosses the view but was not drawn";
      continue;
    }
    ++emitted;
    ASSERT_EQ(lines.size(), 1u);
    const Vec2d a = md.world({num(*lines[0], "x1"), num(*lines[0], "y1")});
    const Vec2d b = md.world({num(*lines[0], "x2"), num(*lines[0], "y2")});
    for (const Vec2d& q : {a, b}) {
      EXPECT_NEAR(locus::perp_dot(u, q - pd), 0.0, tol);  // on the line
      EXPECT_GE(q.x, wl.x - tol);
      EXPECT_LE(q.x, wh.x + tol);
      EXPECT_GE(q.y, wl.y - tol);
      EXPECT_LE(q.y, wh.y + tol);
    }
    double ta = locus::dot(a - pd, u), tb = locus::dot(b - pd, u);
    if (ta > tb) std::swap(ta, tb);
    if (is_ray) {
      EXPECT_GE(ta, -tol);
    }
    if (smin > smax) {
      EXPECT_LE(tb - ta, 2 * dt + tol);  // grazes a corner between samples
      continue;
    }
    EXPECT_LE(ta, smin + tol);
    EXPECT_GE(tb, smax - tol);
    EXPECT_GE(ta, smin - dt - tol);
    EXPECT_LE(tb, smax + dt + tol);
  }
  EXPECT_GT(emitted, 20);
  EXPECT_GT(missed, 5);
}

// ---- arcs, circles and ellipses -----------------------------------------------------------------

// SVG implementation notes F.6.5: endpoint parameterisation to centre parameterisation for a
// circular arc (rx = ry = r, no rotation). Returns the centre and the start and swept angles.
struct SvgArcCentre {
  Vec2d c;
  double theta1, dtheta;
};
SvgArcCentre svg_arc_centre(Vec2d p1, Vec2d p2, double r, bool large, bool sweep) {
  const double x1p = (p1.x - p2.x) / 2, y1p = (p1.y - p2.y) / 2;
  const double num_ = r * r * r * r - r * r * y1p * y1p - r * r * x1p * x1p;
  const double den = r * r * y1p * y1p + r * r * x1p * x1p;
  double coef = std::sqrt(std::max(0.0, num_ / den));
  if (large == sweep) coef = -coef;
  const double cxp = coef * y1p, cyp = -coef * x1p;
  const Vec2d c{cxp + (p1.x + p2.x) / 2, cyp + (p1.y + p2.y) / 2};
  auto angle = [](double ux, double uy, double vx, double vy) {
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  };
  const double ux = (x1p - cxp) / r, uy = (y1p - cyp) / r;
  const double vx = (-x1p - cxp) / r, vy = (-y1p - cyp) / r;
  const double t1 = angle(1, 0, ux, uy);
  double dt = angle(ux, uy, vx, vy);
  if (!sweep && dt > 0) dt -= 2 * kPi;
  if (sweep && dt < 0) dt += 2 * kPi;
  return {c, t1, dt};
}

TYPED_TEST(SvgTyped, ArcsMatchTheSvgCentreParameterisation) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-10, -10}, hi{10, 10};
  SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  for (int rep = 0; rep < 200; ++rep) {
    const Vec2<T> c{static_cast<T>(rng.uniform(-3.0, 3.0)), static_cast<T>(rng.uniform(-3.0, 3.0))};
    const T r = static_cast<T>(rng.uniform(2.0, 7.0));
    double span;
    do span = rng.uniform(0.1, 2 * kPi - 0.1);
    while (std::abs(span - kPi) < 0.3);  // the centre is ill-conditioned for a half circle
    const T a0 = static_cast<T>(rng.uniform(-10.0, 10.0));
    // Give the end angle either directly or wrapped below a0 (counter-clockwise either way).
    T a1 = static_cast<T>(static_cast<double>(a0) + span);
    if (rep % 3 == 1) a1 = static_cast<T>(static_cast<double>(a1) - 2 * kPi);
    if (rep % 3 == 2) a1 = static_cast<T>(static_cast<double>(a1) - 4 * kPi);
    // Exact span from the values actually passed (float rounding of a1 moves it slightly).
    double ex = std::fmod(static_cast<double>(a1) - static_cast<double>(a0), 2 * kPi);
    if (ex < 0) ex += 2 * kPi;
    SvgWriter w(o);
    w.set_view(lo, hi);
    w.arc(c, r, a0, a1);
    const Node root = parse_or_fail(w.to_string());
    const auto paths = elements(root, "path");
    ASSERT_EQ(paths.size(), 1u);
    const auto cmds = parse_path(paths[0]->at("d"));
    ASSERT_EQ(cmds.size(), 2u);
    ASSERT_EQ(cmds[0].op, 'M');
    ASSERT_EQ(cmds[1].op, 'A');
    ASSERT_EQ(cmds[1].v.size(), 7u);
    const Vec2d cd = locus::vec_cast<double>(c);
    const double rd = static_cast<double>(r), a0d = static_cast<double>(a0);
    const Vec2d p0 = md.px(cd + rd * Vec2d{std::cos(a0d), std::sin(a0d)});
    const Vec2d p1 = md.px(cd + rd * Vec2d{std::cos(a0d + ex), std::sin(a0d + ex)});
    const Vec2d m0{cmds[0].v.at(0), cmds[0].v.at(1)};
    const Vec2d m1{cmds[1].v[5], cmds[1].v[6]};
    EXPECT_NEAR(m0.x, p0.x, kPx);
    EXPECT_NEAR(m0.y, p0.y, kPx);
    EXPECT_NEAR(m1.x, p1.x, kPx);
    EXPECT_NEAR(m1.y, p1.y, kPx);
    EXPECT_NEAR(cmds[1].v[0], rd * md.s, kPx);
    EXPECT_NEAR(cmds[1].v[1], rd * md.s, kPx);
    const bool large = cmds[1].v[3] != 0, sweep = cmds[1].v[4] != 0;
    const SvgArcCentre sc = svg_arc_centre(m0, m1, cmds[1].v[0], large, sweep);
    const Vec2d pc = md.px(cd);
    EXPECT_NEAR(sc.c.x, pc.x, 0.05);  // endpoint rounding, amplified by at most tan(span/2)
    EXPECT_NEAR(sc.c.y, pc.y, 0.05);
    // The drawn arc's midpoint is the world arc's midpoint.
    const double tm = sc.theta1 + sc.dtheta / 2;
    const Vec2d mid_svg = sc.c + cmds[1].v[0] * Vec2d{std::cos(tm), std::sin(tm)};
    const Vec2d mid_world = md.px(cd + rd * Vec2d{std::cos(a0d + ex / 2), std::sin(a0d + ex / 2)});
    EXPECT_NEAR(mid_svg.x, mid_world.x, 0.1);
    EXPECT_NEAR(mid_svg.y, mid_world.y, 0.1);
  }
  // A full turn (or more) is a closed circle drawn as two half arcs.
  for (double turn : {2 * kPi, 2 * kPi + 1, 20.0}) {
    SvgWriter w(o);
    w.set_view(lo, hi);
    w.arc(Vec2<T>{1, 1}, T(3), T(0.5), static_cast<T>(0.5 + turn));
    const Node root = parse_or_fail(w.to_string());
    const auto cmds = parse_path(elements(root, "path").at(0)->at("d"));
    ASSERT_EQ(cmds.size(), 3u);
    const Vec2d start{cmds[0].v.at(0), cmds[0].v.at(1)};
    const Vec2d back{cmds[2].v.at(5), cmds[2].v.at(6)};
    EXPECT_NEAR(start.x, back.x, kPx);
    EXPECT_NEAR(start.y, back.y, kPx);
    const Vec2d half = md.px(Vec2d{1, 1} + 3.0 * Vec2d{std::cos(0.5 + kPi), std::sin(0.5 + kPi)});
    EXPECT_NEAR(cmds[1].v.at(5), half.x, kPx);
    EXPECT_NEAR(cmds[1].v.at(6), half.y, kPx);
  }
}

TYPED_TEST(SvgTyped, CirclesAndEllipsesMatchTheirWorldShapes) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-10, -10}, hi{10, 10};
  SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  for (int rep = 0; rep < 100; ++rep) {
    const Vec2<T> c{static_cast<T>(rng.uniform(-3.0, 3.0)), static_cast<T>(rng.uniform(-3.0, 3.0))};
    const Vec2<T> ax = rng.unit<T, 2>() * static_cast<T>(rng.uniform(0.1, 10.0));
    const T e0 = static_cast<T>(rng.uniform(1.0, 6.0)), e1 = static_cast<T>(rng.uniform(1.0, 6.0));
    SvgWriter w(o);
    w.set_view(lo, hi);
    w.circle(c, e0);
    w.ellipse(c, ax, e0, e1);
    const Node root = parse_or_fail(w.to_string());
    const auto circles = elements(root, "circle");
    const auto ellipses = elements(root, "ellipse");
    ASSERT_EQ(circles.size(), 1u);
    ASSERT_EQ(ellipses.size(), 1u);
    const Vec2d pc = md.px(locus::vec_cast<double>(c));
    EXPECT_NEAR(num(*circles[0], "cx"), pc.x, kPx);
    EXPECT_NEAR(num(*circles[0], "cy"), pc.y, kPx);
    EXPECT_NEAR(num(*circles[0], "r"), static_cast<double>(e0) * md.s, kPx);
    // Every world point of the ellipse satisfies the implicit equation of the SVG ellipse.
    const Node& e = *ellipses[0];
    const double cx = num(e, "cx"), cy = num(e, "cy"), rx = num(e, "rx"), ry = num(e, "ry");
    const std::vector<double> tr = numbers_in(e.at("transform"));
    ASSERT_EQ(tr.size(), 3u);
    EXPECT_NEAR(tr[1], cx, kPx);
    EXPECT_NEAR(tr[2], cy, kPx);
    const double ang = tr[0] * kPi / 180.0;
    const Vec2d u = locus::normalize(locus::vec_cast<double>(ax)), v = locus::perp(u);
    for (int i = 0; i < 16; ++i) {
      const double t = 2 * kPi * i / 16;
      const Vec2d wp = locus::vec_cast<double>(c) + static_cast<double>(e0) * std::cos(t) * u +
                       static_cast<double>(e1) * std::sin(t) * v;
      const Vec2d q = md.px(wp) - Vec2d{cx, cy};
      // Undo rotate(ang): SVG's rotation matrix is [cos -sin; sin cos] in its y-down frame.
      const double qx = std::cos(ang) * q.x + std::sin(ang) * q.y;
      const double qy = -std::sin(ang) * q.x + std::cos(ang) * q.y;
      // rx, ry >= 24 px: printed rounding changes the value by at most ~1e-4.
      EXPECT_NEAR(locus::sqr(qx / rx) + locus::sqr(qy / ry), 1.0, 1e-3) << "t = " << t;
    }
  }
}

TEST(Svg, PolygonWithHolesUsesEvenOdd) {
  SvgWriter w;
  const std::vector<Vec2d> outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<std::vector<Vec2d>> holes{{{2, 2}, {4, 2}, {4, 4}},
                                              {{6, 6}, {8, 6}, {8, 8}, {6, 8}}};
  SvgStyle s;
  s.fill = "gray";
  w.polygon(outer, holes, s);
  const Node root = parse_or_fail(w.to_string());
  const auto paths = elements(root, "path");
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0]->at("fill-rule"), "evenodd");
  EXPECT_EQ(paths[0]->at("fill"), "gray");
  const auto cmds = parse_path(paths[0]->at("d"));
  std::vector<int> ring_sizes;
  for (const PathCmd& c : cmds) {
    if (c.op == 'M')
      ring_sizes.push_back(1);
    else if (c.op == 'L')
      ++ring_sizes.back();
  }
  EXPECT_EQ(ring_sizes, (std::vector<int>{4, 3, 4}));
  EXPECT_EQ(std::count_if(cmds.begin(), cmds.end(), [](const PathCmd& c) { return c.op == 'Z'; }),
            3);
}

TEST(Svg, ArrowHeadEndsAtTheTip) {
  const Vec2d lo{0, 0}, hi{10, 10};
  SvgOptions o;
  const Model md(lo, hi, o);
  SvgWriter w(o);
  w.set_view(lo, hi);
  w.arrow(Vec2d{1, 1}, Vec2d{8, 5});
  w.arrow(Vec2d{3, 3}, Vec2d{3, 3});  // zero vector: a dot
  const Node root = parse_or_fail(w.to_string());
  const auto polys = elements(root, "polygon");
  ASSERT_EQ(polys.size(), 1u);
  const auto pts = point_list(polys[0]->at("points"));
  ASSERT_EQ(pts.size(), 3u);
  const Vec2d tip = md.px({8, 5});
  EXPECT_NEAR(pts[0].x, tip.x, kPx);
  EXPECT_NEAR(pts[0].y, tip.y, kPx);
  // The head is symmetric about the shaft.
  const Vec2d tail = md.px({1, 1});
  const Vec2d dir = locus::normalize(tip - tail);
  EXPECT_NEAR(locus::perp_dot(dir, pts[1] - tip), -locus::perp_dot(dir, pts[2] - tip), 4 * kPx);
  EXPECT_EQ(elements(root, "circle").size(), 1u);
}

// ---- files ---------------------------------------------------------------------------------

TEST(Svg, WritesFilesAndReportsIoErrors) {
  SvgWriter w;
  w.circle(Vec2d{0, 0}, 1.0);
  const auto dir = std::filesystem::temp_directory_path();
  const std::string path =
      (dir / ("locus_svg_test_" + std::to_string(Rng().engine()()) + ".svg")).string();
  ASSERT_EQ(w.write_file(path), locus::Status::ok);
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  EXPECT_EQ(ss.str(), w.to_string());
  std::filesystem::remove(path);
  EXPECT_EQ(w.write_file((dir / "no_such_dir_locus" / "x" / "y.svg").string()),
            locus::Status::io_error);
  EXPECT_EQ(w.write_file(""), locus::Status::io_error);
}

// ---- 3D ------------------------------------------------------------------------------------

TYPED_TEST(SvgTyped, OrthographicCameraMatchesTheShadow) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-5, -5}, hi{5, 5};
  // Looking down -z from above: the image is the (x, y) shadow.
  SvgWriter w3, w2;
  w3.set_view(lo, hi);
  w2.set_view(lo, hi);
  SvgCamera cam;
  cam.eye = {0, 0, 10};
  cam.target = {0, 0, 0};
  cam.up = {0, 1, 0};
  cam.ortho_height = 2;
  w3.set_camera(cam);
  for (int i = 0; i < 20; ++i) {
    const Vec3<T> a = rng.vec<T, 3>(T(-4), T(4)), b = rng.vec<T, 3>(T(-4), T(4));
    w3.segment(a, b);
    w2.segment(Vec2<T>{a.x, a.y}, Vec2<T>{b.x, b.y});
    w3.point(a);
    w2.point(Vec2<T>{a.x, a.y});
  }
  EXPECT_EQ(w3.to_string(), w2.to_string());

  // Looking along -x with up = z: image x = y_world... right = f x up = (-1,0,0) x (0,0,1) =
  // (0,1,0).
  SvgWriter s3, s2;
  s3.set_view(lo, hi);
  s2.set_view(lo, hi);
  cam.eye = {10, 0, 0};
  cam.up = {0, 0, 1};
  s3.set_camera(cam);
  for (int i = 0; i < 20; ++i) {
    const Vec3<T> a = rng.vec<T, 3>(T(-4), T(4));
    s3.point(a);
    s2.point(Vec2<T>{a.y, a.z});
  }
  EXPECT_EQ(s3.to_string(), s2.to_string());
}

TYPED_TEST(SvgTyped, PerspectiveCameraMatchesThePinholeModel) {
  using T = TypeParam;
  Rng rng;
  SCOPED_TRACE(rng.trace());
  const Vec2d lo{-2, -2}, hi{2, 2};
  SvgOptions o;
  o.background = "none";
  const Model md(lo, hi, o);
  SvgCamera cam;
  cam.eye = {0, 0, 5};
  cam.target = {0, 0, 0};
  cam.up = {0, 1, 0};
  cam.perspective = true;
  cam.fov_y = kPi / 2;  // tan(fov/2) = 1: image = (x, y) / depth
  cam.near = 0.5;
  SvgWriter w(o);
  w.set_view(lo, hi);
  w.set_camera(cam);
  EXPECT_TRUE(w.camera().perspective);
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 20; ++i) {
    pts.push_back(rng.vec<T, 3>(T(-3), T(3)));
    w.point(pts.back());
  }
  w.point(Vec3<T>{0, 0, 6});       // behind the eye
  w.point(Vec3<T>{0, 0, T(4.8)});  // in front of the eye but before the near plane
  const Node root = parse_or_fail(w.to_string());
  const auto cs = elements(root, "circle");
  ASSERT_EQ(cs.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec3d p = locus::vec_cast<double>(pts[i]);
    const double depth = 5 - p.z;
    const Vec2d q = md.px({p.x / depth, p.y / depth});
    EXPECT_NEAR(num(*cs[i], "cx"), q.x, 2 * kPx);
    EXPECT_NEAR(num(*cs[i], "cy"), q.y, 2 * kPx);
  }

  // A segment through the near plane is clipped there: the visible part ends at depth = near.
  SvgWriter c(o);
  c.set_view(lo, hi);
  c.set_camera(cam);
  c.segment(Vec3<T>{T(0.2), T(0.1), T(0)}, Vec3<T>{T(0.2), T(0.1), T(8)});
  c.segment(Vec3<T>{T(0.2), T(0.1), T(6)}, Vec3<T>{T(0.2), T(0.1), T(8)});  // all behind
  const Node rc = parse_or_fail(c.to_string());
  const auto lines = elements(rc, "line");
  ASSERT_EQ(lines.size(), 1u);
  const Vec2d a = md.world({num(*lines[0], "x1"), num(*lines[0], "y1")});
  const Vec2d b = md.world({num(*lines[0], "x2"), num(*lines[0], "y2")});
  EXPECT_NEAR(a.x, 0.2 / 5, 1e-3);
  EXPECT_NEAR(a.y, 0.1 / 5, 1e-3);
  EXPECT_NEAR(b.x, 0.2 / 0.5, 1e-3);
  EXPECT_NEAR(b.y, 0.1 / 0.5, 1e-3);

  // An unusable camera is ignored.
  SvgCamera bad = cam;
  bad.target = bad.eye;
  c.set_camera(bad);
  EXPECT_EQ(c.camera().target, cam.target);
  bad = cam;
  bad.near = -1;
  c.set_camera(bad);
  EXPECT_EQ(c.camera().near, cam.near);
}

TYPED_TEST(SvgTyped, ClosedPolyline3DThroughTheNearPlaneBecomesSegments) {
  using T = TypeParam;
  SvgCamera cam;
  cam.eye = {0, 0, 5};
  cam.perspective = true;
  cam.fov_y = 1.0;
  cam.near = 1.0;
  SvgWriter w;
  w.set_camera(cam);
  // A square crossing the near plane: two edges fully visible, two clipped, none behind.
  const std::vector<Vec3<T>> sq{{-1, 0, 0}, {1, 0, 0}, {1, 0, 10}, {-1, 0, 10}};
  w.polyline(sq, SvgStyle{}, true);
  // A fully visible square stays one polygon element.
  const std::vector<Vec3<T>> vis{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  w.polyline(vis, SvgStyle{}, true);
  const Node root = parse_or_fail(w.to_string());
  EXPECT_EQ(elements(root, "line").size(), 3u);  // the far edge is entirely behind the eye
  EXPECT_EQ(elements(root, "polygon").size(), 1u);
}

}  // namespace
