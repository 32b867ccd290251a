// Fresnel equations for dielectrics and conductors, and Snell's law.
#pragma once
#include <complex>

#include "base/fresnel_dielectric.h"
#include "base/sampled_spectrum.h"
#include "base/vec.h"

namespace objektiv {

// FresnelDielectric(cos_i, eta): base/fresnel_dielectric.h.

// Fresnel reflectance of a conductor with complex relative index eta + i k.
float FresnelComplex(float cos_i, std::complex<float> eta);
SampledSpectrum FresnelComplex(float cos_i, const SampledSpectrum& eta, const SampledSpectrum& k);

// Refract wi (pointing away from the surface) about n (same side as wi) with relative index
// eta = n_t / n_i. Returns false at total internal reflection; *etap is the eta used.
bool Refract(const Vec3f& wi, Vec3f n, float eta, float* etap, Vec3f* wt);

// Hemispherical-cosine average of FresnelDielectric: 2 * integral of F(mu) mu dmu.
float FresnelDiffuseReflectance(float eta);

}  // namespace objektiv
