#include "mpi_driver/cli/statics_command.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/scene/scene_validation.hpp"
#include "engine/water/block_statics.hpp"
#include "mpi_driver/config/reservoir_json.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/io/statics_json.hpp"

namespace blockfrag {

namespace {

// Six significant digits: enough to read, not to compare (--summary-json is for that).
std::string readable(double x) {
  if (std::isinf(x)) return x > 0 ? "never" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string water_of(const Scene& scene) {
  if (!scene.reservoir) return "no reservoir (dry)";
  const Reservoir& r = *scene.reservoir;
  return "level " + readable(r.level) + " m, depth " + readable(r.depth) + " m, density " +
         readable(r.density) + " kg/m^3, hydrodynamic " + hydrodynamic_name(r.hydrodynamic) +
         ", uplift " + uplift_rule_name(r.uplift) + " (area factor " +
         readable(r.uplift_area_factor) + ")";
}

void write_statics_report(std::ostream& out, const Scene& scene, const BlockStatics& statics,
                          std::optional<double> coefficient, std::optional<SafetyFactors> factors) {
  const YieldAccelerations& y = statics.yield;
  out << "water: " << water_of(scene) << "\n"
      << "loads at rest (per metre of dam when the block's mass is per metre; x downstream, y "
         "up):\n"
      << "  weight:            " << readable(statics.weight) << " N\n"
      << "  hydrostatic force: [" << readable(statics.hydrostatic_x) << ", "
      << readable(statics.hydrostatic_y) << "] N\n"
      << "  uplift:            " << readable(statics.uplift_y) << " N up, "
      << readable(statics.uplift_x) << " N along x\n"
      << "  added mass:        " << readable(statics.added_mass) << " kg\n"
      << "yield acceleration of the ground (g; 'never': no acceleration that way starts it):\n"
      << "  slide downstream: " << readable(y.slide_downstream) << "\n"
      << "  slide upstream:   " << readable(y.slide_upstream) << "\n"
      << "  rock downstream:  " << readable(y.rock_downstream) << "\n"
      << "  rock upstream:    " << readable(y.rock_upstream) << "\n";
  if (coefficient && factors) {
    out << "pseudo-static at K = " << readable(*coefficient)
        << " (seismic load downstream; 'never': nothing drives it):\n"
        << "  sliding safety factor:     " << readable(factors->sliding) << "\n"
        << "  overturning safety factor: " << readable(factors->overturning) << "\n";
  }
}

}  // namespace

int run_statics(const StaticsOptions& options, std::ostream& out) {
  const Scene scene = read_scene_file(options.scene_path);
  validate_scene(scene);
  const BlockStatics statics = block_statics(scene);
  std::optional<SafetyFactors> factors;
  if (options.coefficient) factors = pseudo_static_safety_factors(scene, *options.coefficient);
  if (options.summary_json) {
    out << statics_to_json(statics, options.coefficient, factors).dump() << '\n';
  } else {
    write_statics_report(out, scene, statics, options.coefficient, factors);
  }
  out.flush();
  return 0;
}

}  // namespace blockfrag
