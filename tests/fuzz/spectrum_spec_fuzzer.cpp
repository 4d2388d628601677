// Fuzzes the spectrum spec reader: JSON text -> parse_json_text -> parse_spectrum_config. A spec it
// accepts must read back from its canonical config to the same canonical config and hash.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/spectrum_config.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace blockfrag;
  // Named as a spec in the fuzz folder (never written); nothing is written.
  static const std::string source = (fuzz::folder() / "spectrum.json").string();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return fuzz::run([&] {
    const nlohmann::json document = parse_json_text(text, source);
    if (!fuzz::files_stay_inside(document)) return -1;  // not kept in the corpus
    const SpectrumConfig spec = parse_spectrum_config(document, source);
    SpectrumConfig again;
    try {
      again = parse_spectrum_config(spec.canonical, source);
    } catch (const InvalidInput& error) {
      fuzz::finding("parse_spectrum_config refuses the canonical config of a spec it accepted",
                    &error);
    }
    if (again.hash != spec.hash || again.canonical != spec.canonical) {
      fuzz::finding("the canonical config reads back to another spec: " + spec.canonical.dump());
    }
    return 0;
  });
}
