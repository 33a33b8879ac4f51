// SPDX-License-Identifier: BSL-1.0
// Gallery, appendix A (numerical methods).
#include "gallery.hpp"

#include <vector>

namespace locus_gallery {

std::vector<Figure> appendix_a_figures() { return {}; }

}  // namespace locus_gallery
