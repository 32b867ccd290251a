#include "scene/analytic_shape.h"

#include <cmath>
#include <stdexcept>

#include "base/sampling.h"

namespace objektiv {
namespace {

void BoundsCallback(const RTCBoundsFunctionArguments* args) {
  auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  Bounds3f b = shape->EmbreeBounds();
  RTCBounds* out = args->bounds_o;
  out->lower_x = b.lo.x;
  out->lower_y = b.lo.y;
  out->lower_z = b.lo.z;
  out->upper_x = b.hi.x;
  out->upper_y = b.hi.y;
  out->upper_z = b.hi.z;
}

// N is 1 for single rays and 8 for the packets of Scene::IntersectCoherent; lanes are read
// and written through Embree's structure-of-arrays accessors.
void IntersectCallback(const RTCIntersectFunctionNArguments* args) {
  auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  const unsigned n = args->N;
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, n);
  for (unsigned i = 0; i < n; ++i) {
    if (!args->valid[i]) continue;
    Vec3d o(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    Vec3d d(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    double t;
    Vec2f param;
    if (!shape->Intersect(o, d, RTCRayN_tfar(ray, n, i), &t, &param)) continue;
    if (!(t > RTCRayN_tnear(ray, n, i))) continue;
    RTCRayN_tfar(ray, n, i) = float(t);
    RTCHitN_u(hit, n, i) = param.x;
    RTCHitN_v(hit, n, i) = param.y;
    RTCHitN_Ng_x(hit, n, i) = RTCHitN_Ng_y(hit, n, i) = 0;
    RTCHitN_Ng_z(hit, n, i) = 1;
    RTCHitN_geomID(hit, n, i) = args->geomID;
    RTCHitN_primID(hit, n, i) = args->primID;
    RTCHitN_instID(hit, n, i, 0) = args->context->instID[0];
  }
}

void OccludedCallback(const RTCOccludedFunctionNArguments* args) {
  auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (!args->valid[i]) continue;
    Vec3d o(RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i), RTCRayN_org_z(args->ray, n, i));
    Vec3d d(RTCRayN_dir_x(args->ray, n, i), RTCRayN_dir_y(args->ray, n, i), RTCRayN_dir_z(args->ray, n, i));
    double t;
    Vec2f param;
    if (shape->Intersect(o, d, RTCRayN_tfar(args->ray, n, i), &t, &param) && t > RTCRayN_tnear(args->ray, n, i))
      RTCRayN_tfar(args->ray, n, i) = -std::numeric_limits<float>::infinity();
  }
}

Vec3d ToObject(const Matrix4& inv, const Vec3d& p, bool is_point) {
  const auto& a = inv.m;
  double w = is_point ? 1 : 0;
  return {a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3] * w,
          a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3] * w,
          a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3] * w};
}

Vec3d Column(const Transform& t, int c) {
  const auto& a = t.Matrix().m;
  return {a[0][c], a[1][c], a[2][c]};
}

// Where a world-space ray meets the object-space plane z = 0 of `to_world`, with 0 < t < tmax:
// the parameter and the object-space (x, y).
bool ObjectPlaneHit(const Transform& to_world, const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2d* xy) {
  Vec3d oo = ToObject(to_world.InverseMatrix(), o, true), dd = ToObject(to_world.InverseMatrix(), d, false);
  if (dd.z == 0) return false;
  double th = -oo.z / dd.z;
  if (!(th > 0) || th >= tmax) return false;
  *t = th;
  *xy = {oo.x + th * dd.x, oo.y + th * dd.y};
  return true;
}

// The interaction at object-space point (x, y, 0) of a flat shape with world normal n and
// object-space partial derivatives dpdu, dpdv of its parameterisation.
SurfaceInteraction FlatInteraction(const Transform& to_world, const Vec3f& n, double x, double y, const Ray& ray,
                                   float t, Vec2f uv, const Vec3f& dpdu_obj, const Vec3f& dpdv_obj) {
  SurfaceInteraction si;
  TransformPointWithError(to_world, Vec3d(x, y, 0), &si.p, &si.p_error);
  si.n = n;
  si.uv = uv;
  si.dpdu = to_world.Vector(dpdu_obj);
  si.dpdv = to_world.Vector(dpdv_obj);
  si.shading = Frame::FromNormalTangent(n, si.dpdu);
  si.t = t;
  si.wo = -Normalize(ray.d);
  return si;
}

}  // namespace

