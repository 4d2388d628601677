// A study output's fits read in a child process (read_in_child.hpp): HDF5 is not safe on a
// damaged file, so `blockfrag export` reads the file where a crash or an endless loop of the
// library cannot touch its own memory, and gets the fits back as JSON.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "mpi_driver/io/fragility_fits.hpp"

namespace blockfrag {

// Reading a study's fits takes tens of MB; a file that makes HDF5 ask for more is damaged.
inline constexpr std::size_t fits_memory_bytes = std::size_t{1} << 30;

// The fits as JSON, numbers as their shortest exact text (JSON has no NaN), and back: how the child
// hands them to the parent. `source` is the file, for the parent's messages.
nlohmann::json fits_to_json(const FragilityFits& fits);
FragilityFits fits_from_json(const nlohmann::json& json, const std::string& source);

// read_fragility_fits(path), and its refusals; also InvalidInput naming the file when reading it
// crashes HDF5, takes more than fits_memory_bytes or longer than `limit`.
FragilityFits read_fragility_fits_isolated(const std::filesystem::path& path,
                                           std::chrono::milliseconds limit);

}  // namespace blockfrag
