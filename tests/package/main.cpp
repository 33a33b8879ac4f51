// The README's example, compiled and run by CI as an outside project against the installed
// package (find_package) and the vendored source (add_subdirectory). Keep the two in sync.
#include <cmath>
#include <cstdio>
#include <locus/core/predicates.hpp>
#include <locus/core/transform.hpp>

int main() {
  using namespace locus;
  Vec2d a{0, 0}, b{1, 0}, c{0.5, 1e-30};
  bool ccw = orient2d(a, b, c) == Sign::positive;  // exact, even for 1e-30
  auto r = rotation(Vec3d{1, 1, 0}, Vec3d{0, 0, 1}, pi_v<double> / 2);
  Vec3d p = apply_point(r, Vec3d{2, 1, 0});  // rotate about the axis through (1,1,0)
  std::printf("%d (%g, %g, %g)\n", ccw, p.x, p.y, p.z);
  return ccw && std::abs(p.x - 1) < 1e-12 && std::abs(p.y - 2) < 1e-12 ? 0 : 1;
}
