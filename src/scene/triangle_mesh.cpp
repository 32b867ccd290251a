#include "scene/triangle_mesh.h"

#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "base/rng.h"

namespace objektiv {

TriangleMesh::TriangleMesh(MeshData data, const Transform& to_world, bool flip_normals)
    : data_(std::move(data)), flip_(flip_normals) {
  if (data_.indices.size() % 3 != 0) throw std::invalid_argument("mesh index count is not a multiple of 3");
  for (uint32_t i : data_.indices)
    if (i >= data_.positions.size()) throw std::invalid_argument("mesh index out of range");
  if (!data_.normals.empty() && data_.normals.size() != data_.positions.size())
    throw std::invalid_argument("mesh normal count differs from vertex count");
  if (!data_.uvs.empty() && data_.uvs.size() != data_.positions.size())
    throw std::invalid_argument("mesh uv count differs from vertex count");
  if (!to_world.IsIdentity()) {
    for (Vec3f& p : data_.positions) p = to_world.Point(p);
    for (Vec3f& n : data_.normals) n = Normalize(to_world.Normal(n));
    // A mirroring transform turns counter-clockwise into clockwise: keep the front side.
    if (to_world.SwapsHandedness()) flip_ = !flip_;
  }
  for (size_t i = 0; i < data_.positions.size(); ++i) {
    const Vec3f& p = data_.positions[i];
    if (!WithinSceneLimit(p))
      throw std::invalid_argument(fmt::format("vertex {} lies at ({:g}, {:g}, {:g}), beyond the scene's coordinate limit of {:g}",
                                              i, p.x, p.y, p.z, kMaxSceneCoordinate));
    bounds_.Extend(p);
  }
  std::vector<float> areas(TriangleCount());
  face_normals_.resize(TriangleCount());
  for (size_t i = 0; i < areas.size(); ++i) {
    const Vec3f& p0 = data_.positions[data_.indices[3 * i]];
    const Vec3f& p1 = data_.positions[data_.indices[3 * i + 1]];
    const Vec3f& p2 = data_.positions[data_.indices[3 * i + 2]];
    Vec3f ng = Cross(p1 - p0, p2 - p0);
    float len = Length(ng);
    areas[i] = 0.5f * len;
    area_ += areas[i];
    face_normals_[i] = len > 0 ? ng / len * (flip_ ? -1.f : 1.f) : Vec3f(0, 0, 1);
  }
  if (!areas.empty()) triangle_distribution_ = Distribution1D(areas);
  FindParallelogram();
}

RTCGeometry TriangleMesh::CreateGeometry(RTCDevice device) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree reads the vertex buffer with 16-byte loads: the shared buffer must be padded,
  // so copy into Embree-owned buffers (one extra float at the end).
  float* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3f), data_.positions.size()));
  std::memcpy(v, data_.positions.data(), data_.positions.size() * sizeof(Vec3f));
  uint32_t* idx = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), TriangleCount()));
  std::memcpy(idx, data_.indices.data(), data_.indices.size() * sizeof(uint32_t));
  // The mesh's own BVH (the scene's is two-level): the best Embree builds, spatial splits included.
  rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
  rtcCommitGeometry(geom);
  return geom;
}

