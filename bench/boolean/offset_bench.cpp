// SPDX-License-Identifier: BSL-1.0
// Polygon offsetting (row cg.offset): locus offset() against GEOS's buffer (GEOSBufferWithStyle_r)
// and Clipper 1's ClipperOffset in one run, on a smooth 10^5-vertex ring r = 1 + 0.1 sin 7t
// (edge length about 6.6e-5, concave where sin 7t < -0.2) inflated by delta = 0.0005, 0.005 and
// 0.05 (about 8 to 800 edge lengths), miter joins with miter limit 2 in every library:
//   locus     offset(polygon, delta, {miter}) (resolves the ring, builds the raw contour with
//             the spoke shortcut, one boolean under the positive fill rule);
//   locus_keeping_spokes  the same without the shortcut (detail::offset_keeping_spokes: the
//             construction before it);
//   geos      GEOSBufferWithStyle_r(width delta, 8 quadrant segments, flat caps, mitre joins,
//             limit 2);
//   clipper1  ClipperOffset(MiterLimit 2).Execute on integer coordinates below 2^40 (locus's grid).
// Conversion to each library's layout is outside the timed loop. After it the last output is
// converted and checked once: GEOS's isValid and the area against locus's (counters valid,
// area_rel, out_vertices). items_per_second counts input vertices (for scripts/bench_rounds).
//
//   ninja -C build/bench locus_bench_boolean
//   scripts/bench_rounds --rounds 3 --min-time 0.05 --filter '^offset_' --peer-double geos
//       build/bench/bench/locus_bench_boolean   (one command line)
// Results: bench/results/boolean.md ("Offsetting").

#include <locus/boolean/polygon_offset.hpp>

#include <benchmark/benchmark.h>

#include "boolean/boolean_peers.hpp"

#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace locus_bench_bool;

constexpr std::size_t kRingVertices = 100000;

const Ring& smooth_ring() {
  static const Ring ring = [] {
    Ring r;
    for (std::size_t i = 0; i < kRingVertices; ++i) {
      const double t = 2 * std::numbers::pi * static_cast<double>(i) / kRingVertices;
      const double rad = 1 + 0.1 * std::sin(7 * t);
      r.push_back({rad * std::cos(t), rad * std::sin(t)});
    }
    return r;
  }();
  return ring;
}

Multi run_locus(double delta, bool keep_spokes = false) {
  static const locus::MultiPolygon2<double> poly{{{smooth_ring()}, {}}};
  locus::OffsetOptions o;
  o.join = locus::JoinType::miter;
  o.miter_limit = 2;
  auto r = keep_spokes ? locus::detail::offset_keeping_spokes(poly, delta, o)
                       : locus::offset(poly, delta, o);
  if (r.status != locus::Status::ok) throw std::runtime_error(r.message);
  return std::move(r.polygons);
}

double locus_area(double delta) {
  static std::vector<std::pair<double, double>> cache;
  for (const auto& [d, a] : cache)
    if (d == delta) return a;
  cache.emplace_back(delta, multi_area(run_locus(delta)));
  return cache.back().second;
}

template <class Native>
void measure(benchmark::State& state, double delta, const std::function<Native()>& run,
             const std::function<Multi(const Native&)>& out) {
  Native last{};
  bool threw = false;
  try {
    for (auto _ : state) {
      last = run();
      benchmark::DoNotOptimize(&last);
    }
  } catch (const std::exception& e) {
    threw = true;
    state.SetLabel(std::string("threw: ") + e.what());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(kRingVertices));
  state.counters["threw"] = threw ? 1 : 0;
  if (threw) return;
  const Multi m = out(last);
  bool valid = true;
#if defined(LOCUS_HAVE_GEOS)
  GeosPtr g = geos_multi(m);
  valid = g && GEOSisValid_r(geos(), g.get()) == 1;
#endif
  const double ref = locus_area(delta);
  state.counters["valid"] = valid ? 1 : 0;
  state.counters["area_rel"] = std::abs(multi_area(m) - ref) / ref;
  state.counters["out_vertices"] = static_cast<double>(multi_vertices(m));
}

void bench_locus(benchmark::State& state, double delta, bool keep_spokes) {
  measure<Multi>(
      state, delta, [delta, keep_spokes] { return run_locus(delta, keep_spokes); },
      [](const Multi& m) { return m; });
}

#if defined(LOCUS_HAVE_GEOS)
void bench_geos(benchmark::State& state, double delta) {
  GeosPtr in(geos_polygon(smooth_ring(), {}));
  measure<std::shared_ptr<GEOSGeometry>>(
      state, delta,
      [&] {
        GEOSGeometry* r = GEOSBufferWithStyle_r(geos(), in.get(), delta, 8, GEOSBUF_CAP_FLAT,
                                                GEOSBUF_JOIN_MITRE, 2.0);
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
void bench_clipper1(benchmark::State& state, double delta) {
  const double scale = clipper_scale(1.1, 40);
  const ClipperLib::Paths in = clipper_paths({smooth_ring()}, scale);
  measure<std::shared_ptr<ClipperLib::PolyTree>>(
      state, delta,
      [&] {
        ClipperLib::ClipperOffset co(2.0);
        co.AddPaths(in, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
        auto tree = std::make_shared<ClipperLib::PolyTree>();
        co.Execute(*tree, delta * scale);
        return tree;
      },
      [scale](const std::shared_ptr<ClipperLib::PolyTree>& tree) {
        return clipper_to_multi(*tree, scale);
      });
}
#endif

void register_all() {
  for (const double delta : {0.0005, 0.005, 0.05}) {
    const std::string base = "offset_miter_d" + std::to_string(delta).substr(0, 6) + "/";
    const auto add = [&](const std::string& impl, auto fn) {
      benchmark::RegisterBenchmark((base + impl).c_str(), fn)
          ->Unit(benchmark::kMillisecond)
          ->MeasureProcessCPUTime();
    };
    add("locus", [delta](benchmark::State& s) { bench_locus(s, delta, false); });
    add("locus_keeping_spokes", [delta](benchmark::State& s) { bench_locus(s, delta, true); });
#if defined(LOCUS_HAVE_GEOS)
    add("geos", [delta](benchmark::State& s) { bench_geos(s, delta); });
#endif
#if defined(LOCUS_HAVE_CLIPPER1)
    add("clipper1<40b>", [delta](benchmark::State& s) { bench_clipper1(s, delta); });
#endif
  }
}

[[maybe_unused]] const int registered = (register_all(), 0);

}  // namespace
