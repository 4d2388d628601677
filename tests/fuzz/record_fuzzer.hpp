// The body of the two record fuzz targets: the input is written to a file of the given name in the
// fuzz folder and read back with read_accelerogram. A record it accepts must pass the engine's
// check_accelerogram.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "engine/motion/accelerogram.hpp"
#include "mpi_driver/config/record_file.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace blockfrag::fuzz {

inline int read_record(const std::filesystem::path& file, const std::uint8_t* data,
                       std::size_t size) {
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) finding("cannot write the input to " + file.string());
  }
  return run([&] {
    const Accelerogram record = read_accelerogram(file);
    try {
      check_accelerogram(record);
    } catch (const InvalidInput& error) {
      finding("read_accelerogram accepted a record that check_accelerogram refuses", &error);
    }
    return 0;
  });
}

}  // namespace blockfrag::fuzz
