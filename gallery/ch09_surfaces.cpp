// SPDX-License-Identifier: BSL-1.0
// Gallery, chapter 9 (polynomial surfaces, 9.22-9.26).
#include "gallery.hpp"

#include <vector>

namespace locus_gallery {

std::vector<Figure> chapter9_surface_figures() { return {}; }

}  // namespace locus_gallery
