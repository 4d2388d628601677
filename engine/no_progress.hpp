// The rule that fails a run whose contact state keeps changing while time does not move on: more
// than kMaxInstantEvents contact changes within kInstant (1 + t) s of one another
// (engine/tolerances.hpp).
#pragma once

#include <string>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

class NoProgressGuard {
 public:
  // A contact change at t; throws SimulationFailure past the limit.
  void count_event(double t) {
    if (t - instant_start_ > kInstant * (1.0 + t)) {
      instant_start_ = t;
      events_ = 0;
    } else {
      ++events_;
    }
    if (events_ > kMaxInstantEvents) {
      throw SimulationFailure("no progress: " + std::to_string(kMaxInstantEvents) +
                              " contact changes within 1e-6 (1 + t) s of t = " + std::to_string(t) +
                              " s");
    }
  }

 private:
  double instant_start_ = 0.0;  // the first change of the instant the latest changes are in
  int events_ = 0;
};

}  // namespace blockfrag
