// Option validators shared by the subcommands.
#pragma once

#include <string>

// CLI11 is a large header-only library: only the .cpp files that use it include it.
namespace CLI {
class Validator;
}  // namespace CLI

namespace blockfrag {

// A finite number > 0: CLI11's PositiveNumber lets "nan" and "inf" through.
CLI::Validator positive_finite_number(const std::string& name);

}  // namespace blockfrag
