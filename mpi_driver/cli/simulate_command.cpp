#include "mpi_driver/cli/simulate_command.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "engine/scene/block_geometry.hpp"
#include "engine/simulate.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/io/history_csv.hpp"
#include "mpi_driver/io/output_target.hpp"
#include "mpi_driver/io/summary_json.hpp"

namespace blockfrag {

namespace {

// A history longer than this (about 1 GB of CSV) is refused before the run: rows are held in
// memory until the file is written.
constexpr double kMaxHistoryRows = 1e7;

// Past this many the mode sequence of a chattering block says nothing more to a reader.
constexpr std::size_t modes_shown = 20;

// Six significant digits: enough to read, not to compare (--summary-json is for that).
std::string fixed(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string time_or_never(const std::optional<double>& time) {
  return time ? "t = " + fixed(*time) + " s" : "never";
}

const char* alpha_meaning(const Scene& scene) {
  if (scene.seat) return "the tilt that balances the block on its outermost support";
  return scene.polygon ? "atan(easier corner's tip threshold)" : "atan(a/b)";
}

}  // namespace

void write_simulate_report(std::ostream& out, const Scene& scene, const Summary& summary) {
  const double alpha = block_alpha(scene);
  if (summary.status == Status::failed) {
    out << "verdict: simulation FAILED at t = " << fixed(summary.end_time)
        << " s: " << summary.status_reason << "\n";
  } else if (summary.overturned) {
    out << "verdict: overturned at " << time_or_never(summary.overturn_time) << "\n";
  } else if (summary.fell) {
    out << "verdict: fell off the seat's end at " << time_or_never(summary.fell_time) << "\n";
  } else {
    out << "verdict: did not overturn\n";
  }
  out << "settled: "
      << (summary.settled ? "yes, at " + time_or_never(summary.settle_time)
                          : std::string("no (still moving, or the motion goes on, at the end)"))
      << "\n";
  out << "max |theta|: " << fixed(summary.max_abs_theta)
      << " rad = " << fixed(summary.max_abs_theta / alpha)
      << " alpha (alpha = " << alpha_meaning(scene) << " = " << fixed(alpha) << " rad)\n"
      << "final theta: " << fixed(summary.final_theta) << " rad\n"
      << "slide: final " << fixed(summary.final_slide) << " m, max |slide| "
      << fixed(summary.max_abs_slide) << " m\n"
      << "rocking starts: " << time_or_never(summary.rock_start_time) << "\n"
      << "sliding starts: " << time_or_never(summary.slide_start_time) << "\n"
      << "first impact: " << time_or_never(summary.first_impact_time)
      << "; impacts: " << summary.impacts << "\n"
      << "modes:";
  for (std::size_t i = 0; i < summary.modes.size() && i < modes_shown; ++i) {
    out << (i == 0 ? " " : " -> ") << mode_name(summary.modes[i].mode) << " ("
        << fixed(summary.modes[i].time) << " s)";
  }
  if (summary.modes.size() > modes_shown)
    out << " ... and " << summary.modes.size() - modes_shown << " more";
  out << "\n";
  if (summary.post_earthquake) {
    const auto factor = [](const std::optional<double>& f) {
      return f ? (std::isinf(*f) ? std::string("infinite") : fixed(*f)) : std::string("none");
    };
    out << "after the earthquake (full uplift): sliding safety factor "
        << factor(summary.post_earthquake->sliding_safety_factor) << ", overturning safety factor "
        << factor(summary.post_earthquake->overturning_safety_factor)
        << (summary.post_earthquake->sliding_safety_factor ? ""
                                                           : " (the block does not stand at rest)")
        << "\n";
  }
  out << "end time: " << fixed(summary.end_time) << " s; " << summary.steps << " steps, "
      << summary.rhs_evaluations << " right-hand-side evaluations, " << summary.events
      << " events\n";
}

int run_simulate(const SimulateOptions& options, std::ostream& out) {
  const Scene scene = read_scene_file(options.scene_path);
  if (options.history_path) {
    const double longest = scene_run_end_time(scene);
    if (longest / options.history_interval > kMaxHistoryRows) {
      throw ConfigError({"--history-interval: " + fixed(options.history_interval) +
                         " s over the scene's " + fixed(longest) + " s would write more than " +
                         fixed(kMaxHistoryRows) + " rows; choose at least " +
                         fixed(longest / kMaxHistoryRows) + " s"});
    }
    check_output_targets({{*options.history_path, "--history", "a history CSV", is_history_csv}},
                         {{options.scene_path, "the scene"}});
  }
  Summary summary;
  if (options.history_path) {
    auto result = simulate_with_history(scene, options.history_interval);
    write_history_csv_file(*options.history_path, result.history);
    summary = std::move(result.summary);
  } else {
    summary = simulate(scene);
  }
  if (options.summary_json) {
    out << summary_to_json(summary).dump() << '\n';
  } else {
    write_simulate_report(out, scene, summary);
  }
  out.flush();
  return summary.status == Status::ok ? 0 : exit_code_simulation_failed;
}

}  // namespace blockfrag
