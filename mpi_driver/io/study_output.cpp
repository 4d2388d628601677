#include "mpi_driver/io/study_output.hpp"

#include <algorithm>
#include <cmath>

#include "blockfrag/version.hpp"
#include "engine/scene/block_geometry.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/hdf5_file.hpp"
#include "mpi_driver/study/fragility_tally.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

// Samples at a time in the streaming pass: 64k records and their columns, a few tens of MB.
constexpr std::int64_t kSamplesPerPass = 1 << 16;

// The /samples and /results columns of one block of samples, written where they belong.
class SampleColumns {
 public:
  explicit SampleColumns(const StudyConfig& config)
      : config_(config), inputs_(config.inputs.size()) {}

  // Creates every column, full length, empty.
  void create(Hdf5Writer& file) const {
    const std::int64_t total = config_.total_samples();
    using Type = Hdf5Writer::ColumnType;
    file.create_group("/samples");
    for (const auto& input : config_.inputs) {
      file.create_column(std::string("/samples/") + input_key(input.input), total, Type::float64);
    }
    file.create_column("/samples/level", total, Type::int64);
    file.create_column("/samples/im", total, Type::float64);
    file.set_attribute("/samples/im", "units", std::string(im_unit(config_.intensity.type)));
    if (config_.intensity.surface()) {
      file.create_column("/samples/im2", total, Type::float64);
      file.set_attribute("/samples/im2", "units", std::string("s"));
    }
    for (const char* name : {"/samples/scale", "/samples/pga_g", "/samples/pgv_m_s"}) {
      file.create_column(name, total, Type::float64);
    }
    if (config_.suite) file.create_column("/samples/record", total, Type::int64);
    file.create_group("/results");
    for (const char* name :
         {"status", "overturned", "impacts", "steps", "rhs_evaluations", "settled", "fell"}) {
      file.create_column(std::string("/results/") + name, total, Type::int64);
    }
    for (const char* name : {"max_abs_theta", "final_theta", "final_slide", "max_abs_slide",
                             "overturn_time", "settle_time", "fell_time"}) {
      file.create_column(std::string("/results/") + name, total, Type::float64);
    }
    if (config_.base_scene.reservoir) {
      file.create_column("/results/post_earthquake_safety_factor", total, Type::float64);
    }
    file.set_attribute(
        "/results/status", "meaning",
        std::string("0 ok, 1 failed (engine budget exceeded), 2 rejected (invalid scene)"));
  }

  void clear() {
    for (auto& values : inputs_) values.clear();
    level_.clear();
    record_.clear();
    im_.clear();
    im2_.clear();
    scale_.clear();
    pga_.clear();
    pgv_.clear();
  }

  void add(const StudySample& sample) {
    for (std::size_t k = 0; k < inputs_.size(); ++k) inputs_[k].push_back(sample.values[k]);
    level_.push_back(sample.level);
    record_.push_back(sample.record);
    im_.push_back(sample.im);
    im2_.push_back(sample.im2);
    scale_.push_back(sample.scale);
    pga_.push_back(sample.pga_g);
    pgv_.push_back(sample.pgv_m_s);
  }

