// SPDX-License-Identifier: BSL-1.0
// The gallery runner (captions, file names, index.html) and the shared drawing helpers.
#include "gallery.hpp"

#include <locus/core/angle.hpp>
#include <locus/core/products.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace locus_gallery {

// ---- table and captions -----------------------------------------------------------------------

std::vector<Figure> all_figures() {
  std::vector<Figure> all;
  for (auto part : {chapter2_linear_figures(),
                    chapter3_vector_figures(),
                    chapter3_affine_figures(),
                    chapter4_transform_figures(),
                    chapter4_projection_figures(),
                    chapter5_primitive_figures(),
                    chapter5_curve_figures(),
                    chapter6_distance_figures(),
                    chapter6_gjk_figures(),
                    chapter7_intersection_figures(),
                    chapter8_construction_figures(),
                    chapter9_mesh_figures(),
                    chapter9_surface_figures(),
                    chapter10_distance_figures(),
                    chapter11_intersection_figures(),
                    chapter12_misc_figures(),
                    chapter13_bsp_figures(),
                    chapter13_figures(),
                    chapter13_boolean_figures(),
                    chapter13_polytri_figures(),
                    appendix_a_figures()})
    all.insert(all.end(), part.begin(), part.end());
  // Tables of one chapter may interleave (13.9's figures sit inside chapter13_figures' range).
  std::stable_sort(all.begin(), all.end(), [](const Figure& a, const Figure& b) {
    return figure_order(a.id) < figure_order(b.id);
  });
  return all;
}

std::optional<std::string> caption(std::string_view id) {
  std::string_view text = figures_txt();
  while (!text.empty()) {
    const std::size_t eol = text.find('\n');
    std::string_view line = text.substr(0, eol);
    text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
    if (line.empty() || line[0] == '#') continue;
    const std::size_t t1 = line.find('\t');
    if (t1 == std::string_view::npos || line.substr(0, t1) != id) continue;
    std::string_view rest = line.substr(t1 + 1);
    const std::size_t t2 = rest.find('\t');
    return std::string(rest.substr(0, t2));
  }
  return std::nullopt;
}

std::string coordinates(double x, double y, int prec) {
  char buf[96];
  std::snprintf(buf, sizeof(buf), "(%.*f, %.*f)", prec, x, prec, y);
  return buf;
}

std::pair<int, int> figure_order(std::string_view id) {
  const std::size_t dot = id.find('.');
  if (dot == 0 || dot == std::string_view::npos || dot + 1 == id.size()) return {-1, -1};
  auto number = [](std::string_view digits) {
    int v = 0;
    for (char c : digits) {
      if (c < '0' || c > '9' || v > 100000) return -1;
      v = v * 10 + (c - '0');
    }
    return v;
  };
  const std::string_view head = id.substr(0, dot);
  const int chapter =
      head.size() == 1 && head[0] >= 'A' && head[0] <= 'Z' ? 100 + (head[0] - 'A') : number(head);
  const int figure = number(id.substr(dot + 1));
  if (chapter < 0 || figure < 0) return {-1, -1};
  return {chapter, figure};
}

std::string file_name(std::string_view id) {
  std::string s = "fig_";
  for (char c : id) s += c == '.' ? '_' : c;
  return s + ".svg";
}

Rendered render(const Figure& f) {
  locus::SvgOptions o;
  o.max_width = 520;
  o.max_height = 400;
  o.margin = 28;
  o.title = std::string("Figure ") + f.id + ": " + caption(f.id).value_or("");
  SvgWriter w(o);
  const bool ok = f.draw(w);
  return {ok, w.to_string()};
}

namespace {
std::string html_escape(std::string_view s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}
// "N of the book's M figures, from chapters 2, 3, ... and appendix A": counted from the figures
// the gallery draws and the embedded figure list, so the page never claims more than it shows.
std::string coverage_sentence(const std::vector<Figure>& figures) {
  std::vector<std::string_view> book_ids;  // the list repeats a few ids (continued captions)
  std::string_view text = figures_txt();
  while (!text.empty()) {
    const std::size_t eol = text.find('\n');
    const std::string_view line = text.substr(0, eol);
    text = eol == std::string_view::npos ? std::string_view{} : text.substr(eol + 1);
    if (!line.empty() && line[0] != '#') book_ids.push_back(line.substr(0, line.find('\t')));
  }
  std::sort(book_ids.begin(), book_ids.end());
  const auto book_total =
      static_cast<std::size_t>(std::unique(book_ids.begin(), book_ids.end()) - book_ids.begin());
  std::vector<int> chapters;
  for (const Figure& f : figures) {
    const int c = figure_order(f.id).first;
    if (c >= 0 && std::find(chapters.begin(), chapters.end(), c) == chapters.end())
      chapters.push_back(c);
  }
  std::sort(chapters.begin(), chapters.end());
  std::string numbered, appendices;
  for (const int c : chapters) {
    std::string& list = c >= 100 ? appendices : numbered;
    if (!list.empty()) list += ", ";
    list += c >= 100 ? std::string(1, static_cast<char>('A' + (c - 100))) : std::to_string(c);
  }
  std::string s = std::to_string(figures.size()) + " of the book's " + std::to_string(book_total) +
                  " figures, from chapters " + numbered;
  if (!appendices.empty()) s += " and appendix " + appendices;
  return s;
}
}  // namespace

