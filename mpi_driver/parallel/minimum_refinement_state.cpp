#include "mpi_driver/parallel/minimum_refinement_state.hpp"

#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/study_hash.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/parallel/byte_fields.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"

namespace blockfrag {
namespace {

constexpr std::string_view minimum_magic = "BFMINI01";
constexpr std::size_t minimum_header_size = minimum_magic.size() + 4 * 8;

using bytes::append;
using bytes::read_at;

std::size_t encoded_size(std::int64_t frequencies, std::int64_t segments) {
  return minimum_header_size + static_cast<std::size_t>(frequencies) * 8 +
         static_cast<std::size_t>(segments) * sizeof(MinimumSegment) + 8;
}

// A segment read back must be one the refinement could have written.
bool plausible(const MinimumSegment& s, std::int64_t frequencies) {
  const auto verdict_ok = [](std::int64_t v) {
    return v >= 0 && v <= static_cast<std::int64_t>(SpectrumVerdict::rejected);
  };
  return s.frequency_index >= 0 && s.frequency_index < frequencies && s.low > 0 && s.low < s.high &&
         verdict_ok(s.verdict_low) && verdict_ok(s.verdict_high) && s.state >= 0 &&
         s.state <= static_cast<std::int64_t>(SegmentState::capped);
}

}  // namespace

std::string encode_minimum_refinement(const MinimumRefinement& refinement) {
  const auto frequencies = static_cast<std::int64_t>(refinement.midpoints.size());
  const auto count = static_cast<std::int64_t>(refinement.segments.size());
  std::string out;
  out.reserve(encoded_size(frequencies, count));
  out.append(minimum_magic);
  append(out, refinement.config_hash);
  append(out, refinement.round);
  append(out, frequencies);
  append(out, count);
  for (const std::int64_t midpoints : refinement.midpoints) append(out, midpoints);
  for (const MinimumSegment& s : refinement.segments) append(out, s);
  append(out, fnv1a64(out));
  return out;
}

MinimumRefinement decode_minimum_refinement(std::string_view bytes, const std::string& source,
                                            std::int64_t max_segments, std::int64_t frequencies) {
  const auto fail = [&](const std::string& why) {
    return CheckpointError(source + ": not a usable blockfrag minimum refinement (" + why +
                           "); remove it to start the refinement over");
  };
  if (bytes.size() < minimum_header_size + 8 ||
      bytes.substr(0, minimum_magic.size()) != minimum_magic) {
    throw fail("wrong header");
  }
  if (fnv1a64(bytes.substr(0, bytes.size() - 8)) != read_at<std::uint64_t>(bytes, bytes.size() - 8))
    throw fail("checksum mismatch");
  MinimumRefinement refinement;
  std::size_t at = minimum_magic.size();
  refinement.config_hash = read_at<std::uint64_t>(bytes, at);
  refinement.round = read_at<std::int64_t>(bytes, at + 8);
  const auto stored_frequencies = read_at<std::int64_t>(bytes, at + 16);
  const auto count = read_at<std::int64_t>(bytes, at + 24);
  if (refinement.round < 0 || stored_frequencies != frequencies || count < 0 ||
      count > max_segments || bytes.size() != encoded_size(frequencies, count)) {
    throw fail("wrong length");
  }
  at = minimum_header_size;
  refinement.midpoints.resize(static_cast<std::size_t>(frequencies));
  for (std::int64_t& midpoints : refinement.midpoints) {
    midpoints = read_at<std::int64_t>(bytes, at);
    at += 8;
    if (midpoints < 0) throw fail("a negative count of midpoints");
  }
  refinement.segments.resize(static_cast<std::size_t>(count));
  for (MinimumSegment& s : refinement.segments) {
    s = read_at<MinimumSegment>(bytes, at);
    at += sizeof(MinimumSegment);
    if (!plausible(s, frequencies)) throw fail("a segment out of range");
  }
  return refinement;
}

void write_minimum_refinement(const std::filesystem::path& path,
                              const MinimumRefinement& refinement) {
  write_file_atomically(path, encode_minimum_refinement(refinement));
}

std::optional<MinimumRefinement> read_minimum_refinement(const std::filesystem::path& path,
                                                         std::int64_t max_segments,
                                                         std::int64_t frequencies) {
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return std::nullopt;
  try {
    return decode_minimum_refinement(
        read_input_file(path, {encoded_size(frequencies, max_segments), false}), path.string(),
        max_segments, frequencies);
  } catch (const InputFileError& refused) {
    throw CheckpointError(std::string(refused.what()) + "; remove it to start the refinement over");
  }
}

std::filesystem::path minimum_refinement_path_for(const std::filesystem::path& output) {
  auto path = output;
  path += ".minimum";
  return path;
}

}  // namespace blockfrag
