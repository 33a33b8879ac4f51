// SPDX-License-Identifier: BSL-1.0
#pragma once
// The figure gallery: a table of figures of "Geometric Tools for Computer Graphics" redrawn from
// live locus computations, and the runner that writes them as SVG files with an index page.
//
// Each figure is a function drawing into a locus::SvgWriter. It computes the geometry it shows
// with locus (a rotated shape is the image of the shape under locus::rotation, a projection the
// result of locus::project_onto, ...); only the INPUTS (the shape, the vectors, the angle) are
// written as literals. A figure returns false when a locus computation it relies on reports
// failure (a std::nullopt, a bad Status), which the runner and the gallery test report.
// Figures live in one source file per chapter topic (ch03_vectors.cpp, ...), each exposing its
// table; all_figures() concatenates them in book order.

#include <locus/core/frame.hpp>
#include <locus/core/status.hpp>
#include <locus/core/transform.hpp>
#include <locus/core/vec.hpp>
#include <locus/io/svg.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace locus_gallery {

using locus::SvgStyle;
using locus::SvgWriter;
using locus::Vec2d;
using locus::Vec3d;

/// One gallery entry.
struct Figure {
  const char* id;             ///< the book's figure number, "3.15"
  const char* computed_with;  ///< the locus functions that compute what the figure shows
  bool (*draw)(SvgWriter&);   ///< draws the figure; false when a computation failed
};

// The per-file tables, in book order.
std::vector<Figure> chapter2_linear_figures();        // ch02_linear.cpp: 2.2, 2.3, 2.9
std::vector<Figure> chapter3_vector_figures();        // ch03_vectors.cpp: 3.1-3.17
std::vector<Figure> chapter3_affine_figures();        // ch03_affine.cpp: 3.19-3.42
std::vector<Figure> chapter4_transform_figures();     // ch04_transforms.cpp: 4.1-4.25
std::vector<Figure> chapter4_projection_figures();    // ch04_projections.cpp: 4.26-4.34
std::vector<Figure> chapter5_primitive_figures();     // ch05_primitives.cpp: 5.1-5.16
std::vector<Figure> chapter5_curve_figures();         // ch05_curves.cpp: 5.17, 5.18
std::vector<Figure> chapter6_distance_figures();      // ch06_distance.cpp: distance in 2D, 6.1-6.23
std::vector<Figure> chapter6_gjk_figures();           // ch06_gjk.cpp: GJK, 6.24-6.29
std::vector<Figure> chapter7_intersection_figures();  // ch07_intersection.cpp: 7.1-7.18
std::vector<Figure> chapter8_construction_figures();  // ch08_constructions.cpp: 8.1-8.34
std::vector<Figure> chapter9_mesh_figures();          // ch09_meshes.cpp: 9.5-9.17
std::vector<Figure> chapter9_surface_figures();       // ch09_surfaces.cpp: 9.22-9.26
std::vector<Figure> chapter10_distance_figures();     // ch10_distance.cpp: distance in 3D
std::vector<Figure> chapter11_intersection_figures();  // ch11_intersection.cpp: 11.1-11.77
std::vector<Figure> chapter12_misc_figures();          // ch12_misc.cpp: 12.1-12.10
std::vector<Figure> chapter13_bsp_figures();           // ch13_bsp.cpp: 13.1-13.12, 13.27-31
std::vector<Figure> chapter13_figures();               // ch13_hull_delaunay.cpp: 13.2-13.11
std::vector<Figure> chapter13_boolean_figures();       // ch13_boolean.cpp: 13.20-13.26
std::vector<Figure> chapter13_polytri_figures();       // ch13_triangulate.cpp: 13.53-13.77
std::vector<Figure> chapter13_trapmap_figures();       // ch13_trapezoid_map.cpp: 13.57-67
std::vector<Figure> appendix_a_figures();              // chA_numerics.cpp: A.2-A.24
/// Every figure in book order.
std::vector<Figure> all_figures();

/// gallery/figures.txt, embedded at build time (generated captions.cpp).
std::string_view figures_txt() noexcept;
/// The book's caption of figure `id` ("3.15"), from the embedded figures.txt.
std::optional<std::string> caption(std::string_view id);
/// Book order of figure ids: chapters by number, then appendices by letter ("A.2" after "15.1");
/// returns {chapter, figure} with appendix A as chapter 100, B as 101, ...; {-1, -1} if malformed.
std::pair<int, int> figure_order(std::string_view id);
/// "(x, y)" with `prec` decimals: a point label. (One snprintf: GCC 12 -O3 misreports
/// -Wrestrict on chains of std::string operator+ that start from a literal.)
std::string coordinates(double x, double y, int prec = 2);