RunResult run(const std::string& out_dir) {
  RunResult r{locus::Status::ok, 0, {}};
  const std::vector<Figure> figures = all_figures();
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  const std::filesystem::path dir(out_dir);
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<title>locus gallery: figures of Geometric Tools for Computer Graphics</title>\n"
       << "<style>body{font-family:sans-serif;max-width:1100px;margin:auto;background:#f4f4f4}"
       << "figure{display:inline-block;vertical-align:top;width:520px;margin:10px;padding:8px;"
       << "background:white;border:1px solid #ddd}img{max-width:100%}"
       << "figcaption{font-size:14px}code{font-size:12px;color:#555}</style>\n</head>\n<body>\n"
       << "<h1>locus gallery</h1>\n<p>" << coverage_sentence(figures)
       << " of <i>Geometric Tools for Computer Graphics</i> (Schneider &amp; Eberly), redrawn "
       << "from live locus computations by <code>locus_gallery</code>.</p>\n";
  for (const Figure& f : figures) {
    const Rendered rd = render(f);
    if (!rd.ok) {
      r.status = locus::Status::degenerate_input;
      r.errors.push_back(std::string("figure ") + f.id + ": a locus computation failed");
    }
    const std::string name = file_name(f.id);
    std::ofstream out(dir / name, std::ios::binary | std::ios::trunc);
    out << rd.svg;
    out.close();
    if (!out) {
      r.status = locus::Status::io_error;
      r.errors.push_back("cannot write " + (dir / name).string());
      continue;
    }
    ++r.written;
    html << "<figure id=\"fig-" << f.id << "\"><img src=\"" << name << "\" alt=\"Figure " << f.id
         << "\"><figcaption><b>Figure " << f.id << ".</b> "
         << html_escape(caption(f.id).value_or("(no caption)")) << "<br><code>computed with "
         << html_escape(f.computed_with) << "</code></figcaption></figure>\n";
  }
  html << "</body>\n</html>\n";
  std::ofstream index(dir / "index.html", std::ios::binary | std::ios::trunc);
  index << html.str();
  index.close();
  if (!index) {
    r.status = locus::Status::io_error;
    r.errors.push_back("cannot write " + (dir / "index.html").string());
  }
  return r;
}

// ---- helpers ------------------------------------------------------------------------------------

SvgStyle pen(const char* c, double width) {
  SvgStyle s;
  s.stroke = c;
  s.width = width;
  return s;
}
SvgStyle dashed(const char* c, double width) {
  SvgStyle s = pen(c, width);
  s.dash = {5, 4};
  return s;
}
SvgStyle filled(const char* c, double fill_opacity, double width) {
  SvgStyle s = pen(c, width);
  s.fill = c;
  s.fill_opacity = fill_opacity;
  return s;
}
SvgStyle dot(const char* c, double size) {
  SvgStyle s = pen(c, 1.0);
  s.fill = c;
  s.marker_size = size;
  return s;
}
SvgStyle text_style(const char* c, double dx, double dy, locus::SvgAnchor anchor, double size) {
  SvgStyle s;
  s.stroke = "none";
  s.fill = c;
  s.text_dx = dx;
  s.text_dy = dy;
  s.anchor = anchor;
  s.font_size = size;
  return s;
}

void label(SvgWriter& w, const Vec2d& p, std::string_view s, const char* c, double dx, double dy) {
  w.text(p, s, text_style(c, dx, dy));
}
void label(SvgWriter& w, const Vec3d& p, std::string_view s, const char* c, double dx, double dy) {
  w.text(p, s, text_style(c, dx, dy));
}
void point(SvgWriter& w, const Vec2d& p, std::string_view name, const char* c) {
  w.point(p, dot(c));
  if (!name.empty()) label(w, p, name, c);
}
void point(SvgWriter& w, const Vec3d& p, std::string_view name, const char* c) {
  w.point(p, dot(c));
  if (!name.empty()) label(w, p, name, c);
}

