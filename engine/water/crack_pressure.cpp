#include "engine/water/crack_pressure.hpp"

#include <cmath>

#include "engine/errors.hpp"
#include "engine/water/linear_pressure.hpp"

namespace blockfrag {

CrackPressure crack_pressure(UpliftRule rule, double length, double closed_mouth, double full_head,
                             CrackOpening open) {
  if (!(open.from >= 0.0 && open.from <= open.to && open.to <= 1.0)) {
    throw ContractViolation("crack_pressure: the opening must be [from, to] within [0, 1]");
  }
  CrackPressure pressure;
  if (!(length > 0.0)) return pressure;  // a crack of no length: the block rests on a point
  // The static distribution p(s) = closed_mouth (1 - s / L) over [from, to].
  const auto static_span = [&](double from, double to) {
    return PressureSpan{from, to, closed_mouth * (1.0 - from / length),
                        closed_mouth * (1.0 - to / length)};
  };
  const double a = open.from * length, b = open.to * length;
  switch (rule) {
    case UpliftRule::none: break;
    case UpliftRule::unchanged: pressure.add(static_span(0.0, length)); break;
    case UpliftRule::zero_in_gap:
      pressure.add(static_span(0.0, a));
      pressure.add(static_span(b, length));
      break;
    case UpliftRule::full_head_in_gap:
      if (b > a && a == 0.0) {
        pressure.add({0.0, b, full_head, full_head});
        pressure.add({b, length, closed_mouth, 0.0});
      } else {
        pressure.add(static_span(0.0, a));
        pressure.add({a, b, full_head, full_head});
        pressure.add(static_span(b, length));
      }
      break;
  }
  return pressure;
}

std::vector<double> segment_lengths(std::span<const Vertex> points) {
  std::vector<double> lengths;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    lengths.push_back(std::hypot(points[i + 1][0] - points[i][0], points[i + 1][1] - points[i][1]));
  }
  return lengths;
}

WaterLoad crack_pressure_load(std::span<const Vertex> points, const CrackPressure& pressure,
                              const Vertex& reference) {
  return crack_pressure_load(points, segment_lengths(points), pressure, reference);
}

WaterLoad crack_pressure_load(std::span<const Vertex> points, std::span<const double> lengths,
                              const CrackPressure& pressure, const Vertex& reference) {
  WaterLoad total;
  for_each_pressure_piece(points, lengths, pressure, [&](const PressurePiece& piece) {
    const WaterLoad load = edge_pressure_load(piece.a, piece.b, piece.p_a, piece.p_b, reference);
    total.fx += load.fx;
    total.fy += load.fy;
    total.moment += load.moment;
  });
  return total;
}

}  // namespace blockfrag
