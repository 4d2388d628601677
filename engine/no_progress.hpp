// The rules that fail a run whose contact state keeps changing while time does not move on: more
// than kMaxInstantEvents contact changes within kInstant (1 + t) s of one another, or more than
// kMaxStandstillEvents events in a row that leave the block where it was (engine/tolerances.hpp).
#pragma once

#include <string>

#include "engine/errors.hpp"
#include "engine/scene/block_state.hpp"
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

  // An event at t that ended a stretch with the block at pose s. Counted to the bit: a block that
  // moves at all, however slowly, changes its pose's bits within a few events.
  void count_pose(double t, const BlockState& s) {
    if (standstill_ > 0 && s.x == pose_.x && s.y == pose_.y && s.theta == pose_.theta) {
      ++standstill_;
    } else {
      standstill_ = 1;
      pose_ = s;
    }
    if (standstill_ > kMaxStandstillEvents) {
      throw SimulationFailure(
          "no progress: " + std::to_string(kMaxStandstillEvents) +
          " events in a row without the block moving, at t = " + std::to_string(t) + " s");
    }
  }

 private:
  double instant_start_ = 0.0;  // the first change of the instant the latest changes are in
  int events_ = 0;
  BlockState pose_;     // where the latest events left the block
  int standstill_ = 0;  // how many events in a row left it there
};

}  // namespace blockfrag
