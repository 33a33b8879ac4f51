// SPDX-License-Identifier: BSL-1.0
#pragma once
// SvgWriter: a small SVG writer for 2D geometry and 3D wireframes (the figure gallery's drawing
// surface, no capabilities row of its own; the 3D camera is the pipeline of book section 4.8).
// Details: docs/notes/io.md.
//
// Coordinates: everything is given in WORLD coordinates with the y axis pointing UP, mapped to
// pixels by one uniform scale and a y flip (counter-clockwise in the world is counter-clockwise
// on screen). Styles (stroke width, dashes, marker and font size) are in PIXELS.
// View: by default the bounding box of every bounded item is fitted into options.max_width x
// options.max_height pixels plus options.margin; set_view() fixes the world window instead. The
// canvas grows (the scale stays) where an estimated text label would stick out. Lines and rays
// are clipped to the final canvas; a line that misses it is not emitted.
// Curves: circles, rotated ellipses and circular arcs are exact SVG elements. An arc runs
// COUNTER-CLOCKWISE from angle0 to angle1 (radians from +x; taken mod 2 pi after angle0);
// angle1 - angle0 >= 2 pi draws the full circle, angle1 == angle0 nothing. Other curves: curve()
// samples them.
// 3D: set_camera() (eye, target, up; perspective or orthographic) projects the Vec3 overloads
// through core/projection.hpp's matrices onto the image plane (x right, y up); segments are
// clipped at the near plane, points behind it not drawn; no hidden-line removal. Without
// set_camera() the view is orthographic down -z (the (x, y) shadow).
// Degenerate input: a non-finite coordinate never reaches the output (items skipped, polylines
// split, polygon rings drop the vertex); negative radii or extents and zero directions skip the
// item; numbers overflowing after mapping are skipped, never printed as "inf". An empty drawing
// is a valid, empty SVG document. to_string() returns the document (UTF-8, at most 3 decimals,
// locale-independent); write_file() returns Status::io_error when the file cannot be written.
// Text is XML-escaped; control characters are dropped. Cost: O(total vertices) memory and time.

#include <locus/core/mat.hpp>
#include <locus/core/point_range.hpp>
#include <locus/core/scalar.hpp>
#include <locus/core/status.hpp>
#include <locus/core/vec.hpp>

#include <cstddef>
#include <functional>
#include <iterator>
#include <ranges>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace locus {

/// Shape drawn for a point.
enum class SvgMarker : unsigned char { circle, square, triangle, cross };

/// Horizontal alignment of a text label relative to its anchor.
enum class SvgAnchor : unsigned char { start, middle, end };

/// Drawing style. Colours are any SVG colour text ("black", "#3366cc", "none"); lengths in pixels.
struct SvgStyle {
  std::string stroke = "black";          ///< outline colour; "none" for no outline
  std::string fill = "none";             ///< fill colour of closed shapes, markers and arrow heads
  double width = 1.5;                    ///< stroke width in pixels
  std::vector<double> dash = {};         ///< dash pattern in pixels (empty: solid)
  double opacity = 1.0;                  ///< overall opacity in [0, 1]
  double fill_opacity = 1.0;             ///< fill opacity in [0, 1]
  double marker_size = 3.0;              ///< point marker radius; arrow heads are 3x this long
  SvgMarker marker = SvgMarker::circle;  ///< shape drawn by point()
  double font_size = 14.0;               ///< text size in pixels
  SvgAnchor anchor = SvgAnchor::start;   ///< text alignment
  double text_dx = 4.0;                  ///< text offset from its anchor, pixels to the right
  double text_dy = 4.0;                  ///< text offset from its anchor, pixels UP
};

/// Document options.
struct SvgOptions {
  double max_width = 480.0;  ///< the drawing (without margins) fits in max_width x max_height
  double max_height = 480.0;
  double margin = 24.0;              ///< pixels of free space on each side of the fitted view
  std::string background = "white";  ///< background colour ("none" for transparent)
  std::string title = {};            ///< optional <title> of the document
};

/// Camera for the 3D overloads. fov_y is the full vertical field of view in radians
/// (perspective); ortho_height the height of the orthographic view volume (its scale does not
/// matter for an automatically fitted view). near is the distance of the near clipping plane.
struct SvgCamera {
  Vec3d eye{0.0, 0.0, 1.0};
  Vec3d target{0.0, 0.0, 0.0};
  Vec3d up{0.0, 1.0, 0.0};
  bool perspective = false;
  double fov_y = 0.8;
  double ortho_height = 2.0;
  double near = 1e-3;
};

/// Collects 2D (and projected 3D) geometry and emits it as an SVG document.
class SvgWriter {
 public:
  SvgWriter() = default;
  explicit SvgWriter(SvgOptions options) : options_(std::move(options)) {}

