// SPDX-License-Identifier: BSL-1.0
#pragma once
// The subcommands of the locus command, one registration function per family (cmd_*.cpp).
// A later area adds its family here and in main.cpp (docs/cli.md).

#include <CLI/CLI.hpp>

namespace locus_cli {

void register_hull(CLI::App& app);      // hull, hull3 (cmd_hull.cpp)
void register_delaunay(CLI::App& app);  // delaunay, delaunay3 (cmd_delaunay.cpp)
void register_polygon(CLI::App& app);   // cdt, triangulate (cmd_polygon.cpp)
void register_bounding(CLI::App& app);  // mincircle, minsphere, minrect, minbox (cmd_bounding.cpp)
void register_distance(CLI::App& app);  // distance (cmd_distance.cpp)
void register_numeric(CLI::App& app);   // roots, fit (cmd_numeric.cpp)
void register_mesh(CLI::App& app);      // mesh info|check|orient|generate|convert (cmd_mesh.cpp)
void register_mesh_slice(CLI::App& mesh);    // mesh slice (cmd_mesh_slice.cpp)
void register_mesh_boolean(CLI::App& mesh);  // mesh boolean (cmd_mesh_boolean.cpp)
void register_raycast(CLI::App& app);        // raycast (cmd_raycast.cpp)
void register_sat(CLI::App& app);            // sat (cmd_sat.cpp)
void register_sat3(CLI::App& app);           // sat3 (cmd_sat3.cpp)
void register_construct(CLI::App& app);      // construct <kind> (cmd_construct.cpp)
void register_surfacehit(CLI::App& app);     // surfacehit (cmd_surfacehit.cpp)
void register_partition(CLI::App& app);      // partition (cmd_partition.cpp)
void register_bsp(CLI::App& app);            // bsp classify|boolean (cmd_bsp.cpp)
void register_curvehit(CLI::App& app);       // curvehit (cmd_curvehit.cpp)
void register_boolean(CLI::App& app);        // boolean (cmd_boolean.cpp)
void register_offset(CLI::App& app);         // offset (cmd_offset.cpp)

}  // namespace locus_cli
