// SPDX-License-Identifier: BSL-1.0
// Polygon booleans (row cg.bool2, issue 21 item 7): locus boolean_op against GEOS (C API,
// OverlayNG), Clipper 1 (libpolyclipping) and Boost.Geometry in one run, on the seeded inputs of
// boolean_inputs.hpp: two 10^5-vertex polygons with few crossings ("few") and with many
// ("spiky"), each under intersection, union and difference, and the union of 10^4 small
// overlapping polygons ("many"), each library on its best bulk route:
//   locus     boolean_op over raw rings, non-zero fill (one call for "many": all rings at once);
//   geos      GEOSIntersection_r / GEOSUnion_r / GEOSDifference_r; GEOSUnaryUnion_r for "many";
//   clipper1  one Clipper::Execute (non-zero fill, PolyTree output) with every path; coordinates
//             scaled by a power of two to integers below 2^40 ("clipper1<40b>": locus's grid,
//             Clipper's 128-bit path) or below 2^29 ("clipper1<29b>": its faster 64-bit path,
//             a grid 2^11 times coarser than locus's);
//   boost     bg::intersection / union_ / difference; for "many" a cascaded (balanced pairwise)
//             union, as Boost has no unary union.
// Conversion of the input to each library's layout is outside the timed loop; its output stays in
// its own layout. After the loop the last output is converted and checked once: GEOS's isValid
// (OGC validity) and its area against locus's; counters valid (1/0), threw (1/0), area_rel
// (|area - locus area| / locus area) and out_vertices. items_per_second counts input vertices
// (for scripts/bench_rounds). CGAL's General_polygon_set_2 (Epeck) is not measured (see
// bench/results/boolean.md).
//
//   cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DLOCUS_BENCH_PEERS=ON
//   ninja -C build/bench locus_bench_boolean
//   scripts/bench_rounds --rounds 3 --min-time 0.05 --peer-double geos
//       build/bench/bench/locus_bench_boolean   (one command line)
// Results: bench/results/boolean.md.

#include <locus/boolean/polygon_boolean.hpp>

#include <benchmark/benchmark.h>

#include "boolean/boolean_inputs.hpp"
#include "boolean/boolean_peers.hpp"
#include "support/heap_peak.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace locus_bench_bool;
using locus::BooleanOp;

struct Input {
  std::string name;
  std::vector<Ring> a, b;  // b empty: the union of all of a
  std::size_t vertices = 0;
};

const Input& input(const std::string& name) {
  static std::map<std::string, Input> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Input in{name, {}, {}, 0};
  if (name == "few" || name == "spiky") {
    Pair p = name == "few" ? few_crossings() : many_crossings();
    in.a.push_back(std::move(p.a));
    in.b.push_back(std::move(p.b));
  } else {
    in.a = small_polygons(kSmallPolygons, 25);
  }
  for (const auto* set : {&in.a, &in.b})
    for (const Ring& r : *set) in.vertices += r.size();
  return cache.emplace(name, std::move(in)).first->second;
}

const char* op_name(BooleanOp op) {
  return op == BooleanOp::intersection ? "intersection"
         : op == BooleanOp::union_     ? "union"
                                       : "difference";
}

std::vector<locus::Polygon2<double>> locus_rings(const std::vector<Ring>& rs) {
  std::vector<locus::Polygon2<double>> out;
  for (const Ring& r : rs) out.push_back({r});
  return out;
}

/// What the check after the timed loop found.
struct Outcome {
  bool threw = false;
  bool valid = false;
  double area = 0;
  std::size_t vertices = 0;
};

Outcome check(const Multi& m) {
  Outcome o;
  o.area = multi_area(m);
  o.vertices = multi_vertices(m);
#if defined(LOCUS_HAVE_GEOS)
  GeosPtr g = geos_multi(m);
  o.valid = g && GEOSisValid_r(geos(), g.get()) == 1;
#else
  o.valid = true;  // unchecked without GEOS
#endif
  return o;
}

