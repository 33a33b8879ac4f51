// SPDX-License-Identifier: BSL-1.0
// locus roots: real roots of a polynomial given on the command line (numeric/roots.hpp).
// locus fit: least-squares line, plane, circle or sphere of a point file (fit/).

#include "commands.hpp"
#include "io.hpp"

#include <locus/fit/circle_fit.hpp>
#include <locus/fit/line_fit.hpp>
#include <locus/fit/plane_fit.hpp>
#include <locus/fit/sphere_fit.hpp>
#include <locus/io/svg_primitives.hpp>
#include <locus/numeric/roots.hpp>

#include <algorithm>
#include <charconv>
#include <limits>
#include <memory>

namespace locus_cli {

namespace {

struct RootsOptions {
  std::vector<std::string> coefficients;
  bool low_first = false;
  bool near = false;
  std::vector<double> interval;
  bool json = false;
};

double parse_number(const std::string& s) {
  std::string_view v(s);
  if (v.size() >= 2 && v[0] == '+' && v[1] != '-' && v[1] != '+') v.remove_prefix(1);
  double x = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), x);
  if (v.empty() || r.ptr != v.data() + v.size() || r.ec == std::errc::invalid_argument) {
    throw UsageError("'" + s + "' is not a number");
  }
  if (r.ec == std::errc::result_out_of_range) {
    throw InputError("coefficient '" + s + "' is out of the range of double");
  }
  return x;
}

void run_roots(const RootsOptions& o) {
  std::vector<double> c;
  for (const std::string& s : o.coefficients) c.push_back(parse_number(s));
  if (!o.low_first) std::reverse(c.begin(), c.end());
  double a = -std::numeric_limits<double>::infinity();
  double b = std::numeric_limits<double>::infinity();
  if (!o.interval.empty()) {
    a = o.interval[0];
    b = o.interval[1];
    if (!(a <= b)) throw UsageError("--interval: give a <= b");
  }
  locus::RootOptions opt;
  opt.mode = o.near ? locus::RootMode::near : locus::RootMode::exact;
  const auto r = locus::real_roots(std::span<const double>(c), a, b, opt);
  if (r.status == locus::Status::non_finite_input) {
    throw InputError("a coefficient is not finite");
  }
  if (r.status == locus::Status::degenerate_input) {
    throw InputError("the polynomial is zero: every number is a root");
  }
  if (r.status != locus::Status::limit_exceeded) require_ok(r.status, "roots");
  std::string text;
  std::string values = "[", mult = "[";
  for (std::size_t i = 0; i < r.roots.size(); ++i) {
    text += num(r.roots[i].value) + ' ' + std::to_string(r.roots[i].multiplicity) + '\n';
    values += (i ? "," : "") + json_number(r.roots[i].value);
    mult += (i ? "," : "") + std::to_string(r.roots[i].multiplicity);
  }
  JsonObject j;
  j.str("command", "roots")
      .str("status", locus::to_string(r.status))
      .integer("degree", static_cast<std::int64_t>(c.size()) - 1)
      .raw("roots", values + "]")
      .raw("multiplicities", mult + "]");
  Common out;
  out.json = o.json;
  emit(out, text, j);
}

struct FitOptions {
  Common c;
  std::string model;
  bool algebraic = false;
};

template <int N>
std::string vec_text(const locus::Vec<double, N>& v) {
  std::string s;
  for (int i = 0; i < N; ++i) s += ' ' + num(v[i]);
  return s;
}

void fit_status(locus::Status s, const FitOptions& o) {
  if (s == locus::Status::degenerate_input) {
    throw InputError(o.c.input + ": too few points, or points that do not determine a " + o.model);
  }
  if (s != locus::Status::limit_exceeded) require_ok(s, o.c.input + ": " + o.model + " fit");
}

template <int N>
void fit_line(const FitOptions& o, const std::vector<locus::Vec<double, N>>& pts,
              locus::SvgWriter& svg) {
  const auto f = locus::fit_line(std::span<const locus::Vec<double, N>>(pts));
  fit_status(f.status, o);
  JsonObject j;
  j.str("command", "fit")
      .str("model", "line")
      .raw("origin", json_vec<N>(f.line.origin))
      .raw("direction", json_vec<N>(f.line.direction))
      .number("rms", f.rms);
  emit(o.c,
       "origin" + vec_text<N>(f.line.origin) + "\ndirection" + vec_text<N>(f.line.direction) +
           "\nrms " + num(f.rms) + '\n',
       j);
  if constexpr (N == 2) svg.line(f.line.origin, f.line.direction, result_style());
}

