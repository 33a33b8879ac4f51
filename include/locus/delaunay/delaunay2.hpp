// SPDX-License-Identifier: BSL-1.0
#pragma once
// 2D Delaunay triangulation; CAPABILITIES row cg.delaunay2; book section 13.8, figures
// 13.42-13.51. Incremental insertion in BRIO/Hilbert order with Lawson flips, every decision an
// exact orient2d/incircle (core/predicates.hpp); method: docs/notes/delaunay.md. No input point
// lies strictly inside any triangle's circumcircle.
// Output (Delaunay2Result; the index layout of docs/notes/api.md, as hull/hull3.hpp):
//   triangles[t]       input point indices, counter-clockwise.
//   adjacency[t][i]    the triangle across edge (v[i], v[(i + 1) % 3]) of t; kNoTriangle on
//                      the hull.
//   hull               the hull vertices counter-clockwise, starting at the smallest index; every
//                      input point on the hull boundary is listed (collinear ones included).
//   duplicate_of[i]    i for a point that is a vertex, else the index of the vertex with exactly
//                      the same coordinates (the first one met in insertion order).
//   dimension          2; 1 when all points are collinear (no triangles; hull = the distinct points
//                      sorted lexicographically by (x, y)); 0 when all are equal (hull = the kept
//                      point); -1 for empty or bad input. Lower dimension is data: status stays ok.
// Cocircular input: one valid triangulation, deterministic for the same input values and order;
// a permuted input may give another valid one.
// Bad input: NaN/Inf -> non_finite_input, empty result; no points -> empty_input. Walks fall back
// to an exact scan; an exhausted flip budget (never on a correct triangulation) -> limit_exceeded.
// Exactness: within incircle's range (core/predicates.hpp: double |coordinates| about
// 6e-64 .. 6e73, every float); outside it a triangulation, possibly not Delaunay.
// Cost: O(n log n) expected; peak heap about 88 bytes per point; a reused Delaunay2 keeps its
// own copy of the points and of the result. Timings: bench/results/delaunay.md.

#include <locus/core/point_range.hpp>
#include <locus/core/predicates.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace locus {

/// adjacency[t][i] of an edge on the hull (no triangle beyond it).
inline constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFu;

/// The result of a 2D Delaunay triangulation (see the top of delaunay2.hpp for the layout).
struct Delaunay2Result {
  Status status = Status::empty_input;
  int dimension = -1;  ///< 2, 1 (collinear), 0 (one point), -1 (nothing)
  std::vector<std::array<std::uint32_t, 3>> triangles;  ///< counter-clockwise
  std::vector<std::array<std::uint32_t, 3>> adjacency;  ///< across edge (v[i], v[i+1])
  std::vector<std::uint32_t> hull;          ///< CCW hull vertices (dimension 1: sorted on line)
  std::vector<std::uint32_t> duplicate_of;  ///< per input point: itself, or the kept equal point
  std::size_t duplicate_count = 0;          ///< number of i with duplicate_of[i] != i

  [[nodiscard]] std::size_t triangle_count() const noexcept { return triangles.size(); }
};

/// Where a point lies relative to a triangulation.
enum class Location : std::uint8_t {
  outside,    ///< strictly outside the hull, beyond hull edge `corner` of `triangle`
  inside,     ///< strictly inside `triangle`
  on_edge,    ///< in the interior of edge `corner` (v[corner], v[corner + 1]) of `triangle`
  on_vertex,  ///< equal to vertex `corner` of `triangle`
};

/// The result of locate().
struct LocateResult {
  Status status =
      Status::empty_input;  ///< ok; empty_input (no triangles); non_finite_input;
                            ///< limit_exceeded (the walk ran out of steps; fields unset)
  Location location = Location::outside;
  std::int32_t triangle = -1;  ///< a triangle of the result, -1 when not found
  int corner = -1;             ///< edge or vertex index within the triangle (0..2)
  std::size_t steps = 0;       ///< triangles visited
};

/// Walks from triangle `start` toward p (visibility walk; exact orient2d decides every step) and
/// reports where p lies. max_steps = 0 means 4 * triangle_count + 16, which a walk in a Delaunay
/// triangulation never exceeds (it never visits a triangle twice).
template <Real T>
[[nodiscard]] LocateResult locate(const Delaunay2Result& dt, std::span<const Vec2<T>> points,
                                  const Vec2<T>& p, std::int32_t start = 0,
                                  std::size_t max_steps = 0) noexcept;

/// Reusable 2D Delaunay triangulator: keeps its buffers between calls, accepts further points
/// after a triangulation, and locates points by walking.
template <Real T>
class Delaunay2 {
 public:
  /// Triangulates `points` (copied), replacing any previous state.
  const Delaunay2Result& compute(std::span<const Vec2<T>> points);

