// SPDX-License-Identifier: BSL-1.0
// 2D curve intersections over arrays: circle_circle (intersection/circle_circle.hpp: the count
// decided exactly, points constructed), segment_circle, circle_ellipse and ellipse_ellipse
// (intersection/ circle_ellipse.hpp, ellipse_ellipse.hpp: book section 7.5, up to 4 points,
// multiplicities exact), quadratic_curves (general conic pairs, shared lines), circle_arc
// and arc_arc (up to 2 points or 2 overlap arcs). Inputs are converted to float64 (read in place
// when they already are C-contiguous float64); NaN, infinite or negative radii raise ValueError.
#include "common.hpp"

#include <locus/intersection/arc_arc.hpp>
#include <locus/intersection/circle_arc.hpp>
#include <locus/intersection/circle_circle.hpp>
#include <locus/intersection/circle_ellipse.hpp>
#include <locus/intersection/ellipse_ellipse.hpp>
#include <locus/intersection/quadratic_curve_quadratic_curve.hpp>
#include <locus/intersection/segment_circle.hpp>

#include <limits>
#include <string>

namespace locus::python {

namespace {

py::array_t<double> f64(py::handle obj, const char* fn, const char* name, int ndim, int cols) {
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  py::array a = py::array::ensure(obj);
  if (!a) fail(fn, std::string(name) + " is not convertible to a numpy array");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    fail(fn, std::string(name) + " must hold real numbers, not dtype " +
                 std::string(py::str(a.dtype())));
  if (a.ndim() != ndim || (ndim == 2 && a.shape(1) != cols))
    fail(fn, std::string(name) + " must have shape " + (ndim == 1 ? "(n,)" : "(n, 2)"));
  auto out = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!out) fail(fn, std::string("cannot convert ") + name + " to float64");
  check_finite(out.data(), static_cast<std::size_t>(out.size()), fn, name);
  return out;
}

/// Arcs (circle (n, 2) centres, radii, starts, sweeps) checked and read.
struct ArcsIn {
  py::array_t<double> c, r, start, sweep;
  [[nodiscard]] Arc2<double> at(std::size_t i) const {
    return {
        {{c.data()[2 * i], c.data()[2 * i + 1]}, r.data()[i]}, start.data()[i], sweep.data()[i]};
  }
};

/// CurveIntersections of n queries q(i) (an intersection() result with kind, count, point,
/// multiplicity).
template <std::size_t Cap = 2, class Q>
py::object curve_results(std::size_t count_n, Q&& q) {
  const auto n = static_cast<py::ssize_t>(count_n);
  const auto cap = static_cast<py::ssize_t>(Cap);
  py::array_t<std::uint8_t> kind(n);
  py::array_t<std::int8_t> count(n);
  py::array_t<double> pts({n, cap, py::ssize_t(2)});
  py::array_t<std::int8_t> mult({n, cap});
  std::uint8_t* k = kind.mutable_data();
  std::int8_t* c = count.mutable_data();
  std::int8_t* mu = mult.mutable_data();
  double* p = pts.mutable_data();
  {
    py::gil_scoped_release nogil;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < count_n; ++i) {
      const auto r = q(i);
      k[i] = static_cast<std::uint8_t>(r.kind);
      c[i] = static_cast<std::int8_t>(r.count);
      for (std::size_t j = 0; j < Cap; ++j) {
        const bool has = static_cast<int>(j) < r.count;
        p[2 * Cap * i + 2 * j] = has ? r.point[j].x : nan;
        p[2 * Cap * i + 2 * j + 1] = has ? r.point[j].y : nan;
        mu[Cap * i + j] = static_cast<std::int8_t>(has ? r.multiplicity[j] : 0);
      }
    }
  }
  py::object out = new_result("CurveIntersections", Status::ok);
  out.attr("kind") = kind;
  out.attr("count") = count;
  out.attr("points") = pts;
  out.attr("multiplicity") = mult;
  return out;
}

}  // namespace

