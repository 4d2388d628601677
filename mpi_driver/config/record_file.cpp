#include "mpi_driver/config/record_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {

namespace {

// A file's lines one at a time, numbered from 1, without their line ends (LF or CRLF): no copy of
// the file's lines is kept, so a file of short lines costs no more memory than its bytes. A record
// is text: a NUL byte means a binary file or a damaged one.
class Lines {
 public:
  explicit Lines(const std::filesystem::path& file) : name_(file.string()) {
    try {
      content_ = read_input_file(file, {kMaxRecordBytes});
    } catch (const InputFileError& error) {
      // The reader's message starts with the file's name: keep only its reason.
      const std::string what = error.what();
      throw RecordError(name_, 0, what.substr(std::min(what.size(), name_.size() + 2)));
    }
    // A UTF-8 byte order mark, which some spreadsheet programs write, is not part of the first
    // line.
    constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
    if (content_.starts_with(byte_order_mark)) next_ = byte_order_mark.size();
  }

  const std::string& file() const { return name_; }
  // The number of the line next() returned last (0 before the first).
  std::size_t number() const { return number_; }

  // The next line, or nothing at the end of the file.
  std::optional<std::string_view> next() {
    if (next_ >= content_.size()) return std::nullopt;
    std::size_t end = content_.find('\n', next_);
    if (end == std::string::npos) end = content_.size();
    std::string_view line(content_.data() + next_, end - next_);
    next_ = end + 1;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find('\0') != std::string_view::npos) {
      throw RecordError(name_, number_, "contains a NUL byte (a record is a text file)");
    }
    return line;
  }

 private:
  std::string name_;
  std::string content_;
  std::size_t next_ = 0;
  std::size_t number_ = 0;
};

std::vector<std::string> split(std::string_view line, const char* separators) {
  std::vector<std::string> tokens;
  std::size_t start = line.find_first_not_of(separators);
  while (start != std::string_view::npos) {
    const std::size_t end = line.find_first_of(separators, start);
    tokens.emplace_back(line.substr(start, end - start));
    start = end == std::string_view::npos ? end : line.find_first_not_of(separators, end);
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
  if (!(count > 0) || count != std::floor(count)) {
    throw RecordError(file, line,
                      "NPTS must be a positive whole number (got " + in_quotes(*npts) + ")");
  }
  if (count > static_cast<double>(kMaxRecordSamples)) {
    throw RecordError(file, line,
                      "NPTS = " + in_quotes(*npts) + " is more than " +
                          std::to_string(kMaxRecordSamples) + " samples");
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

// The next of the 4 header lines of a PEER .AT2 file.
std::string header_line(Lines& lines) {
  const std::optional<std::string_view> line = lines.next();
  if (!line) {
    throw RecordError(lines.file(), lines.number() + 1,
                      "the file ends before header line " + std::to_string(lines.number() + 1) +
                          " of 4 (a PEER .AT2 file starts with 4 header lines)");
  }
  return std::string(*line);
}

Accelerogram read_at2(Lines& lines) {
  const std::string& file = lines.file();
  header_line(lines);
  header_line(lines);
  // Line 3 names the quantity and its units: a velocity or displacement file (.VT2, .DT2 renamed),
  // or an acceleration in cm/s^2, would be read as nonsense.
  const std::string quantity = header_line(lines);
  const std::string units = upper(quantity);
  const std::size_t g_at = units.find("UNITS OF G");
  const std::size_t after = g_at + std::string("UNITS OF G").size();
  if (units.find("ACCELERATION") == std::string::npos || g_at == std::string::npos ||
      (after < units.size() && std::isalnum(static_cast<unsigned char>(units[after])))) {
    throw RecordError(
        file, 3, "expected \"ACCELERATION TIME SERIES IN UNITS OF G\", got " + in_quotes(quantity));
  }
  const Header header = read_header_counts(header_line(lines), file);
  if (header.points < 2) throw RecordError(file, 4, "a record needs at least 2 samples (NPTS = 1)");

  Accelerogram record;
  record.acceleration_g.reserve(header.points);
  std::size_t last_line = 4;
  while (const std::optional<std::string_view> line = lines.next()) {
    last_line = lines.number();
    for (const std::string& token : split(*line, " \t")) {
      if (record.acceleration_g.size() == header.points) {
        throw RecordError(file, last_line,
                          "more values than NPTS = " + std::to_string(header.points) +
                              " (the extra one is " + in_quotes(token) + ")");
      }
      record.acceleration_g.push_back(parse_number(token, file, last_line));
    }
  }
  if (record.acceleration_g.size() < header.points) {
    throw RecordError(file, last_line,
                      "the file ends after " + std::to_string(record.acceleration_g.size()) +
                          " values, fewer than NPTS = " + std::to_string(header.points));
  }
  record.times.resize(header.points);
  for (std::size_t k = 0; k < header.points; ++k)
    record.times[k] = static_cast<double>(k) * header.step;
  return record;
}

Accelerogram read_two_columns(Lines& lines) {
  const std::string& file = lines.file();
  Accelerogram record;
  std::string previous_time;  // as written, for the message
  std::size_t last_line = 0;
  while (const std::optional<std::string_view> text = lines.next()) {
    const std::size_t line = last_line = lines.number();
    const auto tokens = split(*text, " \t,");
    if (tokens.empty() || tokens.front().front() == '#') continue;
    if (record.times.size() == kMaxRecordSamples) {
      throw RecordError(file, line, "more than " + std::to_string(kMaxRecordSamples) + " samples");
    }
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
        file, std::max<std::size_t>(last_line, 1),
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
  Lines lines(file);
  const bool at2 = upper(file.extension().string()) == ".AT2";
  return at2 ? read_at2(lines) : read_two_columns(lines);
}

}  // namespace blockfrag
