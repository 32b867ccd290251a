// Bump and normal mapping: materials that shade the material they wrap with a perturbed
// shading frame (Mitsuba 3's `bumpmap` and `normalmap`), and the frames' math.
#pragma once
#include <memory>

#include "scene/material.h"

namespace objektiv {

// The shading frame of the surface displaced along its shading normal n by a height field h
// whose gradient is dh = (dh/du, dh/dv) (pbrt's and Mitsuba's bump mapping, without the
// normal's own change, which Mitsuba also leaves out): the displaced surface has the partial
// derivatives dpdu' = dpdu_t + n dh/du, dpdv' = dpdv_t + n dh/dv (dpdu_t: dpdu less its part
// along n), and the normal dpdu' x dpdv', on n's side. A zero gradient returns si.shading.
Frame BumpedFrame(const SurfaceInteraction& si, Vec2f dh);

// The shading frame whose normal is `local` (x along the shading frame's s, y along t, z
// along n; need not be unit) in si's shading frame: a tangent-space normal map's value.
// A zero or non-finite `local` returns si.shading.
Frame NormalMappedFrame(const SurfaceInteraction& si, Vec3f local);

// A perturbed normal ns that points away from the viewer wo leaves black patches (an opaque
// BSDF scatters nothing toward its back). Following Keller et al. ("The Iray light transport
// simulation and rendering system", 2017, "bump maps and shading normals"), ns is bent just
// enough that wo's mirror image about it stays above the geometric surface (ng): at the
// elevation min(0.01, |wo.ng|) at least. Unperturbed flat shading (ns = ng) is never bent.
// ns is on ng's side; the result is too; wo may lie on either side.
Vec3f AdaptShadingNormal(const Vec3f& ns, const Vec3f& ng, const Vec3f& wo);

// The common part of the two wrappers: the wrapped material shades with Perturb's frame,
// adapted to the viewer, and with light kept from leaking (BSDF::RequireSameSide).
class PerturbedNormalMaterial : public Material {
 public:
  explicit PerturbedNormalMaterial(std::shared_ptr<Material> inner) : inner_(std::move(inner)) {}
  BSDF GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const override;
  Frame ShadingFrame(const SurfaceInteraction& si) const override;
  void SetTwoSided(bool v) override { inner_->SetTwoSided(v); }
  const Spectrum* Absorption() const override { return inner_->Absorption(); }
  float Opacity(const SurfaceInteraction& si) const override { return inner_->Opacity(si); }
  bool HasOpacity() const override { return inner_->HasOpacity(); }
  int Leaves() const override { return inner_->Leaves(); }
  bool MayTransmit() const override { return inner_->MayTransmit(); }

 protected:
  virtual Frame Perturb(const SurfaceInteraction& si) const = 0;

 private:
  // si with the perturbed, adapted shading frame.
  SurfaceInteraction Perturbed(const SurfaceInteraction& si) const;
  std::shared_ptr<Material> inner_;
};

// Heights from a texture's luminance (in scene units once multiplied by `scale`).
class BumpMapMaterial final : public PerturbedNormalMaterial {
 public:
  BumpMapMaterial(std::shared_ptr<Material> inner, std::shared_ptr<const SpectrumTexture> height, float scale)
      : PerturbedNormalMaterial(std::move(inner)), height_(std::move(height)), scale_(scale) {}

 protected:
  Frame Perturb(const SurfaceInteraction& si) const override;

 private:
  std::shared_ptr<const SpectrumTexture> height_;
  float scale_;
};

// Normals from a texture's RGB in [0, 1], mapped to [-1, 1] (x along s, y along t, z along n).
class NormalMapMaterial final : public PerturbedNormalMaterial {
 public:
  NormalMapMaterial(std::shared_ptr<Material> inner, std::shared_ptr<const SpectrumTexture> normals)
      : PerturbedNormalMaterial(std::move(inner)), normals_(std::move(normals)) {}

 protected:
  Frame Perturb(const SurfaceInteraction& si) const override;

 private:
  std::shared_ptr<const SpectrumTexture> normals_;
};

}  // namespace objektiv
