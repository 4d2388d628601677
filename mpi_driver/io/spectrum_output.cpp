#include "mpi_driver/io/spectrum_output.hpp"

#include <algorithm>
#include <limits>

#include "blockfrag/version.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/hdf5_file.hpp"

namespace blockfrag {
namespace {

// Records read from the spool at a time: 64k of them, a few MB.
constexpr std::int64_t kSpoolRecordsPerRead = 1 << 16;

void write_root(Hdf5Writer& file, const SpectrumConfig& config) {
  file.set_attribute("/", "config", canonical_text(config.canonical));
  file.set_attribute("/", "config_hash", hash_to_hex(config.hash));
  file.set_attribute("/", "blockfrag_version", std::string(kVersion));
  file.set_attribute("/", "kind", std::string("overturning spectrum"));
  file.set_attribute("/", "pulse", std::string(spectrum_pulse_name(config.pulse)));
  file.set_attribute("/", "alpha", config.alpha());
  file.set_attribute("/", "tan_alpha", config.tan_alpha());
  file.set_attribute("/", "R", config.R());
  file.set_attribute("/", "p", config.p());
  file.set_attribute("/", "g", config.base_scene.g);
  file.set_attribute("/", "frequency_ratio_definition",
                     std::string("omega_p / p with omega_p = 2 pi / T, T the pulse's period (a "
                                 "rectangular pulse lasts t1 = T / 2 = pi / omega_p), "
                                 "p = sqrt(3 g / (4 R))"));
  file.set_attribute("/", "amplitude_ratio_definition",
                     std::string("a_p / (g tan alpha), a_p the pulse's amplitude (its peak "
                                 "acceleration): 1 is the static tipping threshold"));
  file.set_attribute(
      "/", "units",
      std::string("frequency_ratio and amplitude_ratio 1 (dimensionless); alpha rad; "
                  "R m; p rad/s; g m/s^2; pulse_time_s s; amplitude_g g; "
                  "max_abs_theta rad; overturn_time s"));
}

SpectrumTally write_map(Hdf5Writer& file, const SpectrumConfig& config, const RecordSpool& spool) {
  const auto nf = static_cast<std::int64_t>(config.frequency_ratio.size());
  const auto na = static_cast<std::int64_t>(config.amplitude_ratio.size());
  const std::int64_t total = config.map_points();
  std::vector<std::int64_t> verdict(static_cast<std::size_t>(total)),
      impacts(static_cast<std::size_t>(total));
  std::vector<double> max_abs_theta(static_cast<std::size_t>(total)),
      overturn_time(static_cast<std::size_t>(total));
  SpectrumTally tally;
  std::vector<SampleRecord> records;
  for (std::int64_t first = 0; first < total; first += kSpoolRecordsPerRead) {
    records.resize(static_cast<std::size_t>(std::min(kSpoolRecordsPerRead, total - first)));
    spool.read(first, records);
    for (const SampleRecord& record : records) {
      const std::int64_t index = first + (&record - records.data());
      if (record.index != index)
        throw ContractViolation("the record spool lacks map point " + std::to_string(index));
      const auto at = static_cast<std::size_t>(index);
      const SpectrumVerdict code = spectrum_verdict(record);
      verdict[at] = static_cast<std::int64_t>(code);
      impacts[at] = record.impacts;
      max_abs_theta[at] = record.max_abs_theta;
      overturn_time[at] = record.overturn_time;
      tally.overturned += overturned(code) ? 1 : 0;
      tally.failed += decided(code) ? 0 : 1;
    }
  }
  tally.points = total;
  std::vector<double> pulse_time, amplitude_g;
  for (const double f : config.frequency_ratio)
    pulse_time.push_back(spectrum_pulse_time(config, f));
  for (const double a : config.amplitude_ratio) amplitude_g.push_back(a * config.tan_alpha());
  file.create_group("/map");
  file.write_column("/map/frequency_ratio", config.frequency_ratio);
  file.write_column("/map/amplitude_ratio", config.amplitude_ratio);
  file.write_column("/map/pulse_time_s", pulse_time);
  file.set_attribute(
      "/map/pulse_time_s", "meaning",
      std::string(config.pulse == SpectrumPulse::rectangular ? "the pulse's length t1 (s)"
                                                             : "the pulse's period T (s)"));
  file.write_column("/map/amplitude_g", amplitude_g);
  file.write_matrix("/map/verdict", nf, na, verdict);
  file.set_attribute("/map/verdict", "meaning", spectrum_verdict_meaning());
  file.write_matrix("/map/impacts", nf, na, impacts);
  file.set_attribute("/map/impacts", "meaning",
                     std::string("impacts up to the end of the run (up to the overturning when "
                                 "the block overturned)"));
  file.write_matrix("/map/max_abs_theta", nf, na, max_abs_theta);
  file.write_matrix("/map/overturn_time", nf, na, overturn_time);
  file.set_attribute(
      "/map", "layout",
      std::string("[frequency index][amplitude index]: row i is frequency_ratio[i]"));
  return tally;
}

template <typename T>
void write_field(Hdf5Writer& file, const char* name, const std::vector<SpectrumBracket>& brackets,
                 T (*value)(const SpectrumBracket&)) {
  std::vector<T> values;
  values.reserve(brackets.size());
  for (const SpectrumBracket& bracket : brackets) values.push_back(value(bracket));
  file.write_column(std::string("/boundary/") + name, values);
}

void write_boundary(Hdf5Writer& file, const SpectrumConfig& config,
                    const std::vector<SpectrumBracket>& brackets, SpectrumTally& tally) {
  file.create_group("/boundary");
  write_field<std::int64_t>(file, "frequency_index", brackets,
                            [](const SpectrumBracket& b) { return b.frequency_index; });
  std::vector<double> frequency;
  for (const SpectrumBracket& b : brackets)
    frequency.push_back(config.frequency_ratio[static_cast<std::size_t>(b.frequency_index)]);
  file.write_column("/boundary/frequency_ratio", frequency);
  write_field<double>(file, "amplitude_ratio", brackets,
                      [](const SpectrumBracket& b) { return b.midpoint(); });
  write_field<double>(file, "amplitude_low", brackets,
                      [](const SpectrumBracket& b) { return b.low; });
  write_field<double>(file, "amplitude_high", brackets,
                      [](const SpectrumBracket& b) { return b.high; });
  write_field<std::int64_t>(file, "direction", brackets, [](const SpectrumBracket& b) {
    return static_cast<std::int64_t>(b.direction());
  });
  file.set_attribute("/boundary/direction", "meaning",
                     std::string("+1 the onset of overturning (stands below, overturns above); "
                                 "-1 the end of an overturning band (overturns below, stands "
                                 "above: the lower edge of a safe island)"));
  write_field<std::int64_t>(file, "verdict_low", brackets,
                            [](const SpectrumBracket& b) { return b.verdict_low; });
  write_field<std::int64_t>(file, "verdict_high", brackets,
                            [](const SpectrumBracket& b) { return b.verdict_high; });
  write_field<std::int64_t>(file, "iterations", brackets,
                            [](const SpectrumBracket& b) { return b.iterations; });
  write_field<std::int64_t>(file, "state", brackets,
                            [](const SpectrumBracket& b) { return b.state; });
  file.set_attribute("/boundary/state", "meaning",
                     std::string("1 converged (amplitude_high - amplitude_low <= tolerance x "
                                 "amplitude_high), 2 stopped: a midpoint's scene failed, 3 stopped "
                                 "at max_iterations"));
  file.set_attribute("/boundary", "tolerance", config.bisection_tolerance);
  file.set_attribute("/boundary", "max_iterations",
                     static_cast<std::int64_t>(config.max_iterations));
  file.set_attribute("/boundary", "amplitude_ratio_is",
                     std::string("the midpoint of the final bracket [amplitude_low, "
                                 "amplitude_high], whose ends have verdict_low and verdict_high"));
  for (const SpectrumBracket& b : brackets) {
    (b.direction() > 0 ? tally.onsets : tally.island_edges) += 1;
    tally.converged += b.state == static_cast<std::int64_t>(BracketState::converged) ? 1 : 0;
  }
}

// The map's own minimum of each frequency, without the refinement: its lowest onset as bisected
// (the column's first crossing when that is an onset); none where the map has none or its lowest
// amplitude overturns.
std::vector<const SpectrumBracket*> map_minima(const SpectrumConfig& config,
                                               const std::vector<SpectrumBracket>& brackets) {
  std::vector<const SpectrumBracket*> minima(config.frequency_ratio.size(), nullptr);
  std::vector<bool> seen(minima.size(), false);
  for (const SpectrumBracket& b : brackets) {
    const auto f = static_cast<std::size_t>(b.frequency_index);
    if (seen[f]) continue;
    seen[f] = true;
    if (b.direction() > 0) minima[f] = &b;
  }
  return minima;
}

void count_minima(const std::vector<FrequencyMinimum>& minima,
                  const std::vector<const SpectrumBracket*>& unrefined, SpectrumTally& tally) {
  for (std::size_t f = 0; f < minima.size(); ++f) {
    const auto state = static_cast<MinimumState>(minima[f].state);
    tally.minima_found += state == MinimumState::found ? 1 : 0;
    tally.minima_below_grid += state == MinimumState::below_grid ? 1 : 0;
    tally.minima_uncertain +=
        state == MinimumState::failed || state == MinimumState::capped ? 1 : 0;
    // A lower minimum lies wholly below the map's bracket; otherwise it is that bracket.
    tally.minima_lowered += unrefined[f] && minima[f].high <= unrefined[f]->low ? 1 : 0;
  }
}

void write_minimum(Hdf5Writer& file, const SpectrumConfig& config,
                   const std::vector<SpectrumBracket>& brackets, const MinimumRefinement& minimum,
                   SpectrumTally& tally) {
  const std::vector<FrequencyMinimum> minima = frequency_minima(minimum);
  const std::vector<const SpectrumBracket*> unrefined = map_minima(config, brackets);
  const auto column = [&](auto value) {
    std::vector<decltype(value(minima.front()))> values;
    for (const FrequencyMinimum& m : minima) values.push_back(value(m));
    return values;
  };
  const std::string group = "/minimum_overturning";
  file.create_group(group);
  file.write_column(group + "/frequency_ratio", config.frequency_ratio);
  file.write_column(group + "/amplitude_ratio",
                    column([](const FrequencyMinimum& m) { return m.amplitude_ratio; }));
  file.set_attribute(
      group + "/amplitude_ratio", "meaning",
      std::string("the minimum overturning amplitude ratio, refined: the midpoint of "
                  "[amplitude_low, amplitude_high]; NaN where none was found (state "
                  "2) or it lies below the grid (state 3)"));
  file.write_column(group + "/amplitude_low",
                    column([](const FrequencyMinimum& m) { return m.low; }));
  file.write_column(group + "/amplitude_high",
                    column([](const FrequencyMinimum& m) { return m.high; }));
  file.write_column(group + "/verdict_high",
                    column([](const FrequencyMinimum& m) { return m.verdict_high; }));
  file.set_attribute(group + "/verdict_high", "meaning",
                     "the verdict at amplitude_high (/map/verdict's codes: how the block "
                     "overturns at its minimum), -1 where nothing overturned; " +
                         spectrum_verdict_meaning());
  std::vector<double> map_amplitude;
  for (const SpectrumBracket* b : unrefined)
    map_amplitude.push_back(b ? b->midpoint() : std::numeric_limits<double>::quiet_NaN());
  file.write_column(group + "/map_amplitude_ratio", map_amplitude);
  file.set_attribute(group + "/map_amplitude_ratio", "meaning",
                     std::string("the minimum without the refinement: the map's lowest onset as "
                                 "bisected (/boundary), NaN where the map has none or its lowest "
                                 "amplitude overturns"));
  file.write_column(group + "/state", column([](const FrequencyMinimum& m) { return m.state; }));
  file.set_attribute(
      group + "/state", "meaning",
      std::string("1 found: amplitude_high overturns, amplitude_low stands, amplitude_high - "
                  "amplitude_low <= tolerance x amplitude_high, and every interval below it "
                  "between standing amplitudes with max |theta| / alpha >= near_overturning at "
                  "an end was probed down to the resolution; 2 none: nothing overturned in the "
                  "grid's range; 3 below the grid: the lowest map amplitude overturns "
                  "(amplitude_high); 4 a point below the minimum failed; 5 max_midpoints ran out"));
  file.write_column(group + "/midpoints",
                    column([](const FrequencyMinimum& m) { return m.midpoints; }));
  const MinimumOverturningSettings& settings = config.minimum_overturning;
  file.set_attribute(group, "tolerance", settings.tolerance);
  file.set_attribute(group, "resolution", settings.resolution);
  file.set_attribute(group, "near_overturning", settings.near_overturning);
  file.set_attribute(group, "max_midpoints", settings.max_midpoints);
  count_minima(minima, unrefined, tally);
}

}  // namespace

SpectrumTally write_spectrum_output(const std::filesystem::path& path, const SpectrumConfig& config,
                                    const RecordSpool& spool,
                                    const std::vector<SpectrumBracket>& brackets,
                                    const MinimumRefinement& minimum) {
  SpectrumTally tally;
  replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5Writer file(temporary);
    write_root(file, config);
    tally = write_map(file, config, spool);
    write_boundary(file, config, brackets, tally);
    write_minimum(file, config, brackets, minimum, tally);
    file.close();
  });
  return tally;
}

}  // namespace blockfrag
