// A fixture for hard-case tests that must hold with the paper's RK4 and the adaptive method alike.
#pragma once

#include <array>
#include <initializer_list>

#include <gtest/gtest.h>

#include "engine/scene/scene.hpp"
#include "engine/simulate.hpp"

namespace blockfrag::testing {

class BothMethods : public ::testing::TestWithParam<Method> {
 protected:
  // The scene as given (adaptive), or with the paper's RK4 at its dt.
  Scene with_method(Scene scene) const {
    if (GetParam() == Method::rk4) {
      scene.solver.method = Method::rk4;
      scene.solver.dt = 2.5e-4;
    }
    return scene;
  }
};

// One scene with the adaptive method and with the paper's RK4 (its dt), for tests that compare
// them: each run must finish inside the contact laws, above the ground, and begin with the given
// modes.
inline std::array<Summary, 2> simulate_with_both_methods(
    Scene scene, std::initializer_list<ModeKind> first_modes) {
  std::array<Summary, 2> runs;
  for (const Method method : {Method::adaptive, Method::rk4}) {
    scene.solver.method = method;
    Summary& s = runs[method == Method::adaptive ? 0 : 1];
    s = simulate(scene);
    SCOPED_TRACE(method == Method::adaptive ? "adaptive" : "rk4");
    EXPECT_EQ(s.status, Status::ok);
    EXPECT_LT(s.max_contact_violation, 1e-9);
    EXPECT_LT(s.max_penetration, 1e-9);
    EXPECT_GE(s.modes.size(), first_modes.size());
    std::size_t i = 0;
    for (const ModeKind mode : first_modes) {
      if (i < s.modes.size()) {
        EXPECT_EQ(s.modes[i].mode, mode) << "mode " << i;
      }
      ++i;
    }
  }
  return runs;
}

}  // namespace blockfrag::testing
