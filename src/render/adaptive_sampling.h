// Adaptive sampling: how many camera samples each pixel takes (Sampler::adaptive()).
//
// Statistical (every integrator): each pixel takes `min_samples` (the pilot), then more in
// batches, until the estimated relative standard error of its mean luminance,
//   e = sqrt(variance / n) / max(|mean|, floor),
// (n its samples, mean and variance those of one sample's luminance, from the film's sums as
// for --noise-target) is at most `threshold`, or it has the render's sample count (the cap).
// The rule looks only at fixed counts, min, then each count plus a quarter of it (16, 20, 25,
// 32, 40, 50, 63, ...), so a pixel overshoots what it needs by at most a quarter, and where it
// stops is a function of its own samples alone: the same on any thread count, whatever passes
// (--time-limit, --noise-target) or checkpoints (--resume) the samples came in. A pixel is done
// when it reaches the cap or stands at a look with e <= threshold; a resumed render reads that
// off the film's sums (no flag is stored).
//
// A pixel whose samples all agree (all black: no path of the pilot found light) has no
// variance to judge by, which does not mean it has none: on a face lit only by light that a
// sixth of the paths find, one pixel in 14 misses it in 16 samples and stopped there as a black
// dot. Such a pixel is judged only from kAgreeingSamplesFactor x min_samples on (64 for the
// pilot of 16: a light found by a sixth of the paths is then missed once in 10^5 pixels).
//
// Bias: the stopping rule reads the samples it then averages, so the estimate is biased: a
// pixel whose samples happened to agree stops early, and in a pixel whose light comes in rare
// bright samples (a caustic, a small light seen through glass) the pilot that missed them looks
// converged and stops low. The bias is of the order of the standard error at the stop, i.e.
// about threshold x the pixel's value or less, and it vanishes as threshold -> 0 (or the pilot
// grows); tests/test_adaptive_sampling.cpp measures it against a fixed-rate image. Where that
// matters (references, caustics), render at a fixed rate.
//
// Whitted (classic adaptive supersampling, Whitted 1980; the contrast of Mitchell 1987): per
// pixel, the four corners and the centre; where their luminances' contrast
// (max - min) / (max + min + floor) exceeds `threshold`, each quadrant is sampled at its
// corners and centre (sharing the corners already taken), down to `max_depth` levels. Each
// leaf square weighs its centre 1/2 and its corners 1/8 each, times its area, so the pixel is
// the area-weighted mean of its leaves. The samples of a pixel share one wavelength sample
// (otherwise a coloured surface's spectral noise would look like an edge). Deterministic and
// biased (the placement depends on the values, and a pixel whose corners miss a small object
// never subdivides): meant for the `whitted` integrator, whose image is noise-free; with a
// Monte Carlo integrator its noise trips the contrast everywhere. A pixel takes 5 to
// (2^(depth+1) + 1)^2 samples in one go: it cannot come in sample ranges or passes.
//
// Light paths (ptracer, the path tracer's caustics) are traced one per camera sample taken, so
// they follow where the camera samples went; the film divides the splats by the mean sample
// count, which stays exact since each light path is independent of the stopping decision. The
// rule does not see the splats' noise. The lens's glare tracer traces its own number of paths.
#pragma once
#include <cstdint>

#include "render/film.h"
#include "render/sampler.h"

namespace objektiv {

// How many pilots' worth of samples a pixel whose samples all agree takes before it is judged.
inline constexpr int kAgreeingSamplesFactor = 4;
// The counts at which the statistical rule looks: the first above `count`.
int NextAdaptiveCheck(const AdaptiveSettings& a, int count);
bool IsAdaptiveCheck(const AdaptiveSettings& a, int count);
// e of a pixel (infinite with fewer than 2 samples).
double PixelRelativeError(const Film::LuminanceMoments& m, double floor);
// Whether the pixel needs no more samples (statistical: at the cap `spp` or converged at a look).
bool PixelSamplingDone(const Film& film, Vec2i pixel, const Sampler& sampler, int spp);
// The pixels of the crop that need no more samples up to sample `end` (without adaptive
// sampling: those with every sample up to end).
uint64_t PixelsDone(const Film& film, const Sampler& sampler, int end);
// The whitted mode's most samples per pixel: (2^max_depth + 1)^2 + 4^max_depth (5, 13, 41, 145, 545).
int WhittedMaxSamples(int max_depth);

}  // namespace objektiv
