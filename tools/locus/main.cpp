// SPDX-License-Identifier: BSL-1.0
// The locus command: geometric algorithms on files from the shell (docs/cli.md).
// Exit codes: 0 success; 1 bad input (one line on stderr: file, line, reason); 2 usage error.

#include "commands.hpp"
#include "io.hpp"

#include <locus/config.hpp>

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  CLI::App app("locus: geometric algorithms on point, polygon and mesh files", "locus");
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 bad input (one line on stderr naming the file, line and reason),\n"
      "2 usage error. `locus <command> --help` shows a command's options and an example.\n"
      "Example:\n"
      "  locus hull points.csv --svg hull.svg");
  app.set_version_flag("--version", "locus " + std::to_string(LOCUS_VERSION_MAJOR) + "." +
                                        std::to_string(LOCUS_VERSION_MINOR) + "." +
                                        std::to_string(LOCUS_VERSION_PATCH));
  locus_cli::register_hull(app);
  locus_cli::register_delaunay(app);
  locus_cli::register_polygon(app);
  locus_cli::register_bounding(app);
  locus_cli::register_distance(app);
  locus_cli::register_numeric(app);
  locus_cli::register_mesh(app);
  locus_cli::register_raycast(app);
  locus_cli::register_sat(app);
  locus_cli::register_sat3(app);
  locus_cli::register_construct(app);
  locus_cli::register_surfacehit(app);
  locus_cli::register_partition(app);
  locus_cli::register_bsp(app);
  locus_cli::register_curvehit(app);
  locus_cli::register_boolean(app);
  locus_cli::register_offset(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const locus_cli::UsageError& e) {
    std::cerr << "locus: " << e.what() << '\n';
    return 2;
  } catch (const locus_cli::InputError& e) {
    std::cerr << "locus: " << e.what() << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "locus: out of memory\n";
    return 1;
  }
  return 0;
}
