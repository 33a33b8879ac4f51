// SPDX-License-Identifier: BSL-1.0
// convex_partition (triangulate/convex_partition.hpp) and the BSP tree of a polygon with holes:
// bsp_classify, bsp_partition (bsp/bsp2.hpp), bsp_boolean (bsp/bsp2_boolean.hpp). Polygons are
// given as a list of rings (ring 0 the outer boundary, then the holes, any orientation),
// concatenated here into the library's points + ring_ends form; float32 runs the float
// instantiation only when every array is float32. Also bspline_surface_insert_knot
// (curves/bspline_surface.hpp), registered here with them.
#include "common.hpp"

#include <locus/bsp/bsp2.hpp>
#include <locus/bsp/bsp2_boolean.hpp>
#include <locus/curves/bspline_surface.hpp>
#include <locus/triangulate/convex_partition.hpp>

#include <string>

namespace locus::python {

namespace {

// The rings of a polygon, validated (each an (k, 2) array) but not yet converted.
struct Rings {
  std::vector<ArrayView> views;
  bool all_float = true;
};

Rings read_rings(py::handle rings, const char* fn, const char* name) {
  if (rings.is_none()) fail(fn, std::string(name) + " is None");
  Rings r;
  // A single (n, 2) array is one ring; otherwise a sequence of (k, 2) arrays.
  py::array probe = py::array::ensure(rings);
  if (probe && probe.ndim() == 2 && probe.dtype().kind() != 'O') {
    r.views.push_back(view_array(rings, fn, name, 2, {2}));
  } else {
    if (!py::isinstance<py::sequence>(rings) || py::isinstance<py::str>(rings))
      fail(fn, std::string(name) + " must be an (n, 2) array or a list of (k, 2) arrays");
    const auto seq = py::reinterpret_borrow<py::sequence>(rings);
    for (std::size_t k = 0; k < seq.size(); ++k) {
      const std::string ring_name = std::string(name) + "[" + std::to_string(k) + "]";
      r.views.push_back(view_array(seq[k], fn, ring_name.c_str(), 2, {2}));
    }
  }
  for (const ArrayView& v : r.views) r.all_float = r.all_float && v.is_float;
  return r;
}

// The rings back to back as Vec2<T> (converting when a ring's dtype is not T) and their ends.
template <class T>
void concat_rings(const Rings& r, std::vector<Vec2<T>>& points, std::vector<std::uint32_t>& ends) {
  for (const ArrayView& v : r.views) {
    if (v.is_float == std::is_same_v<T, float>) {
      const auto s = as_points<T, 2>(v);
      points.insert(points.end(), s.begin(), s.end());
    } else {
      const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(v.array);
      const T* d = a.data();
      for (std::size_t i = 0; i < v.rows; ++i) points.push_back(Vec2<T>{d[2 * i], d[2 * i + 1]});
    }
    ends.push_back(static_cast<std::uint32_t>(points.size()));
  }
}

// The data of `v` as a C-contiguous array of T (in place, or converted).
template <class T>
auto as_dtype(const ArrayView& v) {
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(v.array);
}

template <class T>
py::array points_out(const std::vector<Vec2<T>>& p) {
  py::array_t<T> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(p.size()), 2});
  T* d = a.mutable_data();
  for (std::size_t i = 0; i < p.size(); ++i) {
    d[2 * i] = p[i][0];
    d[2 * i + 1] = p[i][1];
  }
  return a;
}

std::int8_t location_code(Bsp2Location l) {
  switch (l) {
    case Bsp2Location::inside:
      return 1;
    case Bsp2Location::outside:
      return -1;
    case Bsp2Location::coincident_same:
      return 2;
    case Bsp2Location::coincident_opposite:
      return -2;
  }
  return -1;
}

}  // namespace

