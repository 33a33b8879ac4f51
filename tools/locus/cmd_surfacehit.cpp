// SPDX-License-Identifier: BSL-1.0
// locus surfacehit: the hits of each ray of a CSV file on a sphere, a general quadric, a torus or
// a Bézier patch (intersection/ray_sphere.hpp, ray_quadric.hpp, ray_torus.hpp, ray_surface.hpp):
// parameters, multiplicities, points and normals.

#include "commands.hpp"
#include "io.hpp"

#include <locus/intersection/ray_quadric.hpp>
#include <locus/intersection/ray_sphere.hpp>
#include <locus/intersection/ray_surface.hpp>
#include <locus/intersection/ray_torus.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace locus_cli {

namespace {

struct SurfaceHitOptions {
  std::string rays;
  std::vector<double> sphere, quadric, torus, bezier;
  std::string output;
  bool json = false;
};

void run_surfacehit(const SurfaceHitOptions& o) {
  const int given = int(!o.sphere.empty()) + int(!o.quadric.empty()) + int(!o.torus.empty()) +
                    int(!o.bezier.empty());
  if (given != 1) throw UsageError("give exactly one of --sphere, --quadric, --torus, --bezier");
  locus::BezierPatch<double, 3> patch{0, 0, {}};
  if (!o.bezier.empty()) {
    const auto& b = o.bezier;
    const bool shape_ok = b.size() >= 2 && b[0] >= 1 && b[1] >= 1 && b[0] <= 64 && b[1] <= 64 &&
                          b[0] == std::floor(b[0]) && b[1] == std::floor(b[1]);
    if (!shape_ok) throw UsageError("--bezier: rows and cols must be integers in [1, 64]");
    patch.rows = static_cast<int>(b[0]);
    patch.cols = static_cast<int>(b[1]);
    if (b.size() != 2 + 3 * std::size_t(patch.rows) * std::size_t(patch.cols))
      throw UsageError("--bezier: expected rows,cols then 3 * rows * cols coordinates");
    for (std::size_t k = 2; k + 2 < b.size(); k += 3)
      patch.control.push_back({b[k], b[k + 1], b[k + 2]});
  }
  const std::vector<locus::Vec<double, 6>> rows = load_rows6(o.rays);
  const auto hits = [&](const locus::Ray3d& ray) -> locus::LinearSurfaceIntersection3<double> {
    if (!o.bezier.empty()) {
      // The patch hits in the quadric result form (at most 4 listed; more is an error).
      const locus::LinearSurfaceHits<double> h = intersection(ray, patch);
      if (h.status != locus::Status::ok)
        throw InputError("surfacehit: " + std::string(locus::to_string(h.status)));
      if (h.hits.size() > 4) throw InputError("surfacehit: more than 4 hits on a ray");
      locus::LinearSurfaceIntersection3<double> r;
      if (h.on_surface) {
        r.kind = locus::Kind::ray;
        r.count = 2;
        return r;
      }
      for (const auto& x : h.hits) {
        const auto i = static_cast<std::size_t>(r.count++);
        r.point[i] = x.point;
        r.param_a[i] = x.t;
        r.param_b[i] = x.uv;
        r.normal[i] = x.normal;
        r.multiplicity[i] = x.tangent ? 2 : 1;
      }
      r.kind = r.count == 0   ? locus::Kind::empty
               : r.count == 1 ? locus::Kind::point
                              : locus::Kind::points;
      return r;
    }
    if (!o.sphere.empty())
      return intersection(ray,
                          locus::Sphere3d{{o.sphere[0], o.sphere[1], o.sphere[2]}, o.sphere[3]});
    if (!o.torus.empty())
      return intersection(ray, locus::Torus3d{{o.torus[0], o.torus[1], o.torus[2]},
                                              {o.torus[3], o.torus[4], o.torus[5]},
                                              o.torus[6],
                                              o.torus[7]});
    const auto& q = o.quadric;
    locus::Quadric3d k{};
    const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) k.a.a[i][j] = q[std::size_t(idx[i][j])];
    k.b = {q[6], q[7], q[8]};
    k.c = q[9];
    return intersection(ray, k);
  };
  std::string text = "# count t0 m0 t1 m1 ...\n";
  std::string results = "[";
  std::int64_t total = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const auto h = hits(locus::Ray3d{{r[0], r[1], r[2]}, {r[3], r[4], r[5]}});
    const bool on = h.kind == locus::Kind::ray;
    const int n = on ? 0 : h.count;
    total += n;
    text += on ? std::string("on_surface") : std::to_string(n);
    results += i ? ",{" : "{";
    results += "\"count\":" + std::to_string(n) + ",\"on_surface\":" + (on ? "true" : "false") +
               ",\"hits\":[";
    for (int k = 0; k < n; ++k) {
      const auto s = std::size_t(k);
      text += ' ' + num(h.param_a[s]) + ' ' + std::to_string(h.multiplicity[s]);
      results += (k ? ",{" : "{") + std::string("\"t\":") + json_number(h.param_a[s]) +
                 ",\"multiplicity\":" + std::to_string(h.multiplicity[s]) +
                 ",\"point\":" + json_vec<3>(h.point[s]) +
                 ",\"normal\":" + json_vec<3>(h.normal[s]) +
                 ",\"uv\":" + json_vec<2>(h.param_b[s]) + "}";
    }
    text += '\n';
    results += "]}";
  }
  results += "]";
  JsonObject j;
  j.str("command", "surfacehit")
      .integer("rays", static_cast<std::int64_t>(rows.size()))
      .integer("hits", total)
      .raw("results", std::move(results));
  Common c;
  c.output = o.output;
  c.json = o.json;
  emit(c, text, j);
}

}  // namespace