void run_fit(const FitOptions& o) {
  const int dim = o.model == "plane" || o.model == "sphere" ? 3
                  : o.model == "circle"                     ? 2
                                                            : input_dimension(o.c);
  locus::SvgWriter svg;
  std::vector<Vec2d> pts2;
  std::vector<Vec3d> pts3;
  if (dim == 2) {
    pts2 = load_points2(o.c);
  } else {
    if (!o.c.svg.empty()) throw UsageError("--svg draws 2D fits only (line, circle)");
    pts3 = load_points3(o.c);
  }
  if (o.model == "line") {
    if (dim == 2) {
      fit_line<2>(o, pts2, svg);
    } else {
      fit_line<3>(o, pts3, svg);
    }
  } else if (o.model == "plane") {
    const auto f = locus::fit_plane(std::span<const Vec3d>(pts3));
    fit_status(f.status, o);
    JsonObject j;
    j.str("command", "fit")
        .str("model", "plane")
        .raw("normal", json_vec<3>(f.plane.normal))
        .number("constant", f.plane.constant)
        .number("rms", f.rms);
    emit(o.c,
         "normal" + vec_text<3>(f.plane.normal) + "\nconstant " + num(f.plane.constant) + "\nrms " +
             num(f.rms) + '\n',
         j);
  } else if (o.model == "circle") {
    const auto f = o.algebraic ? locus::fit_circle_algebraic(std::span<const Vec2d>(pts2))
                               : locus::fit_circle(std::span<const Vec2d>(pts2));
    fit_status(f.status, o);
    JsonObject j;
    j.str("command", "fit")
        .str("model", "circle")
        .raw("center", json_vec<2>(f.circle.center))
        .number("radius", f.circle.radius)
        .number("rms", f.rms)
        .integer("iterations", f.iterations);
    emit(o.c,
         "center" + vec_text<2>(f.circle.center) + "\nradius " + num(f.circle.radius) + "\nrms " +
             num(f.rms) + '\n',
         j);
    locus::draw(svg, f.circle, result_style());
  } else {
    const auto f = o.algebraic ? locus::fit_sphere_algebraic(std::span<const Vec3d>(pts3))
                               : locus::fit_sphere(std::span<const Vec3d>(pts3));
    fit_status(f.status, o);
    JsonObject j;
    j.str("command", "fit")
        .str("model", "sphere")
        .raw("center", json_vec<3>(f.sphere.center))
        .number("radius", f.sphere.radius)
        .number("rms", f.rms)
        .integer("iterations", f.iterations);
    emit(o.c,
         "center" + vec_text<3>(f.sphere.center) + "\nradius " + num(f.sphere.radius) + "\nrms " +
             num(f.rms) + '\n',
         j);
  }
  if (!o.c.svg.empty()) {
    for (const Vec2d& p : pts2) svg.point(p, input_style());
    save_svg(o.c, svg);
  }
}

}  // namespace

void register_numeric(CLI::App& app) {
  {
    auto o = std::make_shared<RootsOptions>();
    CLI::App* sub = app.add_subcommand("roots", "real roots of a polynomial");
    sub->add_option("coefficients", o->coefficients,
                    "coefficients, highest degree first (put -- before a negative first one)")
        ->required();
    sub->add_flag("--low-first", o->low_first, "coefficients are given constant term first");
    sub->add_flag("--near", o->near,
                  "floating-point mode (fast; clusters within noise count as multiple roots)");
    sub->add_option("--interval", o->interval, "only roots in [a, b]")->expected(2);
    sub->add_flag("--json", o->json, "print a JSON summary");
    sub->footer(
        "Prints each distinct real root (exact root of the given coefficients, correctly\n"
        "rounded) and its multiplicity, increasing.\n"
        "Example:\n  locus roots 1 0 -2        # x^2 - 2 = 0: -1.4142135623730951 and "
        "1.4142135623730951\n  locus roots -- -1 3 -3 1  # -(x - 1)^3: 1 with multiplicity 3");
    sub->callback([o] { run_roots(*o); });
  }
  {
    auto o = std::make_shared<FitOptions>();
    CLI::App* sub =
        app.add_subcommand("fit", "least-squares line, plane, circle or sphere of a point file");
    sub->add_option("model", o->model, "line (2D or 3D), plane (3D), circle (2D), sphere (3D)")
        ->required()
        ->check(CLI::IsMember({"line", "plane", "circle", "sphere"}));
    add_common(sub, o->c, true, "points (.csv .txt .tsv .xyz, or a mesh's vertices)");
    sub->add_flag("--algebraic", o->algebraic,
                  "circle, sphere: the algebraic fit instead of the geometric one");
    sub->footer(
        "Orthogonal least squares (line, plane) and geometric fits (circle, sphere; --algebraic\n"
        "for the one-step algebraic fit); rms is the RMS distance of the points to the result.\n"
        "Example:\n  locus fit circle arc.csv --svg fit.svg\n  locus fit plane scan.xyz --json");
    sub->callback([o] { run_fit(*o); });
  }
}

}  // namespace locus_cli
