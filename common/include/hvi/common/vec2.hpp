//! @file Two-component vector in the (x or r, z) plane.
#pragma once
#include <cmath>

namespace hvi {

//! A point or vector in the meridional plane: x is the planar abscissa or the radius r, z is axial.
struct Vec2 {
  double x = 0.0;
  double z = 0.0;

  constexpr Vec2& operator+=(Vec2 o) { x += o.x; z += o.z; return *this; }
  constexpr Vec2& operator-=(Vec2 o) { x -= o.x; z -= o.z; return *this; }
  constexpr Vec2& operator*=(double s) { x *= s; z *= s; return *this; }
  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.z + b.z}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.z - b.z}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.z}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.z}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.z}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.z / s}; }
  friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.z * b.z; }
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.z - a.z * b.x; }
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }

}  // namespace hvi
