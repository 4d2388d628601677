#include "mpi_driver/accuracy/accuracy_output.hpp"

#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "mpi_driver/accuracy/table_cell.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/hdf5_file.hpp"

namespace blockfrag {

namespace {

struct NamedOutput {
  const char* name;
  double OutputErrors::*member;
};
constexpr NamedOutput outputs[] = {{"max_abs_theta", &OutputErrors::max_abs_theta},
                                   {"final_theta", &OutputErrors::final_theta},
                                   {"final_slide", &OutputErrors::final_slide},
                                   {"first_impact_time", &OutputErrors::first_impact_time}};

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) text += (i ? "\n" : "") + lines[i];
  return text;
}

template <class Item, class Fn>
auto collect(const std::vector<Item>& items, Fn&& fn) {
  std::vector<decltype(fn(items.front()))> values;
  for (const auto& item : items) values.push_back(fn(item));
  return values;
}

std::vector<std::int64_t> flags(const std::vector<OutputErrors>& errors, bool OutputErrors::*flag) {
  return collect(errors, [&](const OutputErrors& e) { return std::int64_t{e.*flag}; });
}

double time_or_nan(const std::optional<double>& time) {
  return time.value_or(std::numeric_limits<double>::quiet_NaN());
}

void write_scenes(Hdf5Writer& file, const AccuracyStudy& study) {
  file.create_group("/scenes");
  file.set_attribute("/scenes", "names", joined(study.scene_names));
  file.set_attribute("/scenes", "categories", joined(study.scene_categories));
  const auto& ref = study.reference;
  file.write_column("/scenes/reference_max_abs_theta",
                    collect(ref, [](const Summary& s) { return s.max_abs_theta; }));
  file.write_column("/scenes/reference_final_theta",
                    collect(ref, [](const Summary& s) { return s.final_theta; }));
  file.write_column("/scenes/reference_final_slide",
                    collect(ref, [](const Summary& s) { return s.final_slide; }));
  file.write_column("/scenes/reference_first_impact_time", collect(ref, [](const Summary& s) {
                      return time_or_nan(s.first_impact_time);
                    }));
  file.write_column("/scenes/reference_overturned",
                    collect(ref, [](const Summary& s) { return std::int64_t{s.overturned}; }));
  file.write_column("/scenes/reference_impacts",
                    collect(ref, [](const Summary& s) { return std::int64_t{s.impacts}; }));
  for (const auto& output : outputs) {
    file.write_column(
        std::string("/scenes/check_error_") + output.name,
        collect(study.check_errors, [&](const OutputErrors& e) { return e.*output.member; }));
  }
  file.write_column("/scenes/check_wrong_verdict",
                    flags(study.check_errors, &OutputErrors::wrong_verdict));
}

void write_setting(Hdf5Writer& file, const std::string& group, const SettingResult& result) {
  file.create_group(group);
  file.set_attribute(group, "label", setting_label(result.setting));
  file.set_attribute(group, "method", method_label(result.setting.method));
  file.set_attribute(group, "parameter", result.setting.parameter);
  for (const auto& output : outputs) {
    file.write_column(
        group + "/error_" + output.name,
        collect(result.errors, [&](const OutputErrors& e) { return e.*output.member; }));
  }
  file.write_column(group + "/wrong_verdict", flags(result.errors, &OutputErrors::wrong_verdict));
  file.write_column(group + "/failed", flags(result.errors, &OutputErrors::failed));
  const auto& runs = result.runs;
  file.write_column(group + "/seconds_per_run",
                    collect(runs, [](const TimedRun& r) { return r.seconds; }));
  file.write_column(group + "/repeats",
                    collect(runs, [](const TimedRun& r) { return std::int64_t{r.repeats}; }));
  file.write_column(group + "/steps",
                    collect(runs, [](const TimedRun& r) { return std::int64_t{r.summary.steps}; }));
  file.write_column(group + "/rhs_evaluations", collect(result.runs, [](const TimedRun& r) {
                      return std::int64_t{r.summary.rhs_evaluations};
                    }));
}

