// Fuzzes the study reader: JSON text -> parse_study_config. A study it accepts must read back from
// its canonical config to the same hash.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace blockfrag;
  // The scene's record files are taken from this (never written) file's folder; nothing is written.
  static const std::string source = (fuzz::folder() / "study.json").string();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  return fuzz::run([&] {
    const nlohmann::json document = parse_json_text(text, source);
    if (!fuzz::files_stay_inside(document)) return -1;  // not kept in the corpus
    const StudyConfig study = parse_study_config(document, source);
    StudyConfig again;
    try {
      again = parse_study_config(study.canonical, source);
    } catch (const InvalidInput& error) {
      fuzz::finding("parse_study_config refuses the canonical config of a study it accepted",
                    &error);
    }
    if (again.hash != study.hash || again.canonical != study.canonical) {
      fuzz::finding("the canonical config reads back to another study: " +
                    canonical_text(study.canonical));
    }
    return 0;
  });
}