void vector(SvgWriter& w, const Vec2d& a, const Vec2d& b, std::string_view name, const char* c,
            double off) {
  w.arrow(a, b, pen(c));
  if (name.empty()) return;
  // The label sits beside the middle of the arrow, on its left (counter-clockwise) side.
  const Vec2d n = locus::perp(locus::normalize(b - a));
  SvgStyle s = text_style(c, n.x * off, n.y * off - 5, locus::SvgAnchor::middle);
  w.text(locus::lerp(a, b, 0.5), name, s);
}

void angle_mark(SvgWriter& w, const Vec2d& v, const Vec2d& d0, const Vec2d& d1, double r,
                std::string_view name, const char* c) {
  // The mark spans the smaller angle between the directions, whichever order they come in.
  double sweep = locus::signed_angle(d0, d1);
  const Vec2d from = sweep < 0 ? d1 : d0;
  if (sweep < 0) sweep = -sweep;
  const double a0 = locus::atan2_positive(from.y, from.x);
  w.arc(v, r, a0, a0 + sweep, pen(c, 1.2));
  if (name.empty()) return;
  const double am = a0 + 0.5 * sweep;
  w.text(v + 1.35 * r * Vec2d{std::cos(am), std::sin(am)}, name,
         text_style(c, 0, -5, locus::SvgAnchor::middle, 14));
}

void right_angle_mark(SvgWriter& w, const Vec2d& v, const Vec2d& d0, const Vec2d& d1, double size,
                      const char* c) {
  const Vec2d a = locus::normalize(d0) * size, b = locus::normalize(d1) * size;
  w.polyline(std::vector<Vec2d>{v + a, v + a + b, v + b}, pen(c, 1.0));
}

void frame(SvgWriter& w, const locus::Frame2d& f, const char* c, std::string_view o,
           std::string_view x, std::string_view y) {
  w.arrow(f.origin, f.origin + f.axis[0], pen(c));
  w.arrow(f.origin, f.origin + f.axis[1], pen(c));
  point(w, f.origin, o, c);
  label(w, f.origin + f.axis[0], x, c);
  label(w, f.origin + f.axis[1], y, c);
}

void frame(SvgWriter& w, const locus::Frame3d& f, const char* c, std::string_view o,
           std::string_view x, std::string_view y, std::string_view z) {
  for (int i = 0; i < 3; ++i)
    w.arrow(f.origin, f.origin + f.axis[static_cast<std::size_t>(i)], pen(c));
  point(w, f.origin, o, c);
  label(w, f.origin + f.axis[0], x, c);
  label(w, f.origin + f.axis[1], y, c);
  label(w, f.origin + f.axis[2], z, c);
}

void axes3(SvgWriter& w, double len, const char* c) {
  frame(w, locus::Frame3d{{0, 0, 0}, {Vec3d{len, 0, 0}, Vec3d{0, len, 0}, Vec3d{0, 0, len}}}, c, "",
        "x", "y", "z");
}

void closed(SvgWriter& w, const std::vector<Vec2d>& pts, const SvgStyle& s) {
  w.polyline(pts, s, true);
}
void closed(SvgWriter& w, const std::vector<Vec3d>& pts, const SvgStyle& s) {
  w.polyline(pts, s, true);
}

std::vector<Vec2d> map_points(const locus::Affine2d& a, const std::vector<Vec2d>& pts) {
  std::vector<Vec2d> out;
  for (const Vec2d& p : pts) out.push_back(locus::apply_point(a, p));
  return out;
}
std::vector<Vec3d> map_points(const locus::Affine3d& a, const std::vector<Vec3d>& pts) {
  std::vector<Vec3d> out;
  for (const Vec3d& p : pts) out.push_back(locus::apply_point(a, p));
  return out;
}

std::vector<Vec2d> house(const Vec2d& at, double s) {
  const std::vector<Vec2d> unit{{0, 0},     {1, 0},      {1, 0.6},   {0.5, 1.0},  {0.2, 0.76},
                                {0.2, 1.2}, {0.45, 1.1}, {0.2, 1.0}, {0.2, 0.76}, {0, 0.6}};
  std::vector<Vec2d> out;
  for (const Vec2d& p : unit) out.push_back(at + p * s);
  return out;
}

locus::SvgCamera camera(const Vec3d& eye, const Vec3d& target, bool perspective) {
  locus::SvgCamera c;
  c.eye = eye;
  c.target = target;
  c.up = {0, 0, 1};
  c.perspective = perspective;
  c.fov_y = 0.7;
  c.near = 0.05;
  return c;
}

void box_edges(SvgWriter& w, const std::array<Vec3d, 8>& c, const SvgStyle& s) {
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t bit : {1u, 2u, 4u})
      if (!(i & bit)) w.segment(c[i], c[i | bit], s);
}

}  // namespace locus_gallery