  void write(Hdf5Writer& file, std::int64_t first, const std::vector<SampleRecord>& records) const {
    for (std::size_t k = 0; k < inputs_.size(); ++k) {
      file.write_part(std::string("/samples/") + input_key(config_.inputs[k].input), first,
                      std::span<const double>(inputs_[k]));
    }
    file.write_part("/samples/level", first, std::span<const std::int64_t>(level_));
    file.write_part("/samples/im", first, std::span<const double>(im_));
    if (config_.intensity.surface())
      file.write_part("/samples/im2", first, std::span<const double>(im2_));
    file.write_part("/samples/scale", first, std::span<const double>(scale_));
    file.write_part("/samples/pga_g", first, std::span<const double>(pga_));
    file.write_part("/samples/pgv_m_s", first, std::span<const double>(pgv_));
    if (config_.suite)
      file.write_part("/samples/record", first, std::span<const std::int64_t>(record_));
    write_field(file, "status", first, records, &SampleRecord::status);
    write_field(file, "overturned", first, records, &SampleRecord::overturned);
    write_field(file, "impacts", first, records, &SampleRecord::impacts);
    write_field(file, "steps", first, records, &SampleRecord::steps);
    write_field(file, "rhs_evaluations", first, records, &SampleRecord::rhs_evaluations);
    write_field(file, "max_abs_theta", first, records, &SampleRecord::max_abs_theta);
    write_field(file, "final_theta", first, records, &SampleRecord::final_theta);
    write_field(file, "final_slide", first, records, &SampleRecord::final_slide);
    write_field(file, "max_abs_slide", first, records, &SampleRecord::max_abs_slide);
    write_field(file, "overturn_time", first, records, &SampleRecord::overturn_time);
    write_field(file, "settled", first, records, &SampleRecord::settled);
    write_field(file, "settle_time", first, records, &SampleRecord::settle_time);
    write_field(file, "fell", first, records, &SampleRecord::fell);
    write_field(file, "fell_time", first, records, &SampleRecord::fell_time);
    if (config_.base_scene.reservoir) {
      write_field(file, "post_earthquake_safety_factor", first, records,
                  &SampleRecord::post_earthquake_safety_factor);
    }
  }

 private:
  template <typename T>
  static void write_field(Hdf5Writer& file, const char* name, std::int64_t first,
                          const std::vector<SampleRecord>& records, T SampleRecord::*field) {
    std::vector<T> values;
    values.reserve(records.size());
    for (const auto& record : records) values.push_back(record.*field);
    file.write_part(std::string("/results/") + name, first, std::span<const T>(values));
  }

  const StudyConfig& config_;
  std::vector<std::vector<double>> inputs_;
  std::vector<std::int64_t> level_, record_;
  std::vector<double> im_, im2_, scale_, pga_, pgv_;
};

// The suite's records as recorded: what /samples/record indexes.
void write_records(Hdf5Writer& file, const RecordSuite& suite, const IntensityMeasure& measure) {
  std::vector<std::string> names, verticals;
  std::vector<double> weight, pga, pgv, duration, sa;
  for (const auto& record : suite.records) {
    names.push_back(record.file);
    verticals.push_back(record.vertical_file);
    weight.push_back(record.weight);
    pga.push_back(record.measures.pga_g);
    pgv.push_back(record.measures.pgv);
    duration.push_back(record.measures.significant_duration);
    if (!record.measures.sa_g.empty()) sa.push_back(record.measures.sa_g.front());
  }
  file.create_group("/records");
  file.write_column("/records/file", names);
  file.write_column("/records/vertical", verticals);
  file.write_column("/records/weight", weight);
  file.write_column("/records/pga_g", pga);
  file.write_column("/records/pgv_m_s", pgv);
  file.write_column("/records/duration_s", duration);
  if (measure.type == ImType::sa) {
    file.write_column("/records/sa_g", sa);
    file.set_attribute("/records/sa_g", "period_s", measure.period);
    file.set_attribute("/records/sa_g", "damping", measure.damping);
  }
}

std::string joined_names(const StudyConfig& config, const std::vector<std::size_t>& indices) {
  std::string names;
  for (const std::size_t k : indices) {
    if (!names.empty()) names += ',';
    names += config.limit_states[k].name;
  }
  return names;
}

