// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 10 (distance in 3D).
#include "gallery.hpp"

#include <vector>

namespace locus_gallery {

std::vector<Figure> chapter10_distance_figures() { return {}; }

}  // namespace locus_gallery
