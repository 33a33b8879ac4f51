// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 6 (GJK distance, 6.24-6.29). The Minkowski sets of figure 6.24 are the
// convex hulls (locus::convex_hull) of the pairwise sums / differences of the vertices; the
// closest point and every iteration of figures 6.25-6.29 come from a live locus::gjk_distance
// run with a GjkTrace (V_k, the support point W_k, the new simplex S_{k+1} and V_{k+1}).
#include "gallery.hpp"

#include <locus/distance/gjk.hpp>
#include <locus/hull/hull2.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

/// The convex hull of the points, counter-clockwise (empty when the hull fails).
std::vector<Vec2d> hull_of(const std::vector<Vec2d>& pts) {
  const Hull2Result h = convex_hull(pts);
  std::vector<Vec2d> ring;
  if (h.status != Status::ok) return ring;
  for (std::uint32_t i : h.indices) ring.push_back(pts[i]);
  return ring;
}

/// { a + s b : a in A, b in B } for s = +1 (sum) or -1 (difference), vertices only.
std::vector<Vec2d> minkowski(const std::vector<Vec2d>& a, const std::vector<Vec2d>& b, double s) {
  std::vector<Vec2d> out;
  for (const Vec2d& p : a)
    for (const Vec2d& q : b) out.push_back(p + s * q);
  return out;
}

std::vector<Vec2d> shifted(const std::vector<Vec2d>& pts, const Vec2d& by) {
  std::vector<Vec2d> out;
  for (const Vec2d& p : pts) out.push_back(p + by);
  return out;
}

// 6.24: triangles A and B, -B, A + B and A - B; the gray point is the point of A - B nearest to
// the origin, closest[0] - closest[1] of gjk_distance(A, B).
bool fig_6_24(SvgWriter& w) {
  const std::vector<Vec2d> a{{1.0, 0.6}, {2.6, 1.2}, {1.4, 2.4}};
  const std::vector<Vec2d> b{{-1.6, -0.4}, {-0.4, -1.4}, {-0.2, -0.1}};
  const std::vector<Vec2d> neg_b = minkowski({{0, 0}}, b, -1.0);
  const std::vector<Vec2d> sum = hull_of(minkowski(a, b, 1.0));
  const std::vector<Vec2d> diff = hull_of(minkowski(a, b, -1.0));
  if (sum.size() < 3 || diff.size() < 3) return false;
  const auto r = gjk_distance(ConvexPoints<double, 2>{a}, ConvexPoints<double, 2>{b});
  if (r.status != Status::ok || r.contact != Contact::separated) return false;
  const Vec2d nearest = r.closest[0] - r.closest[1];
  const double gap = 6.5;  // panel spacing
  const char* names[] = {"(a)", "(b)", "(c)", "(d)"};
  for (int k = 0; k < 4; ++k) {
    const Vec2d o{gap * k, 0};
    w.segment(o + Vec2d{-2, 0}, o + Vec2d{4.5, 0}, pen(c::light, 0.8));
    w.segment(o + Vec2d{0, -2}, o + Vec2d{0, 4}, pen(c::light, 0.8));
    label(w, o + Vec2d{1.2, -2.4}, names[k]);
  }
  w.polygon(shifted(a, {0, 0}), filled(c::blue));
  label(w, a[2], "A", c::blue);
  w.polygon(b, filled(c::red));
  label(w, b[0], "B", c::red);
  w.polygon(shifted(neg_b, {gap, 0}), filled(c::red));
  label(w, neg_b[0] + Vec2d{gap, 0}, "-B", c::red);
  w.polygon(shifted(sum, {2 * gap, 0}), filled(c::purple));
  label(w, sum[0] + Vec2d{2 * gap, 0}, "A + B", c::purple);
  w.polygon(shifted(diff, {3 * gap, 0}), filled(c::green));
  label(w, diff[0] + Vec2d{3 * gap, 0}, "A - B", c::green);
  w.point(nearest + Vec2d{3 * gap, 0}, dot(c::gray, 4.5));
  w.segment(Vec2d{3 * gap, 0}, nearest + Vec2d{3 * gap, 0}, dashed(c::gray));
  for (int k = 0; k < 4; ++k) w.point(Vec2d{gap * k, 0}, dot(c::black, 3.5));
  return true;
}

/// The polygons of figures 6.25-6.29 and their GJK run, started along -y (four iterations
/// before the run stops).
struct GjkRun {
  std::vector<Vec2d> a, b, diff;
  GjkTrace<double, 2> trace;
  GjkDistance<double, 2> result;
};

const GjkRun& gjk_run() {
  static const GjkRun run = [] {
    GjkRun r;
    for (int i = 0; i < 10; ++i) {
      const double t = 2 * pi_v<double> * i / 10 + 0.3;
      r.a.push_back({4 + 1.6 * std::cos(t), 1.5 + 1.1 * std::sin(t)});
    }
    for (int i = 0; i < 7; ++i) {
      const double t = 2 * pi_v<double> * i / 7 + 0.1;
      r.b.push_back({-0.5 + 1.2 * std::cos(t), -0.8 + 1.4 * std::sin(t)});
    }
    r.diff = hull_of(minkowski(r.a, r.b, -1.0));
    GjkOptions<double, 2> opt;
    opt.initial_direction = {0, -1};
    opt.trace = &r.trace;
    r.result = gjk_distance(ConvexPoints<double, 2>{r.a}, ConvexPoints<double, 2>{r.b}, opt);
    return r;
  }();
  return run;
}

