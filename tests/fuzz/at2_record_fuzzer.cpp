// Fuzzes the PEER NGA .AT2 record reader (tests/fuzz/record_fuzzer.hpp).
#include "tests/fuzz/record_fuzzer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file = blockfrag::fuzz::folder() / "input.AT2";
  return blockfrag::fuzz::read_record(file, data, size);
}
