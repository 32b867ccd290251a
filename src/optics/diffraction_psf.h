// The diffraction pattern of the aperture stop: the Fraunhofer point-spread function a lens
// forms of a distant point, from the shape of its opening alone (the pupil without
// aberrations: the lens's rays give those).
//
// In the Fraunhofer approximation the image of a point is the squared modulus of the Fourier
// transform of the pupil function P (the stop's amplitude transmittance), at spatial
// frequency x / (lambda z) for a film point x and an exit pupil z from the film:
//     PSF(x) = |F[P](x / (lambda z))|^2 / (lambda^2 z^2 A),    A = integral of |P|^2,
// which integrates to 1 over the film (A: the light the stop passes). Writing the pupil in units of its radius (diameter D,
// working f-number N = z / D), the pattern scales with lambda N: a round stop gives the Airy
// pattern, its first dark ring at 1.22 lambda N and its peak pi / (4 lambda^2 N^2); an iris
// of n straight blades sends a spike perpendicular to each edge: n spikes for even n (opposite
// edges share a line), 2n for odd n.
//
// Computed by an FFT (FFTW) of the pupil sampled on a square grid, each sample the mean of 4 x
// 4 points in its cell (edges anti-aliased), padded so that the grid's frequency step is the
// film pitch asked for (a finer step where the pitch is coarser than the pattern's Nyquist
// rate); each pixel then gets the light over its whole area (the pattern filtered by the
// pixel's box, through a second FFT), not the value at its centre.
#pragma once
#include <functional>
#include <vector>

namespace objektiv {

// Transmittance (of the light) in [0, 1] at (u, v) in units of the stop's radius.
using PupilFunction = std::function<double(double u, double v)>;

struct PsfImage {
  int size = 0;         // pixels per side, the axis at the centre of pixel (size / 2, size / 2)
  double pitch_um = 0;  // film distance between pixel centres
  // Per pixel, row-major: the fraction of the light that falls in it (the whole pattern,
  // including what falls outside the image, sums to 1; the grid holds all but the far tails of
  // the edges' diffraction, half a percent for a round stop).
  std::vector<double> energy;
  double At(int x, int y) const { return energy[size_t(y) * size + x]; }
};

// The pattern of `pupil` at `lambda_nm` for working f-number `fnumber` on a size x size grid
// of pitch `pitch_um`. Throws std::invalid_argument for sizes or scales it cannot sample.
PsfImage FraunhoferPsf(const PupilFunction& pupil, double lambda_nm, double fnumber, double pitch_um, int size);

// The pattern point-sampled on an n x n grid (n a power of two, at least 256) of spacing
// `step_um`, the axis at index (0, 0) (indices wrap: -1 is n - 1), as the fraction of the
// light per sample (summing to 1 over the grid). Unaliased where the pupil spans at most half
// the grid: step_um <= lambda N / 2.
std::vector<double> SampledPattern(const PupilFunction& pupil, double lambda_um, double fnumber, double step_um, int n);

// The radius (um) of the first minimum of the pattern's azimuthal mean about the axis (from
// point samples 1/16 lambda N apart): for a round stop its first dark ring, 1.22 lambda N.
// NaN if there is none within 4 lambda N.
double FirstDarkRingUm(const PupilFunction& pupil, double lambda_nm, double fnumber);

}  // namespace objektiv