std::vector<Vec2d> simplex_points(const GjkSimplex<double, 2>& s) {
  std::vector<Vec2d> pts;
  for (int i = 0; i < s.size; ++i)
    pts.push_back(s.a[static_cast<std::size_t>(i)] - s.b[static_cast<std::size_t>(i)]);
  return pts;
}

void draw_simplex(SvgWriter& w, const std::vector<Vec2d>& pts, const SvgStyle& s) {
  if (pts.size() == 1)
    w.point(pts[0], dot(s.stroke.c_str(), 4));
  else if (pts.size() == 2)
    w.segment(pts[0], pts[1], s);
  else
    w.polyline(pts, s, true);
}

// One GJK iteration k (figures 6.25-6.28 are k = 0..3): A - B, the simplex S_k and V_k, the
// support point W_k along -V_k, conv(S_k + {W_k}) dashed, the new simplex S_{k+1} and V_{k+1}.
bool draw_iteration(SvgWriter& w, std::size_t k) {
  const GjkRun& run = gjk_run();
  if (run.diff.size() < 3 || run.trace.steps.size() < k + 2) return false;
  const GjkStep<double, 2>& step = run.trace.steps[k];
  const std::vector<Vec2d> before =
      k == 0 ? std::vector<Vec2d>{run.trace.v0} : simplex_points(run.trace.steps[k - 1].simplex);
  const std::vector<Vec2d> after = simplex_points(step.simplex);
  w.polygon(run.diff, filled(c::light, 0.35, 1.0));
  label(w, run.diff[run.diff.size() / 2], "A - B", c::gray);
  w.point(Vec2d{0, 0}, dot(c::black, 3.5));
  label(w, Vec2d{0, 0}, "O");
  draw_simplex(w, before, pen(c::blue, 1.6));
  std::vector<Vec2d> grown = before;
  grown.push_back(step.w);
  draw_simplex(w, hull_of(grown).size() >= 3 ? hull_of(grown) : grown, dashed(c::gray));
  draw_simplex(w, after, pen(c::green, 2.4));
  w.arrow(step.v, step.v - 0.35 * step.v, pen(c::orange, 1.2));  // the search direction -V_k
  const std::string kk = std::to_string(k), k1 = std::to_string(k + 1);
  point(w, step.v, "V" + kk, c::blue);
  point(w, step.w, "W" + kk, c::red);
  point(w, step.v_next, "V" + k1, c::green);
  w.segment(Vec2d{0, 0}, step.v_next, dashed(c::green));
  return true;
}

bool fig_6_25(SvgWriter& w) { return draw_iteration(w, 0); }
bool fig_6_26(SvgWriter& w) { return draw_iteration(w, 1); }
bool fig_6_27(SvgWriter& w) { return draw_iteration(w, 2); }
bool fig_6_28(SvgWriter& w) { return draw_iteration(w, 3); }

// 6.29: (a) V_{k+1}, the point of conv(S_k + {W_k}) nearest to the origin, for the first
// iteration whose new simplex drops a point; (b) that new simplex, the smallest subset M of
// S_k + {W_k} whose hull still contains V_{k+1} (from the run's trace).
bool fig_6_29(SvgWriter& w) {
  const GjkRun& run = gjk_run();
  const auto& steps = run.trace.steps;
  for (std::size_t k = 1; k + 1 < steps.size(); ++k) {
    const std::vector<Vec2d> before = simplex_points(steps[k - 1].simplex);
    const std::vector<Vec2d> after = simplex_points(steps[k].simplex);
    if (after.size() > before.size()) continue;  // nothing was dropped
    std::vector<Vec2d> grown = before;
    grown.push_back(steps[k].w);
    const double gap = 9.0;
    for (int panel = 0; panel < 2; ++panel) {
      const Vec2d o{gap * panel, 0};
      w.polygon(shifted(run.diff, o), filled(c::light, 0.25, 0.8));
      w.point(o, dot(c::black, 3.5));
      label(w, o, "O");
      label(w, o + Vec2d{2.5, -2.0}, panel == 0 ? "(a)" : "(b)");
    }
    w.polygon(hull_of(grown), filled(c::blue, 0.15, 1.4));
    for (std::size_t i = 0; i < before.size(); ++i)
      point(w, before[i], "S" + std::to_string(i), c::blue);
    point(w, steps[k].w, "W", c::red);
    point(w, steps[k].v_next, "V", c::green);
    w.segment(Vec2d{0, 0}, steps[k].v_next, dashed(c::green));
    const Vec2d o{gap, 0};
    draw_simplex(w, shifted(after, o), pen(c::green, 2.4));
    for (std::size_t i = 0; i < after.size(); ++i)
      point(w, after[i] + o, "M" + std::to_string(i), c::green);
    w.segment(o, steps[k].v_next + o, dashed(c::green));
    return true;
  }
  return false;
}

}  // namespace

std::vector<Figure> chapter6_gjk_figures() {
  return {
      {"6.24", "convex_hull of vertex sums/differences (A + B, A - B), gjk_distance closest points",
       fig_6_24},
      {"6.25", "gjk_distance with GjkTrace: step 0 (V0, W0, S1, V1)", fig_6_25},
      {"6.26", "gjk_distance with GjkTrace: step 1", fig_6_26},
      {"6.27", "gjk_distance with GjkTrace: step 2", fig_6_27},
      {"6.28", "gjk_distance with GjkTrace: step 3", fig_6_28},
      {"6.29",
       "gjk_distance with GjkTrace: conv(S_k + W_k), its nearest point V_{k+1} and the new "
       "simplex M",
       fig_6_29},
  };
}

}  // namespace locus_gallery
