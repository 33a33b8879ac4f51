// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the GeoJSON reader (property in geo_fuzz.hpp). Built by
// tests/fuzz/CMakeLists.txt.

#include "geo_fuzz.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string e = locus_fuzz::check_geo(false, data, size);
  if (!e.empty()) {
    std::fprintf(stderr, "geojson reader property broken: %s\n", e.c_str());
    std::abort();
  }
  return 0;
}