/// "fig_3_15.svg" for id "3.15", "fig_A_2.svg" for "A.2".
std::string file_name(std::string_view id);

/// Draws one figure; `ok` is the figure's own success flag.
struct Rendered {
  bool ok;
  std::string svg;
};
Rendered render(const Figure& f);

/// Result of run(): how many SVGs were written and what went wrong.
struct RunResult {
  locus::Status status;  ///< ok, or io_error / degenerate_input (a figure's computation failed)
  int written;
  std::vector<std::string> errors;
};
/// Writes every figure and index.html into out_dir (created if missing).
RunResult run(const std::string& out_dir);

// ---- drawing helpers shared by the figure files ---------------------------------------------

namespace colour {
inline constexpr const char* blue = "#1f5fbf";
inline constexpr const char* red = "#c8312a";
inline constexpr const char* green = "#2a8a3a";
inline constexpr const char* orange = "#e07b10";
inline constexpr const char* purple = "#7a3fb0";
inline constexpr const char* gray = "#808080";
inline constexpr const char* light = "#c8c8c8";
inline constexpr const char* black = "#222222";
}  // namespace colour

/// A solid line style.
SvgStyle pen(const char* colour, double width = 1.8);
/// A dashed line style.
SvgStyle dashed(const char* colour, double width = 1.2);
/// A translucent fill with an outline of the same colour.
SvgStyle filled(const char* colour, double fill_opacity = 0.2, double width = 1.5);
/// A point marker.
SvgStyle dot(const char* colour, double size = 3.5);
/// A text style; dx, dy in pixels (dy up).
SvgStyle text_style(const char* colour = colour::black, double dx = 5, double dy = 5,
                    locus::SvgAnchor anchor = locus::SvgAnchor::start, double size = 15);

void label(SvgWriter& w, const Vec2d& p, std::string_view s, const char* c = colour::black,
           double dx = 5, double dy = 5);
void label(SvgWriter& w, const Vec3d& p, std::string_view s, const char* c = colour::black,
           double dx = 5, double dy = 5);
/// A labelled point.
void point(SvgWriter& w, const Vec2d& p, std::string_view name, const char* c = colour::black);
void point(SvgWriter& w, const Vec3d& p, std::string_view name, const char* c = colour::black);
/// A labelled arrow from a to b, the label at the middle offset to the left of the arrow.
void vector(SvgWriter& w, const Vec2d& a, const Vec2d& b, std::string_view name, const char* c,
            double label_offset_px = 10);
/// The arc marking the (smaller) angle at `vertex` between directions d0 and d1, of radius r
/// (world units), optionally labelled at its middle. Uses locus::atan2_positive and
/// locus::signed_angle.
void angle_mark(SvgWriter& w, const Vec2d& vertex, const Vec2d& d0, const Vec2d& d1, double r,
                std::string_view name = "", const char* c = colour::gray);
/// A small square marking the right angle between d0 and d1 at vertex (size in world units).
void right_angle_mark(SvgWriter& w, const Vec2d& vertex, const Vec2d& d0, const Vec2d& d1,
                      double size, const char* c = colour::gray);
/// The axes of a frame as arrows from its origin, labelled with names[i].
void frame(SvgWriter& w, const locus::Frame2d& f, const char* c, std::string_view origin_name,
           std::string_view x_name, std::string_view y_name);
void frame(SvgWriter& w, const locus::Frame3d& f, const char* c, std::string_view origin_name,
           std::string_view x_name, std::string_view y_name, std::string_view z_name);
/// World axes x, y, z from the origin with the given length.
void axes3(SvgWriter& w, double len, const char* c = colour::gray);
/// A closed polygon outline.
void closed(SvgWriter& w, const std::vector<Vec2d>& pts, const SvgStyle& s);
void closed(SvgWriter& w, const std::vector<Vec3d>& pts, const SvgStyle& s);
/// Images of points under an affine map (locus::apply_point).
std::vector<Vec2d> map_points(const locus::Affine2d& a, const std::vector<Vec2d>& pts);
std::vector<Vec3d> map_points(const locus::Affine3d& a, const std::vector<Vec3d>& pts);
/// A generic asymmetric "house with a flag" outline so that rotations and mirrors are visible.
std::vector<Vec2d> house(const Vec2d& at, double size);
/// An orthographic or perspective camera at `eye` looking at `target` with z up.
locus::SvgCamera camera(const Vec3d& eye, const Vec3d& target = {0, 0, 0},
                        bool perspective = false);
/// The 12 edges of the box with the given 8 corners (index bits: x, y, z) drawn with style s.
void box_edges(SvgWriter& w, const std::array<Vec3d, 8>& c, const SvgStyle& s);

}  // namespace locus_gallery
