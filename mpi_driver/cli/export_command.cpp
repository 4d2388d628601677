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

namespace blockfrag {
namespace {

// Reading a study's fits takes a fraction of a second; a file HDF5 is still reading after this
// long is a damaged one it loops on (mpi_driver/io/read_in_child.hpp).
constexpr std::chrono::milliseconds read_limit{10'000};

// A file the export may write: its folder usable, not a folder itself, not the study's output.
void check_target(const std::filesystem::path& target, const std::filesystem::path& results) {
  std::error_code error;
  if (std::filesystem::is_directory(target, error)) {
    throw InvalidInput(target.string() + ": is a folder, not a file the export can write");
  }
  if (std::filesystem::equivalent(target, results, error)) {
    throw InvalidInput(target.string() + ": is the study output " + results.string() +
                       " itself; choose another --output");
  }
  if (const auto problem = folder_write_problem(target)) {
    throw InvalidInput(target.string() + ": " + *problem);
  }
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
  const FragilityFits all = read_fragility_fits_isolated(options.results, read_limit);
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
    check_target(csv, options.results);
    check_target(json, options.results);
    write_file_atomically(csv, model.csv);
    write_file_atomically(json, model.json);
    out << "wrote " << csv.string() << " and " << json.string();
  } else {
    const std::string model = openquake_fragility_model(fits, id);
    check_target(options.output, options.results);
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
