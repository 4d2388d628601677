#include "mpi_driver/cli/export_command.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <system_error>
#include <vector>

#include "engine/errors.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/fragility_export.hpp"
#include "mpi_driver/io/fragility_fits.hpp"
#include "mpi_driver/io/isolated_fits.hpp"
#include "mpi_driver/io/output_target.hpp"

namespace blockfrag {
namespace {

// Reading a study's fits takes a fraction of a second; a file HDF5 is still reading after this
// long is a damaged one it loops on (mpi_driver/io/read_in_child.hpp).
constexpr std::chrono::milliseconds read_limit{10'000};

// What an earlier export wrote, the one kind of file at each name an export replaces.
bool is_openquake_export(const std::filesystem::path& path) {
  return file_starts_with(path,
                          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                          "<nrml xmlns=\"http://openquake.org/xmlns/nrml/0.5\">\n",
                          "<description>blockfrag study ");
}

bool is_pelicun_csv_export(const std::filesystem::path& path) {
  return file_starts_with(path,
                          "ID,Incomplete,Demand-Type,Demand-Unit,Demand-Offset,Demand-Directional");
}

bool is_pelicun_json_export(const std::filesystem::path& path) {
  return file_starts_with(path, "{\n", "\"ShortName\": \"blockfrag study ", 1 << 20);
}

// The pelicun folder: created if missing (its parent must exist), refused if something else.
void prepare_folder(const std::filesystem::path& folder) {
  std::error_code error;
  const auto status = std::filesystem::status(folder, error);
  if (std::filesystem::is_directory(status)) return;
  if (std::filesystem::exists(status)) {
    throw InvalidInput(folder.string() +
                       ": is not a folder; --output names the folder pelicun's files go in");
  }
  // "dl/" names the folder dl, whose parent is ".".
  const auto named = folder.has_filename() ? folder : folder.parent_path();
  const auto parent =
      named.parent_path().empty() ? std::filesystem::path(".") : named.parent_path();
  if (!std::filesystem::is_directory(parent, error)) {
    throw InvalidInput(folder.string() + ": its folder " + parent.string() +
                       " does not exist (export creates the output folder, not its parents)");
  }
  if (!std::filesystem::create_directory(folder, error) && error) {
    throw InvalidInput(folder.string() + ": cannot be created (" + error.message() + ")");
  }
}

}  // namespace

int run_export(const ExportOptions& options, std::ostream& out, std::ostream& log) {
  const FragilityFits read = read_fragility_fits_isolated(options.results, read_limit);
  const FragilityFits all = options.nested ? nested_fits(read) : read;
  std::vector<std::string> left_out;
  const FragilityFits fits = exportable_fits(all, options.fitted_only, left_out);
  const std::string id = options.id ? *options.id : default_export_id(fits);
  check_export_id(id);
  // Every text is made, and so every refusal made, before anything is written.
  if (options.format == ExportFormat::pelicun) {
    const PelicunDamageModel model = pelicun_damage_model(fits, id);
    prepare_folder(options.output);
    const auto csv = options.output / "fragility.csv";
    const auto json = options.output / "fragility.json";
    check_output_targets(
        {{csv, "--output", "a pelicun fragility.csv blockfrag exported", is_pelicun_csv_export},
         {json, "--output", "a pelicun fragility.json blockfrag exported", is_pelicun_json_export}},
        {{options.results, "the study output"}});
    write_file_atomically(csv, model.csv);
    write_file_atomically(json, model.json);
    out << "wrote " << csv.string() << " and " << json.string();
  } else {
    const std::string model = openquake_fragility_model(fits, id);
    check_output_targets({{options.output, "--output",
                           "an OpenQuake fragility model blockfrag "
                           "exported",
                           is_openquake_export}},
                         {{options.results, "the study output"}});
    write_file_atomically(options.output, model);
    out << "wrote " << options.output.string();
  }
  out << " (" << id << ": " << fits.states.size() << " limit state"
      << (fits.states.size() == 1 ? "" : "s") << ", least severe first)\n";
  out.flush();
  const auto exported = [&](const std::string& name) {
    return std::any_of(fits.states.begin(), fits.states.end(),
                       [&](const FragilityFit& state) { return state.name == name; });
  };
  for (const auto& [first, second] : fits.crossing_pairs) {
    if (exported(first) && exported(second)) {
      log << "note: the fits of " << first << " and " << second
          << " cross within the study's levels; both tools take the limit states as nested, "
             "least severe first\n";
    }
  }
  if (!left_out.empty()) {
    log << "left out, without a fit:";
    for (const auto& name : left_out) log << ' ' << name;
    log << '\n';
  }
  log.flush();
  return 0;
}

}  // namespace blockfrag
