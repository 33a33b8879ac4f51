// SPDX-License-Identifier: BSL-1.0
// locus cdt, locus triangulate: polygon input (WKT, GeoJSON) is not readable yet; the
// subcommands are registered when the readers land.

#include "commands.hpp"

namespace locus_cli {

void register_polygon(CLI::App&) {}

}  // namespace locus_cli
