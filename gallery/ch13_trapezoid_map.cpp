// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13.9.2: the horizontal trapezoidal decomposition built by inserting the edges
// of a polygon one at a time (figures 13.57-13.67). Every state is a live locus::TrapezoidMap2
// (the book's order: split_at for each new endpoint, then insert, no merging until merge());
// unbounded trapezoids are clipped to the view box by trapezoid_map_corners. A figure fails when
// a step's status is not ok, the clipped trapezoids do not tile the box (area sum), or locate()
// of a trapezoid's centre does not return that trapezoid.
#include "ch13_sample.hpp"
#include "gallery.hpp"

#include <locus/triangulate/trapezoid_map.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;
using Seg = std::array<std::uint32_t, 2>;

// The book's sample polygon (13.56, ch13_sample.hpp); its edges in the (random) insertion order
// s1 .. s9.
const std::vector<Vec2d>& tz_points = sample_polygon_points;
const std::vector<Seg>& tz_segments = sample_polygon_edges;
const Vec2d box_lo{-1.2, -1.4}, box_hi{10.2, 8.6};

// One step of the book's construction: split at endpoint `end` of segment `seg`, or insert it.
struct Step {
  std::uint32_t seg;
  int end;  // 0 or 1: split at that endpoint; -1: insert the segment
};

struct State {
  TrapezoidMap2<double> map;
  bool ok = true;
  std::uint32_t inserted = 0;  // segments s1 .. s(inserted) are in the map
};

// The map after the given steps (and merge() when asked).
void replay(State& s, const std::vector<Step>& steps, bool merge) {
  s.ok = s.map.begin(std::span<const Vec2d>(tz_points), tz_segments,
                     TrapezoidMapOptions{false, 0}) == Status::ok;
  for (const Step& st : steps) {
    if (st.end >= 0) {
      s.ok = s.ok && s.map.split_at(tz_segments[st.seg][std::size_t(st.end)]) == Status::ok;
    } else {
      s.ok = s.ok && s.map.insert(st.seg) == Status::ok;
      s.inserted = st.seg + 1;
    }
  }
  if (merge) s.map.merge();
}

double twice_area(const std::array<Vec2d, 4>& q) {
  double a = 0;
  for (std::size_t i = 0; i < 4; ++i) a += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
  return a;
}

// Draws a state; `new_point` (or none) marks the split just made, `new_segment` the insertion.
bool draw_state(SvgWriter& w, const State& s, std::uint32_t new_point, std::uint32_t new_segment) {
  if (!s.ok) return false;
  w.set_view(box_lo - Vec2d{0.2, 0.6}, box_hi + Vec2d{0.2, 0.2});
  const std::span<const Vec2d> pts(tz_points);
  const char* cols[] = {c::blue, c::green, c::orange, c::purple, c::red};
  double sum = 0;
  const auto traps = s.map.trapezoids();
  for (std::size_t i = 0; i < traps.size(); ++i) {
    const auto q =
        trapezoid_map_corners(pts, std::span<const Seg>(tz_segments), traps[i], box_lo, box_hi);
    sum += twice_area(q);
    w.polygon(std::vector<Vec2d>(q.begin(), q.end()), filled(cols[i % 5], 0.16, 0.8));
    // The centre of a trapezoid with positive area must locate back to it.
    if (twice_area(q) > 1e-6 && s.map.locate(0.25 * (q[0] + q[1] + q[2] + q[3])) != i) return false;
    // Its horizontal sides that end at a point are drawn as split lines.
    if (traps[i].top != trapezoid_unbounded) w.segment(q[3], q[2], pen(c::gray, 0.8));
    if (traps[i].top == new_point && new_point != trapezoid_unbounded)
      w.segment(q[3], q[2], pen(c::red, 2.4));
  }
  const double box = 2 * (box_hi.x - box_lo.x) * (box_hi.y - box_lo.y);
  if (std::abs(sum - box) > 1e-9 * box) return false;
  for (std::uint32_t k = 0; k < tz_segments.size(); ++k) {
    const Vec2d a = tz_points[tz_segments[k][0]], b = tz_points[tz_segments[k][1]];
    const bool in = k < s.inserted;
    w.segment(a, b,
              k == new_segment ? pen(c::red, 2.8)
              : in             ? pen(c::black, 2.2)
                               : dashed(c::light, 1.2));
    label(w, 0.5 * (a + b), "s" + std::to_string(k + 1), in ? c::black : c::gray, 4, 4);
  }
  for (std::uint32_t p = 0; p < tz_points.size(); ++p) w.point(tz_points[p], dot(c::black, 2.6));
  w.text(Vec2d{box_lo.x, box_lo.y - 0.45},
         std::to_string(traps.size()) + (traps.size() == 1 ? " trapezoid" : " trapezoids"),
         text_style(c::black, 0, 0));
  return true;
}

