// The rule for every file a command writes beside a study's or spectrum's output (which
// mpi_driver/cli/distributed_run.hpp judges by its config hash): at the name there is nothing, or a
// regular file of the kind the command writes there (its own earlier output), which it replaces.
// Never a symbolic link (not even the link itself), a FIFO, a device or a folder, never one of the
// command's input files, and never any other file: another blockfrag output, a user's notes.
// Checked before any work, so a refusal costs nothing and changes nothing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace blockfrag {

struct OutputTarget {
  std::filesystem::path path;
  std::string option;  // how the command line names it, for messages: "--history"
  std::string kind;    // what the command writes there, for messages: "a history CSV"
  // Whether an existing regular file is of that kind (called on regular files only).
  std::function<bool(const std::filesystem::path&)> is_own;
};

// A file the command reads, which none of its outputs may be.
struct CommandInput {
  std::filesystem::path path;
  std::string what;  // for messages: "the scene"
};

// Throws InvalidInput, naming the file and its option, when a target's name is unusable
// (output_name_problem), its folder is missing or not writable, something but nothing or a
// regular file of its kind is at its name, it is one of `inputs` (the same file, by device and
// inode, whatever the spelling or a hard link), or two targets name the same file.
void check_output_targets(const std::vector<OutputTarget>& targets,
                          const std::vector<CommandInput>& inputs);

// For is_own: whether the regular file at path starts with `leading` and, within its first
// `limit` bytes, holds `marker` (empty: no marker). Never follows a link; false when unreadable.
bool file_starts_with(const std::filesystem::path& path, std::string_view leading,
                      std::string_view marker = {}, std::size_t limit = 4096);

}  // namespace blockfrag
