// SPDX-License-Identifier: BSL-1.0
// 3D intersection queries over arrays: triangles_intersect (intersection/triangle_triangle.hpp,
// exact) and ray_triangle_hits (intersection/ray_triangle.hpp watertight_hit, closest hit per
// ray; through the BVH of spatial/bvh.hpp when rays x triangles is large, with the same
// answers). Inputs are converted to float64 (read in place when they already are
// C-contiguous float64); NaN or infinite coordinates raise ValueError.
#include "common.hpp"

#include <locus/intersection/ray_aligned_box.hpp>
#include <locus/intersection/ray_triangle.hpp>
#include <locus/intersection/segment_aligned_box.hpp>
#include <locus/intersection/triangle_triangle.hpp>
#include <locus/spatial/bvh.hpp>

#include <limits>
#include <string>

namespace locus::python {

namespace {

/// A C-contiguous float64 array of shape (n, inner...) (checked), finite.
py::array_t<double> f64(py::handle obj, const char* fn, const char* name,
                        std::initializer_list<py::ssize_t> inner, const char* shape_text) {
  if (obj.is_none()) fail(fn, std::string(name) + " is None");
  py::array a = py::array::ensure(obj);
  if (!a) fail(fn, std::string(name) + " is not convertible to a numpy array");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    fail(fn, std::string(name) + " must hold real numbers, not dtype " +
                 std::string(py::str(a.dtype())));
  bool ok = a.ndim() == static_cast<py::ssize_t>(inner.size()) + 1;
  py::ssize_t axis = 1;
  for (const py::ssize_t d : inner) ok = ok && a.shape(axis++) == d;
  if (!ok) fail(fn, std::string(name) + " must have shape " + shape_text);
  auto out = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!out) fail(fn, std::string("cannot convert ") + name + " to float64");
  check_finite(out.data(), static_cast<std::size_t>(out.size()), fn, name);
  return out;
}

/// hit, t_enter, t_exit of n linear components against n boxes (min, max rows).
template <class Lin>
py::object box_hits(const Lin* lin, const AlignedBox3<double>* box, std::size_t n) {
  const auto rows = static_cast<py::ssize_t>(n);
  py::array_t<bool> hit(rows);
  py::array_t<double> t0(rows), t1(rows);
  bool* h = hit.mutable_data();
  double* a = t0.mutable_data();
  double* b = t1.mutable_data();
  {
    py::gil_scoped_release nogil;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < n; ++i) {
      const auto r = intersection(lin[i], box[i]);
      h[i] = r.kind != Kind::empty;
      a[i] = r.count > 0 ? r.param_a[0] : nan;
      b[i] = r.count > 1 ? r.param_a[1] : a[i];
    }
  }
  py::object out = new_result("BoxHits", Status::ok);
  out.attr("hit") = hit;
  out.attr("t_enter") = t0;
  out.attr("t_exit") = t1;
  return out;
}

}  // namespace

