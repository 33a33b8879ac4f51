// SPDX-License-Identifier: BSL-1.0
// SvgWriter implementation: item storage, view fitting, world-to-pixel mapping, emission.
#include <locus/io/svg.hpp>

#include <locus/core/projection.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <utility>

namespace locus {
namespace {

constexpr double kPi = pi_v<double>;
constexpr double kTwoPi = 2.0 * pi_v<double>;

bool finite2(const Vec2d& p) noexcept { return is_finite(p); }

// Accumulates a world bounding box from finite points only.
struct Bounds {
  Vec2d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2d hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  bool empty = true;
  void add(const Vec2d& p) noexcept {
    if (!finite2(p)) return;
    lo = cwise_min(lo, p);
    hi = cwise_max(hi, p);
    empty = false;
  }
};

// Normalised counter-clockwise span of an arc from a0 to a1, in (0, 2 pi]; 2 pi or more
// means the full circle. A zero span (a0 == a1) stays 0.
double arc_span(double a0, double a1) noexcept {
  double s = a1 - a0;
  if (s >= 0.0) return s;
  s = std::fmod(s, kTwoPi);
  return s + kTwoPi;  // s in (-2pi, 0] -> (0, 2pi]
}

// Number formatting: at most 3 decimals, no trailing zeros, never "-0", locale independent.
void append_number(std::string& out, double x) {
  double r = std::round(x * 1000.0) / 1000.0;
  if (r == 0.0) r = 0.0;  // turns -0 into 0
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof(buf), r, std::chars_format::fixed, 3);
  char* end = res.ptr;
  if (res.ec != std::errc{}) {
    out += '0';
    return;
  }
  // trim trailing zeros of the fraction
  char* dot = std::find(buf, end, '.');
  if (dot != end) {
    while (end > dot + 1 && end[-1] == '0') --end;
    if (end == dot + 1) end = dot;
  }
  out.append(buf, end);
}

void append_escaped(std::string& out, std::string_view s) {
  for (char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (u < 0x20 && ch != '\t' && ch != '\n') break;  // not allowed in XML 1.0
        if (u == 0x7f) break;
        out += ch;
    }
  }
}

// Builds one element; any non-finite number poisons it so the caller drops it.
struct Element {
  std::string s;
  bool ok = true;
  void raw(std::string_view t) { s += t; }
  void num(double x) {
    if (!is_finite(x)) {
      ok = false;
      return;
    }
    append_number(s, x);
  }
  void attr(std::string_view name, double x) {
    s += ' ';
    s += name;
    s += "=\"";
    num(x);
    s += '"';
  }
  void attr(std::string_view name, std::string_view text) {
    s += ' ';
    s += name;
    s += "=\"";
    append_escaped(s, text);
    s += '"';
  }
  void pt(const Vec2d& p) {
    num(p.x);
    s += ',';
    num(p.y);
  }
};

bool nonneg_finite(double x) noexcept { return is_finite(x) && x >= 0.0; }

