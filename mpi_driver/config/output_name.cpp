#include "mpi_driver/config/output_name.hpp"

#include <filesystem>

#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {

std::optional<std::string> output_name_problem(const std::string& name) {
  if (name.empty()) return "must not be empty";
  if (name.find('\0') != std::string::npos) return "must not contain a NUL byte";
  const std::filesystem::path path(name);
  const std::string file = path.filename().string();
  if (file.empty() || file == "." || file == "..")
    return "must name a file, not a folder (got \"" + printable_excerpt(name) + "\")";
  return std::nullopt;
}

}  // namespace blockfrag