void write_curve(Hdf5Writer& file, const std::string& group, const LimitState& state,
                 const FragilityCurve& curve) {
  file.create_group(group);
  file.write_column(group + "/im", curve.im);
  file.write_column(group + "/trials", curve.trials);
  file.write_column(group + "/exceedances", curve.exceedances);
  file.write_column(group + "/probability", curve.probability);
  file.write_column(group + "/ci_low", curve.ci_low);
  file.write_column(group + "/ci_high", curve.ci_high);
  file.set_attribute(group, "type", std::string(limit_state_kind_name(state.kind)));
  file.set_attribute(group, "threshold", state.threshold);
  file.set_attribute(group, "overturned_exceeds",
                     static_cast<std::int64_t>(state.overturned_exceeds ? 1 : 0));
  file.set_attribute(group, "median", curve.median);
  file.set_attribute(group, "beta", curve.beta);
  file.set_attribute(group, "log_likelihood", curve.log_likelihood);
  file.set_attribute(group, "fit_status", curve.fit_status);
  file.set_attribute(group, "median_low", curve.median_low);
  file.set_attribute(group, "median_high", curve.median_high);
  file.set_attribute(group, "interval", std::string("Wilson score, 95 %"));
  file.set_attribute(group, "median_se", curve.median_se);
  file.set_attribute(group, "beta_se", curve.beta_se);
  file.set_attribute(group, "deviance", curve.deviance);
  file.set_attribute(group, "gof_dof", static_cast<std::int64_t>(curve.gof_dof));
  file.set_attribute(group, "gof_p_value", curve.gof_p_value);
  file.set_attribute(group, "max_misfit", curve.max_misfit);
  const BootstrapResult& boot = curve.bootstrap;
  file.set_attribute(group, "bootstrap_resamples", static_cast<std::int64_t>(boot.resamples));
  file.set_attribute(group, "bootstrap_fitted", static_cast<std::int64_t>(boot.fitted));
  if (boot.fitted == 0) return;
  file.set_attribute(group, "median_ci", std::vector<double>{boot.median_low, boot.median_high});
  file.set_attribute(group, "beta_ci", std::vector<double>{boot.beta_low, boot.beta_high});
  file.write_column(group + "/band_im", boot.band_im);
  file.write_column(group + "/band_low", boot.band_low);
  file.write_column(group + "/band_high", boot.band_high);
}

// The common-beta fit (docs/studies.md, "Nested fits"): /fragility's nested_* attributes, and each
// limit state's nested_median and nested_median_se (NaN for one not in it).
void write_nested_fit(Hdf5Writer& file, const StudyConfig& config,
                      const StudyFragility& fragility) {
  const NestedFit& nested = fragility.nested;
  std::string names;
  for (const std::size_t k : fragility.nested_states) {
    if (!names.empty()) names += ',';
    names += config.limit_states[k].name;
  }
  file.set_attribute("/fragility", "nested_status", nested.status);
  file.set_attribute("/fragility", "nested_states", nested.ok() ? names : std::string());
  file.set_attribute("/fragility", "nested_beta", nested.beta);
  file.set_attribute("/fragility", "nested_beta_se", nested.beta_se);
  file.set_attribute("/fragility", "nested_log_likelihood", nested.log_likelihood);
}

void write_fragility(Hdf5Writer& file, const StudyConfig& config, const StudyFragility& fragility) {
  const IntensityMeasure& measure = config.intensity;
  file.create_group("/fragility");
  file.set_attribute("/fragility", "im_name", std::string(im_type_name(measure.type)));
  file.set_attribute("/fragility", "im_units", std::string(im_unit(measure.type)));
  file.set_attribute("/fragility", "im_label", im_label(measure));
  if (measure.type == ImType::sa) {
    file.set_attribute("/fragility", "im_period_s", measure.period);
    file.set_attribute("/fragility", "im_damping", measure.damping);
  }
  file.set_attribute("/fragility", "scaling",
                     std::string(measure.cloud ? "none (a cloud: each sample's own intensity; "
                                                 "points are display bins, the fit is per sample)"
                                               : "stripes"));
  file.set_attribute(
      "/fragility", "trials_exclude",
      std::string("samples whose status is not 0 (failed or rejected) are not trials"));
  file.set_attribute("/fragility", "severity_order", joined_names(config, fragility.severity));
  std::string crossings;
  for (const auto& [i, j] : fragility.crossings) {
    if (!crossings.empty()) crossings += ';';
    crossings += config.limit_states[i].name + ',' + config.limit_states[j].name;
  }
  file.set_attribute("/fragility", "crossing_pairs", crossings);
  if (measure.surface()) {
    file.set_attribute("/fragility", "summed_over",
                       std::string("pulse_period: each level's trials and exceedances are those of "
                                   "its cells at every period of /fragility_surface"));
  }
  file.set_attribute("/fragility", "bootstrap_resamples",
                     static_cast<std::int64_t>(config.bootstrap_resamples));
  write_nested_fit(file, config, fragility);
  for (std::size_t k = 0; k < config.limit_states.size(); ++k) {
    const std::string group = "/fragility/" + config.limit_states[k].name;
    write_curve(file, group, config.limit_states[k], fragility.curves[k]);
    const auto rank = std::find(fragility.severity.begin(), fragility.severity.end(), k) -
                      fragility.severity.begin();
    file.set_attribute(group, "severity_rank", static_cast<std::int64_t>(rank));
    const auto nested =
        std::find(fragility.nested_states.begin(), fragility.nested_states.end(), k);
    const bool in_nested = fragility.nested.ok() && nested != fragility.nested_states.end();
    const auto i = static_cast<std::size_t>(nested - fragility.nested_states.begin());
    file.set_attribute(group, "nested_median",
                       in_nested ? fragility.nested.median[i] : NestedFit::nan);
    file.set_attribute(group, "nested_median_se",
                       in_nested ? fragility.nested.median_se[i] : NestedFit::nan);
  }
}

