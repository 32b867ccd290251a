#include "scene/normal_mapping.h"

#include <cmath>

namespace objektiv {

namespace {

bool Finite(const Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A perturbed normal (unit) that a steep slope or a bad map tilted behind the geometric
// surface is mirrored in it: continuous where it grazes the surface, on ng's side after.
Vec3f KeepInFront(Vec3f n, const Vec3f& ng) {
  const float c = Dot(n, ng);
  return c < 0 ? Normalize(n - ng * (2 * c)) : n;
}

}  // namespace

Frame BumpedFrame(const SurfaceInteraction& si, Vec2f dh) {
  if (dh.x == 0 && dh.y == 0) return si.shading;
  const Vec3f& n = si.shading.n;
  const Vec3f dpdu_t = si.dpdu - n * Dot(n, si.dpdu), dpdv_t = si.dpdv - n * Dot(n, si.dpdv);
  // The normal's part along n is that of dpdu_t x dpdv_t, whatever dh is: its sign says
  // whether the parameterisation turns toward n or away from it (a sphere's turns inward).
  const Vec3f base = Cross(dpdu_t, dpdv_t);
  const float orient = Dot(base, n);
  Vec3f np = base + Cross(dpdu_t, n) * dh.y + Cross(n, dpdv_t) * dh.x;
  if (!(orient != 0) || !Finite(np) || !(LengthSquared(np) > 0)) return si.shading;
  np = Normalize(orient > 0 ? np : -np);
  return Frame::FromNormalTangent(KeepInFront(np, si.n), si.dpdu);
}

Frame NormalMappedFrame(const SurfaceInteraction& si, Vec3f local) {
  const Vec3f n = si.shading.FromLocal(local);
  if (!Finite(n) || !(LengthSquared(n) > 0)) return si.shading;
  return Frame::FromNormalTangent(KeepInFront(Normalize(n), si.n), si.dpdu);
}

Vec3f AdaptShadingNormal(const Vec3f& ns, const Vec3f& ng, const Vec3f& wo) {
  const float side = Dot(wo, ng);
  if (side == 0) return ns;
  // On wo's side of the surface: the geometric normal g, the shading normal n.
  const Vec3f g = side > 0 ? ng : -ng, n = side > 0 ? ns : -ns;
  const float elevation = std::min(0.01f, std::abs(side));
  const Vec3f r = n * (2 * Dot(wo, n)) - wo;  // wo mirrored about n
  const float a = Dot(r, g);
  if (a >= elevation - 1e-5f) return ns;  // (less: rounding where ns = ng and wo grazes)
  // r lifted to the elevation, keeping its direction along the surface; the normal that
  // mirrors wo into it is their half vector (wo and the lifted r both lie above the surface,
  // so the two never cancel, and wo.h > 0).
  const Vec3f along = r - g * a;
  const float len = Length(along);
  const Vec3f lifted =
      len > 0 ? along * (std::sqrt(1 - elevation * elevation) / len) + g * elevation : g;
  const Vec3f h = Normalize(wo + lifted);
  return side > 0 ? h : -h;
}

SurfaceInteraction PerturbedNormalMaterial::Perturbed(const SurfaceInteraction& si) const {
  SurfaceInteraction p = si;
  const Frame f = Perturb(si);
  const Vec3f n = AdaptShadingNormal(f.n, si.n, si.wo);
  p.shading = n.x == f.n.x && n.y == f.n.y && n.z == f.n.z ? f : Frame::FromNormalTangent(n, f.s);
  return p;
}

BSDF PerturbedNormalMaterial::GetBSDF(const SurfaceInteraction& si, SampledWavelengths& lambda) const {
  BSDF b = inner_->GetBSDF(Perturbed(si), lambda);
  b.RequireSameSide(si.shading.n);
  return b;
}

Frame PerturbedNormalMaterial::ShadingFrame(const SurfaceInteraction& si) const {
  return inner_->ShadingFrame(Perturbed(si));
}

Frame BumpMapMaterial::Perturb(const SurfaceInteraction& si) const {
  return BumpedFrame(si, height_->LuminanceGradient(si.uv) * scale_);
}

Frame NormalMapMaterial::Perturb(const SurfaceInteraction& si) const {
  return NormalMappedFrame(si, normals_->Rgb(si.uv) * 2.f - Vec3f(1.f));
}

}  // namespace objektiv