RTCGeometry AnalyticShape::CreateGeometry(RTCDevice device) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, 1);
  rtcSetGeometryUserData(geom, const_cast<AnalyticShape*>(this));
  rtcSetGeometryBoundsFunction(geom, BoundsCallback, nullptr);
  rtcSetGeometryIntersectFunction(geom, IntersectCallback);
  rtcSetGeometryOccludedFunction(geom, OccludedCallback);
  rtcCommitGeometry(geom);
  return geom;
}

void TransformPointWithError(const Transform& t, const Vec3d& p_obj, Vec3f* p, Vec3f* p_error) {
  Vec3d pw = t.Point(p_obj);
  *p = Vec3f(pw);
  // The transform is evaluated in double: what remains is the rounding to float, plus a
  // generous allowance for the object-space point's own error.
  *p_error = Abs(*p) * Gamma(4);
}

// --- Sphere -------------------------------------------------------------------------

Sphere::Sphere(const Vec3f& center, float radius, bool flip_normals, const Transform& to_world)
    : object_radius_(radius), flip_(flip_normals), to_world_(to_world) {
  // to_world must be a similarity: orthogonal columns of equal length.
  Vec3d c0 = Column(to_world, 0), c1 = Column(to_world, 1), c2 = Column(to_world, 2);
  double s0 = Length(c0), s1 = Length(c1), s2 = Length(c2);
  double tol = 1e-5 * std::max(s0, std::max(s1, s2));
  if (std::abs(s0 - s1) > tol || std::abs(s0 - s2) > tol || std::abs(Dot(c0, c1)) > tol * s0 ||
      std::abs(Dot(c0, c2)) > tol * s0 || std::abs(Dot(c1, c2)) > tol * s0)
    throw std::invalid_argument("sphere: to_world must be a rotation, translation and uniform scale");
  center_ = to_world.Point(Vec3d(center));
  radius_ = double(radius) * s0;
  if (!(radius_ > 0)) throw std::invalid_argument("sphere: radius must be positive");
  CheckSceneLimit(WorldBounds(), "the sphere");
}

bool Sphere::Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const {
  Vec3d oc = o - center_;
  double a = Dot(d, d), b = 2 * Dot(oc, d), c = Dot(oc, oc) - radius_ * radius_;
  // Discriminant from the distance of the centre to the line: no cancellation far away.
  Vec3d f = oc - d * (Dot(oc, d) / a);
  double disc = 4 * a * (radius_ * radius_ - Dot(f, f));
  if (disc < 0) return false;
  double root = std::sqrt(disc);
  double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
  double t0 = q / a, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  double th = t0 > 0 ? t0 : t1;
  if (!(th > 0) || th >= tmax) return false;
  *t = th;
  *param = {0, 0};
  return true;
}

ShapeSample Sphere::PointAt(const Vec3d& pd) const {
  Vec3d dir = pd - center_;
  dir = dir / Length(dir);
  Vec3d p = center_ + dir * radius_;  // reprojected onto the surface
  ShapeSample s;
  s.p = Vec3f(p);
  s.p_error = Abs(s.p) * Gamma(5) + Vec3f(float(radius_) * Gamma(5));
  s.n = Vec3f(dir);
  if (flip_) s.n = -s.n;
  Vec3f local = Normalize(Vec3f(ToObject(to_world_.InverseMatrix(), dir, false)));
  float phi = std::atan2(local.y, local.x);
  if (phi < 0) phi += 2 * kPi;
  s.uv = {phi * kInv2Pi, std::acos(Clamp(local.z, -1, 1)) * kInvPi};
  return s;
}

SurfaceInteraction Sphere::ComputeInteraction(const Ray& ray, const RTCHit&, float t) const {
  Vec3d pd = Vec3d(ray.o) + Vec3d(ray.d) * double(t);
  ShapeSample s = PointAt(pd);
  SurfaceInteraction si;
  si.p = s.p;
  si.p_error = s.p_error;
  si.n = s.n;
  si.uv = s.uv;
  // p = c + r (sin theta cos phi, sin theta sin phi, cos theta) in object space, with
  // u = phi / 2 pi and v = theta / pi: dp/du = 2 pi dp/dphi, dp/dv = pi dp/dtheta. The
  // object-space radius times to_world's linear part gives world lengths.
  Vec3f local = Normalize(Vec3f(ToObject(to_world_.InverseMatrix(), pd - center_, false)));
  float sin_theta = std::sqrt(local.x * local.x + local.y * local.y);
  float phi = std::atan2(local.y, local.x);  // 0 at the poles, as the uv
  float r = float(object_radius_);
  si.dpdu = to_world_.Vector(Vec3f(-local.y, local.x, 0) * (2 * kPi * r));
  si.dpdv = to_world_.Vector(Vec3f(local.z * std::cos(phi), local.z * std::sin(phi), -sin_theta) * (kPi * r));
  si.shading = Frame::FromNormalTangent(s.n, si.dpdu);
  si.t = t;
  si.wo = -Normalize(ray.d);
  return si;
}