Multi run_locus(const Input& in, BooleanOp op) {
  static std::map<std::string, std::vector<locus::Polygon2<double>>> cache;
  auto& a = cache[in.name + "/a"];
  auto& b = cache[in.name + "/b"];
  if (a.empty()) a = locus_rings(in.a);
  if (b.empty()) b = locus_rings(in.b);
  auto r = locus::boolean_op<double>(op, a, b, {locus::FillRule::non_zero, 0});
  if (r.status != locus::Status::ok) throw std::runtime_error(r.message);
  return std::move(r.polygons);
}

double locus_reference_area(const Input& in, BooleanOp op) {
  static std::map<std::string, double> cache;
  const std::string key = in.name + op_name(op);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache[key] = multi_area(run_locus(in, op));
}

void report(benchmark::State& state, const Input& in, BooleanOp op, const Outcome& o) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(in.vertices));
  const double ref = locus_reference_area(in, op);
  state.counters["threw"] = o.threw ? 1 : 0;
  state.counters["valid"] = o.valid && !o.threw ? 1 : 0;
  state.counters["area_rel"] = o.threw ? -1 : std::abs(o.area - ref) / ref;
  state.counters["out_vertices"] = static_cast<double>(o.vertices);
}

/// Runs op on in with one library: prepare() once, then run() timed, then to_multi() of the
/// last result checked. Each library's types stay inside its lambdas.
template <class Native>
void measure(benchmark::State& state, const Input& in, BooleanOp op,
             const std::function<Native()>& run, const std::function<Multi(const Native&)>& out) {
  Outcome o;
  Native last{};
  locus::bench::HeapPeak peak;
  try {
    for (auto _ : state) {
      last = run();
      benchmark::DoNotOptimize(&last);
    }
  } catch (const std::exception& e) {
    o.threw = true;
    state.SetLabel(std::string("threw: ") + e.what());
  }
  locus::bench::report_heap_peak(state, peak);
  if (!o.threw) o = check(out(last));
  report(state, in, op, o);
}

void bench_locus(benchmark::State& state, std::string name, BooleanOp op) {
  const Input& in = input(name);
  measure<Multi>(
      state, in, op, [&] { return run_locus(in, op); }, [](const Multi& m) { return m; });
}

#if defined(LOCUS_HAVE_GEOS)
void bench_geos(benchmark::State& state, std::string name, BooleanOp op) {
  const Input& in = input(name);
  std::vector<GEOSGeometry*> parts;
  for (const Ring& r : in.a) parts.push_back(geos_polygon(r, {}));
  GeosPtr a(parts.size() == 1 ? parts[0]
                              : GEOSGeom_createCollection_r(geos(), GEOS_MULTIPOLYGON, parts.data(),
                                                            static_cast<unsigned>(parts.size())));
  GeosPtr b(in.b.empty() ? nullptr : geos_polygon(in.b[0], {}));
  measure<std::shared_ptr<GEOSGeometry>>(
      state, in, op,
      [&] {
        GEOSGeometry* r = nullptr;
        if (!b)
          r = GEOSUnaryUnion_r(geos(), a.get());
        else if (op == BooleanOp::intersection)
          r = GEOSIntersection_r(geos(), a.get(), b.get());
        else if (op == BooleanOp::union_)
          r = GEOSUnion_r(geos(), a.get(), b.get());
        else
          r = GEOSDifference_r(geos(), a.get(), b.get());
        if (!r) throw std::runtime_error("GEOS returned no geometry (an exception inside)");
        return std::shared_ptr<GEOSGeometry>(r, GeosDeleter{});
      },
      [](const std::shared_ptr<GEOSGeometry>& g) {
        Multi m;
        geos_to_multi(g.get(), m);
        return m;
      });
}
#endif

