#include "mpi_driver/parallel/checkpoint.hpp"

#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/parallel/byte_fields.hpp"

namespace blockfrag {
namespace {

constexpr std::string_view magic = "BFCKPT02";
constexpr std::string_view records_magic = "BFCKPT01";
constexpr std::size_t header_size = magic.size() + 3 * 8;

using bytes::append;
using bytes::read_at;

}  // namespace

std::string encode_checkpoint(const CheckpointState& state) {
  std::string out;
  out.reserve(header_size + state.done.size() * 16 + 8);
  out.append(magic);
  append(out, state.config_hash);
  append(out, state.total_samples);
  append(out, static_cast<std::int64_t>(state.done.size()));
  for (const auto& range : state.done) {
    append(out, range.first);
    append(out, range.count);
  }
  append(out, fnv1a64(out));
  return out;
}

CheckpointState decode_checkpoint(std::string_view bytes, const std::string& source) {
  const auto fail = [&](const std::string& why) {
    return CheckpointError(source + ": not a usable blockfrag checkpoint (" + why +
                           "); remove it to start the study over");
  };
  if (bytes.substr(0, records_magic.size()) == records_magic) {
    throw CheckpointError(source +
                          ": a checkpoint of an older blockfrag (format BFCKPT01, records inside); "
                          "finish the study with the version that started it, or remove the "
                          "checkpoint to start over");
  }
  if (bytes.size() < header_size + 8 || bytes.substr(0, magic.size()) != magic) {
    throw fail("wrong header");
  }
  const auto stored_sum = read_at<std::uint64_t>(bytes, bytes.size() - 8);
  if (fnv1a64(bytes.substr(0, bytes.size() - 8)) != stored_sum) throw fail("checksum mismatch");

  CheckpointState state;
  state.config_hash = read_at<std::uint64_t>(bytes, magic.size());
  state.total_samples = read_at<std::int64_t>(bytes, magic.size() + 8);
  const auto count = read_at<std::int64_t>(bytes, magic.size() + 16);
  if (count < 0 || count > kMaxCheckpointRanges ||
      bytes.size() != header_size + static_cast<std::size_t>(count) * 16 + 8) {
    throw fail("wrong length");
  }
  std::int64_t next = 0;
  for (std::int64_t k = 0; k < count; ++k) {
    const std::size_t at = header_size + static_cast<std::size_t>(k) * 16;
    const IndexRange range{read_at<std::int64_t>(bytes, at), read_at<std::int64_t>(bytes, at + 8)};
    if (range.first < next || range.count <= 0 || range.count > state.total_samples - range.first) {
      throw fail("sample ranges out of order, overlapping or outside the study");
    }
    state.done.push_back(range);
    next = range.end();
  }
  return state;
}

void write_checkpoint(const std::filesystem::path& path, const CheckpointState& state,
                      const AtomicWriteHooks& hooks) {
  write_file_atomically(path, encode_checkpoint(state), hooks);
}

std::optional<CheckpointState> read_checkpoint(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return std::nullopt;
  const std::size_t largest = header_size + static_cast<std::size_t>(kMaxCheckpointRanges) * 16 + 8;
  try {
    return decode_checkpoint(read_input_file(path, {largest, false}), path.string());
  } catch (const InputFileError& refused) {
    throw CheckpointError(std::string(refused.what()) + "; remove it to start the study over");
  }
}

std::filesystem::path checkpoint_path_for(const std::filesystem::path& output) {
  auto path = output;
  path += ".checkpoint";
  return path;
}

}  // namespace blockfrag