void bind_partition(py::module_& m) {
  m.def(
      "convex_partition",
      [](py::handle outer, py::object holes, std::string method) -> py::object {
        const char* fn = "convex_partition";
        const bool direct = method == "minimum_direct";
        const bool minimum = method == "minimum" || direct;
        if (!minimum && method != "hertel_mehlhorn")
          fail(fn, "method must be 'hertel_mehlhorn', 'minimum' or 'minimum_direct', not '" +
                       method + "'");
        Rings r;
        r.views.push_back(view_array(outer, fn, "outer", 2, {2}));
        r.all_float = r.views[0].is_float;
        if (!holes.is_none()) {
          const py::array probe = py::array::ensure(holes);
          if (probe && probe.ndim() == 2 && probe.dtype().kind() != 'O')
            fail(fn, "holes must be a list of (k, 2) arrays (wrap a single hole in a list)");
          Rings h = read_rings(holes, fn, "holes");
          for (ArrayView& v : h.views) r.views.push_back(std::move(v));
          r.all_float = r.all_float && h.all_float;
        }
        auto run = [&]<class T>() -> py::object {
          std::vector<Vec2<T>> pts;
          std::vector<std::uint32_t> ends;
          concat_rings<T>(r, pts, ends);
          ConvexPartition cp;
          {
            py::gil_scoped_release nogil;
            const std::span<const Vec2<T>> p(pts);
            const std::span<const std::uint32_t> e(ends);
            cp = minimum ? min_convex_partition(p, e,
                                                direct ? locus::MinConvexMethod::direct
                                                       : locus::MinConvexMethod::keil)
                         : convex_partition(p, e);
          }
          check_status(cp.status, fn);
          py::object out = new_result("ConvexPartitionResult", cp.status);
          out.attr("points") = points_out(pts);
          const auto nv = static_cast<py::ssize_t>(cp.vertices.size());
          out.attr("vertices") = to_numpy(std::move(cp.vertices), {nv});
          const auto npieces = static_cast<py::ssize_t>(cp.piece_ends.size());
          out.attr("piece_ends") = to_numpy(std::move(cp.piece_ends), {npieces});
          out.attr("diagonals") = to_numpy(std::move(cp.diagonals));
          return out;
        };
        return r.all_float ? run.template operator()<float>() : run.template operator()<double>();
      },
      py::arg("outer"), py::arg("holes") = py::none(), py::arg("method") = "hertel_mehlhorn",
      R"doc(Partitions a polygon with holes into convex pieces by diagonals (no new vertices).

outer: (n, 2) ring; holes: None or a list of (k, 2) rings (any orientation, closed implicitly).
method: 'hertel_mehlhorn' (O(n log n), holes allowed, at most 4x the minimum count without
holes) or 'minimum' (exact minimum number of pieces; no holes, else ValueError; above 64
vertices status 'limit_exceeded' with the Hertel-Mehlhorn partition).
ConvexPartitionResult: `points` ((m, 2): outer then the holes, what the indices refer to),
`vertices` (uint32: the pieces back to back, each a counter-clockwise ring of indices into
points), `piece_ends` (piece k is vertices[piece_ends[k-1]:piece_ends[k]], like ring_ends),
`diagonals` ((d, 2) uint32 index pairs separating pieces) and the property `pieces` (a list of
index arrays, one per piece; points[piece] is its (k, 2) ring).
Raises ValueError for empty input, NaN/Inf, invalid rings or an unknown method.)doc");

  m.def(
      "bsp_classify",
      [](py::handle polygon_rings, py::handle points) -> py::object {
        const char* fn = "bsp_classify";
        const Rings r = read_rings(polygon_rings, fn, "polygon_rings");
        const ArrayView q = view_array(points, fn, "points", 2, {2});
        auto run = [&]<class T>() -> py::object {
          std::vector<Vec2<T>> pts;
          std::vector<std::uint32_t> ends;
          concat_rings<T>(r, pts, ends);
          const auto qa = as_dtype<T>(q);
          check_finite(qa.data(), 2 * q.rows, fn, "points");
          std::vector<std::int8_t> side(q.rows);
          Status st = Status::ok;
          {
            py::gil_scoped_release nogil;
            const Bsp2<T> tree{std::span<const Vec2<T>>(pts), std::span<const std::uint32_t>(ends)};
            st = tree.status();
            if (st == Status::ok) {
              const T* d = qa.data();
              for (std::size_t i = 0; i < q.rows; ++i)
                side[i] = static_cast<std::int8_t>(tree.classify(Vec2<T>{d[2 * i], d[2 * i + 1]}));
            }
          }
          check_status(st, fn);
          const auto n = static_cast<py::ssize_t>(side.size());
          return to_numpy(std::move(side), {n});
        };
        return r.all_float && q.is_float ? run.template operator()<float>()
                                         : run.template operator()<double>();
      },
      py::arg("polygon_rings"), py::arg("points"),
      R"doc(Classifies (n, 2) points against a polygon with holes through its BSP tree (exact).

polygon_rings: an (m, 2) ring or a list of rings (ring 0 outer, then holes, any orientation);
the tree is built once per call (bsp/bsp2.hpp, balanced splitting). Returns an int8 array:
1 inside, 0 on the boundary (an edge or a vertex), -1 outside (the values of locus::Side, as
point_in_polygon). Raises ValueError for empty or invalid rings, a zero-area outer ring and
NaN/Inf coordinates.)doc");

  m.def(
      "bsp_partition",
      [](py::handle polygon_rings, py::handle segments) -> py::object {
        const char* fn = "bsp_partition";
        const Rings r = read_rings(polygon_rings, fn, "polygon_rings");
        const ArrayView s = view_array(segments, fn, "segments", 3, {2}, 2);
        auto run = [&]<class T>() -> py::object {
          std::vector<Vec2<T>> pts;
          std::vector<std::uint32_t> ends;
          concat_rings<T>(r, pts, ends);
          const auto sa = as_dtype<T>(s);
          check_finite(sa.data(), 4 * s.rows, fn, "segments");
          std::vector<T> coords;
          std::vector<std::int8_t> location;
          std::vector<std::uint32_t> owner;
          Status st = Status::ok, seg_st = Status::ok;
          std::size_t bad = 0;
          {
            py::gil_scoped_release nogil;
            const Bsp2<T> tree{std::span<const Vec2<T>>(pts), std::span<const std::uint32_t>(ends)};
            st = tree.status();
            const T* d = sa.data();
            for (std::size_t i = 0; i < s.rows && st == Status::ok; ++i) {
              const Bsp2SegmentPartition<T> part = tree.partition(
                  Vec2<T>{d[4 * i], d[4 * i + 1]}, Vec2<T>{d[4 * i + 2], d[4 * i + 3]});
              if (part.status != Status::ok) {
                seg_st = part.status;
                bad = i;
                break;
              }
              for (const Bsp2Piece<T>& piece : part.pieces) {
                for (const Bsp2End<T>& e : piece.end) {
                  coords.push_back(e.point[0]);
                  coords.push_back(e.point[1]);
                }
                location.push_back(location_code(piece.location));
                owner.push_back(static_cast<std::uint32_t>(i));
              }
            }
          }
          check_status(st, fn);
          if (seg_st == Status::degenerate_input)
            fail(fn, "degenerate_input: segments[" + std::to_string(bad) + "] has equal ends");
          check_status(seg_st, fn);
          py::object out = new_result("BspPartition", st);
          const auto k = static_cast<py::ssize_t>(location.size());
          out.attr("pieces") = to_numpy(std::move(coords), {k, 2, 2});
          out.attr("location") = to_numpy(std::move(location), {k});
          out.attr("segment") = to_numpy(std::move(owner), {k});
          return out;
        };
        return r.all_float && s.is_float ? run.template operator()<float>()
                                         : run.template operator()<double>();
      },
      py::arg("polygon_rings"), py::arg("segments"),
      R"doc(Splits (n, 2, 2) segments (rows p0, p1) by a polygon with holes through its BSP tree.

polygon_rings: as bsp_classify (the tree is built once per call). BspPartition: `pieces`
((k, 2, 2), the pieces of every segment in order from p0 to p1, segment after segment; cut
points rounded, every decision exact), `location` (int8 per piece: 1 inside, -1 outside,
2 on the boundary in the direction of the boundary edge (interior on its left), -2 on the
boundary in the opposite direction) and `segment` (uint32: the input segment of each piece).
Raises ValueError for empty or invalid rings, a zero-area outer ring, NaN/Inf coordinates and
a segment with equal ends.)doc");

  m.def(
      "bsp_boolean",
      [](const std::string& op_name, py::handle a_rings, py::handle b_rings) -> py::object {
        const char* fn = "bsp_boolean";
        Bsp2Op op = Bsp2Op::intersection;
        if (op_name == "union")
          op = Bsp2Op::union_;
        else if (op_name == "difference")
          op = Bsp2Op::difference;
        else if (op_name == "xor")
          op = Bsp2Op::exclusive_or;
        else if (op_name != "intersection")
          fail(fn,
               "op must be 'intersection', 'union', 'difference' or 'xor', not '" + op_name + "'");
        const Rings ra = read_rings(a_rings, fn, "a"), rb = read_rings(b_rings, fn, "b");
        auto run = [&]<class T>() -> py::object {
          std::vector<Vec2<T>> pa, pb;
          std::vector<std::uint32_t> ea, eb;
          concat_rings<T>(ra, pa, ea);
          concat_rings<T>(rb, pb, eb);
          for (const Vec2<T>& v : pa)
            if (!is_finite(v)) fail(fn, "non_finite_input: a has a NaN or infinite coordinate");
          for (const Vec2<T>& v : pb)
            if (!is_finite(v)) fail(fn, "non_finite_input: b has a NaN or infinite coordinate");
          Bsp2BooleanResult<T> r;
          {
            py::gil_scoped_release nogil;
            const Bsp2<T> ta{std::span<const Vec2<T>>(pa), std::span<const std::uint32_t>(ea)};
            const Bsp2<T> tb{std::span<const Vec2<T>>(pb), std::span<const std::uint32_t>(eb)};
            r = bsp2_boolean(op, ta, tb);
          }
          check_status(r.status, fn);
          std::vector<T> edges, segs, pts;
          std::vector<std::uint8_t> operand;
          for (const auto& e : r.edges) {
            for (const auto& x : e.end) edges.insert(edges.end(), {x.point.x, x.point.y});
            operand.push_back(e.operand);
          }
          for (const auto& e : r.segments)
            for (const auto& x : e.end) segs.insert(segs.end(), {x.point.x, x.point.y});
          for (const auto& p : r.points) pts.insert(pts.end(), {p.x, p.y});
          py::list loops;
          std::uint32_t begin = 0;
          for (const std::uint32_t end : r.loop_ends) {
            std::vector<T> ring;
            for (std::uint32_t i = begin; i < end; ++i) {
              const Vec2<T>& v = r.edges[r.loop_edges[i]].end[0].point;
              ring.insert(ring.end(), {v.x, v.y});
            }
            loops.append(to_numpy(std::move(ring), {static_cast<py::ssize_t>(end - begin), 2}));
            begin = end;
          }
          py::object out = new_result("BspBoolean", r.status);
          const auto k = static_cast<py::ssize_t>(operand.size());
          out.attr("edges") = to_numpy(std::move(edges), {k, 2, 2});
          out.attr("operand") = to_numpy(std::move(operand), {k});
          out.attr("loops") = loops;
          out.attr("closed") = r.closed;
          const auto ns = static_cast<py::ssize_t>(r.segments.size());
          out.attr("segments") = to_numpy(std::move(segs), {ns, 2, 2});
          const auto np = static_cast<py::ssize_t>(r.points.size());
          out.attr("points") = to_numpy(std::move(pts), {np, 2});
          return out;
        };
        return ra.all_float && rb.all_float ? run.template operator()<float>()
                                            : run.template operator()<double>();
      },
      py::arg("op"), py::arg("a"), py::arg("b"),
      R"doc(The boolean of two polygons with holes through their BSP trees (book section 13.5).

op: 'intersection', 'union', 'difference' (a minus b) or 'xor'; a, b: an (m, 2) ring or a list
of rings (ring 0 outer, then holes, any orientation), as bsp_classify. BspBoolean: `edges`
((k, 2, 2), the directed boundary edges of the regularised result, interior on the left;
crossing points rounded, every decision exact), `operand` (uint8: 0 from a, 1 from b),
`loops` (list of (m, 2) arrays: the edges chained into closed loops, counter-clockwise outer
boundaries and clockwise holes), `closed` (every edge is in a loop), and for an intersection
the lower-dimensional parts of the true set intersection: `segments` ((s, 2, 2), edges shared
with opposite directions) and `points` ((p, 2), vertices where a and b only touch). An empty
or zero-area ring list is the empty set. Raises ValueError for NaN/Inf, invalid rings or an
unknown op (bsp/bsp2_boolean.hpp).)doc");

  m.def(
      "bspline_surface_insert_knot",
      [](py::handle control, py::handle knots_u, py::handle knots_v, int degree_u, int degree_v,
         double t, std::string direction, int times) -> py::object {
        const char* fn = "bspline_surface_insert_knot";
        const ArrayView c = view_array(control, fn, "control", 3, {2, 3});
        if (direction != "u" && direction != "v")
          fail(fn, "direction must be 'u' or 'v', not '" + direction + "'");
        if (times < 1) fail(fn, "times must be at least 1");
        if (!std::isfinite(t)) fail(fn, "non_finite_input: t is NaN or infinite");
        auto knots_in = [&]<class T>(py::handle k, const char* name) {
          const ArrayView kv = view_array(k, fn, name, 1, {});
          const auto a = as_dtype<T>(kv);
          return std::vector<T>(a.data(), a.data() + kv.rows);
        };
        auto run = [&]<class T, int N>() -> py::object {
          BSplineSurface<T, N> s{degree_u,
                                 degree_v,
                                 static_cast<int>(c.array.shape(0)),
                                 static_cast<int>(c.array.shape(1)),
                                 {},
                                 {},
                                 {}};
          const auto ca = as_dtype<T>(c);
          const auto* p = reinterpret_cast<const Vec<T, N>*>(ca.data());
          s.control.assign(p, p + static_cast<std::size_t>(ca.size() / N));
          s.knots_u = knots_in.template operator()<T>(knots_u, "knots_u");
          s.knots_v = knots_in.template operator()<T>(knots_v, "knots_v");
          check_status(validate(s), fn, false);
          {
            py::gil_scoped_release nogil;
            const T tt = static_cast<T>(t);
            s = direction == "u" ? insert_knot_u(s, tt, times) : insert_knot_v(s, tt, times);
          }
          std::vector<T> flat(s.control.size() * N);
          for (std::size_t i = 0; i < s.control.size(); ++i)
            for (int j = 0; j < N; ++j) flat[i * N + static_cast<std::size_t>(j)] = s.control[i][j];
          const auto ku = static_cast<py::ssize_t>(s.knots_u.size());
          const auto kv = static_cast<py::ssize_t>(s.knots_v.size());
          return py::make_tuple(to_numpy(std::move(flat), {s.rows, s.cols, N}),
                                to_numpy(std::move(s.knots_u), {ku}),
                                to_numpy(std::move(s.knots_v), {kv}));
        };
        if (c.is_float)
          return c.last == 2 ? run.template operator()<float, 2>()
                             : run.template operator()<float, 3>();
        return c.last == 2 ? run.template operator()<double, 2>()
                           : run.template operator()<double, 3>();
      },
      py::arg("control"), py::arg("knots_u"), py::arg("knots_v"), py::arg("degree_u"),
      py::arg("degree_v"), py::arg("t"), py::arg("direction") = "u", py::arg("times") = 1,
      R"doc(Inserts a knot into a tensor-product B-spline surface (Boehm; the surface is unchanged).

control: (rows, cols, N) control net, N = 2 or 3, row i along u, column j along v; knots_u has
rows + degree_u + 1 values, knots_v cols + degree_v + 1 (the conventions of
curves/bspline_surface.hpp). t (clamped to the domain) is inserted `times` times along
direction 'u' (every column) or 'v' (every row); the multiplicity is capped at the degree.
Returns (control, knots_u, knots_v) of the refined surface, in control's dtype.
Raises ValueError for inconsistent sizes, bad knot vectors, NaN/Inf, times < 1.)doc");
}

}  // namespace locus::python
