// `blockfrag export RESULTS.h5 --format pelicun --output DIR` writes DIR/fragility.csv and
// DIR/fragility.json (pelicun's damage-model database format; DIR is created if missing, not its
// parents); `--format openquake --output FILE.xml` writes an NRML 0.5 fragility model. Both from
// the study output's lognormal fits (mpi_driver/io/fragility_export.hpp has the formats).
// `--id ID` names the component (pelicun) and the taxonomy (OpenQuake), by default
// BF.BLOCK.<config hash>; `--fitted-only` exports the fitted limit states and names the others on
// stderr, where by default a limit state without a fit is refused; `--nested` exports the study's
// fit of one common beta (curves that do not cross). Files are replaced atomically.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace blockfrag {

enum class ExportFormat { pelicun, openquake };

struct ExportOptions {
  std::filesystem::path results;
  ExportFormat format = ExportFormat::pelicun;
  std::filesystem::path output;
  std::optional<std::string> id;
  bool fitted_only = false;
  bool nested = false;  // the common-beta fit instead of the separate ones
};

// Returns 0 and reports what it wrote on `out`, its notes (fits that cross, states left out) on
// `log`. Throws InvalidInput for a file that is not a study output with fits, a measure or limit
// state that cannot be exported, or an output path that cannot be used; FileError when a file
// cannot be written.
int run_export(const ExportOptions& options, std::ostream& out, std::ostream& log);

}  // namespace blockfrag