float Sphere::Area() const { return float(4 * M_PI * radius_ * radius_); }

Bounds3f Sphere::WorldBounds() const {
  Bounds3f b;
  b.Extend(Vec3f(center_ - Vec3d(radius_)));
  b.Extend(Vec3f(center_ + Vec3d(radius_)));
  b.lo = b.lo - Abs(b.lo) * 1e-6f;
  b.hi = b.hi + Abs(b.hi) * 1e-6f;
  return b;
}

ShapeSample Sphere::SampleArea(Vec2f u) const {
  ShapeSample s = PointAt(center_ + Vec3d(SampleUniformSphere(u)) * radius_);
  s.pdf = 1 / Area();
  return s;
}

ShapeSample Sphere::SampleFrom(const Vec3f& ref, Vec2f u) const {
  Vec3d rd(ref);
  double dc2 = LengthSquared(center_ - rd);
  double r2 = radius_ * radius_;
  if (dc2 <= r2 * (1 + 1e-6)) return Shape::SampleFrom(ref, u);  // inside: area sampling
  // Uniform over the cone of directions the sphere subtends (pbrt-v4's formulation, which
  // stays accurate for tiny cones).
  double dc = std::sqrt(dc2);
  double sin2_max = r2 / dc2, sin_max = std::sqrt(sin2_max);
  double cos_max = std::sqrt(std::max(0.0, 1 - sin2_max)), one_minus_cos_max = 1 - cos_max;
  double cos_t = (cos_max - 1) * u.x + 1;
  double sin2_t = 1 - cos_t * cos_t;
  if (sin2_max < 0.00068523) {  // below ~1.5 degrees: Taylor expansion
    sin2_t = sin2_max * u.x;
    cos_t = std::sqrt(1 - sin2_t);
    one_minus_cos_max = sin2_max / 2;
  }
  // Angle alpha at the centre between the direction to ref and the sampled point.
  double cos_alpha = sin2_t / sin_max + cos_t * std::sqrt(std::max(0.0, 1 - sin2_t / sin2_max));
  double sin_alpha = std::sqrt(std::max(0.0, 1 - cos_alpha * cos_alpha));
  double phi = u.y * 2 * M_PI;
  Vec3d wc = (center_ - rd) / dc;
  Frame f = Frame::FromZ(Vec3f(-wc));
  Vec3d n = Vec3d(f.FromLocal(Vec3f(float(sin_alpha * std::cos(phi)), float(sin_alpha * std::sin(phi)), float(cos_alpha))));
  ShapeSample s = PointAt(center_ + n * radius_);
  s.pdf = float(1 / (2 * M_PI * one_minus_cos_max));
  return s;
}

float Sphere::PdfFrom(const Vec3f& ref, const SurfaceInteraction& hit) const {
  Vec3d rd(ref);
  double dc2 = LengthSquared(center_ - rd), r2 = radius_ * radius_;
  if (dc2 <= r2 * (1 + 1e-6)) return Shape::PdfFrom(ref, hit);
  double sin2_max = r2 / dc2;
  double one_minus_cos_max = sin2_max < 0.00068523 ? sin2_max / 2 : 1 - std::sqrt(std::max(0.0, 1 - sin2_max));
  return float(1 / (2 * M_PI * one_minus_cos_max));
}

// --- Disk ---------------------------------------------------------------------------

Disk::Disk(const Transform& to_world, bool flip_normals) : to_world_(to_world), flip_(flip_normals) {
  normal_ = Normalize(to_world.Normal(Vec3f(0, 0, 1)));
  if (flip_) normal_ = -normal_;
  area_ = float(M_PI * Length(Cross(Column(to_world, 0), Column(to_world, 1))));
  CheckSceneLimit(WorldBounds(), "the disk");
}

