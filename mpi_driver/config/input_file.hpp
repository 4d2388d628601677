// Reading an input file (a scene, a study, a record, a checkpoint) without trusting it: only a
// regular file is read (a FIFO, a device or a folder is refused before any read could block or
// never end), only up to a size cap, and a message quotes at most a short printable excerpt of it.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include <sys/types.h>

#include "engine/errors.hpp"

namespace blockfrag {

// A file that cannot be opened or read, or that is not a regular file: what() names the file.
// InvalidInput: the file is the user's input, not the machine's fault (exit code 2).
class InputFileError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

struct InputFileRules {
  std::size_t max_bytes;
  // Refuse a symbolic link (files the program owns, like its checkpoint); user inputs may be links
  // to regular files.
  bool follow_links = true;
};

// The file's whole content. Opened with O_NONBLOCK (a FIFO cannot hang the open) and checked with
// fstat on the opened descriptor (no race between the check and the read).
std::string read_input_file(const std::filesystem::path& path, const InputFileRules& rules);

// What a file that is not a regular file is, for a message: "a FIFO", "a symbolic link", ...
std::string file_kind(mode_t mode);

// At most `limit` characters of `text` for a message: control characters and bytes outside
// printable ASCII become '?', and a longer text ends in "...". A file's content can be anything (a
// secret, a binary, a 10 MB line): a message quotes only this much of it.
std::string printable_excerpt(std::string_view text, std::size_t limit = 60);

}  // namespace blockfrag
