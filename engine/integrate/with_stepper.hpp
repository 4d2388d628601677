// Calls fn with the stepper a scene's solver names: the loops that take it are instantiated per
// stepper, so no call per step or per right-hand side goes through a virtual function.
#pragma once

#include "engine/integrate/dormand_prince_stepper.hpp"
#include "engine/integrate/gsl_stepper.hpp"
#include "engine/integrate/rk4_stepper.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

template <int N, class Fn>
void with_scene_stepper(const SolverSettings& solver, const OdeState<N>& scale, Fn&& fn) {
  switch (solver.method) {
    case Method::rk4: {
      Rk4Stepper<N> stepper(solver.dt);
      fn(stepper);
      return;
    }
    case Method::adaptive: {
      DormandPrinceStepper<N> stepper(solver.tolerance, scale);
      fn(stepper);
      return;
    }
    case Method::gsl_rkf45:
    case Method::gsl_rk8pd: {
      GslStepper<N> stepper(
          solver.method == Method::gsl_rkf45 ? GslStepperKind::rkf45 : GslStepperKind::rk8pd,
          solver.tolerance, scale);
      fn(stepper);
      return;
    }
  }
}

}  // namespace blockfrag