SurfaceInteraction TriangleMesh::ComputeInteraction(const Ray& ray, const RTCHit& hit, float t) const {
  const uint32_t* tri = &data_.indices[3 * size_t(hit.primID)];
  const Vec3f &p0 = data_.positions[tri[0]], &p1 = data_.positions[tri[1]], &p2 = data_.positions[tri[2]];
  float b1 = hit.u, b2 = hit.v, b0 = 1 - b1 - b2;
  SurfaceInteraction si;
  // Interpolating the vertices is more accurate than o + t d; bound its rounding error.
  si.p = p0 * b0 + p1 * b1 + p2 * b2;
  si.p_error = (Abs(p0 * b0) + Abs(p1 * b1) + Abs(p2 * b2)) * Gamma(7);
  si.n = face_normals_[hit.primID];
  Vec3f ns = si.n;
  if (!data_.normals.empty()) {
    Vec3f nsi = data_.normals[tri[0]] * b0 + data_.normals[tri[1]] * b1 + data_.normals[tri[2]] * b2;
    float l2 = LengthSquared(nsi);
    if (l2 > 0) ns = nsi * ((flip_ ? -1.f : 1.f) / std::sqrt(l2));
  }
  if (data_.uvs.empty()) {
    // No uvs: the barycentric uv (b1 + b2, b2), for which p = p0 + u (p1 - p0) + v (p2 - p1).
    si.uv = {b1 + b2, b2};
    si.dpdu = p1 - p0;
    si.dpdv = p2 - p1;
  } else {
    const Vec2f &uv0 = data_.uvs[tri[0]], &uv1 = data_.uvs[tri[1]], &uv2 = data_.uvs[tri[2]];
    si.uv = uv0 * b0 + uv1 * b1 + uv2 * b2;
    // The affine map from uv to the triangle's plane: p - p2 = dpdu (uv - uv2) + dpdv (...),
    // solved from the edges (p0 - p2, p1 - p2) and (uv0 - uv2, uv1 - uv2) by Cramer's rule.
    Vec2f duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    Vec3f dp02 = p0 - p2, dp12 = p1 - p2;
    float det = duv02.x * duv12.y - duv02.y * duv12.x;
    auto finite = [](const Vec3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    // Relative to the uv edges' size, so that tiny but valid uv triangles are kept.
    float uv_scale = std::max(std::max(std::abs(duv02.x), std::abs(duv02.y)), std::max(std::abs(duv12.x), std::abs(duv12.y)));
    if (std::abs(det) > 1e-9f * uv_scale * uv_scale) {
      si.dpdu = (dp02 * duv12.y - dp12 * duv02.y) / det;
      si.dpdv = (dp12 * duv02.x - dp02 * duv12.x) / det;
    }
    if (!(std::abs(det) > 1e-9f * uv_scale * uv_scale) || !finite(si.dpdu) || !finite(si.dpdv) ||
        !(LengthSquared(Cross(si.dpdu, si.dpdv)) > 0)) {
      // Degenerate uvs (all three alike, or on a line): no derivative exists. A frame around
      // the face normal stands in, with the length of the triangle's edges, so that a bump
      // map's slope keeps a sensible scale.
      Frame f = Frame::FromZ(si.n);
      float len = std::sqrt(Length(Cross(p1 - p0, p2 - p0)));
      si.dpdu = f.s * len;
      si.dpdv = f.t * len;
    }
  }
  si.shading = Frame::FromNormalTangent(ns, si.dpdu);
  si.t = t;
  si.wo = -ray.d * (1 / Length(ray.d));
  return si;
}

void TriangleMesh::FindParallelogram() {
  if (TriangleCount() != 2 || !(area_ > 0)) return;
  const uint32_t *a = &data_.indices[0], *b = &data_.indices[3];
  auto pos = [&](uint32_t v) { return data_.positions[v]; };
  // The two vertices both triangles share (by position: OBJ quads may repeat vertices), each
  // corner of b matched once (a degenerate a may hold one position twice).
  int shared_a[3] = {-1, -1, -1}, shared = 0;
  bool matched_b[3] = {false, false, false};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!matched_b[j] && pos(a[i]) == pos(b[j])) {
        shared_a[i] = j;
        matched_b[j] = true;
        ++shared;
        break;
      }
  if (shared != 2) return;
  Parallelogram q;
  for (int i = 0; i < 3; ++i)
    if (shared_a[i] < 0) q.r_slot = i;
  q.p_slot = (q.r_slot + 1) % 3;
  q.q_slot = (q.r_slot + 2) % 3;
  q.sp_slot = shared_a[q.p_slot];
  q.sq_slot = shared_a[q.q_slot];
  q.s_slot = 3 - q.sp_slot - q.sq_slot;
  // A parallelogram when R + S = P + Q (its diagonals halve each other).
  Vec3f r = pos(a[q.r_slot]), p = pos(a[q.p_slot]), qq = pos(a[q.q_slot]), sv = pos(b[q.s_slot]);
  float scale = MaxComponent(Abs(r)) + MaxComponent(Abs(p)) + MaxComponent(Abs(qq)) + MaxComponent(Abs(sv));
  if (MaxComponent(Abs(r + sv - p - qq)) > 1e-6f * scale) return;
  parallelogram_ = q;
}

