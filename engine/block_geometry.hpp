// The rigid block's shape and mass properties, in body coordinates centred on the centre of mass.
#pragma once

#include <array>
#include <cmath>

#include "engine/scene.hpp"

namespace blockfrag {

struct Vec2 {
  double x, y;
};

// Rot(theta) c: a body vector seen in the world frame (theta counter-clockwise).
inline Vec2 rotate(Vec2 c, double cos_theta, double sin_theta) {
  return {c.x * cos_theta - c.y * sin_theta, c.x * sin_theta + c.y * cos_theta};
}

enum class Corner { left = 0, right = 1 };

inline Corner other(Corner corner) { return corner == Corner::left ? Corner::right : Corner::left; }

class BlockGeometry {
 public:
  static constexpr int kCorners = 4;

  explicit BlockGeometry(const RectangularBlock& block)
      : mass_(block.mass),
        corners_{{{-block.half_width, -block.half_height},
                  {block.half_width, -block.half_height},
                  {block.half_width, block.half_height},
                  {-block.half_width, block.half_height}}},
        size_(std::hypot(block.half_width, block.half_height)),
        inertia_per_mass_(size_ * size_ / 3.0),
        rest_height_(block.half_height) {}

  // Corners 0 and 1 are the base's left and right ends; 2 and 3 the top's.
  Vec2 corner(int i) const { return corners_[static_cast<std::size_t>(i)]; }
  Vec2 base_corner(Corner c) const { return corner(static_cast<int>(c)); }

  double mass() const { return mass_; }
  double inertia() const { return mass_ * inertia_per_mass_; }
  double inertia_per_mass() const { return inertia_per_mass_; }  // I/M
  double size() const { return size_; }                          // R: the length scale
  double rest_height() const { return rest_height_; }  // centre of mass above the base

  // Rocking about a base corner cannot start while lambda stays within these (a/b for a rectangle):
  // the moment of the inertial force about the corner is below gravity's.
  double tip_threshold(Corner c) const {
    const Vec2 r = base_corner(c);
    return std::abs(r.x) / -r.y;
  }
  // Flat sliding keeps both base corners down only while friction's moment about the centre of mass
  // is below what the normal forces can balance: mu <= a/b for a rectangle.
  double flat_slide_friction_limit() const {
    const Vec2 l = base_corner(Corner::left), r = base_corner(Corner::right);
    return std::min(-l.x, r.x) / -l.y;
  }

 private:
  double mass_;
  std::array<Vec2, kCorners> corners_;
  double size_, inertia_per_mass_, rest_height_;
};

}  // namespace blockfrag
