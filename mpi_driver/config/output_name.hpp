// The name of an output file a config or a command line gives: checked before any work.
#pragma once

#include <optional>
#include <string>

namespace blockfrag {

// Why `name` cannot name a file blockfrag writes (empty, a NUL byte, which would cut the name
// short, or a folder: ".", ".." or a trailing '/'); nullopt when it can.
std::optional<std::string> output_name_problem(const std::string& name);

}  // namespace blockfrag
