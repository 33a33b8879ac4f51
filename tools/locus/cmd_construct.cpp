// SPDX-License-Identifier: BSL-1.0
// locus construct <kind> <numbers...>: the chapter 8 constructions (include/locus/construct/):
// circles through points and tangent to lines and circles, tangent lines, the line
// constructions of 8.30-8.34 and Apollonius' problem. Points are "x y", lines "ox oy dx dy",
// circles "cx cy r". Prints one solution per CSV row.

#include "commands.hpp"
#include "io.hpp"

#include <locus/construct/apollonius.hpp>
#include <locus/construct/circle_through.hpp>
#include <locus/construct/circles_of_radius.hpp>
#include <locus/construct/lines.hpp>
#include <locus/construct/tangent_lines.hpp>

#include <functional>
#include <map>
#include <memory>

namespace locus_cli {

namespace {

using locus::Circle2d;
using locus::Line2d;

struct ConstructOptions {
  Common c;
  std::string kind;
  std::vector<double> v;
};

// The result rows and the summary of one construction.
struct Out {
  std::string text;
  int count = 0;
  bool infinite = false;
  locus::Status status = locus::Status::ok;
};

template <class S>
Out circles(const S& s) {
  Out o{"cx,cy,r\n", s.count, s.infinite, s.status};
  for (int i = 0; i < s.count; ++i) {
    const Circle2d& k = s.item[static_cast<std::size_t>(i)];
    o.text += num(k.center.x) + ',' + num(k.center.y) + ',' + num(k.radius) + '\n';
  }
  return o;
}
template <class S>
Out lines(const S& s) {
  Out o{"ox,oy,dx,dy\n", s.count, s.infinite, s.status};
  for (int i = 0; i < s.count; ++i) {
    const Line2d& l = s.item[static_cast<std::size_t>(i)];
    o.text += num(l.origin.x) + ',' + num(l.origin.y) + ',' + num(l.direction.x) + ',' +
              num(l.direction.y) + '\n';
  }
  return o;
}

struct Kind {
  const char* args;  // what the numbers are
  int n;             // how many
  std::function<Out(const std::vector<double>&)> run;
};

Vec2d P(const std::vector<double>& v, int i) { return {v[std::size_t(i)], v[std::size_t(i) + 1]}; }
Line2d L(const std::vector<double>& v, int i) { return {P(v, i), P(v, i + 2)}; }
Circle2d C(const std::vector<double>& v, int i) { return {P(v, i), v[std::size_t(i) + 2]}; }

const std::map<std::string, Kind>& kinds() {
  using V = const std::vector<double>&;
  static const std::map<std::string, Kind> table = {
      {"circle3pts",
       {"p0 p1 p2", 6,
        [](V v) { return circles(locus::circle_through(P(v, 0), P(v, 2), P(v, 4))); }}},
      {"circle3lines",
       {"l0 l1 l2", 12,
        [](V v) { return circles(locus::circles_tangent_to(L(v, 0), L(v, 4), L(v, 8))); }}},
      {"tangent-at",
       {"circle p", 5, [](V v) { return lines(locus::tangent_line_at(C(v, 0), P(v, 3))); }}},
      {"tangent-through",
       {"p circle", 5, [](V v) { return lines(locus::tangent_lines(P(v, 0), C(v, 2))); }}},
      {"tangent-2circles",
       {"c0 c1", 6, [](V v) { return lines(locus::tangent_lines(C(v, 0), C(v, 3))); }}},
      {"circle-2pts-r",
       {"p q r", 5, [](V v) { return circles(locus::circles_of_radius(P(v, 0), P(v, 2), v[4])); }}},
      {"circle-pt-line-r",
       {"p l r", 7, [](V v) { return circles(locus::circles_of_radius(P(v, 0), L(v, 2), v[6])); }}},
      {"circle-2lines-r",
       {"l0 l1 r", 9,
        [](V v) { return circles(locus::circles_of_radius(L(v, 0), L(v, 4), v[8])); }}},
      {"circle-pt-circle-r",
       {"p circle r", 6,
        [](V v) { return circles(locus::circles_of_radius(P(v, 0), C(v, 2), v[5])); }}},
      {"circle-line-circle-r",
       {"l circle r", 8,
        [](V v) { return circles(locus::circles_of_radius(L(v, 0), C(v, 4), v[7])); }}},
      {"circle-2circles-r",
       {"c0 c1 r", 7,
        [](V v) { return circles(locus::circles_of_radius(C(v, 0), C(v, 3), v[6])); }}},
      {"normal", {"l p", 6, [](V v) { return lines(locus::normal_line(L(v, 0), P(v, 4))); }}},
      {"bisector",
       {"p q", 4, [](V v) { return lines(locus::perpendicular_bisector(P(v, 0), P(v, 2))); }}},
      {"parallel", {"l d", 5, [](V v) { return lines(locus::parallel_lines(L(v, 0), v[4])); }}},
      {"parallel-vertical",
       {"l d", 5, [](V v) { return lines(locus::parallel_lines_vertical(L(v, 0), v[4])); }}},
      {"parallel-horizontal",
       {"l d", 5, [](V v) { return lines(locus::parallel_lines_horizontal(L(v, 0), v[4])); }}},
      {"tangent-normal",
       {"circle l", 7,
        [](V v) { return lines(locus::tangent_lines_normal_to(C(v, 0), L(v, 3))); }}},
      {"apollonius",
       {"c0 c1 c2", 9,
        [](V v) {
          const auto s = locus::apollonius(C(v, 0), C(v, 3), C(v, 6));
          Out o{"type,a,b,c,d,s0,s1,s2\n", s.circles.count + s.lines.count, s.circles.infinite,
                s.circles.status};
          const auto signs = [](const std::array<int, 3>& x) {
            return std::to_string(x[0]) + ',' + std::to_string(x[1]) + ',' + std::to_string(x[2]);
          };
          for (int i = 0; i < s.circles.count; ++i) {
            const auto& k = s.circles.item[static_cast<std::size_t>(i)];
            o.text += "circle," + num(k.circle.center.x) + ',' + num(k.circle.center.y) + ',' +
                      num(k.circle.radius) + ",," + signs(k.s) + '\n';
          }
          for (int i = 0; i < s.lines.count; ++i) {
            const auto& l = s.lines.item[static_cast<std::size_t>(i)];
            o.text += "line," + num(l.line.origin.x) + ',' + num(l.line.origin.y) + ',' +
                      num(l.line.direction.x) + ',' + num(l.line.direction.y) + ',' + signs(l.s) +
                      '\n';
          }
          return o;
        }}},
  };
  return table;
}

void run_construct(const ConstructOptions& o) {
  const auto it = kinds().find(o.kind);
  if (it == kinds().end()) throw UsageError("construct: unknown kind '" + o.kind + "'");
  const Kind& k = it->second;
  if (static_cast<int>(o.v.size()) != k.n)
    throw UsageError("construct " + o.kind + ": expects " + std::to_string(k.n) + " numbers (" +
                     k.args + "), got " + std::to_string(o.v.size()));
  const Out r = k.run(o.v);
  require_ok(r.status, "construct " + o.kind);
  JsonObject j;
  j.str("command", "construct")
      .str("kind", o.kind)
      .integer("count", r.count)
      .boolean("infinite", r.infinite);
  emit(o.c, r.text, j);
}

}  // namespace

void register_construct(CLI::App& app) {
  auto o = std::make_shared<ConstructOptions>();
  CLI::App* sub = app.add_subcommand(
      "construct", "circles and lines of chapter 8: tangents, circles of a radius, Apollonius");
  sub->add_option("kind", o->kind, "the construction (see below)")->required();
  sub->add_option("numbers", o->v, "its arguments: points x y, lines ox oy dx dy, circles cx cy r");
  sub->add_option("-o,--output", o->c.output, "write the CSV here instead of stdout");
  sub->add_flag("--json", o->c.json, "print a JSON summary (count, infinite) on stdout");
  std::string footer = "Kinds (arguments):\n";
  for (const auto& [name, k] : kinds()) footer += "  " + name + " (" + k.args + ")\n";
  footer +=
      "Prints CSV: circles cx,cy,r; lines ox,oy,dx,dy (unit direction); apollonius rows\n"
      "circle,cx,cy,r,,s0,s1,s2 and line,ox,oy,dx,dy,s0,s1,s2. Put -- before negative numbers.\n"
      "Example:\n  locus construct tangent-2circles 0 0 2 6 8 3";
  sub->footer(footer);
  sub->callback([o] { run_construct(*o); });
}

}  // namespace locus_cli
