// SPDX-License-Identifier: BSL-1.0
// Replays the fuzz targets' property (tests/fuzz/mesh_fuzz.hpp) on every committed input: the
// seed corpus (tests/fuzz/corpus/<format>/, valid files that must read ok) and the inputs that
// once broke a reader (tests/fuzz/regressions/<format>/, any status). So the GCC build checks
// what the clang-only fuzz step found.

#include "fuzz/mesh_fuzz.hpp"
#include "support/files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

using locus_test::slurp;

TEST(MeshFuzzCorpus, EveryCommittedInputKeepsTheReaderProperty) {
  const std::filesystem::path root = std::filesystem::path(LOCUS_SOURCE_DIR) / "tests" / "fuzz";
  const std::pair<const char*, locus::MeshFormat> formats[] = {{"obj", locus::MeshFormat::obj},
                                                               {"off", locus::MeshFormat::off},
                                                               {"ply", locus::MeshFormat::ply},
                                                               {"stl", locus::MeshFormat::stl}};
  int seeds = 0;
  for (const auto& [name, format] : formats) {
    for (const char* kind : {"corpus", "regressions"}) {
      const auto dir = root / kind / name;
      if (!std::filesystem::is_directory(dir)) continue;
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        SCOPED_TRACE(entry.path().string());
        const std::string bytes = slurp(entry.path());
        EXPECT_EQ(locus_fuzz::check_both(
                      format, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
                  "");
        if (std::string(kind) == "corpus") {
          ++seeds;
          const auto r = locus::parse_mesh<double>(bytes, format, entry.path().string());
          EXPECT_EQ(r.status, locus::Status::ok) << r.message;
          EXPECT_GT(locus::face_count(r.mesh), 0u);
        }
      }
    }
  }
  EXPECT_GE(seeds, 16);
}

}  // namespace
