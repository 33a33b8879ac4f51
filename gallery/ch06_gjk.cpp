// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 6 (GJK distance, 6.24-6.29).
#include "gallery.hpp"

#include <vector>

namespace locus_gallery {

std::vector<Figure> chapter6_gjk_figures() { return {}; }

}  // namespace locus_gallery
