#include "mpi_driver/cli/cli_validators.hpp"

#include <cmath>
#include <exception>

#include <CLI/CLI.hpp>

namespace blockfrag {

CLI::Validator positive_finite_number(const std::string& name) {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double x = std::stod(text, &used);
          if (used == text.size() && std::isfinite(x) && x > 0) return {};
        } catch (const std::exception&) {
        }
        return "must be a positive number (got " + text + ")";
      },
      name);
}

}  // namespace blockfrag