// A surface study's grids and fitted surfaces (docs/studies.md, "Fragility surfaces").
void write_surfaces(Hdf5Writer& file, const StudyConfig& config, const StudyFragility& fragility) {
  const IntensityMeasure& measure = config.intensity;
  file.create_group("/fragility_surface");
  file.set_attribute("/fragility_surface", "im1_name", std::string(im_type_name(measure.type)));
  file.set_attribute("/fragility_surface", "im1_units", std::string(im_unit(measure.type)));
  file.set_attribute("/fragility_surface", "im1_label", im_label(measure));
  file.set_attribute("/fragility_surface", "im2_name", std::string("pulse_period"));
  file.set_attribute("/fragility_surface", "im2_units", std::string("s"));
  file.set_attribute("/fragility_surface", "im2_label", std::string("pulse period"));
  file.set_attribute("/fragility_surface", "model",
                     std::string("P = Phi(b0 + b1 ln im1 + b2 ln im2); for each im2 a lognormal "
                                 "in im1 with ln median = -(b0 + b2 ln im2) / b1, beta = 1 / b1"));
  const auto n1 = static_cast<std::int64_t>(measure.levels.size());
  const auto n2 = static_cast<std::int64_t>(measure.periods.size());
  for (std::size_t k = 0; k < config.limit_states.size(); ++k) {
    const LimitState& state = config.limit_states[k];
    const SurfaceGrid& grid = fragility.surfaces[k];
    const SurfaceFit& fit = grid.fit;
    const std::string group = "/fragility_surface/" + state.name;
    file.create_group(group);
    file.write_column(group + "/im1", grid.im1);
    file.write_column(group + "/im2", grid.im2);
    file.write_matrix(group + "/trials", n1, n2, grid.trials);
    file.write_matrix(group + "/exceedances", n1, n2, grid.exceedances);
    file.write_matrix(group + "/probability", n1, n2, grid.probability);
    file.write_matrix(group + "/ci_low", n1, n2, grid.ci_low);
    file.write_matrix(group + "/ci_high", n1, n2, grid.ci_high);
    std::vector<double> covariance, median_im1;
    for (const auto& row : fit.covariance)
      covariance.insert(covariance.end(), row.begin(), row.end());
    for (const double x2 : grid.im2) median_im1.push_back(fit.median_im1(x2));
    file.write_matrix(group + "/covariance", 3, 3, covariance);
    file.write_column(group + "/median_im1", median_im1);
    file.set_attribute(group, "type", std::string(limit_state_kind_name(state.kind)));
    file.set_attribute(group, "threshold", state.threshold);
    file.set_attribute(group, "overturned_exceeds",
                       static_cast<std::int64_t>(state.overturned_exceeds ? 1 : 0));
    file.set_attribute(group, "interval", std::string("Wilson score, 95 %"));
    file.set_attribute(group, "fit_status", std::string(surface_fit_status_name(fit.status)));
    file.set_attribute(group, "coefficients",
                       std::vector<double>(fit.coefficients.begin(), fit.coefficients.end()));
    file.set_attribute(group, "standard_errors",
                       std::vector<double>(fit.standard_errors.begin(), fit.standard_errors.end()));
    file.set_attribute(group, "log_likelihood", fit.log_likelihood);
    file.set_attribute(group, "iterations", static_cast<std::int64_t>(fit.iterations));
    file.set_attribute(group, "newton_decrement", fit.newton_decrement);
    file.set_attribute(group, "ln_median_intercept", fit.ln_median_intercept);
    file.set_attribute(group, "ln_median_intercept_se", fit.ln_median_intercept_se);
    file.set_attribute(group, "ln_median_slope", fit.ln_median_slope);
    file.set_attribute(group, "ln_median_slope_se", fit.ln_median_slope_se);
    file.set_attribute(group, "beta1", fit.beta1);
    file.set_attribute(group, "beta1_se", fit.beta1_se);
    file.set_attribute(group, "deviance", grid.gof.deviance);
    file.set_attribute(group, "gof_dof", static_cast<std::int64_t>(grid.gof.dof));
    file.set_attribute(group, "gof_p_value", grid.gof.p_value);
    file.set_attribute(group, "max_misfit", grid.gof.max_misfit);
  }
}