void bind_intersection2(py::module_& m) {
  m.def(
      "circle_circle",
      [](py::handle c0, py::handle r0, py::handle c1, py::handle r1) -> py::object {
        const char* fn = "circle_circle";
        const auto pc0 = f64(c0, fn, "c0", 2, 2), pc1 = f64(c1, fn, "c1", 2, 2);
        const auto pr0 = f64(r0, fn, "r0", 1, 0), pr1 = f64(r1, fn, "r1", 1, 0);
        const py::ssize_t n = pc0.shape(0);
        if (pc1.shape(0) != n || pr0.shape(0) != n || pr1.shape(0) != n)
          fail(fn, "c0, r0, c1, r1 must have the same length n");
        for (const auto* r : {&pr0, &pr1})
          for (py::ssize_t i = 0; i < n; ++i)
            if (r->data()[i] < 0)
              fail(fn, "invalid_input: negative radius at entry " + std::to_string(i));
        const auto* a = reinterpret_cast<const Vec2<double>*>(pc0.data());
        const auto* b = reinterpret_cast<const Vec2<double>*>(pc1.data());
        const double* ra = pr0.data();
        const double* rb = pr1.data();
        return curve_results(static_cast<std::size_t>(n), [&](std::size_t i) {
          return intersection(Circle2<double>{a[i], ra[i]}, Circle2<double>{b[i], rb[i]});
        });
      },
      py::arg("c0"), py::arg("r0"), py::arg("c1"), py::arg("r1"),
      R"doc(Common points of n pairs of circles (c0[i], r0[i]) and (c1[i], r1[i]): centres (n, 2),
radii (n,) >= 0.

The count is decided exactly (separated, tangent, crossing, nested, equal); points are
constructed. CurveIntersections: kind (codes, names in locus.KIND_NAMES: 0 empty, 1 point (a
tangency), 2 points (two crossings, point 0 right of c0 -> c1), 11 coincident (equal circles,
count 0)), count (0..2), points ((n, 2, 2), NaN where unused), multiplicity ((n, 2): 1 crossing,
2 tangency, 0 unused).)doc");

  m.def(
      "segment_circle",
      [](py::handle segments, py::handle centers, py::handle radii) -> py::object {
        const char* fn = "segment_circle";
        py::array sa = py::array::ensure(segments);
        if (!sa || sa.ndim() != 3 || sa.shape(1) != 2 || sa.shape(2) != 2)
          fail(fn, "segments must have shape (n, 2, 2): n segments (p0, p1) in 2D");
        const auto s2 = f64(sa.reshape({sa.shape(0), py::ssize_t(4)}), fn, "segments", 2, 4);
        const auto c = f64(centers, fn, "centers", 2, 2);
        const auto r = f64(radii, fn, "radii", 1, 0);
        const py::ssize_t n = s2.shape(0);
        if (c.shape(0) != n || r.shape(0) != n)
          fail(fn, "segments, centers and radii must have the same length n");
        for (py::ssize_t i = 0; i < n; ++i)
          if (r.data()[i] < 0)
            fail(fn, "invalid_input: negative radius at entry " + std::to_string(i));
        const auto* ps = reinterpret_cast<const Segment2<double>*>(s2.data());
        const auto* pc = reinterpret_cast<const Vec2<double>*>(c.data());
        const double* pr = r.data();
        return curve_results(static_cast<std::size_t>(n), [&](std::size_t i) {
          return intersection(ps[i], Circle2<double>{pc[i], pr[i]});
        });
      },
      py::arg("segments"), py::arg("centers"), py::arg("radii"),
      R"doc(Common points of n segments (n, 2, 2) (rows p0, p1) and circles (centers (n, 2), radii
(n,) >= 0).

The count is decided exactly (tangency included); points are constructed, by increasing
parameter along the segment. CurveIntersections: kind (0 empty, 1 point, 2 points), count,
points ((n, 2, 2), NaN where unused), multiplicity (1 crossing, 2 tangency).)doc");

  m.def(
      "ellipse_ellipse",
      [](py::handle c0, py::handle angle0, py::handle e0, py::handle c1, py::handle angle1,
         py::handle e1) -> py::object {
        const char* fn = "ellipse_ellipse";
        const auto pc0 = f64(c0, fn, "c0", 2, 2), pc1 = f64(c1, fn, "c1", 2, 2);
        const auto pa0 = f64(angle0, fn, "angle0", 1, 0), pa1 = f64(angle1, fn, "angle1", 1, 0);
        const auto pe0 = f64(e0, fn, "e0", 2, 2), pe1 = f64(e1, fn, "e1", 2, 2);
        const py::ssize_t n = pc0.shape(0);
        if (pc1.shape(0) != n || pa0.shape(0) != n || pa1.shape(0) != n || pe0.shape(0) != n ||
            pe1.shape(0) != n)
          fail(fn, "c0, angle0, e0, c1, angle1, e1 must have the same length n");
        for (const auto* e : {&pe0, &pe1})
          for (py::ssize_t i = 0; i < 2 * n; ++i)
            if (e->data()[i] <= 0)
              fail(fn, "invalid_input: non-positive extent at entry " + std::to_string(i / 2));
        auto ellipse = [](const double* c, double angle, const double* e) {
          const Vec2<double> u{std::cos(angle), std::sin(angle)};
          return Ellipse2<double>{{c[0], c[1]}, {u, {-u.y, u.x}}, {e[0], e[1]}};
        };
        return curve_results<4>(static_cast<std::size_t>(n), [&](std::size_t i) {
          return intersection(ellipse(pc0.data() + 2 * i, pa0.data()[i], pe0.data() + 2 * i),
                              ellipse(pc1.data() + 2 * i, pa1.data()[i], pe1.data() + 2 * i));
        });
      },
      py::arg("c0"), py::arg("angle0"), py::arg("e0"), py::arg("c1"), py::arg("angle1"),
      py::arg("e1"),
      R"doc(Common points of n pairs of ellipses: centres c0, c1 (n, 2), the angle (radians, (n,))
of each ellipse's first axis from the x axis, half-axis lengths e0, e1 (n, 2) > 0 (along the
first axis and the second, counter-clockwise from it).

