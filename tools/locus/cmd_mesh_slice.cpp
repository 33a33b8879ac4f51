// SPDX-License-Identifier: BSL-1.0
// `locus mesh slice`: the cross-section of a mesh file by a plane, as polylines (closed loops,
// open chains for open meshes), from locus::slice_mesh (intersection/plane_mesh.hpp).

#include "commands.hpp"
#include "io.hpp"

#include <locus/core/status.hpp>
#include <locus/intersection/plane_mesh.hpp>
#include <locus/primitives/plane.hpp>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace locus_cli {

namespace {

struct SliceOptions {
  Common common;
  std::string plane;  // --plane a,b,c,d: the plane a x + b y + c z + d = 0
};

locus::Plane3<double> parse_plane(const std::string& s) {
  std::vector<double> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size()) throw UsageError("--plane: not a number: " + item);
    } catch (const std::logic_error&) {
      throw UsageError("--plane: not a number: " + item);
    }
  }
  if (v.size() != 4) throw UsageError("--plane expects four numbers a,b,c,d");
  return {{v[0], v[1], v[2]}, -v[3]};
}

void run_slice(const SliceOptions& o) {
  const Common& c = o.common;
  const locus::Plane3<double> pl = parse_plane(o.plane);
  const locus::PolygonMesh<double> m = load_mesh(c.input, c.format);
  const locus::MeshSlice<double> s = locus::slice_mesh(
      std::span<const Vec3d>(m.vertices), std::span<const std::uint32_t>(m.face_offsets),
      std::span<const std::uint32_t>(m.face_indices), pl);
  if (s.status != locus::Status::ok && s.status != locus::Status::empty_input) {
    throw InputError(c.input + ": mesh slice: " + std::string(locus::to_string(s.status)));
  }
  std::string text, lines = "[";
  std::size_t closed = 0;
  for (std::size_t i = 0; i < s.polylines.size(); ++i) {
    const auto& p = s.polylines[i];
    closed += p.closed;
    text += std::string(p.closed ? "closed " : "open ") + std::to_string(p.vertices.size()) + '\n';
    std::string pts = "[";
    for (std::size_t k = 0; k < p.vertices.size(); ++k) {
      const Vec3d& v = p.vertices[k];
      text += num(v.x) + ' ' + num(v.y) + ' ' + num(v.z) + '\n';
      pts += (k ? "," : "") + json_vec<3>(v);
    }
    lines += std::string(i ? "," : "") + "{\"closed\":" + (p.closed ? "true" : "false") +
             ",\"points\":" + pts + "]}";
  }
  JsonObject j;
  j.str("command", "mesh slice")
      .str("status", locus::to_string(s.status))
      .integer("polylines", static_cast<std::int64_t>(s.polylines.size()))
      .integer("closed", static_cast<std::int64_t>(closed))
      .raw("slice", lines + "]");
  emit(c, text, j);
  if (!c.svg.empty()) {
    // Drawn in the plane's own coordinates (primitives/plane.hpp plane_frame).
    const auto frame = locus::plane_frame(pl);
    locus::SvgWriter svg;
    for (const auto& p : s.polylines) {
      std::vector<Vec2d> q;
      for (const Vec3d& v : p.vertices) q.push_back(locus::to_plane(*frame, v));
      svg.polyline(q, result_style(), p.closed);
    }
    save_svg(c, svg);
  }
}

}  // namespace

void register_mesh_slice(CLI::App& mesh) {
  auto o = std::make_shared<SliceOptions>();
  CLI::App* sub = mesh.add_subcommand("slice", "cross-section of a mesh by a plane (book 11.5)");
  add_common(sub, o->common, true, "a mesh (.obj .off .ply .stl)");
  sub->add_option("--plane", o->plane, "the plane a x + b y + c z + d = 0 as a,b,c,d")->required();
  sub->footer(
      "Prints each polyline as 'closed N' or 'open N' and its N points (x y z); --json gives\n"
      "them as arrays, --svg draws them in the plane's coordinates. A vertex on the plane counts\n"
      "as on the positive side, so every loop of a closed mesh closes.\n"
      "Example:\n  locus mesh slice --plane 0,0,1,-0.5 bunny.obj --json");
  sub->callback([o] { run_slice(*o); });
}

}  // namespace locus_cli