ShapeSample TriangleMesh::SampleArea(Vec2f u) const {
  int i;
  float b[3];  // barycentric weights of triangle i's three vertices
  if (parallelogram_) {
    // u maps affinely onto the parallelogram R + u (P - R) + v (Q - R): the triangle (R, P, Q)
    // where u + v <= 1, else (S, P, Q) with S = P + Q - R.
    const Parallelogram& q = *parallelogram_;
    if (u.x + u.y <= 1) {
      i = 0;
      b[q.r_slot] = 1 - u.x - u.y;
      b[q.p_slot] = u.x;
      b[q.q_slot] = u.y;
    } else {
      i = 1;
      b[q.s_slot] = u.x + u.y - 1;
      b[q.sp_slot] = 1 - u.y;
      b[q.sq_slot] = 1 - u.x;
    }
  } else {
    float pmf;
    i = triangle_distribution_.SampleDiscrete(u.x, &pmf);
    // Reuse u.x within the chosen triangle's slice of the CDF.
    float ux = std::min((u.x - triangle_distribution_.CdfAt(i)) / pmf, kOneMinusEpsilon);
    Vec2f bt = SampleUniformTriangle({ux, u.y});
    b[0] = bt.x;
    b[1] = bt.y;
    b[2] = 1 - bt.x - bt.y;
  }
  const uint32_t* tri = &data_.indices[3 * size_t(i)];
  const Vec3f &p0 = data_.positions[tri[0]], &p1 = data_.positions[tri[1]], &p2 = data_.positions[tri[2]];
  ShapeSample s;
  s.p = p0 * b[0] + p1 * b[1] + p2 * b[2];
  s.p_error = (Abs(p0 * b[0]) + Abs(p1 * b[1]) + Abs(p2 * b[2])) * Gamma(6);
  s.n = face_normals_[i];
  if (data_.uvs.empty()) {
    s.uv = {b[1] + b[2], b[2]};  // as ComputeInteraction: barycentric uv
  } else {
    s.uv = data_.uvs[tri[0]] * b[0] + data_.uvs[tri[1]] * b[1] + data_.uvs[tri[2]] * b[2];
  }
  s.pdf = 1 / area_;
  return s;
}

MeshData TriangleMesh::Rectangle() {
  MeshData m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 2, 3, 0};
  return m;
}

MeshData TriangleMesh::Cube() {
  MeshData m;
  // Six faces, each with its own four vertices so that normals and uvs are per face.
  const Vec3f normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Vec3f& n : normals) {
    // Two tangents completing a right-handed frame with n.
    Vec3f a = std::abs(n.x) > 0 ? Vec3f(0, 1, 0) : Vec3f(1, 0, 0);
    Vec3f b = Cross(n, a);
    uint32_t base = uint32_t(m.positions.size());
    const Vec2f corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const Vec2f& c : corners) {
      m.positions.push_back(n + a * c.x + b * c.y);
      m.normals.push_back(n);
      m.uvs.push_back({(c.x + 1) / 2, (c.y + 1) / 2});
    }
    // Wind counter-clockwise seen from outside: (a, b, n) is right-handed.
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base + 2, base + 3, base});
  }
  return m;
}

}  // namespace objektiv