// The steps of figures 13.58 .. 13.65 in order, then s4 .. s9 inserted whole.
std::vector<Step> book_steps(std::size_t count) {
  std::vector<Step> all{{0, 0}, {0, 1}, {0, -1}, {1, 1}, {1, 0}, {1, -1}, {2, 1}, {2, -1}};
  for (std::uint32_t k = 3; k < tz_segments.size(); ++k) all.push_back({k, -1});
  all.resize(std::min(count, all.size()));
  return all;
}

bool figure_after(SvgWriter& w, std::size_t count, bool merge = false) {
  State s;
  const std::vector<Step> steps = book_steps(count);
  replay(s, steps, merge);
  std::uint32_t new_point = trapezoid_unbounded, new_segment = trapezoid_unbounded;
  if (!steps.empty() && !merge) {
    const Step& last = steps.back();
    if (last.end >= 0)
      new_point = s.map.canonical(tz_segments[last.seg][std::size_t(last.end)]);
    else
      new_segment = last.seg;
  }
  return draw_state(w, s, new_point, new_segment);
}

// 13.57: before any split the whole plane is one trapezoid (the edges to come dashed).
bool fig_13_57(SvgWriter& w) { return figure_after(w, 0); }
bool fig_13_58(SvgWriter& w) { return figure_after(w, 1); }
bool fig_13_59(SvgWriter& w) { return figure_after(w, 2); }
bool fig_13_60(SvgWriter& w) { return figure_after(w, 3); }
bool fig_13_61(SvgWriter& w) { return figure_after(w, 4); }
bool fig_13_62(SvgWriter& w) { return figure_after(w, 5); }
bool fig_13_63(SvgWriter& w) { return figure_after(w, 6); }
// 13.64: s3 shares its first endpoint with s1, so only its second one splits.
bool fig_13_64(SvgWriter& w) { return figure_after(w, 7); }
bool fig_13_65(SvgWriter& w) { return figure_after(w, 8); }
// 13.66: every edge inserted (s4 .. s8 like s1 .. s3); no merging yet.
bool fig_13_66(SvgWriter& w) { return figure_after(w, 99); }
// 13.67: merge() joins vertically adjacent trapezoids with the same left and right edges.
bool fig_13_67(SvgWriter& w) { return figure_after(w, 99, true); }

}  // namespace

std::vector<Figure> chapter13_trapmap_figures() {
  const char* split = "TrapezoidMap2::split_at, locate, trapezoid_map_corners";
  const char* insert = "TrapezoidMap2::insert, locate, trapezoid_map_corners";
  return {
      {"13.57", "TrapezoidMap2::begin (the plane), trapezoid_map_corners", fig_13_57},
      {"13.58", split, fig_13_58},
      {"13.59", split, fig_13_59},
      {"13.60", insert, fig_13_60},
      {"13.61", split, fig_13_61},
      {"13.62", split, fig_13_62},
      {"13.63", insert, fig_13_63},
      {"13.64", split, fig_13_64},
      {"13.65", insert, fig_13_65},
      {"13.66", insert, fig_13_66},
      {"13.67", "TrapezoidMap2::merge, locate, trapezoid_map_corners", fig_13_67},
  };
}

}  // namespace locus_gallery
