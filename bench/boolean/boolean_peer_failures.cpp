// SPDX-License-Identifier: BSL-1.0
// Cases the peers fail that locus passes (issue 21): runs GEOS (C API, OverlayNG), Boost.Geometry
// and Clipper 1 on the overlay corpus in tests/data/corpus and lists, per case, operation and peer,
// where the peer throws (an exception, or GEOS's null result), returns invalid output (GEOS
// isValid, OGC rules) or an area off locus's by more than 1e-6 of the operands' areas, on the
// cases where locus's output passes the independent validity checker (tests/support/
// polygon_validity.hpp) and satisfies the exact area identities (|A u B| + |A n B| = |A| + |B|,
// |A \ B| + |A n B| = |A|, |A xor B| = |A u B| - |A n B|, within the snap-rounding bound).
//   Boost.Geometry overlay cases and the JTS XML overlay suites (general TestOverlayAA and
//   TestNGOverlayA, failure/TestOverlayNGFailure, robust/overlay/*): every case whose two operands
//   are polygons or multipolygons that GEOS deems valid; intersection, union, a \ b and xor, every
//   peer on the same coordinates (Boost: counter-clockwise closed polygons; Clipper 1: all
//   rings, even-odd fill, coordinates scaled by a power of two to integers below 2^40,
//   StrictlySimple on).
// The case files are read by the tests' readers (tests/support/corpus.hpp), the WKT texts by
// locus::parse_wkt; only the WKB hex of a few JTS files is read by GEOS (locus reads no WKB).
//   Clipper2's Tests/Polygons.txt: raw rings with fill rules, which only Clipper 1 shares (same
//   clip types and fill rules); locus passes when valid and within Clipper2's own area tolerance
//   of SOL_AREA (as tests/boolean/clipper2_corpus_test.cpp).
// A script, not a test: peer failures are facts about the installed peer versions.
//   ninja -C build/bench locus_boolean_peer_failures
//   build/bench/bench/locus_boolean_peer_failures > failures.md
// Results: bench/results/boolean.md.

#include <locus/boolean/polygon_boolean.hpp>

#include "boolean/boolean_peers.hpp"
#include "support/corpus.hpp"
#include "support/files.hpp"
#include "support/polygon_validity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace locus_bench_bool;
using locus::BooleanOp;

std::string geos_error;

/// A corpus operand: the polygons as locus reads them and the same polygons as a GEOS geometry
/// for the GEOS runs (WKB hex, which only GEOS reads, goes the other way).
struct Operand {
  Multi polygons;
  GeosPtr geos;
};

/// The operand of a WKT or WKB hex text; false unless it is a nonempty polygon or multipolygon
/// that GEOS deems valid.
bool read_operand(const std::string& text, Operand& out) {
  const auto b = text.find_first_not_of(" \t\r\n"), e = text.find_last_not_of(" \t\r\n");
  if (b == std::string::npos) return false;
  const std::string t = text.substr(b, e - b + 1);
  if (t.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos) {
    GEOSWKBReader* r = GEOSWKBReader_create_r(geos());
    out.geos.reset(GEOSWKBReader_readHEX_r(
        geos(), r, reinterpret_cast<const unsigned char*>(t.data()), t.size()));
    GEOSWKBReader_destroy_r(geos(), r);
    if (!out.geos) return false;
    const int type = GEOSGeomTypeId_r(geos(), out.geos.get());
    if (type != GEOS_POLYGON && type != GEOS_MULTIPOLYGON) return false;
    geos_to_multi(out.geos.get(), out.polygons);
  } else {
    if (!locus_test::read_polygonal(t, out.polygons)) return false;
    out.geos = geos_multi(out.polygons);
  }
  return !out.polygons.empty() && GEOSisValid_r(geos(), out.geos.get()) == 1;
}

const char* op_name(BooleanOp op) {
  switch (op) {
    case BooleanOp::intersection:
      return "intersection";
    case BooleanOp::union_:
      return "union";
    case BooleanOp::difference:
      return "difference";
    case BooleanOp::symmetric_difference:
      return "xor";
  }
  return "?";
}

struct PeerResult {
  std::string kind;  // "" (passes), "threw", "invalid", "wrong area"
  std::string detail;
};

/// A peer's output judged against locus's area (ref) with tolerance tol.
PeerResult judge(const Multi& out, double ref, double tol, bool valid_known, bool valid) {
  if (!valid_known) {
    GeosPtr g = geos_multi(out);
    char* why = GEOSisValidReason_r(geos(), g.get());
    valid = why && std::string(why) == "Valid Geometry";
    const std::string reason = why ? why : "";
    if (why) GEOSFree_r(geos(), why);
    if (!valid) return {"invalid", reason};
  } else if (!valid) {
    return {"invalid", ""};
  }
  const double area = multi_area(out);
  if (std::abs(area - ref) > tol) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "area %.9g, locus %.9g", area, ref);
    return {"wrong area", buf};
  }
  return {};
}