Book section 7.5 (intersection/ellipse_ellipse.hpp): the number of distinct real common
points and each one's multiplicity are decided exactly (an integer resultant after a shear,
a certified floating-point filter first); distinct points are never merged. CurveIntersections: kind
(0 empty, 1 point, 2 points, 11 coincident), count (0..4), points ((n, 4, 2), by increasing
angle on the first ellipse, NaN where unused), multiplicity ((n, 4): 1 crossing, 2 tangency, 3 or 4
higher contact, 0 unused).)doc");

  m.def(
      "circle_ellipse",
      [](py::handle centers, py::handle radii, py::handle c1, py::handle angle1,
         py::handle e1) -> py::object {
        const char* fn = "circle_ellipse";
        const auto pc0 = f64(centers, fn, "centers", 2, 2), pr = f64(radii, fn, "radii", 1, 0);
        const auto pc1 = f64(c1, fn, "c1", 2, 2), pa1 = f64(angle1, fn, "angle1", 1, 0);
        const auto pe1 = f64(e1, fn, "e1", 2, 2);
        const py::ssize_t n = pc0.shape(0);
        if (pr.shape(0) != n || pc1.shape(0) != n || pa1.shape(0) != n || pe1.shape(0) != n)
          fail(fn, "centers, radii, c1, angle1, e1 must have the same length n");
        for (py::ssize_t i = 0; i < n; ++i)
          if (pr.data()[i] < 0)
            fail(fn, "invalid_input: negative radius at entry " + std::to_string(i));
        for (py::ssize_t i = 0; i < 2 * n; ++i)
          if (pe1.data()[i] <= 0)
            fail(fn, "invalid_input: non-positive extent at entry " + std::to_string(i / 2));
        return curve_results<4>(static_cast<std::size_t>(n), [&](std::size_t i) {
          const Vec2<double> u{std::cos(pa1.data()[i]), std::sin(pa1.data()[i])};
          const double* c = pc1.data() + 2 * i;
          const double* e = pe1.data() + 2 * i;
          return intersection(
              Circle2<double>{{pc0.data()[2 * i], pc0.data()[2 * i + 1]}, pr.data()[i]},
              Ellipse2<double>{{c[0], c[1]}, {u, {-u.y, u.x}}, {e[0], e[1]}});
        });
      },
      py::arg("centers"), py::arg("radii"), py::arg("c1"), py::arg("angle1"), py::arg("e1"),
      R"doc(Common points of n circles (centers (n, 2), radii (n,) >= 0) and ellipses (c1 (n, 2),
angle1 (n,) of the first axis, half-axes e1 (n, 2) > 0), as ellipse_ellipse
(intersection/circle_ellipse.hpp): CurveIntersections with points (n, 4, 2) by increasing angle
on the circle, multiplicity (n, 4) (1 crossing, 2 tangency), kind, count.)doc");

  m.def(
      "quadratic_curves",
      [](py::handle q0, py::handle q1) -> py::object {
        const char* fn = "quadratic_curves";
        const auto a = f64(q0, fn, "q0", 2, 6), b = f64(q1, fn, "q1", 2, 6);
        const py::ssize_t n = a.shape(0);
        if (b.shape(0) != n) fail(fn, "q0 and q1 must have the same length n");
        return curve_results<4>(static_cast<std::size_t>(n), [&](std::size_t i) {
          const double* x = a.data() + 6 * i;
          const double* y = b.data() + 6 * i;
          return intersection(QuadraticCurve2<double>{x[0], x[1], x[2], x[3], x[4], x[5]},
                              QuadraticCurve2<double>{y[0], y[1], y[2], y[3], y[4], y[5]});
        });
      },
      py::arg("q0"), py::arg("q1"),
      R"doc(Common points of n pairs of quadratic curves a x^2 + b xy + c y^2 + d x + e y + f = 0,
coefficients q0, q1 (n, 6) in that order.

Book section 7.5 (intersection/quadratic_curve_quadratic_curve.hpp): the number of distinct real
common points and each one's intersection multiplicity are decided exactly for the curves as
given (an integer resultant after a shear). CurveIntersections: kind (0 empty, 1 point,
2 points, 5 line: a line shared by two line pairs, points 0 and 1 on it and point 2 the isolated
common point of the other components when count is 3; 11 coincident: proportional
coefficients), count (0..4), points ((n, 4, 2), by increasing x then y, NaN where unused),
multiplicity ((n, 4): 1 crossing, 2 tangency, 3 or 4 higher contact, 0 for the line's points).)doc");

  const auto arcs = [](const char* fn, py::handle c, py::handle r, py::handle st, py::handle sw,
                       const char* names, py::ssize_t n) {
    ArcsIn in{f64(c, fn, "centers", 2, 2), f64(r, fn, "radii", 1, 0), f64(st, fn, "starts", 1, 0),
              f64(sw, fn, "sweeps", 1, 0)};
    if (in.c.shape(0) != n || in.r.shape(0) != n || in.start.shape(0) != n ||
        in.sweep.shape(0) != n)
      fail(fn, std::string(names) + " must have the same length n");
    for (py::ssize_t i = 0; i < n; ++i) {
      if (in.r.data()[i] < 0)
        fail(fn, "invalid_input: negative radius at entry " + std::to_string(i));
      if (in.sweep.data()[i] < 0)
        fail(fn, "invalid_input: negative sweep at entry " + std::to_string(i));
    }
    return in;
  };

  m.def(
      "circle_arc",
      [arcs](py::handle centers, py::handle radii, py::handle c1, py::handle r1, py::handle start1,
             py::handle sweep1) -> py::object {
        const char* fn = "circle_arc";
        const auto pc = f64(centers, fn, "centers", 2, 2), pr = f64(radii, fn, "radii", 1, 0);
        const py::ssize_t n = pc.shape(0);
        if (pr.shape(0) != n) fail(fn, "centers and radii must have the same length n");
        for (py::ssize_t i = 0; i < n; ++i)
          if (pr.data()[i] < 0)
            fail(fn, "invalid_input: negative radius at entry " + std::to_string(i));
        const ArcsIn b =
            arcs(fn, c1, r1, start1, sweep1, "centers, radii, c1, r1, start1, sweep1", n);
        return curve_results<6>(static_cast<std::size_t>(n), [&](std::size_t i) {
          return intersection(
              Circle2<double>{{pc.data()[2 * i], pc.data()[2 * i + 1]}, pr.data()[i]}, b.at(i));
        });
      },
      py::arg("centers"), py::arg("radii"), py::arg("c1"), py::arg("r1"), py::arg("start1"),
      py::arg("sweep1"),
      R"doc(Common points of n circles (centers (n, 2), radii (n,) >= 0) and arcs (circle c1 (n, 2),
r1 (n,), start angle start1 (n,), counter-clockwise sweep1 (n,) >= 0, radians; >= 2 pi the whole
circle).

intersection/circle_arc.hpp: the circle-circle count decided exactly, then each point's angle
tested against the arc (a point within a few ulps of an arc end may fall either way).
CurveIntersections with points (n, 6, 2): kind 0 empty, 1 point, 2 points (multiplicity 1
crossing, 2 tangency), 9 arc (the arc lies on the circle: start, middle, end, multiplicity 0),
11 coincident (both whole circles).)doc");

  m.def(
      "arc_arc",
      [arcs](py::handle c0, py::handle r0, py::handle start0, py::handle sweep0, py::handle c1,
             py::handle r1, py::handle start1, py::handle sweep1) -> py::object {
        const char* fn = "arc_arc";
        const auto n = f64(c0, fn, "c0", 2, 2).shape(0);
        const char* names = "c0, r0, start0, sweep0, c1, r1, start1, sweep1";
        const ArcsIn a = arcs(fn, c0, r0, start0, sweep0, names, n);
        const ArcsIn b = arcs(fn, c1, r1, start1, sweep1, names, n);
        return curve_results<6>(static_cast<std::size_t>(n),
                                [&](std::size_t i) { return intersection(a.at(i), b.at(i)); });
      },
      py::arg("c0"), py::arg("r0"), py::arg("start0"), py::arg("sweep0"), py::arg("c1"),
      py::arg("r1"), py::arg("start1"), py::arg("sweep1"),
      R"doc(Common points of n pairs of arcs (centre (n, 2), radius (n,), start angle (n,),
counter-clockwise sweep (n,) >= 0 each, radians).

intersection/arc_arc.hpp: as circle_arc; on a common circle the overlap is one or two arcs
(kind 9 arc, three points each: start, middle, end; count 3 or 6). CurveIntersections with
points (n, 6, 2), multiplicity (n, 6).)doc");
}

}  // namespace locus::python
