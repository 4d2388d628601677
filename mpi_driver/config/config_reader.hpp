// Reading JSON configs so that every error points at the offending value by its JSON pointer and
// all of a document's errors are reported together, once:
//   scene.json: /contact/friction: must be >= 0 (got -0.3)
// Usage: parse the text, wrap the root in an ObjectReader over a ConfigErrors, read typed values
// (each read records the key as known), call finish() on every object to report the keys nobody
// asked for, add cross-field errors, then throw_if_any().
#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/errors.hpp"
#include "engine/scene/parameter_domains.hpp"

namespace blockfrag {

using JsonPointer = nlohmann::json::json_pointer;

// A config that cannot be used; what() is every message, one per line.
class ConfigError : public InvalidInput {
 public:
  explicit ConfigError(std::vector<std::string> messages);
  const std::vector<std::string>& messages() const noexcept { return messages_; }

 private:
  std::vector<std::string> messages_;
};

// The errors found in one document, each prefixed with the document's name.
class ConfigErrors {
 public:
  explicit ConfigErrors(std::string source) : source_(std::move(source)) {}

  void add(const JsonPointer& path, std::string_view rule);  // "source: /path: rule"
  void add_message(std::string message);                     // already formatted
  bool empty() const noexcept { return messages_.empty(); }
  std::size_t size() const noexcept { return messages_.size(); }
  const std::string& source() const noexcept { return source_; }
  void throw_if_any() const;

 private:
  std::string source_;
  std::vector<std::string> messages_;
};

// An interval of allowed numbers and the words that report a value outside it.
class Range {
 public:
  static Range any() { return Range{}; }
  static Range greater_than(double bound) { return Range{Bound{bound, false, {}}, {}}; }
  static Range at_least(double bound) { return Range{Bound{bound, true, {}}, {}}; }
  static Range at_most(double bound) { return Range{{}, Bound{bound, true, {}}}; }
  static Range closed(double low, double high) {
    return {Bound{low, true, {}}, Bound{high, true, {}}};
  }
  static Range open(double low, double high) {
    return {Bound{low, false, {}}, Bound{high, false, {}}};
  }
  static Range left_open(double low, double high) {
    return {Bound{low, false, {}}, Bound{high, true, {}}};
  }
  // A scene parameter's domain (engine/scene/parameter_domains.hpp), with its labels.
  static Range of(const Domain& domain) {
    std::optional<Bound> high;
    if (domain.high != std::numeric_limits<double>::infinity()) {
      high = Bound{domain.high, domain.high_inclusive, domain.high_label ? domain.high_label : ""};
    }
    return {Bound{domain.low, domain.low_inclusive, domain.low_label ? domain.low_label : ""},
            high};
  }

  // Names the bounds in messages where the digits would not speak, e.g. "pi/2".
  Range labelled(std::string low_label, std::string high_label) const;

  bool contains(double x) const;
  std::string rule() const;  // "must be > 0", "must be in (0, 0.1]"

 private:
  struct Bound {
    double value;
    bool inclusive;
    std::string label;
  };
  Range() = default;
  Range(std::optional<Bound> low, std::optional<Bound> high)
      : low_(std::move(low)), high_(std::move(high)) {}
  static std::string text(const Bound& bound);

