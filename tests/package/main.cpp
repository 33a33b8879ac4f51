// Consumer smoke test: compiles against the installed (or vendored) locus and calls into both
// the header part and the compiled part of the library.
#include <locus/core/mat.hpp>
#include <locus/core/vec.hpp>
#if __has_include(<locus/core/predicates.hpp>)
#include <locus/core/predicates.hpp>
#endif

#include <cstdio>

int main() {
  using namespace locus;
  const Vec3d n = cross(Vec3d{1, 0, 0}, Vec3d{0, 1, 0});
  const auto inv = inverse(Mat3d::identity() * 2.0);
  int ok = n == Vec3d{0, 0, 1} && inv && (*inv)(1, 1) == 0.5;
#if __has_include(<locus/core/predicates.hpp>)
  ok = ok && orient2d(Vec2d{0, 0}, Vec2d{1, 0}, Vec2d{0, 1}) == Sign::positive;
#endif
  set_assert_handler(nullptr);
  std::printf("consumer: %s\n", ok ? "ok" : "FAILED");
  return ok ? 0 : 1;
}
