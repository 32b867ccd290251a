#include "io/lens_psf.h"

#include "io/white_light.h"

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
  return WhiteLightImage(size, size, 10, [&](double l) { return FraunhoferPsf(pupil, l, fnumber, pitch_um, size).energy; });
}

}  // namespace objektiv