// An adaptive study's batches (docs/studies.md, "The HDF5 output").
void write_adaptive(Hdf5Writer& file, const StudyConfig& config, const AdaptiveHistory& history) {
  file.create_group("/adaptive");
  file.write_column("/adaptive/level_batch", history.level_batch);
  file.write_column("/adaptive/level_im", config.intensity.levels);
  file.write_column("/adaptive/batch_samples", history.samples);
  file.write_column("/adaptive/batch_median", history.median);
  file.write_column("/adaptive/batch_beta", history.beta);
  file.write_column("/adaptive/batch_relative_width", history.relative_width);
  file.set_attribute("/adaptive", "limit_state", config.adaptive->limit_state);
  file.set_attribute("/adaptive", "target_relative_width", config.adaptive->target_relative_width);
  file.set_attribute("/adaptive", "pair_probability", config.adaptive->pair_probability);
  file.set_attribute("/adaptive", "max_samples", config.adaptive->max_samples);
  file.set_attribute("/adaptive", "stop_reason", history.stop_reason);
}

}  // namespace

StudyTallies write_study_output(const std::filesystem::path& path, const StudyConfig& config,
                                const RecordSpool& spool, const AdaptiveHistory* adaptive) {
  FragilityTally fragility(config);
  StudyTallies tallies;
  replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5Writer file(temporary);
    file.set_attribute("/", "config", canonical_text(config.canonical));
    file.set_attribute("/", "config_hash", hash_to_hex(config.hash));
    file.set_attribute("/", "blockfrag_version", std::string(kVersion));
    file.set_attribute("/", "total_samples", config.total_samples());
    file.set_attribute("/", "samples_per_level",
                       static_cast<std::int64_t>(config.samples_per_level));
    file.set_attribute(
        "/", "design",
        std::string(config.design == Design::monte_carlo ? "monte_carlo" : "latin_hypercube"));
    SampleColumns columns(config);
    columns.create(file);
    StudySampler sampler(config);
    std::vector<SampleRecord> records;
    const std::int64_t total = config.total_samples();
    for (std::int64_t first = 0; first < total; first += kSamplesPerPass) {
      records.resize(static_cast<std::size_t>(std::min(kSamplesPerPass, total - first)));
      spool.read(first, records);
      columns.clear();
      for (const SampleRecord& record : records) {
        if (record.index != first + (&record - records.data())) {
          throw ContractViolation("the record spool lacks sample " +
                                  std::to_string(first + (&record - records.data())));
        }
        const StudySample sample = sampler.draw(record.index, true);
        columns.add(sample);
        fragility.add(record, block_alpha(sample.scene), sample.im);
        tallies.failures.add(record);
      }
      columns.write(file, first, records);
    }
    if (config.suite) write_records(file, *config.suite, config.intensity);
    if (adaptive) write_adaptive(file, config, *adaptive);
    tallies.fragility = fragility.finish();
    write_fragility(file, config, tallies.fragility);
    if (config.intensity.surface()) write_surfaces(file, config, tallies.fragility);
    file.close();
  });
  return tallies;
}

std::string output_config_hash(const std::filesystem::path& path) {
  try {
    return read_root_string_attribute(path, "config_hash");
  } catch (const Hdf5Error&) {
    return {};
  }
}

}  // namespace blockfrag
