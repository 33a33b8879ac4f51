// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 6 (distance in 2D).
#include "gallery.hpp"

#include <vector>

namespace locus_gallery {

std::vector<Figure> chapter6_distance_figures() { return {}; }

}  // namespace locus_gallery
