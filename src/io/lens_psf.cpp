#include "io/lens_psf.h"

#include "base/cie.h"
#include "base/color_space.h"

namespace objektiv {

Image DiffractionImage(const PupilFunction& pupil, double fnumber, std::optional<double> lambda_nm, double pitch_um,
                       int size) {
  Image image(size, size, {"R", "G", "B"});
  if (lambda_nm) {
    const PsfImage psf = FraunhoferPsf(pupil, *lambda_nm, fnumber, pitch_um, size);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        for (int c = 0; c < 3; ++c) image.At(x, y, c) = float(psf.At(x, y));
    return image;
  }
  // White light: XYZ = sum over wavelengths of D65 x the colour matching functions x the
  // pattern, normalised so that the total Y is 1; then RGB.
  std::vector<Vec3f> xyz(size_t(size) * size, Vec3f(0.f));
  double total_y = 0;
  for (double l = 400; l <= 700; l += 10) {
    const Vec3f weight = CieXyz(float(l)) * D65Normalized(float(l));
    total_y += weight.y;
    const PsfImage psf = FraunhoferPsf(pupil, l, fnumber, pitch_um, size);
    for (size_t i = 0; i < xyz.size(); ++i) xyz[i] += weight * float(psf.energy[i]);
  }
  const ColorSpace& rec709 = ColorSpace::Rec709();
  // The white point's RGB is (1, 1, 1) for Y = 1 of D65 light.
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Vec3f rgb = rec709.ToRGB(xyz[size_t(y) * size + x] / float(total_y));
      for (int c = 0; c < 3; ++c) image.At(x, y, c) = rgb[c];
    }
  return image;
}

}  // namespace objektiv
