// Fuzzes the HDF5 reader as `blockfrag export` uses it: the input is written to input.h5 in the
// fuzz folder and read with read_fragility_fits, then the fitted limit states go through
// exportable_fits and both tools' writers. A file the reader accepts must give an export whose
// default ID is valid and whose OpenQuake moments are finite, with a positive stddev.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpi_driver/io/fragility_export.hpp"
#include "mpi_driver/io/fragility_fits.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace blockfrag;
  static const std::filesystem::path file = fuzz::folder() / "input.h5";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) fuzz::finding("cannot write the input to " + file.string());
  }
  return fuzz::run([&] {
    const FragilityFits all = read_fragility_fits(file);
    std::vector<std::string> left_out;
    const FragilityFits fits = exportable_fits(all, true, left_out);
    const std::string id = default_export_id(fits);
    try {
      check_export_id(id);
    } catch (const InvalidInput& error) {
      fuzz::finding("the reader accepted a config hash that makes no valid ID", &error);
    }
    for (const auto& state : fits.states) {
      const LognormalMoments moments = lognormal_moments(state.median, state.beta);
      if (!(std::isfinite(moments.mean) && std::isfinite(moments.stddev) && moments.stddev > 0.0)) {
        fuzz::finding("the reader accepted a fit whose OpenQuake moments are not finite: " +
                      state.name);
      }
    }
    pelicun_damage_model(fits, id);
    openquake_fragility_model(fits, id);
    return 0;
  });
}