// Stroke-related attributes of a style. `fill` overrides the style's fill.
void style_attrs(Element& e, const SvgStyle& st, std::string_view fill, bool stroke = true) {
  if (stroke) {
    e.attr("stroke", st.stroke.empty() ? std::string_view("none") : std::string_view(st.stroke));
    if (nonneg_finite(st.width)) e.attr("stroke-width", st.width);
    bool dash_ok = !st.dash.empty();
    double dash_sum = 0.0;
    for (double d : st.dash) {
      if (!nonneg_finite(d))
        dash_ok = false;
      else
        dash_sum += d;
    }
    if (dash_ok && dash_sum > 0.0) {
      e.raw(" stroke-dasharray=\"");
      for (std::size_t i = 0; i < st.dash.size(); ++i) {
        if (i) e.raw(" ");
        e.num(st.dash[i]);
      }
      e.raw("\"");
    }
    e.raw(" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
  } else {
    e.raw(" stroke=\"none\"");
  }
  e.attr("fill", fill.empty() ? std::string_view("none") : fill);
  if (is_finite(st.opacity) && st.opacity >= 0.0 && st.opacity < 1.0) e.attr("opacity", st.opacity);
  if (is_finite(st.fill_opacity) && st.fill_opacity >= 0.0 && st.fill_opacity < 1.0)
    e.attr("fill-opacity", st.fill_opacity);
}

std::string_view solid_colour(const SvgStyle& st) {
  if (!st.fill.empty() && st.fill != "none") return st.fill;
  return st.stroke.empty() ? std::string_view("black") : std::string_view(st.stroke);
}

// Liang-Barsky clip of p + t d, t in [t0, t1], to the box [lo, hi]. Returns false if empty.
bool clip_param(const Vec2d& p, const Vec2d& d, const Vec2d& lo, const Vec2d& hi, double& t0,
                double& t1) noexcept {
  for (int i = 0; i < 2; ++i) {
    if (d[i] == 0.0) {
      if (p[i] < lo[i] || p[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - p[i]) / d[i];
    double tb = (hi[i] - p[i]) / d[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (!(t0 <= t1)) return false;
  }
  return true;
}

}  // namespace

// ---- configuration ---------------------------------------------------------------------------

void SvgWriter::set_view(const Vec2d& lo, const Vec2d& hi) {
  if (!finite2(lo) || !finite2(hi) || !(lo.x < hi.x) || !(lo.y < hi.y)) return;
  has_view_ = true;
  view_lo_ = lo;
  view_hi_ = hi;
}

// ---- adding items ----------------------------------------------------------------------------

void SvgWriter::add_point(const Vec2d& p, const SvgStyle& s) {
  if (!finite2(p)) return;
  items_.push_back(Item{Item::Kind::point, {{p}}, 0, 0, 0, false, {}, s});
}

void SvgWriter::add_segment(const Vec2d& a, const Vec2d& b, const SvgStyle& s) {
  if (!finite2(a) || !finite2(b)) return;
  items_.push_back(Item{Item::Kind::segment, {{a, b}}, 0, 0, 0, false, {}, s});
}

void SvgWriter::add_line(const Vec2d& p, const Vec2d& d, bool ray, const SvgStyle& s) {
  if (!finite2(p) || !finite2(d) || (d.x == 0.0 && d.y == 0.0)) return;
  // Store a unit direction so that clipping parameters stay well scaled.
  const Vec2d u = normalize(d);
  if (u.x == 0.0 && u.y == 0.0) return;
  items_.push_back(Item{ray ? Item::Kind::ray : Item::Kind::line, {{p, u}}, 0, 0, 0, false, {}, s});
}

void SvgWriter::add_arrow(const Vec2d& a, const Vec2d& b, const SvgStyle& s) {
  if (!finite2(a) || !finite2(b)) return;
  items_.push_back(Item{Item::Kind::arrow, {{a, b}}, 0, 0, 0, false, {}, s});
}

void SvgWriter::add_polyline(std::vector<Vec2d> pts, bool closed, const SvgStyle& s) {
  Item it{Item::Kind::polyline, {}, 0, 0, 0, closed, {}, s};
  if (closed) {
    std::vector<Vec2d> ring;
    for (const auto& p : pts)
      if (finite2(p)) ring.push_back(p);
    if (ring.size() >= 2) it.pts.push_back(std::move(ring));
  } else {
    std::vector<Vec2d> run;
    for (const auto& p : pts) {
      if (finite2(p)) {
        run.push_back(p);
        continue;
      }
      if (run.size() >= 2) it.pts.push_back(std::move(run));
      run.clear();
    }
    if (run.size() >= 2) it.pts.push_back(std::move(run));
  }
  if (!it.pts.empty()) items_.push_back(std::move(it));
}

void SvgWriter::add_polygon(std::vector<std::vector<Vec2d>> rings, const SvgStyle& s) {
  Item it{Item::Kind::polygon, {}, 0, 0, 0, true, {}, s};
  for (auto& r : rings) {
    std::vector<Vec2d> ring;
    for (const auto& p : r)
      if (finite2(p)) ring.push_back(p);
    if (ring.size() >= 2) it.pts.push_back(std::move(ring));
  }
  if (!it.pts.empty()) items_.push_back(std::move(it));
}

void SvgWriter::add_circle(const Vec2d& c, double r, const SvgStyle& s) {
  if (!finite2(c) || !nonneg_finite(r)) return;
  items_.push_back(Item{Item::Kind::circle, {{c}}, r, 0, 0, false, {}, s});
}

void SvgWriter::add_ellipse(const Vec2d& c, const Vec2d& axis0, double e0, double e1,
                            const SvgStyle& s) {
  if (!finite2(c) || !nonneg_finite(e0) || !nonneg_finite(e1)) return;
  const Vec2d u = normalize(axis0);
  if (u.x == 0.0 && u.y == 0.0) return;
  items_.push_back(Item{Item::Kind::ellipse, {{c, u}}, e0, e1, 0, false, {}, s});
}

void SvgWriter::add_arc(const Vec2d& c, double r, double a0, double a1, const SvgStyle& s) {
  if (!finite2(c) || !nonneg_finite(r) || !is_finite(a0) || !is_finite(a1)) return;
  const double span = arc_span(a0, a1);
  if (!(span > 0.0)) return;
  items_.push_back(Item{Item::Kind::arc, {{c}}, r, a0, std::min(span, kTwoPi), false, {}, s});
}

void SvgWriter::add_text(const Vec2d& p, std::string_view str, const SvgStyle& s) {
  if (!finite2(p)) return;
  items_.push_back(Item{Item::Kind::text, {{p}}, 0, 0, 0, false, std::string(str), s});
}

void SvgWriter::curve(const std::function<Vec2d(double)>& f, double t0, double t1, int n,
                      const SvgStyle& s) {
  if (!f || n < 1 || !is_finite(t0) || !is_finite(t1)) return;
  std::vector<Vec2d> pts;
  pts.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const double t = i == n ? t1 : t0 + (t1 - t0) * (static_cast<double>(i) / n);
    pts.push_back(f(t));
  }
  add_polyline(std::move(pts), false, s);
}

// ---- view and mapping ------------------------------------------------------------------------

SvgWriter::Mapping SvgWriter::mapping() const {
  Bounds b;
  if (has_view_) {
    b.add(view_lo_);
    b.add(view_hi_);
  } else {
    for (const Item& it : items_) {
      switch (it.kind) {
        case Item::Kind::line:
        case Item::Kind::ray:
          b.add(it.pts[0][0]);
          break;
        case Item::Kind::circle: {
          const Vec2d c = it.pts[0][0];
          b.add(c - Vec2d{it.a, it.a});
          b.add(c + Vec2d{it.a, it.a});
          break;
        }
        case Item::Kind::ellipse: {
          const Vec2d c = it.pts[0][0], u = it.pts[0][1], v = perp(u);
          const Vec2d h{std::hypot(it.a * u.x, it.b * v.x), std::hypot(it.a * u.y, it.b * v.y)};
          b.add(c - h);
          b.add(c + h);
          break;
        }
        case Item::Kind::arc: {
          const Vec2d c = it.pts[0][0];
          const double r = it.a, a0 = it.b, span = it.c;
          b.add(c + r * Vec2d{std::cos(a0), std::sin(a0)});
          b.add(c + r * Vec2d{std::cos(a0 + span), std::sin(a0 + span)});
          // Axis-extreme points inside the sweep.
          double k = std::ceil(a0 / (kPi / 2));
          for (int i = 0; i < 5; ++i, k += 1.0) {
            const double a = k * (kPi / 2);
            if (a > a0 + span) break;
            const int q = static_cast<int>(std::fmod(std::fmod(k, 4.0) + 4.0, 4.0));
            const Vec2d dir = q == 0   ? Vec2d{1, 0}
                              : q == 1 ? Vec2d{0, 1}
                              : q == 2 ? Vec2d{-1, 0}
                                       : Vec2d{0, -1};
            b.add(c + r * dir);
          }
          break;
        }
        default:
          for (const auto& ring : it.pts)
            for (const auto& p : ring) b.add(p);
      }
    }
  }

  Mapping m{};
  m.margin = nonneg_finite(options_.margin) ? options_.margin : 0.0;
  const double mw =
      is_finite(options_.max_width) && options_.max_width > 1.0 ? options_.max_width : 480.0;
  const double mh =
      is_finite(options_.max_height) && options_.max_height > 1.0 ? options_.max_height : 480.0;
  Vec2d lo = b.empty ? Vec2d{-1, -1} : b.lo;
  Vec2d hi = b.empty ? Vec2d{1, 1} : b.hi;
  // Half extents computed without overflow; centre likewise.
  Vec2d half{hi.x * 0.5 - lo.x * 0.5, hi.y * 0.5 - lo.y * 0.5};
  Vec2d mid{lo.x * 0.5 + hi.x * 0.5, lo.y * 0.5 + hi.y * 0.5};
  auto fit = [&](const Vec2d& h) {
    const double sx = h.x > 0.0 ? mw / (2.0 * h.x) : std::numeric_limits<double>::infinity();
    const double sy = h.y > 0.0 ? mh / (2.0 * h.y) : std::numeric_limits<double>::infinity();
    return std::min(sx, sy);
  };
  double scale = fit(half);
  if (!(scale > 0.0) || !is_finite(scale)) {
    // A single point (or an extent too small to scale): show a unit square around it.
    const double h = std::max(1.0, std::max(std::abs(mid.x), std::abs(mid.y)) * 1e-9);
    half = {h, h};
    scale = fit(half);
  }
  m.scale = scale;
  m.inner_lo = mid - half;
  m.inner_hi = mid + half;
  m.width = 2.0 * half.x * scale + 2.0 * m.margin;
  m.height = 2.0 * half.y * scale + 2.0 * m.margin;
  m.origin_px = {m.margin, m.margin};

  // Grow the canvas (never shrink the scale) so that text labels fit. The extent of a label is
  // estimated: 0.6 em per character (UTF-8 continuation bytes do not count), 1 em high.
  double grow_l = 0, grow_r = 0, grow_t = 0, grow_b = 0;
  for (const Item& it : items_) {
    if (it.kind != Item::Kind::text) continue;
    const SvgStyle& st = it.style;
    const double fs = nonneg_finite(st.font_size) ? st.font_size : 14.0;
    double chars = 0;
    for (char ch : it.str)
      if ((static_cast<unsigned char>(ch) & 0xC0) != 0x80) chars += 1;
    const double tw = 0.6 * fs * chars;
    const Vec2d p = it.pts[0][0];
    const double x =
        (p.x - m.inner_lo.x) * scale + m.margin + (is_finite(st.text_dx) ? st.text_dx : 0);
    const double y =
        (m.inner_hi.y - p.y) * scale + m.margin - (is_finite(st.text_dy) ? st.text_dy : 0);
    const double x0 = st.anchor == SvgAnchor::start    ? x
                      : st.anchor == SvgAnchor::middle ? x - 0.5 * tw
                                                       : x - tw;
    if (!is_finite(x0) || !is_finite(y)) continue;
    grow_l = std::max(grow_l, -x0 + 2.0);
    grow_r = std::max(grow_r, x0 + tw + 2.0 - m.width);
    grow_t = std::max(grow_t, -(y - 0.8 * fs) + 2.0);
    grow_b = std::max(grow_b, y + 0.3 * fs + 2.0 - m.height);
  }
  m.origin_px += Vec2d{grow_l, grow_t};
  m.width += grow_l + grow_r;
  m.height += grow_t + grow_b;
  m.lo = {m.inner_lo.x - m.origin_px.x / scale, m.inner_hi.y - (m.height - m.origin_px.y) / scale};
  m.hi = {m.inner_lo.x + (m.width - m.origin_px.x) / scale, m.inner_hi.y + m.origin_px.y / scale};
  return m;
}

// ---- 3D ---------------------------------------------------------------------------------------

void SvgWriter::set_camera(const SvgCamera& camera) {
  // The view matrix: the given up vector, or a coordinate axis when up is parallel to the view
  // direction (look_at rejects that); an unusable camera is ignored.
  std::optional<Mat4d> view = look_at(camera.eye, camera.target, camera.up);
  for (const Vec3d& up : {Vec3d{0, 0, 1}, Vec3d{0, 1, 0}, Vec3d{1, 0, 0}})
    if (!view) view = look_at(camera.eye, camera.target, up);
  if (!view) return;
  // Only x and y of the clip space are used: the depth range is irrelevant, far is generous.
  std::optional<Mat4d> proj;
  if (camera.perspective) {
    if (!(camera.near > 0.0) || !is_finite(camera.near)) return;
    proj = perspective_fov(camera.fov_y, 1.0, camera.near, camera.near * 1e9);
  } else {
    const double h = 0.5 * camera.ortho_height;
    if (!(h > 0.0) || !is_finite(h)) return;
    proj = orthographic_box(-h, h, -h, h, -1.0, 1.0);
  }
  if (!proj) return;
  camera_ = camera;
  view_ = *view;
  view_proj_ = *proj * *view;
}

bool SvgWriter::project(const Vec3d& p, Vec2d& out) const noexcept {
  if (!is_finite(p)) return false;
  if (camera_.perspective) {
    const Vec4d q = view_ * Vec4d{p.x, p.y, p.z, 1.0};
    if (!(-q.z >= camera_.near)) return false;
  }
  const ProjectedPoint<double, 3> r = project_point(view_proj_, p);
  if (!r.in_front) return false;
  out = Vec2d{r.point.x, r.point.y};
  return is_finite(out);
}

void SvgWriter::add_segment3(const Vec3d& a, const Vec3d& b, bool arrow, const SvgStyle& s) {
  if (!is_finite(a) || !is_finite(b)) return;
  Vec3d pa = a, pb = b;
  if (camera_.perspective) {
    // Clip against the near plane in camera space: keep -z >= near.
    const Vec4d qa = view_ * Vec4d{a.x, a.y, a.z, 1.0};
    const Vec4d qb = view_ * Vec4d{b.x, b.y, b.z, 1.0};
    const double da = -qa.z - camera_.near, db = -qb.z - camera_.near;
    if (da < 0.0 && db < 0.0) return;
    if (da < 0.0) pa = lerp(a, b, da / (da - db));
    if (db < 0.0) pb = lerp(a, b, da / (da - db));
  }
  // The clipped end lies on the near plane up to rounding; project it without the near test.
  const auto proj = [this](const Vec3d& p, Vec2d& out) {
    const ProjectedPoint<double, 3> r = project_point(view_proj_, p);
    out = Vec2d{r.point.x, r.point.y};
    return r.in_front && is_finite(out);
  };
  Vec2d q0, q1;
  if (!proj(pa, q0) || !proj(pb, q1)) return;
  if (arrow)
    add_arrow(q0, q1, s);
  else
    add_segment(q0, q1, s);
}

void SvgWriter::add_point3(const Vec3d& p, const SvgStyle& s) {
  Vec2d q;
  if (project(p, q)) add_point(q, s);
}

void SvgWriter::add_text3(const Vec3d& p, std::string_view str, const SvgStyle& s) {
  Vec2d q;
  if (project(p, q)) add_text(q, str, s);
}

void SvgWriter::add_polyline3(const std::vector<Vec3d>& pts, bool closed, const SvgStyle& s) {
  const std::size_t n = pts.size();
  if (n < 2) return;
  const std::size_t edges = closed ? n : n - 1;
  // Fast path: every vertex visible -> one polyline (keeps joins and fill).
  std::vector<Vec2d> all;
  all.reserve(n);
  bool visible = true;
  for (const auto& p : pts) {
    Vec2d q;
    if (!project(p, q)) {
      visible = false;
      break;
    }
    all.push_back(q);
  }
  if (visible) {
    add_polyline(std::move(all), closed, s);
    return;
  }
  for (std::size_t i = 0; i < edges; ++i) add_segment3(pts[i], pts[(i + 1) % n], false, s);
}

// ---- emission ---------------------------------------------------------------------------------

namespace {

using Item = SvgWriter::Item;

// World to pixel coordinates (y flipped) under a mapping.
struct PixelMap {
  const SvgWriter::Mapping& m;
  [[nodiscard]] Vec2d operator()(const Vec2d& p) const noexcept {
    return {(p.x - m.inner_lo.x) * m.scale + m.origin_px.x,
            (m.inner_hi.y - p.y) * m.scale + m.origin_px.y};
  }
};

double marker_radius(const SvgStyle& st) noexcept {
  return nonneg_finite(st.marker_size) ? st.marker_size : 3.0;
}

// The XML declaration and the opening <svg> tag with the canvas size.
void write_document_open(std::string& out, const SvgWriter::Mapping& m) {
  Element e;
  e.raw("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"");
  e.attr("width", m.width);
  e.attr("height", m.height);
  e.raw(" viewBox=\"0 0 ");
  e.num(m.width);
  e.raw(" ");
  e.num(m.height);
  e.raw("\">\n");
  out += e.s;
}

void write_title(std::string& out, const SvgOptions& options) {
  if (options.title.empty()) return;
  out += "<title>";
  append_escaped(out, options.title);
  out += "</title>\n";
}

// A rectangle over the whole canvas in the background colour.
void write_background(std::string& out, const SvgWriter::Mapping& m, const SvgOptions& options) {
  if (options.background.empty() || options.background == "none") return;
  Element e;
  e.raw("<rect x=\"0\" y=\"0\"");
  e.attr("width", m.width);
  e.attr("height", m.height);
  e.attr("fill", options.background);
  e.raw("/>\n");
  if (e.ok) out += e.s;
}

// A point as its marker (circle, square, triangle or cross) of radius marker_size.
void write_point_marker(Element& e, const Item& it, const PixelMap& px) {
  const SvgStyle& st = it.style;
  const Vec2d p = px(it.pts[0][0]);
  const double r = marker_radius(st);
  switch (st.marker) {
    case SvgMarker::circle:
      e.raw("<circle");
      e.attr("cx", p.x);
      e.attr("cy", p.y);
      e.attr("r", r);
      style_attrs(e, st, solid_colour(st));
      break;
    case SvgMarker::square:
      e.raw("<rect");
      e.attr("x", p.x - r);
      e.attr("y", p.y - r);
      e.attr("width", 2 * r);
      e.attr("height", 2 * r);
      style_attrs(e, st, solid_colour(st));
      break;
    case SvgMarker::triangle:
      e.raw("<polygon points=\"");
      e.pt({p.x, p.y - 1.3 * r});
      e.raw(" ");
      e.pt({p.x - 1.15 * r, p.y + 0.7 * r});
      e.raw(" ");
      e.pt({p.x + 1.15 * r, p.y + 0.7 * r});
      e.raw("\"");
      style_attrs(e, st, solid_colour(st));
      break;
    case SvgMarker::cross:
      e.raw("<path d=\"M");
      e.pt({p.x - r, p.y - r});
      e.raw(" L");
      e.pt({p.x + r, p.y + r});
      e.raw(" M");
      e.pt({p.x - r, p.y + r});
      e.raw(" L");
      e.pt({p.x + r, p.y - r});
      e.raw("\"");
      style_attrs(e, st, "none");
      break;
  }
  e.raw("/>\n");
}

// A segment as a <line>; a line or ray (stored as origin, direction) clipped to the view first,
// and nothing when it misses the view.
void write_segment_line_or_ray(Element& e, const Item& it, const SvgWriter::Mapping& m,
                               const PixelMap& px) {
  Vec2d a = it.pts[0][0], b = it.pts[0][1];
  if (it.kind != Item::Kind::segment) {
    const Vec2d p = a, d = b;
    double t0 = it.kind == Item::Kind::ray ? 0.0 : -std::numeric_limits<double>::infinity();
    double t1 = std::numeric_limits<double>::infinity();
    if (!clip_param(p, d, m.lo, m.hi, t0, t1) || !is_finite(t0) || !is_finite(t1)) return;
    a = p + t0 * d;
    b = p + t1 * d;
  }
  const Vec2d pa = px(a), pb = px(b);
  e.raw("<line");
  e.attr("x1", pa.x);
  e.attr("y1", pa.y);
  e.attr("x2", pb.x);
  e.attr("y2", pb.y);
  style_attrs(e, it.style, "none");
  e.raw("/>\n");
}

// An arrow as a group of its shaft (<line>) and head (<polygon>); a zero vector as a dot.
void write_arrow(Element& e, const Item& it, const PixelMap& px) {
  const SvgStyle& st = it.style;
  const Vec2d pa = px(it.pts[0][0]), pb = px(it.pts[0][1]);
  const Vec2d d = pb - pa;
  const double len = length(d);
  const std::string_view colour = st.stroke.empty() || st.stroke == "none"
                                      ? std::string_view("black")
                                      : std::string_view(st.stroke);
  if (!(len > 0.0) || !is_finite(len)) {
    e.raw("<circle");
    e.attr("cx", pa.x);
    e.attr("cy", pa.y);
    e.attr("r", marker_radius(st));
    style_attrs(e, st, colour, false);
    e.raw("/>\n");
    return;
  }
  const Vec2d u = d / len, v = perp(u);
  const double head = std::min(len, 3.0 * marker_radius(st));
  const Vec2d base = pb - head * u;
  e.raw("<g>");
  if (len > head) {
    e.raw("<line");
    e.attr("x1", pa.x);
    e.attr("y1", pa.y);
    e.attr("x2", base.x);
    e.attr("y2", base.y);
    style_attrs(e, st, "none");
    e.raw("/>");
  }
  e.raw("<polygon points=\"");
  e.pt(pb);
  e.raw(" ");
  e.pt(base + 0.4 * head * v);
  e.raw(" ");
  e.pt(base - 0.4 * head * v);
  e.raw("\"");
  SvgStyle hs = st;
  hs.fill_opacity = st.opacity;
  style_attrs(e, hs, colour, false);
  e.raw("/></g>\n");
}

// A polyline as one <polyline> (or <polygon> when closed) per finite run, each dropped alone
// when it holds a non-finite number.
void write_polyline_runs(std::string& out, const Item& it, const PixelMap& px) {
  const SvgStyle& st = it.style;
  for (const auto& run : it.pts) {
    Element r;
    r.raw(it.closed ? "<polygon points=\"" : "<polyline points=\"");
    for (std::size_t i = 0; i < run.size(); ++i) {
      if (i) r.raw(" ");
      r.pt(px(run[i]));
    }
    r.raw("\"");
    style_attrs(r, st, it.closed ? std::string_view(st.fill) : std::string_view("none"));
    r.raw("/>\n");
    if (r.ok) out += r.s;
  }
}

// A polygon with holes as one <path> of closed rings under the even-odd rule.
void write_polygon_path(Element& e, const Item& it, const PixelMap& px) {
  e.raw("<path d=\"");
  for (std::size_t k = 0; k < it.pts.size(); ++k) {
    const auto& ring = it.pts[k];
    if (k) e.raw(" ");
    for (std::size_t i = 0; i < ring.size(); ++i) {
      e.raw(i ? " L" : "M");
      e.pt(px(ring[i]));
    }
    e.raw(" Z");
  }
  e.raw("\" fill-rule=\"evenodd\"");
  style_attrs(e, it.style, it.style.fill);
  e.raw("/>\n");
}

void write_circle(Element& e, const Item& it, const SvgWriter::Mapping& m, const PixelMap& px) {
  const Vec2d c = px(it.pts[0][0]);
  e.raw("<circle");
  e.attr("cx", c.x);
  e.attr("cy", c.y);
  e.attr("r", it.a * m.scale);
  style_attrs(e, it.style, it.style.fill);
  e.raw("/>\n");
}

// An ellipse as an axis-aligned <ellipse> rotated about its centre to its first axis.
void write_ellipse(Element& e, const Item& it, const SvgWriter::Mapping& m, const PixelMap& px) {
  const Vec2d c = px(it.pts[0][0]), u = it.pts[0][1];
  // The y flip turns a counter-clockwise world angle into a clockwise pixel angle.
  const double deg = -std::atan2(u.y, u.x) * (180.0 / kPi);
  e.raw("<ellipse");
  e.attr("cx", c.x);
  e.attr("cy", c.y);
  e.attr("rx", it.a * m.scale);
  e.attr("ry", it.b * m.scale);
  e.raw(" transform=\"rotate(");
  e.num(deg);
  e.raw(" ");
  e.num(c.x);
  e.raw(" ");
  e.num(c.y);
  e.raw(")\"");
  style_attrs(e, it.style, it.style.fill);
  e.raw("/>\n");
}

// A circular arc as a <path> of elliptical-arc commands (two half turns for a full circle).
void write_arc_path(Element& e, const Item& it, const SvgWriter::Mapping& m, const PixelMap& px) {
  const Vec2d c = it.pts[0][0];
  const double r = it.a, a0 = it.b, span = it.c;
  const double rp = r * m.scale;
  auto at = [&](double t) { return px(c + r * Vec2d{std::cos(t), std::sin(t)}); };
  e.raw("<path d=\"M");
  e.pt(at(a0));
  // Counter-clockwise in the world is sweep-flag 0 after the y flip.
  if (span >= kTwoPi) {
    for (int h = 1; h <= 2; ++h) {
      e.raw(" A");
      e.num(rp);
      e.raw(",");
      e.num(rp);
      e.raw(" 0 0 0 ");
      e.pt(at(a0 + h * kPi));
    }
  } else {
    e.raw(" A");
    e.num(rp);
    e.raw(",");
    e.num(rp);
    e.raw(span > kPi ? " 0 1 0 " : " 0 0 0 ");
    e.pt(at(a0 + span));
  }
  e.raw("\"");
  style_attrs(e, it.style, it.style.fill);
  e.raw("/>\n");
}

// A label as a <text> offset by (text_dx, text_dy) pixels, y up.
void write_text(Element& e, const Item& it, const PixelMap& px) {
  const SvgStyle& st = it.style;
  const Vec2d p = px(it.pts[0][0]);
  const double dx = is_finite(st.text_dx) ? st.text_dx : 0.0;
  const double dy = is_finite(st.text_dy) ? st.text_dy : 0.0;
  e.raw("<text");
  e.attr("x", p.x + dx);
  e.attr("y", p.y - dy);
  e.attr("font-size", nonneg_finite(st.font_size) ? st.font_size : 14.0);
  e.raw(" font-family=\"serif\"");
  e.raw(st.anchor == SvgAnchor::start    ? " text-anchor=\"start\""
        : st.anchor == SvgAnchor::middle ? " text-anchor=\"middle\""
                                         : " text-anchor=\"end\"");
  style_attrs(e, st, solid_colour(st), false);
  e.raw(">");
  append_escaped(e.s, it.str);
  e.raw("</text>\n");
}

// One stored item; an element holding a non-finite number is dropped.
void write_item(std::string& out, const Item& it, const SvgWriter::Mapping& m, const PixelMap& px) {
  Element e;
  switch (it.kind) {
    case Item::Kind::point:
      write_point_marker(e, it, px);
      break;
    case Item::Kind::segment:
    case Item::Kind::line:
    case Item::Kind::ray:
      write_segment_line_or_ray(e, it, m, px);
      break;
    case Item::Kind::arrow:
      write_arrow(e, it, px);
      break;
    case Item::Kind::polyline:
      write_polyline_runs(out, it, px);
      break;
    case Item::Kind::polygon:
      write_polygon_path(e, it, px);
      break;
    case Item::Kind::circle:
      write_circle(e, it, m, px);
      break;
    case Item::Kind::ellipse:
      write_ellipse(e, it, m, px);
      break;
    case Item::Kind::arc:
      write_arc_path(e, it, m, px);
      break;
    case Item::Kind::text:
      write_text(e, it, px);
      break;
  }
  if (e.ok) out += e.s;
}

}  // namespace

std::string SvgWriter::to_string() const {
  const Mapping m = mapping();
  const PixelMap px{m};
  std::string out;
  out.reserve(512 + items_.size() * 96);
  write_document_open(out, m);
  write_title(out, options_);
  write_background(out, m, options_);
  for (const Item& it : items_) write_item(out, it, m, px);
  out += "</svg>\n";
  return out;
}

Status SvgWriter::write_file(const std::string& path) const {
  const std::string doc = to_string();
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) return Status::io_error;
  f.write(doc.data(), static_cast<std::streamsize>(doc.size()));
  f.flush();
  if (!f) return Status::io_error;
  f.close();
  return f ? Status::ok : Status::io_error;
}

}  // namespace locus
