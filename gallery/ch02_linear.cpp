// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 2 (linear systems): figures 2.2, 2.3 and 2.9. Lines of the equations come
// from locus::to_parametric of their implicit forms, solutions from locus::solve (its singular
// flag decides between one, none and infinitely many solutions) and the fitted line from
// locus::least_squares.
#include "gallery.hpp"

#include <locus/core/linear_system.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/numeric/least_squares.hpp>
#include <locus/primitives/line.hpp>

#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace locus_gallery {
namespace {

using namespace locus;
namespace c = colour;

std::string fmt(double x, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, x);
  return buf;
}

// 2.2: the solutions of 3 x1 + 2 x2 = 6 are a line; a few of them marked.
bool fig_2_2(SvgWriter& w) {
  const ImplicitLine2<double> eq{{3, 2}, -6};  // 3 x1 + 2 x2 - 6 = 0
  const auto line = to_parametric(eq);
  if (!line) return false;
  w.set_view(Vec2d{-1, -1.5}, Vec2d{4, 4.5});
  w.line(Vec2d{0, 0}, Vec2d{1, 0}, pen(c::light, 1));
  w.line(Vec2d{0, 0}, Vec2d{0, 1}, pen(c::light, 1));
  draw(w, *line, pen(c::blue, 2));
  for (double t : {-0.3, 0.0, 0.3}) {
    const Vec2d p = point_at(*line, t);
    point(w, p, coordinates(p.x, p.y), c::red);
  }
  label(w, Vec2d{3.8, 0}, "x\u2081", c::gray);
  label(w, Vec2d{0, 4.3}, "x\u2082", c::gray);
  return true;
}

// 2.3: two equations in two unknowns: one solution, none (parallel), or infinitely many
// (the same line), decided by locus::solve and the residual of a point of the first line.
bool fig_2_3(SvgWriter& w) {
  struct System {
    Vec2d n0;
    double c0;
    Vec2d n1;
    double c1;
  };
  const System systems[] = {
      {{1, 1}, 3, {1, -2}, 0}, {{1, 2}, 2, {1, 2}, 4}, {{1, -1}, 1, {2, -2}, 2}};
  for (int k = 0; k < 3; ++k) {
    const System& s = systems[k];
    const Vec2d off{5.0 * k, 0};
    w.polyline(std::vector<Vec2d>{off + Vec2d{-0.5, -1}, off + Vec2d{3.8, -1},
                                  off + Vec2d{3.8, 3.2}, off + Vec2d{-0.5, 3.2}},
               pen(c::light, 1), true);
    // Each line is drawn as a segment of its parametric form inside the panel.
    for (int e = 0; e < 2; ++e) {
      const ImplicitLine2<double> eq{e ? s.n1 : s.n0, -(e ? s.c1 : s.c0)};
      const auto line = to_parametric(eq);
      if (!line) return false;
      // A piece of length 4 around the point of the line nearest the panel centre.
      const Vec2d centre{1.65, 1.1};
      const double dd = dot(line->direction, line->direction);
      const double t0 = dot(centre - line->origin, line->direction) / dd, h = 2.0 / std::sqrt(dd);
      const Line2<double> moved{line->origin + off, line->direction};
      draw(w, Segment<double, 2>{point_at(moved, t0 - h), point_at(moved, t0 + h)},
           pen(e ? c::red : c::blue, e ? 1.6 : 3.5));
    }
    const auto sol = solve(Mat2d::from_rows(s.n0, s.n1), Vec2d{s.c0, s.c1});
    std::string verdict;
    if (!sol.singular) {
      point(w, off + sol.x, coordinates(sol.x.x, sol.x.y), c::black);
      verdict = "(a) one solution";
    } else {
      // Singular: the lines are parallel; they coincide when a point of the first satisfies the
      // second.
      const auto l0 = to_parametric(ImplicitLine2<double>{s.n0, -s.c0});
      if (!l0) return false;
      const double r = evaluate(ImplicitLine2<double>{s.n1, -s.c1}, l0->origin);
      verdict = std::abs(r) <= 1e-12 ? "(c) infinitely many solutions" : "(b) no solution";
    }
    label(w, off + Vec2d{-0.4, -1.5}, verdict, c::black, 0, 0);
  }
  return true;
}

// 2.9: the least-squares line y = m x + b through noisy points (locus::least_squares on the
// over-determined system [x 1] (m, b) = y), with the vertical residuals it minimises.
bool fig_2_9(SvgWriter& w) {
  const std::vector<Vec2d> pts{{0.2, 0.9}, {0.8, 1.1}, {1.3, 1.9}, {2.1, 2.0},
                               {2.6, 2.9}, {3.2, 2.8}, {3.9, 3.7}, {4.5, 3.9}};
  std::vector<double> a, b;
  for (const Vec2d& p : pts) {
    a.push_back(p.x);
    a.push_back(1.0);
    b.push_back(p.y);
  }
  const auto ls = least_squares(std::span<const double>(a), static_cast<int>(pts.size()), 2,
                                std::span<const double>(b));
  if (ls.status != Status::ok) return false;
  const double m = ls.x[0], k = ls.x[1];
  w.segment(Vec2d{0, k}, Vec2d{4.8, m * 4.8 + k}, pen(c::blue, 2));
  for (const Vec2d& p : pts) {
    w.segment(p, Vec2d{p.x, m * p.x + k}, pen(c::red, 1));
    w.point(p, dot(c::black, 3.5));
  }
  label(w, Vec2d{0.1, 4.0},
        "y = " + fmt(m, 3) + " x + " + fmt(k, 3) + ",  residual " + fmt(ls.residual_norm, 3),
        c::black, 0, 0);
  return true;
}

}  // namespace

std::vector<Figure> chapter2_linear_figures() {
  return {
      {"2.2", "ImplicitLine2, to_parametric, point_at", fig_2_2},
      {"2.3", "solve (singular flag), to_parametric, evaluate", fig_2_3},
      {"2.9", "least_squares", fig_2_9},
  };
}

}  // namespace locus_gallery
