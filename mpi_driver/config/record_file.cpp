#include "mpi_driver/config/record_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {

namespace {

// A file's lines, numbered from 1, without their line ends (LF or CRLF). A record is text: a NUL
// byte means a binary file or a damaged one.
std::vector<std::string> read_lines(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::string content;
  try {
    content = read_input_file(file, {kMaxRecordBytes});
  } catch (const InputFileError& error) {
    // The reader's message starts with the file's name: keep only its reason.
    const std::string what = error.what();
    throw RecordError(name, 0, what.substr(std::min(what.size(), name.size() + 2)));
  }
  std::vector<std::string> lines;
  // A UTF-8 byte order mark, which some spreadsheet programs write, is not part of the first line.
  constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
  std::size_t start = content.starts_with(byte_order_mark) ? byte_order_mark.size() : 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string::npos) end = content.size();
    std::string line = content.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find('\0') != std::string::npos) {
      throw RecordError(name, lines.size() + 1, "contains a NUL byte (a record is a text file)");
    }
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::vector<std::string> split(const std::string& line, const char* separators) {
  std::vector<std::string> tokens;
  std::size_t start = line.find_first_not_of(separators);
  while (start != std::string::npos) {
    const std::size_t end = line.find_first_of(separators, start);
    tokens.push_back(line.substr(start, end - start));
    start = end == std::string::npos ? end : line.find_first_not_of(separators, end);
  }
  return tokens;
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// A file's text in a message: at most a short printable excerpt (input_file.hpp).
std::string in_quotes(const std::string& text) { return "\"" + printable_excerpt(text) + "\""; }

// A decimal number that is the whole token, with an optional sign: refuses words, "1.5x", hex
// floats ("0x1p3"), nan and inf.
double parse_number(const std::string& token, const std::string& file, std::size_t line) {
  const char* first = token.data();
  const char* last = token.data() + token.size();
  // from_chars takes a '-' but no '+'; records may write one.
  if (last - first > 1 && first[0] == '+' && first[1] != '-') ++first;
  double value = 0.0;
  const auto [end, error] = std::from_chars(first, last, value, std::chars_format::general);
  if (error == std::errc::result_out_of_range || (error == std::errc{} && !std::isfinite(value))) {
    throw RecordError(file, line, "not a finite number: " + in_quotes(token));
  }
  if (error != std::errc{} || end != last) {
    throw RecordError(file, line, "not a number: " + in_quotes(token));
  }
  return value;
}

// The token that follows `key` (e.g. "NPTS=") on an upper-cased header line with commas blanked.
std::optional<std::string> value_after(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(key);
  if (at == std::string::npos) return std::nullopt;
  const auto tokens = split(line.substr(at + key.size()), " \t");
  if (tokens.empty()) return std::nullopt;
  return tokens.front();
}

struct Header {
  std::size_t points;
  double step;
};

// Line 4: "NPTS=  4000, DT=   .0050 SEC" (NGA-West2) or "4000    .0050    NPTS, DT" (older).
Header read_header_counts(const std::string& text, const std::string& file) {
  constexpr std::size_t line = 4;
  std::string normalized = upper(text);
  std::replace(normalized.begin(), normalized.end(), ',', ' ');
  std::optional<std::string> npts = value_after(normalized, "NPTS=");
  std::optional<std::string> dt = value_after(normalized, "DT=");
  if (!npts && !dt) {
    const auto tokens = split(normalized, " \t");
    if (tokens.size() >= 4 && tokens[2] == "NPTS" && tokens[3] == "DT") {
      npts = tokens[0];
      dt = tokens[1];
    }
  }
  if (!npts || !dt) {
    throw RecordError(
        file, line,
        "expected NPTS and DT as \"NPTS= 4000, DT= .0050 SEC\" or \"4000 .0050 NPTS, DT\", got " +
            in_quotes(text));
  }
  const double count = parse_number(*npts, file, line);
  // Each value takes at least two bytes ("0 "): no file under the size cap holds more.
  if (!(count > 0) || count != std::floor(count) || count > kMaxRecordBytes / 2.0) {
    throw RecordError(file, line,
                      "NPTS must be a positive whole number (got " + in_quotes(*npts) + ")");
  }
  const double step = parse_number(*dt, file, line);
  if (!(step > 0)) throw RecordError(file, line, "DT must be > 0 (got " + in_quotes(*dt) + ")");
  if ((count - 1) * step > domain::record_time.high) {
    throw RecordError(file, line,
                      "the record lasts (NPTS - 1) DT = " + format_number((count - 1) * step) +
                          " s, more than " + format_number(domain::record_time.high) + " s");
  }
  return {static_cast<std::size_t>(count), step};
}

Accelerogram read_at2(const std::vector<std::string>& lines, const std::string& file) {
  constexpr std::size_t header_lines = 4;
  if (lines.size() < header_lines) {
    throw RecordError(file, lines.size() + 1,
                      "the file ends before header line " + std::to_string(lines.size() + 1) +
                          " of 4 (a PEER .AT2 file starts with 4 header lines)");
  }
  // Line 3 names the quantity and its units: a velocity or displacement file (.VT2, .DT2 renamed),
  // or an acceleration in cm/s^2, would be read as nonsense.
  const std::string units = upper(lines[2]);
  const std::size_t g_at = units.find("UNITS OF G");
  const std::size_t after = g_at + std::string("UNITS OF G").size();
  if (units.find("ACCELERATION") == std::string::npos || g_at == std::string::npos ||
      (after < units.size() && std::isalnum(static_cast<unsigned char>(units[after])))) {
    throw RecordError(
        file, 3, "expected \"ACCELERATION TIME SERIES IN UNITS OF G\", got " + in_quotes(lines[2]));
  }
  const Header header = read_header_counts(lines[3], file);
  if (header.points < 2) throw RecordError(file, 4, "a record needs at least 2 samples (NPTS = 1)");

  Accelerogram record;
  // NPTS is the file's word: reserve no more than a plausible record before the values are read.
  record.acceleration_g.reserve(std::min<std::size_t>(header.points, std::size_t{1} << 20));
  for (std::size_t i = header_lines; i < lines.size(); ++i) {
    for (const std::string& token : split(lines[i], " \t")) {
      if (record.acceleration_g.size() == header.points) {
        throw RecordError(file, i + 1,
                          "more values than NPTS = " + std::to_string(header.points) +
                              " (the extra one is " + in_quotes(token) + ")");
      }
      record.acceleration_g.push_back(parse_number(token, file, i + 1));
    }
  }
  if (record.acceleration_g.size() < header.points) {
    throw RecordError(file, lines.size(),
                      "the file ends after " + std::to_string(record.acceleration_g.size()) +
                          " values, fewer than NPTS = " + std::to_string(header.points));
  }
  record.times.resize(header.points);
  for (std::size_t k = 0; k < header.points; ++k)
    record.times[k] = static_cast<double>(k) * header.step;
  return record;
}

Accelerogram read_two_columns(const std::vector<std::string>& lines, const std::string& file) {
  Accelerogram record;
  std::string previous_time;  // as written, for the message
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t line = i + 1;
    const auto tokens = split(lines[i], " \t,");
    if (tokens.empty() || tokens.front().front() == '#') continue;
    std::vector<double> values;
    for (const std::string& token : tokens) values.push_back(parse_number(token, file, line));
    if (values.size() != 2) {
      throw RecordError(
          file, line,
          "expected 2 numbers (time acceleration_g), found " + std::to_string(values.size()));
    }
    if (values[0] < 0)
      throw RecordError(file, line, "time must be >= 0 (got " + printable_excerpt(tokens[0]) + ")");
    if (values[0] > domain::record_time.high) {
      throw RecordError(file, line,
                        "time must be <= " + format_number(domain::record_time.high) + " s (got " +
                            printable_excerpt(tokens[0]) + ")");
    }
    if (!record.times.empty() && !(values[0] > record.times.back())) {
      throw RecordError(file, line,
                        "times must increase strictly (" + printable_excerpt(tokens[0]) +
                            " follows " + printable_excerpt(previous_time) + ")");
    }
    previous_time = tokens[0];
    record.times.push_back(values[0]);
    record.acceleration_g.push_back(values[1]);
  }
  if (record.times.size() < 2) {
    throw RecordError(
        file, std::max<std::size_t>(lines.size(), 1),
        "a record needs at least 2 samples (found " + std::to_string(record.times.size()) + ")");
  }
  return record;
}

}  // namespace

namespace {

// Built by appending: g++ 12 warns (-Wrestrict, a false positive) on the chained operator+.
std::string located(const std::string& file, std::size_t line, const std::string& reason) {
  std::string message = file;
  if (line > 0) message.append(":").append(std::to_string(line));
  return message.append(": ").append(reason);
}

}  // namespace

RecordError::RecordError(const std::string& file, std::size_t line, const std::string& reason)
    : InvalidInput(located(file, line, reason)), file_(file), reason_(reason), line_(line) {}

Accelerogram read_accelerogram(const std::filesystem::path& file) {
  const std::vector<std::string> lines = read_lines(file);
  const bool at2 = upper(file.extension().string()) == ".AT2";
  return at2 ? read_at2(lines, file.string()) : read_two_columns(lines, file.string());
}

}  // namespace blockfrag