struct Tally {
  int runs = 0, threw = 0, invalid = 0, wrong_area = 0;
};
std::map<std::string, Tally> tallies;  // peer -> counts on the cases locus passes
std::vector<std::string> rows;         // markdown table rows
int locus_cases = 0, locus_passes = 0;
std::vector<std::string> locus_failures;

void record(const std::string& source, const std::string& name, const char* op,
            const std::string& peer, const PeerResult& r) {
  Tally& t = tallies[peer];
  ++t.runs;
  if (r.kind.empty()) return;
  if (r.kind == "threw") ++t.threw;
  if (r.kind == "invalid") ++t.invalid;
  if (r.kind == "wrong area") ++t.wrong_area;
  std::string detail = r.detail;
  for (char& c : detail)
    if (c == '|' || c == '\n') c = ' ';
  if (detail.size() > 140) detail = detail.substr(0, 140) + "...";
  rows.push_back("| " + source + " | " + name + " | " + op + " | " + peer + " | " + r.kind + " | " +
                 detail + " |");
}

double perimeter(const Multi& m) {
  double s = 0;
  for (const auto& p : m)
    for (std::size_t k = 0; k <= p.holes.size(); ++k) {
      const auto& r = k == 0 ? p.outer.vertices : p.holes[k - 1].vertices;
      for (std::size_t i = 0; i < r.size(); ++i)
        s += std::hypot(r[i].x - r[(i + 1) % r.size()].x, r[i].y - r[(i + 1) % r.size()].y);
    }
  return s;
}

