// Writes the procedural sky used by scenes/still-life: a latitude-longitude HDR image in
// Mitsuba's envmap convention (row 0 = straight up), with a blue gradient sky, a warm sun
// disc, a grey ground and two soft rectangular "windows" that make reflections readable.
// Usage: make_sky OUTPUT.exr [WIDTH]
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/error.h"
#include "io/image_io.h"

using namespace objektiv;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_sky OUTPUT.exr [WIDTH]\n");
    return 2;
  }
  int w = argc > 2 ? std::atoi(argv[2]) : 256, h = w / 2;
  Image img(w, h, {"R", "G", "B"});
  const Vec3f sun_dir = Normalize(Vec3f(0.5f, 0.55f, -0.45f));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float theta = kPi * (y + 0.5f) / h, phi = 2 * kPi * (x + 0.5f) / w;
      Vec3f d(std::sin(phi) * std::sin(theta), std::cos(theta), -std::cos(phi) * std::sin(theta));
      Vec3f c;
      if (d.y > 0) {
        float t = std::pow(1 - d.y, 3.f);
        c = Vec3f(0.25f, 0.45f, 0.9f) * (1 - t) + Vec3f(0.85f, 0.9f, 1.f) * t;
      } else {
        c = Vec3f(0.18f, 0.16f, 0.14f) * (1 + d.y * 0.5f);
      }
      float cs = Dot(d, sun_dir);
      if (cs > std::cos(Radians(2.5f))) c = Vec3f(400, 330, 250);
      else c += Vec3f(1.0f, 0.8f, 0.6f) * (2.f * std::pow(std::max(0.f, cs), 64.f));
      // Two bright panels low on the horizon, opposite the sun.
      float az = std::atan2(d.x, -d.z);
      if (d.y > 0.05f && d.y < 0.45f && std::abs(az - 2.4f) < 0.25f) c = Vec3f(6, 6, 6);
      if (d.y > 0.1f && d.y < 0.35f && std::abs(az + 2.6f) < 0.15f) c = Vec3f(2, 3.5f, 6);
      for (int k = 0; k < 3; ++k) img.At(x, y, k) = c[k];
    }
  try {
    WriteExr(argv[1], img);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