  /// Fixes the world window to [lo, hi] instead of fitting the drawn geometry. A window that is
  /// not finite or has hi <= lo in a coordinate is ignored (the view stays automatic).
  void set_view(const Vec2d& lo, const Vec2d& hi);
  /// Returns to the automatically fitted view.
  void clear_view() { has_view_ = false; }
  /// Sets the camera of the 3D overloads (see the header comment). When `up` is parallel to the
  /// view direction a coordinate axis replaces it; a camera that is still unusable (eye ==
  /// target, non-finite, near <= 0, fov_y outside (0, pi), ortho_height <= 0) is ignored.
  void set_camera(const SvgCamera& camera);
  [[nodiscard]] const SvgCamera& camera() const noexcept { return camera_; }
  [[nodiscard]] const SvgOptions& options() const noexcept { return options_; }
  /// Number of stored items (for tests; skipped items are not stored).
  [[nodiscard]] std::size_t size() const noexcept { return items_.size(); }

  // ---- 2D ------------------------------------------------------------------------------------

  /// A point marker (style.marker, radius style.marker_size, filled with style.fill or, when
  /// fill is "none", with the stroke colour).
  template <Real T>
  void point(const Vec2<T>& p, const SvgStyle& s = {}) {
    add_point(d2(p), s);
  }
  template <Real T>
  void segment(const Vec2<T>& a, const Vec2<T>& b, const SvgStyle& s = {}) {
    add_segment(d2(a), d2(b), s);
  }
  /// The infinite line through p with direction d, clipped to the view.
  template <Real T>
  void line(const Vec2<T>& p, const Vec2<T>& d, const SvgStyle& s = {}) {
    add_line(d2(p), d2(d), false, s);
  }
  /// The ray p + t d, t >= 0, clipped to the view.
  template <Real T>
  void ray(const Vec2<T>& p, const Vec2<T>& d, const SvgStyle& s = {}) {
    add_line(d2(p), d2(d), true, s);
  }
  /// A vector drawn as an arrow from `from` to `to` (head at `to`, filled with the stroke colour).
  template <Real T>
  void arrow(const Vec2<T>& from, const Vec2<T>& to, const SvgStyle& s = {}) {
    add_arrow(d2(from), d2(to), s);
  }
  /// An open polyline (closed = true joins the last vertex to the first; it is filled then).
  template <PointRange2 R>
  void polyline(const R& pts, const SvgStyle& s = {}, bool closed = false) {
    add_polyline(to_d2(pts), closed, s);
  }
  /// A polygon, filled with the even-odd rule; `rings` are its outer boundary and holes.
  template <PointRange2 R>
  void polygon(const R& outer, const SvgStyle& s = {}) {
    std::vector<std::vector<Vec2d>> rings;
    rings.push_back(to_d2(outer));
    add_polygon(std::move(rings), s);
  }
  template <PointRange2 R, class H>
  void polygon(const R& outer, const H& holes, const SvgStyle& s) {
    std::vector<std::vector<Vec2d>> rings;
    rings.push_back(to_d2(outer));
    for (const auto& h : holes) rings.push_back(to_d2(h));
    add_polygon(std::move(rings), s);
  }
  template <Real T>
  void circle(const Vec2<T>& center, T radius, const SvgStyle& s = {}) {
    add_circle(d2(center), static_cast<double>(radius), s);
  }
  /// Ellipse center + e0 cos(t) u0 + e1 sin(t) u1 with u0 = axis0/|axis0|, u1 = perp(u0).
  template <Real T>
  void ellipse(const Vec2<T>& center, const Vec2<T>& axis0, T e0, T e1, const SvgStyle& s = {}) {
    add_ellipse(d2(center), d2(axis0), static_cast<double>(e0), static_cast<double>(e1), s);
  }
  /// Circular arc center + r (cos t, sin t), t from angle0 counter-clockwise to angle1.
  template <Real T>
  void arc(const Vec2<T>& center, T radius, T angle0, T angle1, const SvgStyle& s = {}) {
    add_arc(d2(center), static_cast<double>(radius), static_cast<double>(angle0),
            static_cast<double>(angle1), s);
  }
  /// A text label at p, offset by (style.text_dx, style.text_dy) pixels.
  template <Real T>
  void text(const Vec2<T>& p, std::string_view str, const SvgStyle& s = {}) {
    add_text(d2(p), str, s);
  }
  /// Samples f at n+1 evenly spaced parameters in [t0, t1] and draws the polyline (split where
  /// f is not finite).
  void curve(const std::function<Vec2d(double)>& f, double t0, double t1, int n,
             const SvgStyle& s = {});

  // ---- 3D (through the camera) ---------------------------------------------------------------

