// SPDX-License-Identifier: BSL-1.0
// The chapter 8 constructions (include/locus/construct/) as one function, construct(kind, args):
// the same kinds and argument order as `locus construct` (docs/cli.md). Points are x y, lines
// ox oy dx dy, circles cx cy r. Returns a Construction result: circles (k, 3) [cx, cy, r],
// lines (m, 4) [ox, oy, dx, dy] (unit direction), infinite, and for apollonius the tangency
// signs circle_signs (k, 3) and line_signs (m, 3) (empty for the other kinds). Bad input (NaN, a
// zero direction, a bad radius) raises ValueError with the library's status.
#include "common.hpp"

#include <pybind11/stl.h>

#include <locus/construct/apollonius.hpp>
#include <locus/construct/circle_through.hpp>
#include <locus/construct/circles_of_radius.hpp>
#include <locus/construct/lines.hpp>
#include <locus/construct/tangent_lines.hpp>

#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

namespace locus::python {

namespace {

using Vd = const std::vector<double>&;

struct Built {
  std::vector<double> circles, lines;  // 3 / 4 numbers per solution
  std::vector<int> csigns, lsigns;     // apollonius only
  bool infinite = false;
  Status status = Status::ok;
};

// push_back one by one: GCC 12 -O3 misreports -Wstringop-overflow on vector::insert of a list.
template <class X, class R>
void add(std::vector<X>& v, const R& values) {
  for (const auto x : values) v.push_back(x);
}
void add(std::vector<double>& v, std::initializer_list<double> values) {
  for (const double x : values) v.push_back(x);
}

template <class S>
Built circles(const S& s) {
  Built b;
  b.infinite = s.infinite;
  b.status = s.status;
  for (int i = 0; i < s.count; ++i) {
    const Circle2d& k = s.item[static_cast<std::size_t>(i)];
    add(b.circles, {k.center.x, k.center.y, k.radius});
  }
  return b;
}
template <class S>
Built lines(const S& s) {
  Built b;
  b.infinite = s.infinite;
  b.status = s.status;
  for (int i = 0; i < s.count; ++i) {
    const Line2d& l = s.item[static_cast<std::size_t>(i)];
    add(b.lines, {l.origin.x, l.origin.y, l.direction.x, l.direction.y});
  }
  return b;
}

Vec2d P(Vd v, int i) { return {v[std::size_t(i)], v[std::size_t(i) + 1]}; }
Line2d L(Vd v, int i) { return {P(v, i), P(v, i + 2)}; }
Circle2d C(Vd v, int i) { return {P(v, i), v[std::size_t(i) + 2]}; }

struct Kind {
  int n;
  std::function<Built(Vd)> run;
};

const std::map<std::string, Kind>& kinds() {
  static const std::map<std::string, Kind> table = {
      {"circle3pts", {6, [](Vd v) { return circles(circle_through(P(v, 0), P(v, 2), P(v, 4))); }}},
      {"circle3lines",
       {12, [](Vd v) { return circles(circles_tangent_to(L(v, 0), L(v, 4), L(v, 8))); }}},
      {"tangent-at", {5, [](Vd v) { return lines(tangent_line_at(C(v, 0), P(v, 3))); }}},
      {"tangent-through", {5, [](Vd v) { return lines(tangent_lines(P(v, 0), C(v, 2))); }}},
      {"tangent-2circles", {6, [](Vd v) { return lines(tangent_lines(C(v, 0), C(v, 3))); }}},
      {"circle-2pts-r",
       {5, [](Vd v) { return circles(circles_of_radius(P(v, 0), P(v, 2), v[4])); }}},
      {"circle-pt-line-r",
       {7, [](Vd v) { return circles(circles_of_radius(P(v, 0), L(v, 2), v[6])); }}},
      {"circle-2lines-r",
       {9, [](Vd v) { return circles(circles_of_radius(L(v, 0), L(v, 4), v[8])); }}},
      {"circle-pt-circle-r",
       {6, [](Vd v) { return circles(circles_of_radius(P(v, 0), C(v, 2), v[5])); }}},
      {"circle-line-circle-r",
       {8, [](Vd v) { return circles(circles_of_radius(L(v, 0), C(v, 4), v[7])); }}},
      {"circle-2circles-r",
       {7, [](Vd v) { return circles(circles_of_radius(C(v, 0), C(v, 3), v[6])); }}},
      {"normal", {6, [](Vd v) { return lines(normal_line(L(v, 0), P(v, 4))); }}},
      {"bisector", {4, [](Vd v) { return lines(perpendicular_bisector(P(v, 0), P(v, 2))); }}},
      {"parallel", {5, [](Vd v) { return lines(parallel_lines(L(v, 0), v[4])); }}},
      {"parallel-vertical",
       {5, [](Vd v) { return lines(parallel_lines_vertical(L(v, 0), v[4])); }}},
      {"parallel-horizontal",
       {5, [](Vd v) { return lines(parallel_lines_horizontal(L(v, 0), v[4])); }}},
      {"tangent-normal",
       {7, [](Vd v) { return lines(tangent_lines_normal_to(C(v, 0), L(v, 3))); }}},
      {"apollonius",
       {9,
        [](Vd v) {
          const auto s = apollonius(C(v, 0), C(v, 3), C(v, 6));
          Built b = circles(Solutions<Circle2d, 8>{});
          b.infinite = s.circles.infinite;
          b.status = s.circles.status;
          for (int i = 0; i < s.circles.count; ++i) {
            const auto& k = s.circles.item[static_cast<std::size_t>(i)];
            add(b.circles, {k.circle.center.x, k.circle.center.y, k.circle.radius});
            add(b.csigns, k.s);
          }
          for (int i = 0; i < s.lines.count; ++i) {
            const auto& l = s.lines.item[static_cast<std::size_t>(i)];
            add(b.lines,
                {l.line.origin.x, l.line.origin.y, l.line.direction.x, l.line.direction.y});
            add(b.lsigns, l.s);
          }
          return b;
        }}},
  };
  return table;
}

template <class X>
py::array_t<X> rows(const std::vector<X>& v, py::ssize_t cols) {
  py::array_t<X> a({static_cast<py::ssize_t>(v.size()) / cols, cols});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

}  // namespace

void bind_construction(py::module_& m) {
  m.def(
      "construct",
      [](const std::string& kind, const std::vector<double>& args) -> py::object {
        const char* fn = "construct";
        const auto it = kinds().find(kind);
        if (it == kinds().end()) fail(fn, "unknown kind '" + kind + "'");
        if (static_cast<int>(args.size()) != it->second.n)
          fail(fn, kind + " expects " + std::to_string(it->second.n) + " numbers, got " +
                       std::to_string(args.size()));
        const Built b = it->second.run(args);
        check_status(b.status, fn, false);
        py::object out = new_result("Construction", b.status);
        out.attr("circles") = rows(b.circles, 3);
        out.attr("lines") = rows(b.lines, 4);
        out.attr("infinite") = b.infinite;
        out.attr("circle_signs") = rows(b.csigns, 3);  // empty unless apollonius
        out.attr("line_signs") = rows(b.lsigns, 3);
        return out;
      },
      py::arg("kind"), py::arg("args"),
      "The chapter 8 constructions: kind as in `locus construct` (circle3pts, circle3lines, "
      "tangent-at, tangent-through, tangent-2circles, circle-2pts-r, circle-pt-line-r, "
      "circle-2lines-r, circle-pt-circle-r, circle-line-circle-r, circle-2circles-r, normal, "
      "bisector, parallel, parallel-vertical, parallel-horizontal, tangent-normal, apollonius); "
      "args the numbers (points x y, lines ox oy dx dy, circles cx cy r, then a radius or "
      "distance). Returns Construction: circles (k, 3), lines (m, 4), infinite; for apollonius "
      "also circle_signs and line_signs (+1 outside / left).");
}

}  // namespace locus::python