  /// Adds one point (index = points().size() before the call) and restores the Delaunay
  /// property. O(1) expected near the previous point in 2D; when the current triangulation has
  /// dimension < 2 it is rebuilt from all points. A non-finite point is refused
  /// (non_finite_input, nothing added).
  Status insert(const Vec2<T>& p);

  /// The triangulation of every point so far (compacted lazily after insert()).
  const Delaunay2Result& result();

  /// Moves the result out and resets the object to an empty triangulation.
  Delaunay2Result take_result();

  /// locate() on result(), starting from the triangle of the last inserted point.
  [[nodiscard]] LocateResult locate(const Vec2<T>& p, std::size_t max_steps = 0);

  [[nodiscard]] std::span<const Vec2<T>> points() const noexcept { return points_; }

 private:
  template <Real U>
  friend Delaunay2Result delaunay(std::span<const Vec2<U>> points);

  void reset();
  void run(std::span<const Vec2<T>> in);
  std::uint32_t walk(const Vec2<T>& p, std::uint32_t start, std::uint32_t* duplicate) noexcept;
  std::uint32_t scan(const Vec2<T>& p, std::uint32_t* duplicate) const noexcept;
  bool insert_vertex(std::uint32_t v);
  void set_triangle(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                    std::uint32_t opp_ab, std::uint32_t opp_bc, std::uint32_t opp_ca,
                    std::uint32_t* out_edges) noexcept;
  bool in_conflict(std::uint32_t p, std::uint32_t e) const noexcept;
  void compact(bool in_place);
  void lower_dimensional(std::span<const Vec2<T>> in);
  // The triangles are stored in the result's type (compact() hands them over in place) and
  // addressed as flat half-edge slots 3t + i: std::array<std::uint32_t, 3> is exactly three
  // uint32 without padding (static_assert in the source).
  [[nodiscard]] static std::uint32_t* flat(std::vector<std::array<std::uint32_t, 3>>& v) noexcept {
    return reinterpret_cast<std::uint32_t*>(v.data());
  }
  [[nodiscard]] std::uint32_t* tri() noexcept { return flat(tri_); }
  [[nodiscard]] const std::uint32_t* tri() const noexcept {
    return reinterpret_cast<const std::uint32_t*>(tri_.data());
  }
  [[nodiscard]] std::uint32_t* adj() noexcept { return flat(adj_); }
  [[nodiscard]] const std::uint32_t* adj() const noexcept {
    return reinterpret_cast<const std::uint32_t*>(adj_.data());
  }

  std::vector<Vec2<T>> points_;  // as given
  std::vector<Vec2<T>> sorted_;  // internal vertex k = points_[orig_[k]], Hilbert order
  std::vector<std::uint32_t> orig_;
  // Internally half-edges: slot 3t + i of tri() is vertex i of triangle t, adj()[3t + i] the
  // half-edge opposite to the one from vertex i to vertex i + 1 (the surface is closed).
  std::vector<std::array<std::uint32_t, 3>> tri_;  // with ghost triangles (kGhost at corner 2)
  std::vector<std::array<std::uint32_t, 3>> adj_;  // opposite half-edges
  std::vector<std::uint32_t> order_;               // compact(): the ghost triangles
  std::vector<std::uint32_t> stack_;
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint64_t> keys_tmp_;
  std::uint32_t nt_ = 0;        // triangles in use in tri_ / adj_ (sized ahead)
  std::uint32_t last_ = 0;      // a triangle incident to the last inserted vertex
  std::uint32_t last_out_ = 0;  // the same triangle in result() numbering
  int dimension_ = -1;
  bool dirty_ = false;
  Status status_ = Status::empty_input;
  Delaunay2Result result_;
};

/// Delaunay triangulation of `points` (one call over Delaunay2).
template <Real T>
[[nodiscard]] Delaunay2Result delaunay(std::span<const Vec2<T>> points);

/// The same for any point range (core/point_range.hpp).
template <PointRange2 R>
[[nodiscard]] Delaunay2Result delaunay(const R& points) {
  return delaunay(point_span(points));
}
template <PointRange2 R>
[[nodiscard]] LocateResult locate(const Delaunay2Result& dt, const R& points,
                                  const range_point_t<R>& p, std::int32_t start = 0,
                                  std::size_t max_steps = 0) noexcept {
  return locate(dt, point_span(points), p, start, max_steps);
}

extern template class Delaunay2<float>;
extern template class Delaunay2<double>;
extern template Delaunay2Result delaunay<float>(std::span<const Vec2<float>>);
extern template Delaunay2Result delaunay<double>(std::span<const Vec2<double>>);
extern template LocateResult locate<float>(const Delaunay2Result&, std::span<const Vec2<float>>,
                                           const Vec2<float>&, std::int32_t, std::size_t) noexcept;
extern template LocateResult locate<double>(const Delaunay2Result&, std::span<const Vec2<double>>,
                                            const Vec2<double>&, std::int32_t,
                                            std::size_t) noexcept;

}  // namespace locus
