// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the CSV and XYZ point-list reader (property in csv_fuzz.hpp). Built by
// tests/fuzz/CMakeLists.txt.

#include "csv_fuzz.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string e = locus_fuzz::check_point_lists(data, size);
  if (!e.empty()) {
    std::fprintf(stderr, "point-list reader property broken: %s\n", e.c_str());
    std::abort();
  }
  return 0;
}
