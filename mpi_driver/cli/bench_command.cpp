#include "mpi_driver/cli/bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <vector>

#include "engine/simulate.hpp"
#include "mpi_driver/accuracy/accuracy_metrics.hpp"
#include "mpi_driver/cli/simulate_command.hpp"
#include "mpi_driver/config/scene_json.hpp"
#include "mpi_driver/io/summary_json.hpp"
#include "postproc/fragility/sample_quantile.hpp"

namespace blockfrag {

int run_bench(const BenchOptions& options, std::ostream& out) {
  using Clock = std::chrono::steady_clock;
  const Scene scene = read_scene_file(options.scene_path);
  const Summary summary = simulate(scene);  // the warm-up: caches, page faults, lazy binding
  std::vector<double> microseconds;
  microseconds.reserve(static_cast<std::size_t>(options.repeat));
  for (long i = 0; i < options.repeat; ++i) {
    const auto start = Clock::now();
    simulate(scene);
    microseconds.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  const nlohmann::json result = {
      {"scene", options.scene_path.string()},
      {"solver", scene_to_json(scene)["solver"]},
      {"repeat", options.repeat},
      {"median_us", sample_quantile(microseconds, 0.5)},
      {"min_us", *std::min_element(microseconds.begin(), microseconds.end())},
      {"max_us", *std::max_element(microseconds.begin(), microseconds.end())},
      {"steps", summary.steps},
      {"rhs_evaluations", summary.rhs_evaluations},
      {"summary", summary_to_json(summary)}};
  out << result.dump() << '\n';
  out.flush();
  return summary.status == Status::ok ? 0 : exit_code_simulation_failed;
}

}  // namespace blockfrag
