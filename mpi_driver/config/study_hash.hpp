// A 64-bit FNV-1a hash: enough to tell a changed config or a damaged checkpoint from the expected
// one (nothing here defends against a deliberate collision), and free of any crypto library.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace blockfrag {

std::uint64_t fnv1a64(std::string_view bytes);

// 16 lower-case hexadecimal digits, the form stored in files and printed in messages.
std::string hash_to_hex(std::uint64_t hash);

}  // namespace blockfrag