void register_surfacehit(CLI::App& app) {
  auto o = std::make_shared<SurfaceHitOptions>();
  CLI::App* sub = app.add_subcommand(
      "surfacehit", "hits of rays on a sphere, a quadric, a torus or a Bezier patch");
  sub->add_option("rays", o->rays, "rays, one per CSV row: ox,oy,oz,dx,dy,dz (- for stdin)")
      ->required();
  sub->add_option("--sphere", o->sphere, "cx,cy,cz,r")->expected(4)->delimiter(',');
  sub->add_option("--quadric", o->quadric,
                  "a00,a01,a02,a11,a12,a22,b0,b1,b2,c: x^T A x + b.x + c = 0")
      ->expected(10)
      ->delimiter(',');
  sub->add_option("--torus", o->torus, "cx,cy,cz,nx,ny,nz,R,r (centre, axis, radii)")
      ->expected(8)
      ->delimiter(',');
  sub->add_option("--bezier", o->bezier,
                  "rows,cols,x00,y00,z00,x01,...: a Bezier patch, control net row-major")
      ->expected(2, 2 + 3 * 64 * 64)
      ->delimiter(',');
  sub->add_option("-o,--output", o->output, "write the result here (default: stdout)");
  sub->add_flag("--json", o->json, "a JSON summary (points, normals, (u, v)) on stdout");
  sub->footer(
      "For each ray (o + t d, t >= 0) prints `count t0 m0 t1 m1 ...`: the hit parameters by\n"
      "increasing t with their multiplicities (2 at a tangency), or `on_surface` when the ray\n"
      "lies on the quadric. Sphere and quadric counts and tangencies are exact for the data as\n"
      "given; torus roots come from the quartic in double (a tangency within the rounding bound\n"
      "is one double root). --bezier: hierarchy refinement then Newton (multiplicity 2 marks a\n"
      "tangential hit; on_surface a ray lying in the patch; at most 4 hits per ray).\n"
      "--json adds each hit's point, unit normal and surface parameters.\n"
      "Example:\n  locus surfacehit rays.csv --torus 0,0,0,0,0,1,4,1 --json");
  sub->callback([o] { run_surfacehit(*o); });
}

}  // namespace locus_cli
