// SPDX-License-Identifier: BSL-1.0
#pragma once
// Adapters between locus's polygon layout (MultiPolygon2<double>, rings without a closing
// vertex) and the boolean peers of boolean_bench.cpp and boolean_peer_failures.cpp: GEOS (C API,
// reentrant _r functions), Clipper 1 (integer coordinates: doubles scaled by a power of two and
// rounded) and Boost.Geometry (counter-clockwise closed polygons). Each part is compiled only
// when its peer was found (LOCUS_HAVE_GEOS, LOCUS_HAVE_CLIPPER1, LOCUS_HAVE_BOOST).

#include <locus/boolean/polygon_boolean.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#if defined(LOCUS_HAVE_GEOS)
#include <geos_c.h>
#endif
#if defined(LOCUS_HAVE_CLIPPER1)
#include <polyclipping/clipper.hpp>
#endif
#if defined(LOCUS_HAVE_BOOST)
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#endif

namespace locus_bench_bool {

using Ring = std::vector<locus::Vec2<double>>;
using Multi = locus::MultiPolygon2<double>;

inline double ring_area(const Ring& r) {
  double s = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const auto p = r[i], q = r[(i + 1) % n];
    s += p.x * q.y - p.y * q.x;
  }
  return s / 2;
}
/// Area of polygons with holes (shell areas minus hole areas, orientation ignored).
inline double multi_area(const Multi& m) {
  double s = 0;
  for (const auto& p : m) {
    s += std::abs(ring_area(p.outer.vertices));
    for (const auto& h : p.holes) s -= std::abs(ring_area(h.vertices));
  }
  return s;
}
inline std::size_t multi_vertices(const Multi& m) {
  std::size_t n = 0;
  for (const auto& p : m) {
    n += p.outer.vertices.size();
    for (const auto& h : p.holes) n += h.vertices.size();
  }
  return n;
}
/// Outer rings counter-clockwise, holes clockwise (by the floating-point area sign).
inline void orient(Multi& m) {
  for (auto& p : m) {
    if (ring_area(p.outer.vertices) < 0)
      std::reverse(p.outer.vertices.begin(), p.outer.vertices.end());
    for (auto& h : p.holes)
      if (ring_area(h.vertices) > 0) std::reverse(h.vertices.begin(), h.vertices.end());
  }
}

#if defined(LOCUS_HAVE_GEOS)
inline GEOSContextHandle_t geos() {
  static GEOSContextHandle_t h = GEOS_init_r();
  return h;
}
struct GeosDeleter {
  void operator()(GEOSGeometry* g) const {
    if (g) GEOSGeom_destroy_r(geos(), g);
  }
};
using GeosPtr = std::unique_ptr<GEOSGeometry, GeosDeleter>;

inline GEOSGeometry* geos_ring(const Ring& r) {
  if (r.empty()) return GEOSGeom_createLinearRing_r(geos(), GEOSCoordSeq_create_r(geos(), 0, 2));
  std::vector<double> xy;
  xy.reserve(2 * r.size() + 2);
  for (const auto& p : r) {
    xy.push_back(p.x);
    xy.push_back(p.y);
  }
  xy.push_back(r[0].x);
  xy.push_back(r[0].y);
  GEOSCoordSequence* s = GEOSCoordSeq_copyFromBuffer_r(
      geos(), xy.data(), static_cast<unsigned>(r.size() + 1), false, false);
  return GEOSGeom_createLinearRing_r(geos(), s);
}
inline GEOSGeometry* geos_polygon(const Ring& outer, const std::vector<Ring>& holes) {
  std::vector<GEOSGeometry*> hs;
  for (const Ring& h : holes) hs.push_back(geos_ring(h));
  return GEOSGeom_createPolygon_r(geos(), geos_ring(outer), hs.data(),
                                  static_cast<unsigned>(hs.size()));
}
inline GeosPtr geos_multi(const Multi& m) {
  std::vector<GEOSGeometry*> ps;
  for (const auto& p : m) {
    std::vector<Ring> holes;
    for (const auto& h : p.holes) holes.push_back(h.vertices);
    ps.push_back(geos_polygon(p.outer.vertices, holes));
  }
  return GeosPtr(GEOSGeom_createCollection_r(geos(), GEOS_MULTIPOLYGON, ps.data(),
                                             static_cast<unsigned>(ps.size())));
}
inline Ring geos_ring_points(const GEOSGeometry* ring) {
  const GEOSCoordSequence* s = GEOSGeom_getCoordSeq_r(geos(), ring);
  unsigned n = 0;
  GEOSCoordSeq_getSize_r(geos(), s, &n);
  Ring r;
  for (unsigned i = 0; i + 1 < n; ++i) {
    double x = 0, y = 0;
    GEOSCoordSeq_getXY_r(geos(), s, i, &x, &y);
    r.push_back({x, y});
  }
  return r;
}
/// The polygons of a GEOS result (a polygon, a multipolygon or a collection holding them).
inline void geos_to_multi(const GEOSGeometry* g, Multi& out) {
  const int type = GEOSGeomTypeId_r(geos(), g);
  if (type == GEOS_POLYGON) {
    if (GEOSisEmpty_r(geos(), g)) return;
    locus::PolygonWithHoles2<double> p;
    p.outer.vertices = geos_ring_points(GEOSGetExteriorRing_r(geos(), g));
    const int nh = GEOSGetNumInteriorRings_r(geos(), g);
    for (int k = 0; k < nh; ++k)
      p.holes.push_back({geos_ring_points(GEOSGetInteriorRingN_r(geos(), g, k))});
    out.push_back(std::move(p));
    return;
  }
  const int n = GEOSGetNumGeometries_r(geos(), g);
  if (type == GEOS_MULTIPOLYGON || type == GEOS_GEOMETRYCOLLECTION)
    for (int k = 0; k < n; ++k) geos_to_multi(GEOSGetGeometryN_r(geos(), g, k), out);
}
#endif