void write_summary(Hdf5Writer& file, const AccuracyStudy& study) {
  const auto& settings = study.settings;
  file.create_group("/summary");
  file.set_attribute(
      "/summary", "labels",
      joined(collect(settings, [](const SettingResult& r) { return setting_label(r.setting); })));
  file.set_attribute("/summary", "methods", joined(collect(settings, [](const SettingResult& r) {
                       return method_label(r.setting.method);
                     })));
  file.write_column("/summary/parameter",
                    collect(settings, [](const SettingResult& r) { return r.setting.parameter; }));
  for (const auto& output : outputs) {
    const auto error_column = [&](const char* prefix,
                                  const OutputErrors SettingStatistics::*statistic) {
      file.write_column(std::string("/summary/") + prefix + output.name,
                        collect(settings, [&](const SettingResult& r) {
                          return (r.statistics.*statistic).*output.member;
                        }));
    };
    error_column("max_error_", &SettingStatistics::max_error);
    error_column("median_error_", &SettingStatistics::median_error);
  }
  const auto stat = [&](const char* name, auto member) {
    file.write_column(
        std::string("/summary/") + name,
        collect(settings, [&](const SettingResult& r) { return r.statistics.*member; }));
  };
  const auto count = [&](const char* name, long SettingStatistics::*member) {
    file.write_column(std::string("/summary/") + name,
                      collect(settings, [&](const SettingResult& r) {
                        return std::int64_t{r.statistics.*member};
                      }));
  };
  count("scenes_over_target", &SettingStatistics::scenes_over_target);
  count("wrong_verdicts", &SettingStatistics::wrong_verdicts);
  count("failures", &SettingStatistics::failures);
  stat("wrong_verdict_rate", &SettingStatistics::wrong_verdict_rate);
  stat("median_seconds", &SettingStatistics::median_seconds);
  stat("p95_seconds", &SettingStatistics::p95_seconds);
  stat("median_rhs_evaluations", &SettingStatistics::median_rhs_evaluations);
  stat("mean_rhs_evaluations", &SettingStatistics::mean_rhs_evaluations);
  stat("median_steps", &SettingStatistics::median_steps);
}

}  // namespace

void write_accuracy_hdf5(const std::filesystem::path& path, const AccuracyStudy& study,
                         const std::string& suite_name) {
  replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5Writer file(temporary);
    file.set_attribute("/", "reference_method", method_label(study.reference_setting.method));
    file.set_attribute("/", "reference_tolerance", study.reference_setting.parameter);
    file.set_attribute("/", "check_method", method_label(study.check_setting.method));
    file.set_attribute("/", "min_batch_seconds", study.min_batch_seconds);
    file.set_attribute("/", "scene_count", static_cast<std::int64_t>(study.scene_names.size()));
    file.set_attribute("/", "setting_count", static_cast<std::int64_t>(study.settings.size()));
    file.set_attribute("/", "suite", suite_name);
    write_scenes(file, study);
    file.create_group("/settings");
    for (std::size_t i = 0; i < study.settings.size(); ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "/settings/%02zu", i);
      write_setting(file, name, study.settings[i]);
    }
    write_summary(file, study);
    file.close();
  });
}

void write_accuracy_table(std::ostream& out, const AccuracyStudy& study) {
  const SettingStatistics& check = study.check_statistics;
  out << "Reference: " << setting_label(study.reference_setting)
      << "; check: " << setting_label(study.check_setting) << " on " << study.scene_names.size()
      << " scenes. Largest |check - reference|: max|theta| "
      << table_cell(check.max_error.max_abs_theta, "%.2e") << " rad, final theta "
      << table_cell(check.max_error.final_theta, "%.2e") << " rad, final slide "
      << table_cell(check.max_error.final_slide, "%.2e") << " m, first impact "
      << table_cell(check.max_error.first_impact_time, "%.2e")
      << " s; verdicts that differ: " << check.wrong_verdicts << "; failures: " << check.failures
      << ".\n\n";
  out << "| setting | max err max\\|theta\\| (rad) | scenes with err max\\|theta\\| > 1e-6 | max "
         "err final theta (rad) "
         "| max err final slide (m) | max err first impact (s) | wrong verdicts | failed "
         "| median time/scene (ms) | p95 time/scene (ms) | median RHS evals/scene |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  const std::size_t scenes = study.scene_names.size();
  for (const SettingResult& result : study.settings) {
    const SettingStatistics& s = result.statistics;
    out << "| " << setting_label(result.setting) << " | "
        << table_cell(s.max_error.max_abs_theta, "%.2e") << " | " << s.scenes_over_target << "/"
        << scenes << " | " << table_cell(s.max_error.final_theta, "%.2e") << " | "
        << table_cell(s.max_error.final_slide, "%.2e") << " | "
        << table_cell(s.max_error.first_impact_time, "%.2e") << " | " << s.wrong_verdicts << "/"
        << scenes << " | " << s.failures << " | " << table_cell(1e3 * s.median_seconds, "%.3g")
        << " | " << table_cell(1e3 * s.p95_seconds, "%.3g") << " | "
        << table_cell(s.median_rhs_evaluations, "%.0f") << " |\n";
  }
}

}  // namespace blockfrag
