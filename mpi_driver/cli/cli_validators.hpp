// Option validators shared by the subcommands.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace blockfrag {

// A finite number > 0: CLI11's PositiveNumber lets "nan" and "inf" through.
CLI::Validator positive_finite_number(const std::string& name);

}  // namespace blockfrag
