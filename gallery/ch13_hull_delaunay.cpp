// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 13 (hulls, Delaunay, bounding shapes, containment).
#include "gallery.hpp"

#include <vector>

namespace locus_gallery {

std::vector<Figure> chapter13_figures() { return {}; }

}  // namespace locus_gallery