#if defined(LOCUS_HAVE_CLIPPER1)
void bench_clipper1(benchmark::State& state, std::string name, BooleanOp op, int bits) {
  const Input& in = input(name);
  double max_abs = 0;
  for (const auto* set : {&in.a, &in.b})
    for (const Ring& r : *set)
      for (const V& p : r) max_abs = std::max({max_abs, std::abs(p.x), std::abs(p.y)});
  const double scale = clipper_scale(max_abs, bits);
  const ClipperLib::Paths a = clipper_paths(in.a, scale), b = clipper_paths(in.b, scale);
  const ClipperLib::ClipType type = op == BooleanOp::intersection ? ClipperLib::ctIntersection
                                    : op == BooleanOp::union_     ? ClipperLib::ctUnion
                                                                  : ClipperLib::ctDifference;
  measure<std::shared_ptr<ClipperLib::PolyTree>>(
      state, in, op,
      [&] {
        ClipperLib::Clipper c;
        c.AddPaths(a, ClipperLib::ptSubject, true);
        if (!b.empty()) c.AddPaths(b, ClipperLib::ptClip, true);
        auto tree = std::make_shared<ClipperLib::PolyTree>();
        if (!c.Execute(type, *tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero))
          throw std::runtime_error("Clipper::Execute returned false");
        return tree;
      },
      [scale](const std::shared_ptr<ClipperLib::PolyTree>& tree) {
        return clipper_to_multi(*tree, scale);
      });
}
#endif

#if defined(LOCUS_HAVE_BOOST)
BPoly boost_polygon(const Ring& r) {
  BPoly p;
  boost_ring(r, p.outer());
  return p;
}

void bench_boost(benchmark::State& state, std::string name, BooleanOp op) {
  const Input& in = input(name);
  std::vector<BMulti> parts;
  for (const Ring& r : in.a) parts.push_back(BMulti{boost_polygon(r)});
  const BMulti b = in.b.empty() ? BMulti{} : BMulti{boost_polygon(in.b[0])};
  measure<BMulti>(
      state, in, op,
      [&] {
        if (!in.b.empty()) {
          BMulti r;
          if (op == BooleanOp::intersection)
            bg::intersection(parts[0], b, r);
          else if (op == BooleanOp::union_)
            bg::union_(parts[0], b, r);
          else
            bg::difference(parts[0], b, r);
          return r;
        }
        // Cascaded union: unite neighbours level by level (parts are in random order).
        std::vector<BMulti> level = parts;
        while (level.size() > 1) {
          std::vector<BMulti> next;
          for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
            BMulti u;
            bg::union_(level[i], level[i + 1], u);
            next.push_back(std::move(u));
          }
          if (level.size() % 2 == 1) next.push_back(std::move(level.back()));
          level.swap(next);
        }
        return level[0];
      },
      [](const BMulti& r) { return boost_to_multi(r); });
}
#endif

void register_all() {
  const std::pair<const char*, std::vector<BooleanOp>> sets[] = {
      {"few", {BooleanOp::intersection, BooleanOp::union_, BooleanOp::difference}},
      {"spiky", {BooleanOp::intersection, BooleanOp::union_, BooleanOp::difference}},
      {"many", {BooleanOp::union_}}};
  for (const auto& [set_name, ops] : sets) {
    const std::string name = set_name;
    for (BooleanOp op : ops) {
      const std::string base = name + "_" + op_name(op) + "/";
      const auto add = [&](const std::string& impl, auto fn) {
        benchmark::RegisterBenchmark((base + impl).c_str(), fn)
            ->Unit(benchmark::kMillisecond)
            ->MeasureProcessCPUTime();
      };
      add("locus", [name, op](benchmark::State& s) { bench_locus(s, name, op); });
#if defined(LOCUS_HAVE_GEOS)
      add("geos", [name, op](benchmark::State& s) { bench_geos(s, name, op); });
#endif
#if defined(LOCUS_HAVE_CLIPPER1)
      add("clipper1<40b>", [name, op](benchmark::State& s) { bench_clipper1(s, name, op, 40); });
      add("clipper1<29b>", [name, op](benchmark::State& s) { bench_clipper1(s, name, op, 29); });
#endif
#if defined(LOCUS_HAVE_BOOST)
      add("boost", [name, op](benchmark::State& s) { bench_boost(s, name, op); });
#endif
    }
  }
}

[[maybe_unused]] const int registered = (register_all(), 0);

}  // namespace
