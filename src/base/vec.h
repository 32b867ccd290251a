// Small fixed-size vectors used everywhere: Vec2, Vec3 (points, directions and normals alike).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace objektiv {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 0.31830988618379067154f;
constexpr float kInv2Pi = 0.15915494309189533577f;
constexpr float kInv4Pi = 0.07957747154594766788f;

template <typename T>
struct Vec2 {
  T x = 0, y = 0;
  constexpr Vec2() = default;
  constexpr Vec2(T x_, T y_) : x(x_), y(y_) {}
  constexpr T operator[](int i) const { return i == 0 ? x : y; }
  constexpr T& operator[](int i) { return i == 0 ? x : y; }
  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator*(T s) const { return {x * s, y * s}; }
  constexpr Vec2 operator*(Vec2 o) const { return {x * o.x, y * o.y}; }
  constexpr bool operator==(const Vec2&) const = default;
};

template <typename T>
struct Vec3 {
  T x = 0, y = 0, z = 0;
  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Vec3(T s) : x(s), y(s), z(s) {}
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(T s) const { T inv = T(1) / s; return {x * inv, y * inv, z * inv}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
  constexpr bool operator==(const Vec3&) const = default;
};

template <typename T> constexpr Vec3<T> operator*(T s, const Vec3<T>& v) { return v * s; }
template <typename T> constexpr T Dot(const Vec3<T>& a, const Vec3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename T> constexpr T AbsDot(const Vec3<T>& a, const Vec3<T>& b) { return std::abs(Dot(a, b)); }
template <typename T> constexpr Vec3<T> Cross(const Vec3<T>& a, const Vec3<T>& b) {
  // Products in double where T is float would be more exact; float suffices for shading frames.
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T> T LengthSquared(const Vec3<T>& v) { return Dot(v, v); }
template <typename T> T Length(const Vec3<T>& v) { return std::sqrt(Dot(v, v)); }
template <typename T> Vec3<T> Normalize(const Vec3<T>& v) { return v / Length(v); }
template <typename T> Vec3<T> Abs(const Vec3<T>& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
template <typename T> Vec3<T> Min(const Vec3<T>& a, const Vec3<T>& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
template <typename T> Vec3<T> Max(const Vec3<T>& a, const Vec3<T>& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
template <typename T> T MaxComponent(const Vec3<T>& v) { return std::max(v.x, std::max(v.y, v.z)); }
template <typename T> T MinComponent(const Vec3<T>& v) { return std::min(v.x, std::min(v.y, v.z)); }
// Flip v to lie in the same hemisphere as ref.
template <typename T> Vec3<T> FaceForward(const Vec3<T>& v, const Vec3<T>& ref) { return Dot(v, ref) < 0 ? -v : v; }
template <typename T> Vec3<T> Reflect(const Vec3<T>& wo, const Vec3<T>& n) { return -wo + n * (2 * Dot(wo, n)); }

using Vec2f = Vec2<float>;
using Vec2d = Vec2<double>;
using Vec2i = Vec2<int>;
using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

inline float Clamp(float v, float lo, float hi) { return std::min(std::max(v, lo), hi); }
inline float Lerp(float t, float a, float b) { return (1 - t) * a + t * b; }
inline float SafeSqrt(float x) { return std::sqrt(std::max(0.f, x)); }
inline double SafeSqrt(double x) { return std::sqrt(std::max(0.0, x)); }
inline float Sqr(float x) { return x * x; }
inline float Radians(float deg) { return deg * (kPi / 180.f); }
inline float Degrees(float rad) { return rad * (180.f / kPi); }

// Spherical coordinates in a local frame whose z axis is the normal.
inline float CosTheta(const Vec3f& w) { return w.z; }
inline float AbsCosTheta(const Vec3f& w) { return std::abs(w.z); }
inline float Cos2Theta(const Vec3f& w) { return w.z * w.z; }
inline float Sin2Theta(const Vec3f& w) { return std::max(0.f, 1.f - w.z * w.z); }
inline float Tan2Theta(const Vec3f& w) { return Sin2Theta(w) / Cos2Theta(w); }
inline bool SameHemisphere(const Vec3f& a, const Vec3f& b) { return a.z * b.z > 0; }

}  // namespace objektiv
