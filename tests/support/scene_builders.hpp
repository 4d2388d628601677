// Small builders for the scenes the physics tests use, and the closed forms they compare against.
#pragma once

#include <cmath>

#include "engine/scene/scene.hpp"

namespace blockfrag::testing {

inline Scene block_scene(double a, double b, double mu, double e, GroundMotion motion,
                         double duration, double tolerance = 1e-10) {
  Scene scene;
  scene.block = {a, b, 1.0};
  scene.contact = {mu, e};
  scene.ground_motion = motion;
  scene.duration = duration;
  scene.solver.method = Method::adaptive;
  scene.solver.tolerance = tolerance;
  return scene;
}

inline Scene rk4(Scene scene, double dt) {
  scene.solver.method = Method::rk4;
  scene.solver.dt = dt;
  return scene;
}

// Housner's frequency parameter p = sqrt(3 g / (4 R)).
inline double housner_p(double a, double b, double g = 9.81) {
  return std::sqrt(3.0 * g / (4.0 * std::hypot(a, b)));
}

}  // namespace blockfrag::testing
