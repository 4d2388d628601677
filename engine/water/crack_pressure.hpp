// The water's pressure in the crack under a block (engine/water/crack_path.hpp) under each uplift
// rule (engine/scene/reservoir.hpp), closed or opened by the shaking, and its resultant. Along the
// crack, s is the length from the mouth and L the crack's length; h is the head at the mouth, c
// the uplift's effective area factor (CADAM3D), rho_w g the water's unit weight.
//
// Closed, the crack holds the static uplift (USACE EM 1110-2-2200, 1995; FERC's guidelines
// chapter III; USBR; compared by Ebeling et al. 2000, ERDC/ITL TR-00-1): the head at the mouth
// falling linearly to zero at the end, on the effective area c:
//   p(s) = c rho_w g h (1 - s / L).
// The shaking may open a part [a, b] of it (a block rocking about either end of its base opens all
// of it but the pivot, a block in flight all of it). Practice brackets the unknown water in it
// (Leclerc, Leger & Tinawi, CADAM; CADAM3D's three options for cracks during earthquakes):
//   unchanged (USACE EM 1110-2-2100, FERC chapter III): the pre-earthquake p(s) stays, opened or
//     not;
//   zero_in_gap (USBR 1987: "uplift pressure within the crack is assumed to be zero"): no
//     pressure on [a, b], p(s) on the closed rest;
//   full_head_in_gap (ICOLD 1986): the full head rho_w g h on [a, b], on the whole area (water
//     fills the opening); opened from the mouth (a = 0), the closed rest carries c rho_w g h at
//     the crack's tip falling linearly to zero at the end (the USACE distribution for a partial
//     crack), otherwise p(s);
//   none: no pressure at all.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "engine/contact/crack_seating.hpp"
#include "engine/scene/reservoir.hpp"
#include "engine/water/water_load.hpp"

namespace blockfrag {

// The part of the crack the shaking has opened, [from, to] as fractions of its length from the
// mouth; from == to: closed.
struct CrackOpening {
  double from = 0.0, to = 0.0;

  static constexpr CrackOpening closed() { return {0.0, 0.0}; }
  // A block rocking about either end of its base (all but the pivot lifts) or in flight.
  static constexpr CrackOpening whole() { return {0.0, 1.0}; }
  // A seated block's crack opened over `fraction` of its length from the side that lifts: from the
  // mouth under a lifting heel, from the end under a lifting toe
  // (engine/contact/crack_seating.hpp).
  static constexpr CrackOpening from_side(LiftingSide side, double fraction) {
    return side == LiftingSide::upstream ? CrackOpening{0.0, fraction}
                                         : CrackOpening{1.0 - fraction, 1.0};
  }
};

// The pressure over [from, to] of the crack's length (m), linear from p_from to p_to (Pa).
struct PressureSpan {
  double from, to, p_from, p_to;
};

struct CrackPressure {
  std::array<PressureSpan, 3> spans{};
  std::size_t count = 0;

  void add(const PressureSpan& span) {
    if (span.to > span.from) spans[count++] = span;
  }
};

// The pressure along a crack of length `length` under `rule`: `closed_mouth` = c rho_w g h, the
// closed crack's pressure at the mouth; `full_head` = rho_w g h. "unchanged" ignores `open` (its
// caller gives the pre-earthquake head). Throws ContractViolation for an opening outside [0, 1] or
// backwards.
CrackPressure crack_pressure(UpliftRule rule, double length, double closed_mouth, double full_head,
                             CrackOpening open);

// One straight piece of the crack with its pressure, pressing on the block whose outward normal
// there is `outward`.
struct PressurePiece {
  Vertex a, b;
  double p_a, p_b;
  Vertex outward;
};

// The lengths of the crack's straight pieces, points[i] to points[i + 1].
std::vector<double> segment_lengths(std::span<const Vertex> points);

// Calls visit(const PressurePiece&) for each piece of the crack `points` (mouth to end, along the
// counter-clockwise block's bottom) under one span of `pressure`; `lengths` are its pieces'
// (segment_lengths: a moving crack keeps its lengths at rest, which place pressure spans found at
// rest where they were).
template <class Visit>
void for_each_pressure_piece(std::span<const Vertex> points, std::span<const double> lengths,
                             const CrackPressure& pressure, Visit&& visit) {
  double s0 = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vertex& a = points[i];
    const Vertex& b = points[i + 1];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = lengths[i];
    const double s1 = s0 + length;
    // A counter-clockwise outline's outward normal is (dy, -dx) / length.
    const Vertex outward{dy / length, -dx / length};
    for (std::size_t k = 0; k < pressure.count; ++k) {
      const PressureSpan& span = pressure.spans[k];
      const double from = std::max(s0, span.from), to = std::min(s1, span.to);
      if (!(to > from)) continue;
      const auto at = [&](double s) -> Vertex {
        const double t = (s - s0) / length;
        return {a[0] + t * dx, a[1] + t * dy};
      };
      const auto p = [&](double s) {
        return span.p_from + (span.p_to - span.p_from) * ((s - span.from) / (span.to - span.from));
      };
      visit(PressurePiece{at(from), at(to), p(from), p(to), outward});
    }
    s0 = s1;
  }
}

template <class Visit>
void for_each_pressure_piece(std::span<const Vertex> points, const CrackPressure& pressure,
                             Visit&& visit) {
  for_each_pressure_piece(points, segment_lengths(points), pressure, visit);
}

// The resultant on the block about `reference` (engine/water/linear_pressure.hpp).
WaterLoad crack_pressure_load(std::span<const Vertex> points, const CrackPressure& pressure,
                              const Vertex& reference);
// The same with the pieces' lengths given (segment_lengths).
WaterLoad crack_pressure_load(std::span<const Vertex> points, std::span<const double> lengths,
                              const CrackPressure& pressure, const Vertex& reference);

}  // namespace blockfrag
