// SPDX-License-Identifier: BSL-1.0
// locus sat3: two convex polyhedra (the hulls of two 3D point sets, hull/hull3.hpp) by separating
// axes (intersection/sat.hpp): whether they meet (exact); with --tmax, moving polyhedra: the first
// time of contact and the contact set.

#include "commands.hpp"
#include "io.hpp"

#include <locus/hull/hull3.hpp>
#include <locus/intersection/sat.hpp>

#include <memory>
#include <string>
#include <vector>

namespace locus_cli {

namespace {

struct Sat3Options {
  Common c;
  std::string other;
  std::vector<double> va{0, 0, 0}, vb{0, 0, 0};
  double tmax = -1;
};

/// The triangles of the hull of p (a flat set gives a fan of its polygon; lower dimensions none).
std::vector<std::array<std::uint32_t, 3>> hull_triangles(const std::vector<Vec3d>& p,
                                                         const std::string& name) {
  const locus::Hull3Result h = locus::convex_hull(p);
  if (h.status != locus::Status::ok)
    throw InputError(name + ": convex hull: " + std::string(locus::to_string(h.status)));
  if (h.dimension == 3) return h.triangles;
  std::vector<std::array<std::uint32_t, 3>> fan;
  if (h.dimension == 2)
    for (std::size_t i = 1; i + 1 < h.polygon.size(); ++i)
      fan.push_back({h.polygon[0], h.polygon[i], h.polygon[i + 1]});
  if (fan.empty())
    throw InputError(name + ": convex polyhedron: " +
                     std::string(locus::to_string(locus::Status::degenerate_input)));
  return fan;
}

void run_sat3(const Sat3Options& o) {
  const std::vector<Vec3d> a = load_points3(o.c);
  Common oc = o.c;
  oc.input = o.other;
  oc.format.clear();
  const std::vector<Vec3d> b = load_points3(oc);
  if (a.empty()) throw InputError(o.c.input + ": convex polyhedron: empty_input");
  if (b.empty()) throw InputError(o.other + ": convex polyhedron: empty_input");
  const auto ta = hull_triangles(a, o.c.input), tb = hull_triangles(b, o.other);
  const locus::ConvexMesh3<double> pa{a, ta}, pb{b, tb};
  JsonObject j;
  j.str("command", "sat3");
  std::string text;
  if (o.tmax < 0) {
    const locus::SatTest3 r = locus::sat_test(pa, pb);
    if (r.status != locus::Status::ok)
      throw InputError(o.c.input + ": sat3: " + std::string(locus::to_string(r.status)));
    text = std::string("intersects ") + (r.intersects ? "yes" : "no") + '\n';
    j.boolean("intersects", r.intersects);
  } else {
    const Vec3d va{o.va[0], o.va[1], o.va[2]}, vb{o.vb[0], o.vb[1], o.vb[2]};
    const locus::Contact3<double> r = locus::first_contact(pa, va, pb, vb, o.tmax);
    if (r.status != locus::Status::ok)
      throw InputError(o.c.input + ": sat3: " + std::string(locus::to_string(r.status)));
    const std::string kind = r.overlap ? "overlap" : std::string(locus::to_string(r.kind));
    text = "kind " + kind + '\n';
    if (r) text += "time " + num(r.time) + '\n';
    std::string pj = "[";
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const Vec3d& p = r.points[i];
      text += "point " + num(p.x) + ' ' + num(p.y) + ' ' + num(p.z) + '\n';
      pj += (i ? "," : "") + json_vec<3>(p);
    }
    j.str("kind", kind).raw("points", pj + "]");
    if (r) j.number("time", r.time);
  }
  emit(o.c, text, j);
}

}  // namespace

void register_sat3(CLI::App& app) {
  auto o = std::make_shared<Sat3Options>();
  CLI::App* sub = app.add_subcommand(
      "sat3", "two convex polyhedra (hulls of 3D points): do they meet; moving: first contact");
  add_common(sub, o->c, true, "the first polyhedron's points (3D; their convex hull is used)");
  sub->add_option("--other", o->other, "the second polyhedron's points")->required();
  sub->add_option("--va", o->va, "velocity of the first polyhedron (with --tmax)")->expected(3);
  sub->add_option("--vb", o->vb, "velocity of the second polyhedron (with --tmax)")->expected(3);
  sub->add_option("--tmax", o->tmax, "moving polyhedra over [0, tmax]: first contact");
  sub->footer(
      "Prints `intersects yes|no` (exact); with --tmax: `kind` (empty, point, segment, polygon,\n"
      "or overlap when the interiors overlap at time 0), `time` of first contact and the contact\n"
      "set's `point x y z` lines.\n"
      "Example:\n  locus sat3 a.xyz --other b.xyz\n"
      "  locus sat3 a.xyz --other b.xyz --va 1 0 0 --vb -1 0 0 --tmax 10");
  sub->callback([o] { run_sat3(*o); });
}

}  // namespace locus_cli