bool Disk::Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const {
  Vec2d xy;
  if (!ObjectPlaneHit(to_world_, o, d, tmax, t, &xy) || xy.x * xy.x + xy.y * xy.y > 1) return false;
  *param = {float(xy.x), float(xy.y)};
  return true;
}

SurfaceInteraction Disk::ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const {
  float phi = std::atan2(hit.v, hit.u);
  if (phi < 0) phi += 2 * kPi;
  Vec2f uv(std::sqrt(hit.u * hit.u + hit.v * hit.v), phi * kInv2Pi);  // (r, phi / 2 pi)
  // p = (r cos phi, r sin phi, 0): dp/du = (cos phi, sin phi, 0), dp/dv = 2 pi (-y, x, 0).
  return FlatInteraction(to_world_, normal_, hit.u, hit.v, ray, t, uv, Vec3f(std::cos(phi), std::sin(phi), 0),
                         Vec3f(-hit.v, hit.u, 0) * (2 * kPi));
}

Bounds3f Disk::WorldBounds() const {
  Bounds3f b;
  // The ellipse lies inside the image of the square [-1,1]^2.
  for (int i = 0; i < 4; ++i) b.Extend(to_world_.Point(Vec3f(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, 0)));
  Vec3f pad = (Abs(b.lo) + Abs(b.hi)) * 1e-6f + Vec3f(1e-30f);
  b.lo = b.lo - pad;
  b.hi = b.hi + pad;
  return b;
}

ShapeSample Disk::SampleArea(Vec2f u) const {
  Vec2f d = SampleUniformDiskConcentric(u);
  ShapeSample s;
  TransformPointWithError(to_world_, Vec3d(d.x, d.y, 0), &s.p, &s.p_error);
  s.n = normal_;
  float phi = std::atan2(d.y, d.x);
  if (phi < 0) phi += 2 * kPi;
  s.uv = {std::sqrt(d.x * d.x + d.y * d.y), phi * kInv2Pi};
  s.pdf = 1 / area_;
  return s;
}

// --- Cylinder -----------------------------------------------------------------------

Cylinder::Cylinder(const Transform& object_to_world, bool flip_normals) : to_world_(object_to_world), flip_(flip_normals) {
  Vec3d c0 = Column(object_to_world, 0), c1 = Column(object_to_world, 1), c2 = Column(object_to_world, 2);
  double r0 = Length(c0), r1 = Length(c1), h = Length(c2);
  double tol = 1e-5 * std::max(r0, h);
  if (std::abs(r0 - r1) > tol || std::abs(Dot(c0, c1)) > tol * r0 || std::abs(Dot(c0, c2)) > tol * h ||
      std::abs(Dot(c1, c2)) > tol * h)
    throw std::invalid_argument("cylinder: to_world must keep the cross-section circular (no shear or unequal scale)");
  area_ = float(2 * M_PI * r0 * h);
  CheckSceneLimit(WorldBounds(), "the cylinder");
}

bool Cylinder::Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const {
  Vec3d oo = ToObject(to_world_.InverseMatrix(), o, true), dd = ToObject(to_world_.InverseMatrix(), d, false);
  double a = dd.x * dd.x + dd.y * dd.y;
  if (a == 0) return false;
  double b = 2 * (oo.x * dd.x + oo.y * dd.y), c = oo.x * oo.x + oo.y * oo.y - 1;
  double disc = b * b - 4 * a * c;
  if (disc < 0) return false;
  double root = std::sqrt(disc);
  double q = b < 0 ? -0.5 * (b - root) : -0.5 * (b + root);
  double ts[2] = {q / a, c / q};
  if (ts[0] > ts[1]) std::swap(ts[0], ts[1]);
  for (double th : ts) {
    if (!(th > 0) || th >= tmax) continue;
    double z = oo.z + th * dd.z;
    if (z < 0 || z > 1) continue;
    double phi = std::atan2(oo.y + th * dd.y, oo.x + th * dd.x);
    *t = th;
    *param = {float(phi), float(z)};
    return true;
  }
  return false;
}

ShapeSample Cylinder::PointAt(double phi, double z) const {
  ShapeSample s;
  TransformPointWithError(to_world_, Vec3d(std::cos(phi), std::sin(phi), z), &s.p, &s.p_error);
  s.n = Normalize(to_world_.Normal(Vec3f(float(std::cos(phi)), float(std::sin(phi)), 0)));
  if (flip_) s.n = -s.n;
  double u = phi < 0 ? phi + 2 * M_PI : phi;
  s.uv = {float(u / (2 * M_PI)), float(z)};
  return s;
}

