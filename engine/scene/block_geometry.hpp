// The rigid block's shape and mass properties, in body coordinates centred on the centre of mass.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/scene/scene.hpp"
#include "engine/sine_cosine.hpp"

namespace blockfrag {

struct Vec2 {
  double x, y;
};

// Rot(theta) c: a body vector seen in the world frame (theta counter-clockwise).
inline Vec2 rotate(Vec2 c, double cos_theta, double sin_theta) {
  return {c.x * cos_theta - c.y * sin_theta, c.x * sin_theta + c.y * cos_theta};
}

struct Rotation {
  double cos, sin;
};

inline Vec2 rotate(Vec2 c, Rotation r) { return rotate(c, r.cos, r.sin); }

enum class Corner { left = 0, right = 1 };

// The base corner a block released tilted by theta and turning at omega turns about: the one its
// tilt lowers, or, flat, the one its turning keeps on the ground (the right one for omega < 0).
inline Corner release_pivot(double theta, double omega) {
  if (theta != 0.0) return theta < 0 ? Corner::right : Corner::left;
  return omega < 0 ? Corner::right : Corner::left;
}

inline Corner other(Corner corner) { return corner == Corner::left ? Corner::right : Corner::left; }

class BlockGeometry {
 public:
  // A rectangle is the polygon with its four corners: one path for every block, so a polygon given
  // a rectangle's vertices is that rectangle to the last bit.
  explicit BlockGeometry(const RectangularBlock& block)
      : BlockGeometry(PolygonBlock{{{-block.half_width, -block.half_height},
                                    {block.half_width, -block.half_height},
                                    {block.half_width, block.half_height},
                                    {-block.half_width, block.half_height}},
                                   block.mass}) {}
  // Mass properties from the polygon (engine/scene/polygon_properties.hpp); it must have no defect.
  explicit BlockGeometry(const PolygonBlock& block);

  // Corners 0 and 1 are the base's left and right ends; the others follow counter-clockwise
  // (2 and 3 are the top's right and left for a rectangle). A polygon's corners are its convex
  // hull's: a reflex corner never touches a flat ground.
  int corner_count() const { return static_cast<int>(corners_.size()); }
  Vec2 corner(int i) const { return corners_[static_cast<std::size_t>(i)]; }
  Vec2 base_corner(Corner c) const { return corner(static_cast<int>(c)); }

  // The dynamics are per unit mass: forces, impulses and energies scale with M, and every output
  // is per unit mass or per weight, so working at M = 1 makes results independent of the mass to
  // the bit, for any positive finite mass.
  double inertia_per_mass() const { return inertia_per_mass_; }  // I/M
  // R, the length scale: the largest distance of a corner from the centre of mass (the rectangle's
  // half-diagonal), so omega^2 R bounds every corner's centripetal acceleration.
  double size() const { return size_; }
  double rest_height() const { return rest_height_; }  // centre of mass above the base

  // Rocking about a base corner cannot start while lambda stays within these (a/b for a rectangle):
  // the moment of the inertial force about the corner is below gravity's.
  double tip_threshold(Corner c) const {
    const Vec2 r = base_corner(c);
    return std::abs(r.x) / -r.y;
  }
  // Flat sliding with slip sign s keeps both base corners down only while friction's moment about
  // the centre of mass is below what the normal forces can balance: mu <= the leading corner's
  // tip threshold (the right corner's when sliding to +x), a/b for a rectangle either way.
  double flat_slide_friction_limit(int slip_sign) const {
    return tip_threshold(slip_sign > 0 ? Corner::right : Corner::left);
  }
  // The same for whichever way it slides.
  double flat_slide_friction_limit() const {
    return std::min(tip_threshold(Corner::left), tip_threshold(Corner::right));
  }
  // |theta| at which rocking about this base corner lays the face next to it on the ground (the
  // block has overturned): counter-clockwise about the left corner, clockwise about the right; pi/2
  // for a rectangle. While theta stays within (-angle(right), angle(left)) only base corners can be
  // the lowest point of the block (a corner of its convex hull).
  double overturn_angle(Corner c) const { return overturn_angle_[static_cast<std::size_t>(c)]; }
  // theta that lays the block on the face next to the corner it rotates towards (sign of theta).
  double overturn_theta(double direction) const {
    return direction > 0 ? overturn_angle(Corner::left) : -overturn_angle(Corner::right);
  }
  // How far theta is from overturning either way (> 0 inside; pi/2 - |theta| for a rectangle).
  double overturn_margin(double theta) const {
    return std::min(overturn_angle(Corner::left) - theta, overturn_angle(Corner::right) + theta);
  }

  // cos(theta) and sin(theta) (engine/sine_cosine.hpp), remembering the last angle's: the
  // right-hand side at a step's end, the guards there, the contact forces, the observer and the
  // contact resolution all turn the block by the same theta, and remembering its sine and cosine
  // saves 5% of the instructions of the type A pulse on the flat ground. The angle is compared
  // bit for bit (-0 is not +0). Whoever turns the block holds the geometry non-const; the flat
  // simulation owns it and its resolver, rules, systems and observer share it, so a geometry is
  // not to be shared between threads.
  Rotation rotation(double theta) {
    const auto bits = std::bit_cast<std::uint64_t>(theta);
    if (bits != remembered_bits_) {
      const SineCosine turn = sine_cosine(theta);
      remembered_rotation_ = {turn.cos, turn.sin};
      remembered_bits_ = bits;
    }
    return remembered_rotation_;
  }
  // Corner i relative to the centre of mass in the world frame, the block turned by theta.
  Vec2 corner_at(int i, double theta) { return rotate(corner(i), rotation(theta)); }
  Vec2 base_corner_at(Corner c, double theta) { return corner_at(static_cast<int>(c), theta); }

 private:
  std::vector<Vec2> corners_;
  double size_, inertia_per_mass_, rest_height_;
  std::array<double, 2> overturn_angle_;  // by Corner
  // rotation's last angle and value; the bits of a NaN no angle has, so the first call computes.
  std::uint64_t remembered_bits_ = 0x7ff8dead'beefcafeULL;
  Rotation remembered_rotation_{1.0, 0.0};
};

// The geometry of the scene's block: its polygon if it has one, else the rectangle.
inline BlockGeometry scene_geometry(const Scene& scene) {
  return scene.polygon ? BlockGeometry(*scene.polygon) : BlockGeometry(scene.block);
}

// alpha, the angle results are measured in (max |theta| / alpha): atan(a/b) for a rectangle; for a
// polygon, atan of the easier corner's tip threshold, the tilt at which the block balances on that
// corner (the smaller of its two alphas); on a seat, the tilt that balances it on its outermost
// support (engine/scene/seat.hpp).
double block_alpha(const Scene& scene);

}  // namespace blockfrag
