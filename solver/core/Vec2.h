#pragma once
/// @file Vec2.h
/// @brief A plain 2D vector for geometry and per-particle results (not for particle storage,
/// which is one array per component, see particles/ParticleSet.h).

#include <cmath>

namespace wcmps {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2() = default;
  constexpr Vec2(double ax, double ay) : x(ax), y(ay) {}

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
};

constexpr Vec2 operator*(double s, Vec2 v) {
  return v * s;
}
constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
/// z-component of the 3D cross product (a, 0) x (b, 0).
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
inline double norm(Vec2 a) {
  return std::sqrt(dot(a, a));
}
/// The vector turned by -90 degrees: the right-hand normal of a direction.
constexpr Vec2 right_normal(Vec2 d) {
  return {d.y, -d.x};
}

}  // namespace wcmps
