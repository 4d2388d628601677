#include "mpi_driver/config/output_name.hpp"

#include <filesystem>

#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {
namespace {

// TARGET.tmp.XXXXXX, the name of a temporary file (mpi_driver/io/atomic_file.hpp).
bool temporary_file_name(const std::string& file) {
  constexpr std::string_view infix = ".tmp.";
  return file.size() > infix.size() + 6 &&
         file.compare(file.size() - 6 - infix.size(), infix.size(), infix) == 0;
}

}  // namespace

std::optional<std::string> output_name_problem(const std::string& name) {
  if (name.empty()) return "must not be empty";
  if (name.find('\0') != std::string::npos) return "must not contain a NUL byte";
  const std::filesystem::path path(name);
  const std::string file = path.filename().string();
  if (file.empty() || file == "." || file == "..")
    return "must name a file, not a folder (got \"" + printable_excerpt(name) + "\")";
  for (const std::string_view ending : kSideFileEndings) {
    if (file.size() > ending.size() && file.ends_with(ending)) {
      return "must not end in \"" + std::string(ending) +
             "\", the ending of a run's own files (got \"" + printable_excerpt(name) + "\")";
    }
  }
  if (temporary_file_name(file)) {
    return "must not end in \".tmp.\" and six characters, the name of a temporary file (got \"" +
           printable_excerpt(name) + "\")";
  }
  return std::nullopt;
}

}  // namespace blockfrag