#if defined(LOCUS_HAVE_CLIPPER1)
/// The power of two that scales coordinates of magnitude below max_abs to below 2^bits.
inline double clipper_scale(double max_abs, int bits) {
  int e = 0;
  (void)std::frexp(max_abs, &e);
  return std::ldexp(1.0, bits - e);
}
inline ClipperLib::Paths clipper_paths(const std::vector<Ring>& rs, double scale) {
  ClipperLib::Paths ps;
  for (const Ring& r : rs) {
    ClipperLib::Path p;
    for (const auto& q : r)
      p.push_back({static_cast<ClipperLib::cInt>(std::llround(q.x * scale)),
                   static_cast<ClipperLib::cInt>(std::llround(q.y * scale))});
    ps.push_back(std::move(p));
  }
  return ps;
}
/// Outer nodes of a PolyTree with their hole children; a hole's children are outers again.
inline Multi clipper_to_multi(const ClipperLib::PolyTree& tree, double scale) {
  Multi m;
  const auto ring = [&](const ClipperLib::Path& p) {
    Ring r;
    for (const auto& q : p)
      r.push_back({static_cast<double>(q.X) / scale, static_cast<double>(q.Y) / scale});
    return r;
  };
  std::vector<const ClipperLib::PolyNode*> stack(tree.Childs.begin(), tree.Childs.end());
  while (!stack.empty()) {
    const ClipperLib::PolyNode* n = stack.back();
    stack.pop_back();
    locus::PolygonWithHoles2<double> p;
    p.outer.vertices = ring(n->Contour);
    for (const ClipperLib::PolyNode* h : n->Childs) {
      p.holes.push_back({ring(h->Contour)});
      for (const ClipperLib::PolyNode* o : h->Childs) stack.push_back(o);
    }
    m.push_back(std::move(p));
  }
  return m;
}
#endif

#if defined(LOCUS_HAVE_BOOST)
namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPoly = bg::model::polygon<BPoint, false, true>;  // counter-clockwise, closed
using BMulti = bg::model::multi_polygon<BPoly>;

template <class BRing>
void boost_ring(const Ring& r, BRing& out) {
  if (r.empty()) return;
  for (const auto& q : r) out.push_back({q.x, q.y});
  out.push_back({r[0].x, r[0].y});
}
/// m must be oriented (orient()): outer rings counter-clockwise, holes clockwise.
inline BMulti boost_multi(const Multi& m) {
  BMulti out;
  for (const auto& p : m) {
    BPoly b;
    boost_ring(p.outer.vertices, b.outer());
    for (const auto& h : p.holes) {
      b.inners().emplace_back();
      boost_ring(h.vertices, b.inners().back());
    }
    out.push_back(std::move(b));
  }
  return out;
}
inline Multi boost_to_multi(const BMulti& r) {
  Multi m;
  const auto ring = [](const auto& br) {
    Ring out;
    for (std::size_t i = 0; i + 1 < br.size(); ++i) out.push_back({br[i].x(), br[i].y()});
    return out;
  };
  for (const BPoly& p : r) {
    locus::PolygonWithHoles2<double> q;
    q.outer.vertices = ring(p.outer());
    for (const auto& h : p.inners()) q.holes.push_back({ring(h)});
    m.push_back(std::move(q));
  }
  return m;
}
#endif

}  // namespace locus_bench_bool
