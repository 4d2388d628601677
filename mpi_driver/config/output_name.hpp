// The name of an output file a config or a command line gives: checked before any work.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace blockfrag {

// The endings of the files a run keeps beside its output OUTPUT (OUTPUT.checkpoint, ...). None
// ends with another, and no output may end with one (nor with a temporary file's
// ".tmp.XXXXXX"), so no output and none of its files can ever have the name of another output's
// file: a run reads, replaces or removes only its own.
inline constexpr std::array<std::string_view, 7> kSideFileEndings = {
    ".checkpoint",       ".records",       ".bisection", ".minimum",
    ".round-checkpoint", ".round-records", ".lock"};

// Why `name` cannot name a file blockfrag writes (empty, a NUL byte, which would cut the name
// short, a folder: ".", ".." or a trailing '/', or a name that ends as a run's own files do);
// nullopt when it can.
std::optional<std::string> output_name_problem(const std::string& name);

}  // namespace blockfrag
