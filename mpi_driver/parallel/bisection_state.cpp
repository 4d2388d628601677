#include "mpi_driver/parallel/bisection_state.hpp"

#include <cstring>

#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/parallel/byte_fields.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"

namespace blockfrag {
namespace {

constexpr std::string_view bisection_magic = "BFBISE01";
constexpr std::size_t bisection_header_size = bisection_magic.size() + 3 * 8;

using bytes::append;
using bytes::read_at;

// A bracket read back must be one the runner could have written.
bool plausible(const SpectrumBracket& bracket, std::int64_t frequencies) {
  const auto verdict_ok = [](std::int64_t v) {
    return v >= 0 && v <= static_cast<std::int64_t>(SpectrumVerdict::rejected);
  };
  return bracket.frequency_index >= 0 && bracket.frequency_index < frequencies && bracket.low > 0 &&
         bracket.low < bracket.high && verdict_ok(bracket.verdict_low) &&
         verdict_ok(bracket.verdict_high) && bracket.iterations >= 0 && bracket.state >= 0 &&
         bracket.state <= static_cast<std::int64_t>(BracketState::capped);
}

}  // namespace

std::string encode_bisection_state(const BisectionState& state) {
  std::string out;
  out.reserve(bisection_header_size + state.brackets.size() * sizeof(SpectrumBracket) + 8);
  out.append(bisection_magic);
  append(out, state.config_hash);
  append(out, state.round);
  append(out, static_cast<std::int64_t>(state.brackets.size()));
  for (const SpectrumBracket& bracket : state.brackets) append(out, bracket);
  append(out, fnv1a64(out));
  return out;
}

BisectionState decode_bisection_state(std::string_view bytes, const std::string& source,
                                      std::int64_t max_brackets, std::int64_t frequencies) {
  const auto fail = [&](const std::string& why) {
    return CheckpointError(source + ": not a usable blockfrag bisection state (" + why +
                           "); remove it to start the bisection over");
  };
  if (bytes.size() < bisection_header_size + 8 ||
      bytes.substr(0, bisection_magic.size()) != bisection_magic) {
    throw fail("wrong header");
  }
  if (fnv1a64(bytes.substr(0, bytes.size() - 8)) != read_at<std::uint64_t>(bytes, bytes.size() - 8))
    throw fail("checksum mismatch");
  BisectionState state;
  state.config_hash = read_at<std::uint64_t>(bytes, bisection_magic.size());
  state.round = read_at<std::int64_t>(bytes, bisection_magic.size() + 8);
  const auto count = read_at<std::int64_t>(bytes, bisection_magic.size() + 16);
  if (state.round < 0 || count < 0 || count > max_brackets ||
      bytes.size() !=
          bisection_header_size + static_cast<std::size_t>(count) * sizeof(SpectrumBracket) + 8) {
    throw fail("wrong length");
  }
  state.brackets.resize(static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < state.brackets.size(); ++k) {
    state.brackets[k] =
        read_at<SpectrumBracket>(bytes, bisection_header_size + k * sizeof(SpectrumBracket));
    if (!plausible(state.brackets[k], frequencies)) throw fail("a bracket out of range");
  }
  return state;
}

void write_bisection_state(const std::filesystem::path& path, const BisectionState& state) {
  write_file_atomically(path, encode_bisection_state(state));
}

std::optional<BisectionState> read_bisection_state(const std::filesystem::path& path,
                                                   std::int64_t max_brackets,
                                                   std::int64_t frequencies) {
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return std::nullopt;
  const std::size_t largest =
      bisection_header_size + static_cast<std::size_t>(max_brackets) * sizeof(SpectrumBracket) + 8;
  try {
    return decode_bisection_state(read_input_file(path, {largest, false}), path.string(),
                                  max_brackets, frequencies);
  } catch (const InputFileError& refused) {
    throw CheckpointError(std::string(refused.what()) + "; remove it to start the bisection over");
  }
}

std::filesystem::path bisection_state_path_for(const std::filesystem::path& output) {
  auto path = output;
  path += ".bisection";
  return path;
}

}  // namespace blockfrag