  template <Real T>
  void point(const Vec3<T>& p, const SvgStyle& s = {}) {
    add_point3(d3(p), s);
  }
  template <Real T>
  void segment(const Vec3<T>& a, const Vec3<T>& b, const SvgStyle& s = {}) {
    add_segment3(d3(a), d3(b), false, s);
  }
  template <Real T>
  void arrow(const Vec3<T>& from, const Vec3<T>& to, const SvgStyle& s = {}) {
    add_segment3(d3(from), d3(to), true, s);
  }
  template <PointRange3 R>
  void polyline(const R& pts, const SvgStyle& s = {}, bool closed = false) {
    add_polyline3(to_d3(pts), closed, s);
  }
  template <Real T>
  void text(const Vec3<T>& p, std::string_view str, const SvgStyle& s = {}) {
    add_text3(d3(p), str, s);
  }
  /// Projects a 3D point with the camera into the 2D drawing's coordinates; false (and `out`
  /// untouched) when the point is not finite or, for a perspective camera, before the near plane.
  [[nodiscard]] bool project(const Vec3d& p, Vec2d& out) const noexcept;

  // ---- output --------------------------------------------------------------------------------

  /// The SVG document.
  [[nodiscard]] std::string to_string() const;
  /// Writes the document to `path`; Status::io_error when it cannot be written.
  [[nodiscard]] Status write_file(const std::string& path) const;

  /// The world window the document is emitted with (fitted or fixed) and its pixel mapping:
  /// pixel = ((x - inner_lo.x) * scale + origin_px.x, (inner_hi.y - y) * scale + origin_px.y).
  /// origin_px is (margin, margin) unless text labels stick out of the canvas; then the canvas
  /// grows on that side (the scale stays) by the label's estimated extent (0.6 em a character).
  struct Mapping {
    Vec2d lo, hi;              ///< world window of the whole canvas (margins included)
    double scale;              ///< pixels per world unit
    double width, height;      ///< document size in pixels
    double margin;             ///< pixels
    Vec2d inner_lo, inner_hi;  ///< fitted (or fixed) world window without the margins
    Vec2d origin_px;           ///< pixel position of (inner_lo.x, inner_hi.y)
  };
  [[nodiscard]] Mapping mapping() const;

  /// Stored item (public so the implementation file can use it; not part of the API).
  struct Item {
    enum class Kind : unsigned char {
      point,
      segment,
      line,
      ray,
      arrow,
      polyline,
      polygon,
      circle,
      ellipse,
      arc,
      text
    } kind;
    std::vector<std::vector<Vec2d>> pts;  // geometry; meaning depends on kind
    double a = 0, b = 0, c = 0;           // radius / extents / angles
    bool closed = false;
    std::string str;
    SvgStyle style;
  };

 private:
  template <Real T>
  static Vec2d d2(const Vec2<T>& p) noexcept {
    return {static_cast<double>(p.x), static_cast<double>(p.y)};
  }
  template <Real T>
  static Vec3d d3(const Vec3<T>& p) noexcept {
    return {static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z)};
  }
  template <class R>
  static std::vector<Vec2d> to_d2(const R& pts) {
    std::vector<Vec2d> v;
    v.reserve(std::ranges::size(pts));
    for (const auto& p : pts) v.push_back(d2(p));
    return v;
  }
  template <class R>
  static std::vector<Vec3d> to_d3(const R& pts) {
    std::vector<Vec3d> v;
    v.reserve(std::ranges::size(pts));
    for (const auto& p : pts) v.push_back(d3(p));
    return v;
  }

  void add_point(const Vec2d& p, const SvgStyle& s);
  void add_segment(const Vec2d& a, const Vec2d& b, const SvgStyle& s);
  void add_line(const Vec2d& p, const Vec2d& d, bool ray, const SvgStyle& s);
  void add_arrow(const Vec2d& a, const Vec2d& b, const SvgStyle& s);
  void add_polyline(std::vector<Vec2d> pts, bool closed, const SvgStyle& s);
  void add_polygon(std::vector<std::vector<Vec2d>> rings, const SvgStyle& s);
  void add_circle(const Vec2d& c, double r, const SvgStyle& s);
  void add_ellipse(const Vec2d& c, const Vec2d& axis0, double e0, double e1, const SvgStyle& s);
  void add_arc(const Vec2d& c, double r, double a0, double a1, const SvgStyle& s);
  void add_text(const Vec2d& p, std::string_view str, const SvgStyle& s);
  void add_point3(const Vec3d& p, const SvgStyle& s);
  void add_segment3(const Vec3d& a, const Vec3d& b, bool arrow, const SvgStyle& s);
  void add_polyline3(const std::vector<Vec3d>& pts, bool closed, const SvgStyle& s);
  void add_text3(const Vec3d& p, std::string_view str, const SvgStyle& s);

  SvgOptions options_{};
  SvgCamera camera_{};
  Mat4d view_proj_ = Mat4d::identity();  // camera matrices, composed once in set_camera
  Mat4d view_ = Mat4d::identity();
  bool has_view_ = false;
  Vec2d view_lo_{}, view_hi_{};
  std::vector<Item> items_;
};

}  // namespace locus
