#include "engine/water/crack_pressure.hpp"

#include <algorithm>
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

std::vector<double> segment_lengths(const std::vector<Vertex>& points) {
  std::vector<double> lengths;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    lengths.push_back(std::hypot(points[i + 1][0] - points[i][0], points[i + 1][1] - points[i][1]));
  }
  return lengths;
}

WaterLoad crack_pressure_load(const std::vector<Vertex>& points, const CrackPressure& pressure,
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

std::vector<PressurePlace> pressure_places(std::span<const double> lengths,
                                           const CrackPressure& pressure) {
  // The lengths and spans of for_each_pressure_piece, with each point's place kept.
  std::vector<PressurePlace> places;
  double s0 = 0.0;
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    const double length = lengths[i];
    const double s1 = s0 + length;
    for (std::size_t k = 0; k < pressure.count; ++k) {
      const PressureSpan& span = pressure.spans[k];
      const double from = std::max(s0, span.from), to = std::min(s1, span.to);
      if (!(to > from)) continue;
      const auto weight = [&](double s) { return (s - span.from) / (span.to - span.from); };
      places.push_back({i, k, (from - s0) / length, (to - s0) / length, weight(from), weight(to)});
    }
    s0 = s1;
  }
  return places;
}

WaterLoad crack_pressure_load(std::span<const Vertex> points, std::span<const PressurePlace> places,
                              const CrackPressure& pressure, const Vertex& reference) {
  WaterLoad total;
  for (const PressurePlace& place : places) {
    const Vertex& a = points[place.piece];
    const Vertex& b = points[place.piece + 1];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const PressureSpan& span = pressure.spans[place.span];
    const auto p = [&](double weight) { return span.p_from + (span.p_to - span.p_from) * weight; };
    const WaterLoad load = edge_pressure_load({a[0] + place.t_from * dx, a[1] + place.t_from * dy},
                                              {a[0] + place.t_to * dx, a[1] + place.t_to * dy},
                                              p(place.weight_from), p(place.weight_to), reference);
    total.fx += load.fx;
    total.fy += load.fy;
    total.moment += load.moment;
  }
  return total;
}

}  // namespace blockfrag