  std::optional<Bound> low_, high_;
};

// One value read at a known path. Each returns nullopt and records an error when the value is not
// what was asked; a number must be finite, an integer must have no fractional part.
std::optional<double> read_number(const nlohmann::json& value, const JsonPointer& path,
                                  ConfigErrors& errors, const Range& range = Range::any());
std::optional<long> read_integer(const nlohmann::json& value, const JsonPointer& path,
                                 ConfigErrors& errors, const Range& range = Range::any());
std::optional<bool> read_boolean(const nlohmann::json& value, const JsonPointer& path,
                                 ConfigErrors& errors);
std::optional<std::string> read_string(const nlohmann::json& value, const JsonPointer& path,
                                       ConfigErrors& errors);
std::optional<std::string> read_choice(const nlohmann::json& value, const JsonPointer& path,
                                       ConfigErrors& errors,
                                       std::span<const std::string_view> choices);
std::optional<std::string> read_choice(const nlohmann::json& value, const JsonPointer& path,
                                       ConfigErrors& errors,
                                       std::initializer_list<std::string_view> choices);

class ArrayReader;

// Reads the members of one JSON object. Reading a key (present or not) makes it known; finish()
// reports every present key that is not known, with the nearest known key as a hint. A reader over
// a missing or non-object value is inert: it reads nothing and reports nothing more.
// For each type: `T name_or(key, fallback)` (absent: the fallback), `optional<T> name(key)`
// (absent: nullopt), `optional<T> required_name(key)` (absent: an error). Invalid values are
// always errors and come back as the fallback or nullopt.
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& value, JsonPointer path, ConfigErrors& errors);
  ObjectReader(JsonPointer path, ConfigErrors& errors);  // inert: stands for an absent object

  bool valid() const noexcept { return object_ != nullptr; }
  const JsonPointer& path() const noexcept { return path_; }
  JsonPointer path_of(std::string_view key) const;
  ConfigErrors& errors() const noexcept { return *errors_; }

  bool has(std::string_view key);
  // The raw value for reading that the typed getters do not cover; nullptr when absent.
  const nlohmann::json* raw(std::string_view key);
  void add_error(std::string_view key, std::string_view rule);  // e.g. a cross-field rule

  std::optional<double> number(std::string_view key, const Range& range = Range::any());
  std::optional<double> required_number(std::string_view key, const Range& range = Range::any());
  double number_or(std::string_view key, double fallback, const Range& range = Range::any());

  std::optional<long> integer(std::string_view key, const Range& range = Range::any());
  std::optional<long> required_integer(std::string_view key, const Range& range = Range::any());
  long integer_or(std::string_view key, long fallback, const Range& range = Range::any());

  std::optional<bool> boolean(std::string_view key);
  std::optional<bool> required_boolean(std::string_view key);
  bool boolean_or(std::string_view key, bool fallback);

  std::optional<std::string> string(std::string_view key);
  std::optional<std::string> required_string(std::string_view key);
  std::string string_or(std::string_view key, std::string fallback);

  std::optional<std::string> choice(std::string_view key,
                                    std::span<const std::string_view> choices);
  std::optional<std::string> required_choice(std::string_view key,
                                             std::span<const std::string_view> choices);
  std::optional<std::string> choice(std::string_view key,
                                    std::initializer_list<std::string_view> choices) {
    return choice(key, std::span(choices.begin(), choices.size()));
  }
  std::optional<std::string> required_choice(std::string_view key,
                                             std::initializer_list<std::string_view> choices) {
    return required_choice(key, std::span(choices.begin(), choices.size()));
  }

  ObjectReader object(std::string_view key);           // inert when absent
  ObjectReader required_object(std::string_view key);  // inert when absent, after an error
  ArrayReader array(std::string_view key);
  ArrayReader required_array(std::string_view key);

  // Reports the unknown keys; `context` (e.g. `for type "sine_pulse"`) follows the key's name.
  void finish(std::string_view context = {});

 private:
  const nlohmann::json* find(std::string_view key);  // marks the key known
  const nlohmann::json* find_required(std::string_view key);

  const nlohmann::json* object_;
  JsonPointer path_;
  ConfigErrors* errors_;
  std::vector<std::string> known_;
};

// Reads the elements of one JSON array; inert, like ObjectReader, over a missing or non-array
// value.
class ArrayReader {
 public:
  ArrayReader(const nlohmann::json& value, JsonPointer path, ConfigErrors& errors);
  ArrayReader(JsonPointer path, ConfigErrors& errors);  // inert: stands for an absent array

  bool valid() const noexcept { return array_ != nullptr; }
  std::size_t size() const noexcept { return array_ ? array_->size() : 0; }
  const JsonPointer& path() const noexcept { return path_; }
  JsonPointer path_of(std::size_t index) const { return path_ / index; }
  const nlohmann::json& raw(std::size_t index) const { return array_->at(index); }

  std::optional<double> number(std::size_t index, const Range& range = Range::any());
  std::optional<long> integer(std::size_t index, const Range& range = Range::any());
  std::optional<std::string> string(std::size_t index);
  ObjectReader object(std::size_t index);

 private:
  const nlohmann::json* array_;
  JsonPointer path_;
  ConfigErrors* errors_;
};

// Optimal string alignment distance (Levenshtein plus adjacent transpositions).
std::size_t edit_distance(std::string_view a, std::string_view b);
// The candidate a typo most likely meant, if any is close enough to suggest.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates);

// A config nests at most this deep (a scene's deepest value is 4 levels down): a deeper document
// is refused before it is parsed, since each level costs the parser time and memory.
inline constexpr std::size_t kMaxJsonDepth = 64;
// A config file is at most this large (a 10,000-vertex polygon takes under 1 MB).
inline constexpr std::size_t kMaxConfigBytes = 64u << 20;

// Parses JSON text. Malformed text, or text nested deeper than kMaxJsonDepth, throws ConfigError
// "source:line:column: malformed JSON: why"; duplicate keys (which nlohmann would resolve silently
// to the last) throw ConfigError too.
nlohmann::json parse_json_text(std::string_view text, const std::string& source);
// Reads (mpi_driver/config/input_file.hpp) and parses a file, named in messages as given. Throws
// InputFileError if it is not a readable regular file of at most kMaxConfigBytes.
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace blockfrag