/// Runs locus and the three peers on two valid polygonal operands.
void run_pair(const std::string& source, const std::string& name, const Operand& oa,
              const Operand& ob) {
  const GEOSGeometry *ga = oa.geos.get(), *gb = ob.geos.get();
  Multi a = oa.polygons, b = ob.polygons;
  orient(a);
  orient(b);
  if (a.empty() || b.empty()) return;
  ++locus_cases;
  const BooleanOp ops[] = {BooleanOp::intersection, BooleanOp::union_, BooleanOp::difference,
                           BooleanOp::symmetric_difference};
  mpq_class area[4];
  double grid = 0;
  std::string why;
  for (int k = 0; k < 4; ++k) {
    const auto r = locus::boolean_op(ops[k], a, b);
    if (r.status != locus::Status::ok) {
      why = "status " + r.message;
      break;
    }
    const std::string v = locus_test::polygon_validity(r.polygons);
    if (!v.empty()) why = std::string(op_name(ops[k])) + ": " + v;
    area[k] = locus_test::exact_area(r.polygons);
    grid = r.grid;
  }
  const mpq_class area_a = locus_test::exact_area(locus::boolean_union(a, Multi{}).polygons);
  const mpq_class area_b = locus_test::exact_area(locus::boolean_union(b, Multi{}).polygons);
  const mpq_class bound = mpq_class(4 * grid * (perimeter(a) + perimeter(b)));
  if (why.empty() && !(abs(area[1] + area[0] - area_a - area_b) <= bound &&
                       abs(area[2] + area[0] - area_a) <= bound &&
                       abs(area[3] - (area[1] - area[0])) <= 2 * bound))
    why = "area identities";
  if (!why.empty()) {
    locus_failures.push_back(source + " " + name + ": " + why);
    return;
  }
  ++locus_passes;
  const double tol = 1e-6 * (area_a.get_d() + area_b.get_d()) + bound.get_d();
  const BMulti ba = boost_multi(a), bb = boost_multi(b);
  // Boost's own verdict on its operands (noted on its failure rows: where Boost deems an
  // operand invalid that GEOS accepts, its wrong answer follows from that disagreement).
  std::string boost_input_note;
  for (const BMulti* m : {&ba, &bb}) {
    std::string msg;
    if (!bg::is_valid(*m, msg) && boost_input_note.empty())
      boost_input_note = " (Boost: operand " + std::string(m == &ba ? "a" : "b") + " " + msg + ")";
  }
  double max_abs = 0;
  for (const Multi* m : {&a, &b})
    for (const auto& p : *m)
      for (std::size_t k = 0; k <= p.holes.size(); ++k)
        for (const auto& q : k == 0 ? p.outer.vertices : p.holes[k - 1].vertices)
          max_abs = std::max({max_abs, std::abs(q.x), std::abs(q.y)});
  const double scale = clipper_scale(max_abs, 40);
  const auto all_rings = [](const Multi& m) {
    std::vector<Ring> rs;
    for (const auto& p : m) {
      rs.push_back(p.outer.vertices);
      for (const auto& h : p.holes) rs.push_back(h.vertices);
    }
    return rs;
  };
  const ClipperLib::Paths ca = clipper_paths(all_rings(a), scale),
                          cb = clipper_paths(all_rings(b), scale);
  for (int k = 0; k < 4; ++k) {
    const double ref = area[k].get_d();
    const char* op = op_name(ops[k]);
    // GEOS
    {
      geos_error.clear();
      GEOSGeometry* r = ops[k] == BooleanOp::intersection ? GEOSIntersection_r(geos(), ga, gb)
                        : ops[k] == BooleanOp::union_     ? GEOSUnion_r(geos(), ga, gb)
                        : ops[k] == BooleanOp::difference ? GEOSDifference_r(geos(), ga, gb)
                                                          : GEOSSymDifference_r(geos(), ga, gb);
      if (!r) {
        record(source, name, op, "GEOS", {"threw", geos_error});
      } else {
        GeosPtr keep(r);
        Multi m;
        geos_to_multi(r, m);
        char* reason = GEOSisValidReason_r(geos(), r);
        const std::string rs = reason ? reason : "";
        if (reason) GEOSFree_r(geos(), reason);
        PeerResult pr = judge(m, ref, tol, true, rs == "Valid Geometry");
        if (pr.kind == "invalid") pr.detail = rs;
        record(source, name, op, "GEOS", pr);
      }
    }
    // Boost.Geometry
    {
      BMulti r;
      PeerResult pr;
      try {
        if (ops[k] == BooleanOp::intersection)
          bg::intersection(ba, bb, r);
        else if (ops[k] == BooleanOp::union_)
          bg::union_(ba, bb, r);
        else if (ops[k] == BooleanOp::difference)
          bg::difference(ba, bb, r);
        else
          bg::sym_difference(ba, bb, r);
        pr = judge(boost_to_multi(r), ref, tol, false, false);
      } catch (const std::exception& e) {
        pr = {"threw", e.what()};
      }
      if (!pr.kind.empty()) pr.detail += boost_input_note;
      record(source, name, op, "Boost.Geometry", pr);
    }
    // Clipper 1
    {
      PeerResult pr;
      try {
        ClipperLib::Clipper c;
        c.StrictlySimple(true);
        c.AddPaths(ca, ClipperLib::ptSubject, true);
        c.AddPaths(cb, ClipperLib::ptClip, true);
        const ClipperLib::ClipType type =
            ops[k] == BooleanOp::intersection ? ClipperLib::ctIntersection
            : ops[k] == BooleanOp::union_     ? ClipperLib::ctUnion
            : ops[k] == BooleanOp::difference ? ClipperLib::ctDifference
                                              : ClipperLib::ctXor;
        ClipperLib::PolyTree tree;
        if (!c.Execute(type, tree, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd))
          pr = {"threw", "Execute returned false"};
        else
          pr = judge(clipper_to_multi(tree, scale), ref, tol, false, false);
      } catch (const std::exception& e) {
        pr = {"threw", e.what()};
      }
      record(source, name, op, "Clipper 1", pr);
    }
  }
}

// ---- Boost.Geometry overlay_cases.json ----
void boost_cases(const std::string& dir) {
  for (const auto& c : locus_test::read_boost_overlay_cases(
           locus_test::slurp(dir + "/boost-geometry/overlay_cases.json"))) {
    Operand a, b;
    if (c.wkt.size() == 2 && read_operand(c.wkt[0], a) && read_operand(c.wkt[1], b))
      run_pair("boost", c.name, a, b);
  }
}

// ---- JTS XML: <case> ... <a> WKT or hex WKB </a> <b> ... </b> ----
void jts_file(const std::filesystem::path& path) {
  const std::string xml = locus_test::slurp(path);
  if (locus_test::jts_fixed_precision(xml)) return;
  int k = 0;
  for (const auto& c : locus_test::read_jts_cases(xml)) {
    const std::string name = path.stem().string() + "-" + std::to_string(k++);
    Operand a, b;
    if (read_operand(c.a, a) && read_operand(c.b, b)) run_pair("jts", name, a, b);
  }
}

// ---- Clipper2 Tests/Polygons.txt (Clipper 1 only: raw rings under fill rules) ----
std::vector<Ring> rings(const std::vector<locus::Polygon2<double>>& polygons) {
  std::vector<Ring> out;
  for (const auto& p : polygons) out.push_back(p.vertices);
  return out;
}

