// SPDX-License-Identifier: BSL-1.0
#pragma once
// Runs the locus command (LOCUS_CLI_PATH, set by tests/CMakeLists.txt for the CLI tests) with
// its output and error streams captured in files of a test's scratch directory.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/files.hpp"

#ifndef LOCUS_CLI_PATH
#error "LOCUS_CLI_PATH (the locus tool) is not defined"
#endif

namespace locus_test {

/// The exit code and the two captured streams of one run.
struct CliRun {
  int code = -1;
  std::string out, err;
};

/// `locus <args>` (args as a shell fragment), run in no particular directory; dir holds the
/// captured streams.
inline CliRun run_locus(const std::filesystem::path& dir, const std::string& args) {
  const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
  const std::string cmd =
      std::string("'") + LOCUS_CLI_PATH + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int s = std::system(cmd.c_str());
  return {WIFEXITED(s) ? WEXITSTATUS(s) : -1, slurp(out), slurp(err)};
}

}  // namespace locus_test
