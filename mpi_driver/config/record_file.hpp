// Reading a recorded accelerogram from a PEER NGA .AT2 file or a two-column text file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "engine/errors.hpp"
#include "engine/motion/accelerogram.hpp"
#include "engine/scene/parameter_domains.hpp"

namespace blockfrag {

// A record file that cannot be used. what() is "<file>:<line>: <reason>", or "<file>: <reason>"
// when no line is to blame (a file that cannot be opened); the file is named as the caller gave it.
class RecordError : public InvalidInput {
 public:
  RecordError(const std::string& file, std::size_t line, const std::string& reason);
  const std::string& file() const noexcept { return file_; }
  std::size_t line() const noexcept { return line_; }  // 1-based; 0 for the whole file
  const std::string& reason() const noexcept { return reason_; }

 private:
  std::string file_, reason_;
  std::size_t line_;
};

// A record file is at most this large: 256 MB, 17 hours of a 3-component 200 Hz record in text.
inline constexpr std::size_t kMaxRecordBytes = 256u << 20;
// A record has at most domain::kMaxRecordSamples samples (engine/scene/parameter_domains.hpp).
inline constexpr std::size_t kMaxRecordSamples = domain::kMaxRecordSamples;

// Reads a record, choosing the format by the extension: ".AT2" (any case) is PEER NGA (4 header
// lines, the 4th giving NPTS and DT, then NPTS values in g, any number per line, sample k at k DT);
// anything else is two columns "time acceleration_g" per line, separated by whitespace or commas,
// blank lines and lines starting with '#' ignored. Throws RecordError for every malformed input.
Accelerogram read_accelerogram(const std::filesystem::path& file);

}  // namespace blockfrag