void clipper2_cases(const std::string& dir) {
  for (const auto& c :
       locus_test::read_clipper2_cases(locus_test::slurp(dir + "/clipper2/tests/Polygons.txt"))) {
    const std::string name = "case " + std::to_string(c.id);
    const locus_test::Clipper2Boolean job = locus_test::clipper2_boolean(c);
    const BooleanOp op = job.op;
    const ClipperLib::PolyFillType pft = c.fill_rule == "NONZERO"    ? ClipperLib::pftNonZero
                                         : c.fill_rule == "POSITIVE" ? ClipperLib::pftPositive
                                         : c.fill_rule == "NEGATIVE" ? ClipperLib::pftNegative
                                                                     : ClipperLib::pftEvenOdd;
    ++locus_cases;
    const auto res = locus::boolean_op<double>(op, job.subjects, job.clips, {job.rule, 0});
    const double tol = locus_test::clipper2_area_tolerance(c.id);
    std::string why;
    if (res.status != locus::Status::ok) why = res.message;
    if (why.empty()) why = locus_test::polygon_validity(res.polygons);
    const double area = locus_test::exact_area(res.polygons).get_d();
    // Case 44's SOL_AREA is Clipper2's integer-rounded answer, 2.9% off the exact area (see
    // tests/boolean/clipper2_corpus_test.cpp): validity alone decides it.
    if (why.empty() && c.id != 44 && c.sol_area > 0 &&
        std::abs(area - c.sol_area) > tol * c.sol_area)
      why = "area off SOL_AREA";
    if (!why.empty()) {
      locus_failures.push_back("clipper2 " + name + ": " + why);
      continue;
    }
    ++locus_passes;
    double max_abs = 0;
    for (const auto* set : {&c.subjects, &c.clips})
      for (const auto& r : *set)
        for (const auto& q : r.vertices)
          max_abs = std::max({max_abs, std::abs(q.x), std::abs(q.y)});
    const double scale = clipper_scale(max_abs, 40);
    PeerResult pr;
    try {
      ClipperLib::Clipper cl;
      cl.StrictlySimple(true);
      cl.AddPaths(clipper_paths(rings(c.subjects), scale), ClipperLib::ptSubject, true);
      cl.AddPaths(clipper_paths(rings(c.clips), scale), ClipperLib::ptClip, true);
      const ClipperLib::ClipType type = op == BooleanOp::intersection ? ClipperLib::ctIntersection
                                        : op == BooleanOp::union_     ? ClipperLib::ctUnion
                                        : op == BooleanOp::difference ? ClipperLib::ctDifference
                                                                      : ClipperLib::ctXor;
      ClipperLib::PolyTree tree;
      if (!cl.Execute(type, tree, pft, pft))
        pr = {"threw", "Execute returned false"};
      else
        pr = judge(clipper_to_multi(tree, scale), area, 1e-6 * std::max(area, c.sol_area) + 1e-9,
                   false, false);
    } catch (const std::exception& e) {
      pr = {"threw", e.what()};
    }
    record("clipper2", name, op_name(op), "Clipper 1", pr);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : LOCUS_CORPUS_DIR;
  GEOSContext_setErrorMessageHandler_r(
      geos(), [](const char* message, void*) { geos_error = message; }, nullptr);
  boost_cases(dir);
  const std::filesystem::path jts = std::filesystem::path(dir) / "jts-testxml";
  std::vector<std::filesystem::path> files = {jts / "general" / "TestOverlayAA.xml",
                                              jts / "general" / "TestNGOverlayA.xml",
                                              jts / "failure" / "TestOverlayNGFailure.xml"};
  std::vector<std::filesystem::path> robust;
  for (const auto& e : std::filesystem::directory_iterator(jts / "robust" / "overlay"))
    if (e.path().extension() == ".xml") robust.push_back(e.path());
  std::sort(robust.begin(), robust.end());
  files.insert(files.end(), robust.begin(), robust.end());
  for (const auto& f : files) jts_file(f);
  clipper2_cases(dir);

  std::printf("GEOS %s, Boost %d, Clipper %s\n\n", GEOSversion(), BOOST_VERSION, CLIPPER_VERSION);
  std::printf("locus: %d cases, %d pass (valid, exact area identities or Clipper2's SOL_AREA)\n",
              locus_cases, locus_passes);
  for (const auto& f : locus_failures) std::printf("  locus fails: %s\n", f.c_str());
  std::printf("\n| peer | runs | threw | invalid | wrong area |\n|---|---|---|---|---|\n");
  for (const auto& [peer, t] : tallies)
    std::printf("| %s | %d | %d | %d | %d |\n", peer.c_str(), t.runs, t.threw, t.invalid,
                t.wrong_area);
  std::printf(
      "\n| corpus | case | operation | peer | failure | detail |\n|---|---|---|---|---|---|\n");
  for (const auto& r : rows) std::printf("%s\n", r.c_str());
  return 0;
}
