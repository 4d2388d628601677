#include "mpi_driver/io/study_output.hpp"

#include <algorithm>
#include <cmath>

#include "engine/scene/block_geometry.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/hdf5_file.hpp"
#include "mpi_driver/study/fragility_summary.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

template <typename T, typename Field>
std::vector<T> column(const std::vector<SampleRecord>& records, Field field) {
  std::vector<T> values;
  values.reserve(records.size());
  for (const auto& record : records) values.push_back(record.*field);
  return values;
}

// Each sample's block alpha and intensity, which the fragility needs.
struct SampleMeasures {
  std::vector<double> alphas;
  std::vector<double> ims;
};

SampleMeasures write_samples(Hdf5Writer& file, const StudyConfig& config) {
  const auto total = static_cast<std::size_t>(config.total_samples());
  std::vector<std::vector<double>> inputs(config.inputs.size(), std::vector<double>(total));
  std::vector<std::int64_t> level(total), record(total);
  std::vector<double> scale(total), pga(total), pgv(total);
  SampleMeasures measures{std::vector<double>(total), std::vector<double>(total)};
  StudySampler sampler(config);
  for (std::size_t i = 0; i < total; ++i) {
    const StudySample sample = sampler.draw(static_cast<std::int64_t>(i), true);
    for (std::size_t k = 0; k < inputs.size(); ++k) inputs[k][i] = sample.values[k];
    level[i] = sample.level;
    record[i] = sample.record;
    scale[i] = sample.scale;
    pga[i] = sample.pga_g;
    pgv[i] = sample.pgv_m_s;
    measures.ims[i] = sample.im;
    measures.alphas[i] = block_alpha(sample.scene);
  }
  file.create_group("/samples");
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    file.write_column(std::string("/samples/") + input_key(config.inputs[k].input), inputs[k]);
  }
  file.write_column("/samples/level", level);
  file.write_column("/samples/im", measures.ims);
  file.set_attribute("/samples/im", "units", std::string(im_unit(config.intensity.type)));
  file.write_column("/samples/scale", scale);
  file.write_column("/samples/pga_g", pga);
  file.write_column("/samples/pgv_m_s", pgv);
  if (config.suite) file.write_column("/samples/record", record);
  return measures;
}

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

void write_results(Hdf5Writer& file, const std::vector<SampleRecord>& records) {
  file.create_group("/results");
  file.write_column("/results/status", column<std::int64_t>(records, &SampleRecord::status));
  file.set_attribute(
      "/results/status", "meaning",
      std::string("0 ok, 1 failed (engine budget exceeded), 2 rejected (invalid scene)"));
  file.write_column("/results/overturned",
                    column<std::int64_t>(records, &SampleRecord::overturned));
  file.write_column("/results/impacts", column<std::int64_t>(records, &SampleRecord::impacts));
  file.write_column("/results/steps", column<std::int64_t>(records, &SampleRecord::steps));
  file.write_column("/results/rhs_evaluations",
                    column<std::int64_t>(records, &SampleRecord::rhs_evaluations));
  file.write_column("/results/max_abs_theta",
                    column<double>(records, &SampleRecord::max_abs_theta));
  file.write_column("/results/final_theta", column<double>(records, &SampleRecord::final_theta));
  file.write_column("/results/final_slide", column<double>(records, &SampleRecord::final_slide));
  file.write_column("/results/max_abs_slide",
                    column<double>(records, &SampleRecord::max_abs_slide));
  file.write_column("/results/overturn_time",
                    column<double>(records, &SampleRecord::overturn_time));
  file.write_column("/results/settled", column<std::int64_t>(records, &SampleRecord::settled));
  file.write_column("/results/settle_time", column<double>(records, &SampleRecord::settle_time));
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

StudyFragility write_fragility(Hdf5Writer& file, const StudyConfig& config,
                               const std::vector<SampleRecord>& records,
                               const SampleMeasures& measures) {
  const IntensityMeasure& measure = config.intensity;
  StudyFragility fragility = study_fragility(config, records, measures.alphas, measures.ims);
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
  file.set_attribute("/fragility", "bootstrap_resamples",
                     static_cast<std::int64_t>(config.bootstrap_resamples));
  for (std::size_t k = 0; k < config.limit_states.size(); ++k) {
    const std::string group = "/fragility/" + config.limit_states[k].name;
    write_curve(file, group, config.limit_states[k], fragility.curves[k]);
    const auto rank = std::find(fragility.severity.begin(), fragility.severity.end(), k) -
                      fragility.severity.begin();
    file.set_attribute(group, "severity_rank", static_cast<std::int64_t>(rank));
  }
  return fragility;
}

}  // namespace

StudyFragility write_study_output(const std::filesystem::path& path, const StudyConfig& config,
                                  const std::vector<SampleRecord>& records) {
  StudyFragility fragility;
  replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5Writer file(temporary);
    file.set_attribute("/", "config", canonical_text(config.canonical));
    file.set_attribute("/", "config_hash", hash_to_hex(config.hash));
    file.set_attribute("/", "blockfrag_version", std::string(BLOCKFRAG_VERSION));
    file.set_attribute("/", "total_samples", config.total_samples());
    file.set_attribute("/", "samples_per_level",
                       static_cast<std::int64_t>(config.samples_per_level));
    file.set_attribute(
        "/", "design",
        std::string(config.design == Design::monte_carlo ? "monte_carlo" : "latin_hypercube"));
    const SampleMeasures measures = write_samples(file, config);
    if (config.suite) write_records(file, *config.suite, config.intensity);
    write_results(file, records);
    fragility = write_fragility(file, config, records, measures);
    file.close();
  });
  return fragility;
}

std::string output_config_hash(const std::filesystem::path& path) {
  try {
    return read_root_string_attribute(path, "config_hash");
  } catch (const Hdf5Error&) {
    return {};
  }
}

}  // namespace blockfrag
