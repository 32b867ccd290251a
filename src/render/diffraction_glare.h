// The stop's diffraction applied to a rendered image: every pixel's light spread by the
// Fraunhofer pattern of the opening (optics/diffraction_psf.h), per wavelength, at the lens's
// working f-number: the starbursts of bright points.
//
// The kernel: a pattern scales with lambda N (intensity with 1 / (lambda N)^2), so the pattern
// is computed once, finely sampled, at the longest wavelength (780 nm), and each fine sample's
// light is moved to lambda / 780 of its distance from the axis and dropped into the pixel it
// lands in, for wavelengths evenly spread over 380..780 nm, weighted by the CIE matching
// functions: a kernel per X, Y and Z (each summing to 1) for light of even spectrum. A pixel's
// spectrum is not known (the film keeps XYZ), so coloured light is spread as white light of its
// X, Y and Z would be: exact for grey light, close for the broad spectra of lamps and the sun.
// Its reach: the fine FFT covers at most 4096 samples per side, 1024 lambda N across at 780
// nm, and the shortest wavelength's copy half as much: the kernel reaches as far as all
// wavelengths do (at f/8: about 3 mm of film, 110 pixels of 28 um either side; twice as far
// at f/16), faded out over its outer quarter alike for every wavelength, round; the light
// beyond (the far tails, about 1% at f/8 on 28 um pixels) is left in the kernel's sum (each
// channel renormalised to 1), so the spikes of a very bright light end there.
//
// Convolution: by FFT over the image padded by the kernel's radius (light from outside the
// image is not known and does not come in; light spread past its edges leaves).
#pragma once
#include <vector>

#include "optics/diffraction_psf.h"

namespace objektiv {

struct DiffractionKernel {
  int radius = 0;           // pixels: the kernel is (2 radius + 1)^2, the axis at its centre
  std::vector<float> xyz;   // interleaved X, Y, Z weights, each channel summing to 1
  int Size() const { return 2 * radius + 1; }
};

// `pitch_um`: the film pixel's width and height; `max_radius`: pixels (the reach is also
// bounded as said above).
DiffractionKernel MakeDiffractionKernel(const PupilFunction& pupil, double fnumber, double pitch_x_um,
                                        double pitch_y_um, int max_radius, int wavelengths = 16);

// `xyz` (width x height, interleaved) convolved with the kernel, in place.
void ApplyDiffraction(std::vector<float>& xyz, int width, int height, const DiffractionKernel& kernel);

}  // namespace objektiv