SurfaceInteraction Cylinder::ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const {
  ShapeSample s = PointAt(hit.u, hit.v);
  SurfaceInteraction si;
  si.p = s.p;
  si.p_error = s.p_error;
  si.n = s.n;
  si.uv = s.uv;
  // p = (cos phi, sin phi, z) with u = phi / 2 pi, v = z.
  si.dpdu = to_world_.Vector(Vec3f(-std::sin(hit.u), std::cos(hit.u), 0) * (2 * kPi));
  si.dpdv = to_world_.Vector(Vec3f(0, 0, 1));
  si.shading = Frame::FromNormalTangent(s.n, si.dpdu);
  si.t = t;
  si.wo = -Normalize(ray.d);
  return si;
}

Bounds3f Cylinder::WorldBounds() const {
  Bounds3f b;
  for (int i = 0; i < 8; ++i)
    b.Extend(to_world_.Point(Vec3f(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : 0.f)));
  Vec3f pad = (Abs(b.lo) + Abs(b.hi)) * 1e-6f;
  b.lo = b.lo - pad;
  b.hi = b.hi + pad;
  return b;
}

ShapeSample Cylinder::SampleArea(Vec2f u) const {
  ShapeSample s = PointAt(2 * M_PI * u.x, u.y);
  s.pdf = 1 / area_;
  return s;
}

// --- Infinite plane -----------------------------------------------------------------

InfinitePlane::InfinitePlane(const Transform& to_world, bool flip_normals) : to_world_(to_world), flip_(flip_normals) {
  Bounds3f origin;
  origin.Extend(to_world.Point(Vec3f(0.f)));
  CheckSceneLimit(origin, "the plane's origin");
  normal_ = Normalize(to_world.Normal(Vec3f(0, 0, 1)));
  if (flip_) normal_ = -normal_;
  // The points p of the plane n.(p - p0) = 0 inside the cube |p_j| <= R satisfy, along axis i,
  // |p_i - p0_i| <= sum over j != i of |n_j| (R + |p0_j|) / |n_i|: a thin slab for a plane
  // facing an axis (the BVH then skips it for rays that stay on one side), the cube otherwise.
  const double R = kInfinitePlaneExtent;
  const auto& inv = to_world.InverseMatrix().m;
  const Vec3d n(inv[2][0], inv[2][1], inv[2][2]);  // (0, 0, 1) by the inverse transpose
  const Vec3d p0 = to_world.Point(Vec3d(0, 0, 0));
  for (int i = 0; i < 3; ++i) {
    double lo = -R, hi = R;
    if (n[i] != 0) {
      double half = 0;
      for (int j = 0; j < 3; ++j)
        if (j != i) half += std::abs(n[j]) * (R + std::abs(p0[j])) / std::abs(n[i]);
      lo = std::max(lo, p0[i] - half);
      hi = std::min(hi, p0[i] + half);
    }
    if (!(lo <= hi)) throw std::invalid_argument("plane: it lies beyond the reach of the scene (1e18 units)");
    // Widened past the rounding to float (and the double arithmetic above).
    embree_bounds_.lo[i] = float(lo - 1e-6 * std::abs(lo)) - 1e-30f;
    embree_bounds_.hi[i] = float(hi + 1e-6 * std::abs(hi)) + 1e-30f;
  }
}

bool InfinitePlane::Intersect(const Vec3d& o, const Vec3d& d, double tmax, double* t, Vec2f* param) const {
  Vec2d xy;
  if (!ObjectPlaneHit(to_world_, o, d, tmax, t, &xy)) return false;
  *param = {float(xy.x), float(xy.y)};
  return true;
}

SurfaceInteraction InfinitePlane::ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const {
  // The hit again in double: far away the float (u, v) Embree carried would put the point off
  // the plane by more than its error bound.
  double th;
  Vec2d xy(hit.u, hit.v);
  ObjectPlaneHit(to_world_, Vec3d(ray.o), Vec3d(ray.d), std::numeric_limits<double>::infinity(), &th, &xy);
  return FlatInteraction(to_world_, normal_, xy.x, xy.y, ray, t, {float(xy.x), float(xy.y)}, Vec3f(1, 0, 0),
                         Vec3f(0, 1, 0));
}

}  // namespace objektiv