void bind_intersection3(py::module_& m) {
  m.def(
      "triangles_intersect",
      [](py::handle a, py::handle b) -> py::array {
        const char* fn = "triangles_intersect";
        const auto ta = f64(a, fn, "a", {3, 3}, "(n, 3, 3): n triangles (v0, v1, v2) in 3D");
        const auto tb = f64(b, fn, "b", {3, 3}, "(n, 3, 3): n triangles (v0, v1, v2) in 3D");
        if (ta.shape(0) != tb.shape(0))
          fail(fn, "a and b must hold the same number of triangles, got " +
                       std::to_string(ta.shape(0)) + " and " + std::to_string(tb.shape(0)));
        const auto n = static_cast<std::size_t>(ta.shape(0));
        py::array_t<bool> out(static_cast<py::ssize_t>(n));
        bool* o = out.mutable_data();
        const auto* pa = reinterpret_cast<const Triangle3<double>*>(ta.data());
        const auto* pb = reinterpret_cast<const Triangle3<double>*>(tb.data());
        {
          py::gil_scoped_release nogil;
          for (std::size_t i = 0; i < n; ++i) o[i] = intersects(pa[i], pb[i]);
        }
        return out;
      },
      py::arg("a"), py::arg("b"),
      R"doc(Whether triangles a[i] and b[i] (each (n, 3, 3)) have a common point: bool (n,).

Closed triangles (touching at a vertex or edge counts), decided exactly with orient3d /
orient2d signs, no tolerance; degenerate triangles act as their segment or point.)doc");

  m.def(
      "ray_triangle_hits",
      [](py::handle origins, py::handle directions, py::handle triangles,
         py::object faces) -> py::object {
        const char* fn = "ray_triangle_hits";
        const auto o = f64(origins, fn, "origins", {3}, "(n, 3)");
        const auto d = f64(directions, fn, "directions", {3}, "(n, 3)");
        if (o.shape(0) != d.shape(0))
          fail(fn, "origins and directions must have the same number of rows, got " +
                       std::to_string(o.shape(0)) + " and " + std::to_string(d.shape(0)));
        std::vector<Triangle3<double>> tris;
        if (faces.is_none()) {
          const auto t = f64(triangles, fn, "triangles", {3, 3}, "(m, 3, 3), or give faces");
          const auto* p = reinterpret_cast<const Triangle3<double>*>(t.data());
          tris.assign(p, p + t.shape(0));
        } else {
          const auto v = f64(triangles, fn, "vertices", {3}, "(k, 3) when faces is given");
          const auto* p = reinterpret_cast<const Vec3<double>*>(v.data());
          const std::vector<std::uint32_t> f =
              index_array(faces, fn, "faces", 2, 3, static_cast<std::size_t>(v.shape(0)));
          for (std::size_t i = 0; i + 2 < f.size(); i += 3)
            tris.push_back({p[f[i]], p[f[i + 1]], p[f[i + 2]]});
        }
        const auto n = static_cast<std::size_t>(o.shape(0));
        const auto rows = static_cast<py::ssize_t>(n);
        py::array_t<bool> hit(rows), front(rows);
        py::array_t<double> t(rows), bary({rows, py::ssize_t(3)}), point({rows, py::ssize_t(3)});
        py::array_t<std::int64_t> index(rows);
        const auto* po = reinterpret_cast<const Vec3<double>*>(o.data());
        const auto* pd = reinterpret_cast<const Vec3<double>*>(d.data());
        bool* h = hit.mutable_data();
        bool* fr = front.mutable_data();
        double* pt = t.mutable_data();
        double* pb = bary.mutable_data();
        double* pp = point.mutable_data();
        std::int64_t* pi = index.mutable_data();
        {
          py::gil_scoped_release nogil;
          const double nan = std::numeric_limits<double>::quiet_NaN();
          // Large inputs go through a BVH over the triangle soup: the same watertight test on
          // every candidate, the same closest triangle (ties: lowest index) and t.
          Bvh<double> bvh;
          const bool use_bvh = tris.size() >= 16 && n * tris.size() > 4096;
          if (use_bvh) {
            std::vector<Vec3<double>> pts;
            std::vector<std::array<std::uint32_t, 3>> soup;
            pts.reserve(3 * tris.size());
            for (const auto& tr : tris) {
              const auto b = static_cast<std::uint32_t>(pts.size());
              pts.insert(pts.end(), {tr.v0, tr.v1, tr.v2});
              soup.push_back({b, b + 1, b + 2});
            }
            bvh = Bvh<double>(pts, soup);
          }
          for (std::size_t i = 0; i < n; ++i) {
            const Ray3<double> ray{po[i], pd[i]};
            TriangleHit<double> best;
            std::int64_t best_k = -1;
            if (use_bvh) {
              const MeshHit<double> mh = bvh.closest_hit(ray);
              if (mh) {
                best = watertight_hit(ray, tris[mh.triangle]);
                best_k = static_cast<std::int64_t>(mh.triangle);
              }
            }
            for (std::size_t k = 0; !use_bvh && k < tris.size(); ++k) {
              const TriangleHit<double> r = watertight_hit(ray, tris[k]);
              if (r.hit && (best_k < 0 || r.t < best.t)) {
                best = r;
                best_k = static_cast<std::int64_t>(k);
              }
            }
            h[i] = best_k >= 0;
            fr[i] = best_k >= 0 && best.front;
            pi[i] = best_k;
            pt[i] = best_k >= 0 ? best.t : nan;
            for (int c = 0; c < 3; ++c) {
              pb[3 * i + static_cast<std::size_t>(c)] = best_k >= 0 ? best.barycentric[c] : nan;
              pp[3 * i + static_cast<std::size_t>(c)] = best_k >= 0 ? best.point[c] : nan;
            }
          }
        }
        py::object out = new_result("RayHits", Status::ok);
        out.attr("hit") = hit;
        out.attr("t") = t;
        out.attr("triangle") = index;
        out.attr("barycentric") = bary;
        out.attr("point") = point;
        out.attr("front") = front;
        return out;
      },
      py::arg("origins"), py::arg("directions"), py::arg("triangles"),
      py::arg("faces") = py::none(),
      R"doc(Closest watertight hit of each ray origins[i] + t directions[i] (t >= 0) with a set of
triangles: (m, 3, 3) corner coordinates, or vertices (k, 3) with faces (m, 3).

Brute force for small inputs, else through a bounding volume hierarchy (the same answers).
Watertight: a ray through a shared edge or vertex of a
closed mesh hits exactly one of the triangles there; edge-on and degenerate triangles are never
hit; zero directions never hit. Ties in t go to the lowest triangle index. RayHits: hit (bool),
t (NaN where no hit), triangle (int64, -1 where no hit), barycentric ((n, 3): weights of v0, v1,
v2), point ((n, 3)), front (hit from the side (v1 - v0) x (v2 - v0) points to).)doc");

  m.def(
      "ray_box_hits",
      [](py::handle origins, py::handle directions, py::handle boxes) -> py::object {
        const char* fn = "ray_box_hits";
        const auto o = f64(origins, fn, "origins", {3}, "(n, 3)");
        const auto d = f64(directions, fn, "directions", {3}, "(n, 3)");
        const auto b = f64(boxes, fn, "boxes", {2, 3}, "(n, 2, 3): rows min, max");
        if (o.shape(0) != d.shape(0) || o.shape(0) != b.shape(0))
          fail(fn, "origins, directions and boxes must have the same number of rows");
        const auto n = static_cast<std::size_t>(o.shape(0));
        std::vector<Ray3<double>> rays(n);
        const auto* po = reinterpret_cast<const Vec3<double>*>(o.data());
        const auto* pd = reinterpret_cast<const Vec3<double>*>(d.data());
        for (std::size_t i = 0; i < n; ++i) rays[i] = {po[i], pd[i]};
        return box_hits(rays.data(), reinterpret_cast<const AlignedBox3<double>*>(b.data()), n);
      },
      py::arg("origins"), py::arg("directions"), py::arg("boxes"),
      R"doc(Part of each ray origins[i] + t directions[i] (t >= 0) inside the closed box boxes[i]
((n, 2, 3): rows min, max), by slab clipping with exact comparisons of the slab parameters.

BoxHits: hit (bool), t_enter, t_exit (NaN where no hit; equal when the ray only touches the
box). A zero direction acts as its origin point; an empty box (min > max) is never hit.)doc");

  m.def(
      "segment_box_hits",
      [](py::handle segments, py::handle boxes) -> py::object {
        const char* fn = "segment_box_hits";
        const auto s = f64(segments, fn, "segments", {2, 3}, "(n, 2, 3): rows p0, p1");
        const auto b = f64(boxes, fn, "boxes", {2, 3}, "(n, 2, 3): rows min, max");
        if (s.shape(0) != b.shape(0))
          fail(fn, "segments and boxes must have the same number of rows");
        return box_hits(reinterpret_cast<const Segment3<double>*>(s.data()),
                        reinterpret_cast<const AlignedBox3<double>*>(b.data()),
                        static_cast<std::size_t>(s.shape(0)));
      },
      py::arg("segments"), py::arg("boxes"),
      R"doc(Part of each segment p0 + t (p1 - p0), t in [0, 1], inside the closed box boxes[i]
((n, 2, 3): rows min, max); exact decisions as in ray_box_hits.

BoxHits: hit (bool), t_enter, t_exit (NaN where no hit).)doc");
}

}  // namespace locus::python
