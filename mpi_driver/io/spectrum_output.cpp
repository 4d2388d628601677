#include "mpi_driver/io/spectrum_output.hpp"

#include <algorithm>

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

}  // namespace

SpectrumTally write_spectrum_output(const std::filesystem::path& path, const SpectrumConfig& config,
                                    const RecordSpool& spool,
                                    const std::vector<SpectrumBracket>& brackets) {
  SpectrumTally tally;
  replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5Writer file(temporary);
    write_root(file, config);
    tally = write_map(file, config, spool);
    write_boundary(file, config, brackets, tally);
    file.close();
  });
  return tally;
}

}  // namespace blockfrag
