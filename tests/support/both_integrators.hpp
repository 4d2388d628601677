// A fixture for hard-case tests that must hold with the paper's RK4 and the adaptive method alike.
#pragma once

#include <gtest/gtest.h>

#include "engine/scene.hpp"

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

}  // namespace blockfrag::testing
