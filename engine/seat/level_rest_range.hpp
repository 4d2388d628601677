// The lambda range of rest of a dry block standing on a level line (the flat ground, or a seat of
// one horizontal segment) on two of its vertices or more: it slides once |lambda| passes the
// friction coefficient, and tips about its outermost contact on the side lambda pushes it to once
// lambda passes that contact's arm over its depth below the centre of mass (x / -y of the
// contact's r), whichever comes first. The flat ground's thresholds; on a seat, the contact
// problem's rest search (SeatSimulation::set_rest_thresholds) finds the same to its tolerance
// (kRestTolerance of g: about 1.4e-13 above each, measured), at about a million instructions a
// rest against a few dozen here: a study's every scene starts at rest.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

#include "engine/contact/planar_contact.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

struct RestRange {
  double low, high;  // rest holds for low <= lambda / (1 + lambda_v) <= high
};

// The range where every contact is a block vertex pushed straight up (normal (0, 1) exactly) and
// the centre of mass is strictly between the outermost two; none otherwise (the search decides).
inline std::optional<RestRange> level_rest_range(std::span<const PlanarContact> contacts,
                                                 double friction) {
  if (contacts.size() < 2) return std::nullopt;
  const PlanarContact* left = &contacts[0];
  const PlanarContact* right = &contacts[0];
  for (const PlanarContact& c : contacts) {
    if (c.kind != ContactKind::block_vertex || c.normal.x != 0.0 || c.normal.y != 1.0) {
      return std::nullopt;
    }
    if (c.r.x < left->r.x) left = &c;
    if (c.r.x > right->r.x) right = &c;
  }
  if (!(left->r.x < 0.0 && right->r.x > 0.0 && left->r.y < 0.0 && right->r.y < 0.0)) {
    return std::nullopt;
  }
  // Past kRestSearchLimit rest holds for any lambda, as the search has it.
  const auto threshold = [&](const PlanarContact& c) {
    const double lambda = std::min(friction, std::abs(c.r.x) / -c.r.y);
    return lambda >= kRestSearchLimit ? std::numeric_limits<double>::infinity() : lambda;
  };
  return RestRange{-threshold(*left), threshold(*right)};
}

}  // namespace blockfrag
