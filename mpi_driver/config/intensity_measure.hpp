// A study's intensity measure: what its levels mean and how a sample's motion is scaled to one.
//   "intensity_measure": {"type": "pga", "levels": [0.1, 0.2, ...]}       (stripes, in g)
//   {"type": "pgv", "from": 0.1, "to": 1.5, "count": 15}                    (m/s)
//   {"type": "sa", "period": 1.0, "damping": 0.05, "levels": [...]}         (g)
//   {"type": "pga_over_g_tan_alpha", "levels": [...]}                        (dimensionless)
//   {"type": "pulse_amplitude", ...}  the default for pulses: the pulse's amplitude_g (g)
//   {"type": "pga", "scaling": "none", "scale": 1.0}  a cloud: every motion as recorded (times a
//   fixed scale), each sample's own measure recorded.
//   {"type": "pulse_amplitude", "levels": [...], "second": {"type": "pulse_period", "levels":
//   [0.5, 1, 2]}}  a grid for a fragility surface: every level of the first measure at every
//   period (s) of the pulse.
// Stripes scale each sample's motion so that its measure equals the level; the direction input
// gives the sign. The measures are of the foundation's horizontal motion as the sample ran it.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

enum class ImType { pulse_amplitude, pga, pgv, sa, pga_over_g_tan_alpha };

struct IntensityMeasure {
  ImType type = ImType::pulse_amplitude;
  double period = 1.0;         // sa: the oscillator's period T, s, in (0, 10]
  double damping = 0.05;       // sa: its damping ratio, in [0, 1)
  bool cloud = false;          // "scaling": "none"
  double scale = 1.0;          // cloud: the factor on every motion (its sign from direction)
  std::vector<double> levels;  // stripes: > 0, increasing, in the measure's unit; cloud: none
  // A fragility surface's second axis: the pulse's period in s, increasing (the one second
  // measure: a cosine pulse's PGV/PGA is proportional to it); empty for a study of one measure.
  std::vector<double> periods;

  bool surface() const { return !periods.empty(); }
  // The study's levels: its cells for a surface, cell c at (levels[c / n2], periods[c % n2]).
  std::size_t level_count() const {
    return cloud ? 1 : levels.size() * (surface() ? periods.size() : 1);
  }
  // The first measure's level of a cell (of a level, for a study of one measure).
  std::size_t first_level(std::size_t cell) const {
    return surface() ? cell / periods.size() : cell;
  }
};

// The most cells a fragility surface's grid may have: its fit's separation check is cubic in them.
inline constexpr std::size_t kMaxSurfaceCells = 1000;

// "pga", "pgv", "sa", "pga_over_g_tan_alpha", "pulse_amplitude".
const char* im_type_name(ImType type);
// "g", "m/s", or "1" for the dimensionless measure.
const char* im_unit(ImType type);
// The name a plot or a message gives it: "PGA", "Sa(1 s, 5 %)", "PGA/(g tan alpha)", ...
std::string im_label(const IntensityMeasure& measure);

// The largest level a study may have in the measure's unit (far past any earthquake).
double largest_level(ImType type);

// Reads the measure; `default_type` is the one a study's motion takes without a "type".
IntensityMeasure read_intensity_measure(ObjectReader reader, ImType default_type);
nlohmann::json intensity_measure_to_json(const IntensityMeasure& measure);

}  // namespace blockfrag
