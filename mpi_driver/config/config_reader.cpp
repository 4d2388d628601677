#include "mpi_driver/config/config_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "mpi_driver/config/input_file.hpp"
#include "sampling/validation.hpp"  // format_number

namespace blockfrag {

namespace {

using nlohmann::json;

std::string join_lines(const std::vector<std::string>& lines) {
  std::string joined;
  for (const auto& line : lines) {
    if (!joined.empty()) joined += '\n';
    joined += line;
  }
  return joined;
}

// JSON text of a scalar for a message: at most a short printable excerpt of what the file holds;
// a string with invalid UTF-8 must not make the message throw.
std::string dump(const json& value) {
  return printable_excerpt(value.dump(-1, ' ', false, json::error_handler_t::replace));
}

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::binary: return "binary data";
    case json::value_t::number_float: return format_number(value.get<double>());
    default: return dump(value);
  }
}

std::string lowercase(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

// Strings people write when they mean a non-finite number, which JSON cannot express.
bool names_non_finite(std::string_view text) {
  std::string word = lowercase(text);
  if (!word.empty() && (word.front() == '-' || word.front() == '+')) word.erase(0, 1);
  return word == "nan" || word == "inf" || word == "infinity";
}

std::string not_a_number(const json& value) {
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (names_non_finite(text)) {
      return "must be a finite number (got " + dump(value) + "; JSON has no NaN or Infinity)";
    }
    return "must be a number, not a string (got " + dump(value) + ")";
  }
  return "must be a number (got " + describe(value) + ")";
}

bool check_range(double x, const std::string& shown, const JsonPointer& path, ConfigErrors& errors,
                 const Range& range) {
  if (range.contains(x)) return true;
  errors.add(path, range.rule() + " (got " + shown + ")");
  return false;
}

std::string quoted_list(std::span<const std::string_view> words) {
  std::string list;
  for (const auto word : words) {
    if (!list.empty()) list += ", ";
    list += '"';
    list += word;
    list += '"';
  }
  return list;
}

}  // namespace

ConfigError::ConfigError(std::vector<std::string> messages)
    : InvalidInput(join_lines(messages)), messages_(std::move(messages)) {}

void ConfigErrors::add(const JsonPointer& path, std::string_view rule) {
  // The path is made of the file's own keys: quoted no longer than a few of them.
  const std::string where =
      path.empty() ? std::string{} : printable_excerpt(path.to_string(), 120) + ": ";
  messages_.push_back(source_ + ": " + where + std::string(rule));
}

void ConfigErrors::add_message(std::string message) { messages_.push_back(std::move(message)); }

void ConfigErrors::throw_if_any() const {
  if (!messages_.empty()) throw ConfigError(messages_);
}

Range Range::labelled(std::string low_label, std::string high_label) const {
  Range range = *this;
  if (range.low_) range.low_->label = std::move(low_label);
  if (range.high_) range.high_->label = std::move(high_label);
  return range;
}

bool Range::contains(double x) const {
  if (low_ && !(low_->inclusive ? x >= low_->value : x > low_->value)) return false;
  if (high_ && !(high_->inclusive ? x <= high_->value : x < high_->value)) return false;
  return true;
}

std::string Range::text(const Bound& bound) {
  return bound.label.empty() ? format_number(bound.value) : bound.label;
}

std::string Range::rule() const {
  if (low_ && high_) {
    return "must be in " + std::string(low_->inclusive ? "[" : "(") + text(*low_) + ", " +
           text(*high_) + (high_->inclusive ? "]" : ")");
  }
  if (low_) return std::string("must be ") + (low_->inclusive ? ">= " : "> ") + text(*low_);
  if (high_) return std::string("must be ") + (high_->inclusive ? "<= " : "< ") + text(*high_);
  return "may be any number";
}

std::optional<double> read_number(const json& value, const JsonPointer& path, ConfigErrors& errors,
                                  const Range& range) {
  if (!value.is_number()) {
    errors.add(path, not_a_number(value));
    return std::nullopt;
  }
  const double x = value.get<double>();
  if (!std::isfinite(x)) {
    errors.add(path, "must be a finite number (got " + format_number(x) + ")");
    return std::nullopt;
  }
  if (!check_range(x, describe(value), path, errors, range)) return std::nullopt;
  return x;
}

std::optional<long> read_integer(const json& value, const JsonPointer& path, ConfigErrors& errors,
                                 const Range& range) {
  if (!value.is_number()) {
    errors.add(path, not_a_number(value));
    return std::nullopt;
  }
  long n = 0;
  if (value.is_number_unsigned()) {
    if (value.get<unsigned long>() > static_cast<unsigned long>(std::numeric_limits<long>::max())) {
      errors.add(path, "must be an integer that fits in 64 bits (got " + dump(value) + ")");
      return std::nullopt;
    }
    n = value.get<long>();
  } else if (value.is_number_integer()) {
    n = value.get<long>();
  } else {
    // 1e6 is an integer written in exponent form; 2.5 is not. 2^63 is where long ends.
    const double x = value.get<double>();
    if (!std::isfinite(x) || std::floor(x) != x || std::fabs(x) >= 9.2233720368547758e18) {
      errors.add(path, "must be an integer (got " + format_number(x) + ")");
      return std::nullopt;
    }
    n = static_cast<long>(x);
  }
  if (!check_range(static_cast<double>(n), std::to_string(n), path, errors, range))
    return std::nullopt;
  return n;
}

std::optional<bool> read_boolean(const json& value, const JsonPointer& path, ConfigErrors& errors) {
  if (!value.is_boolean()) {
    errors.add(path, "must be true or false (got " + describe(value) + ")");
    return std::nullopt;
  }
  return value.get<bool>();
}

std::optional<std::string> read_string(const json& value, const JsonPointer& path,
                                       ConfigErrors& errors) {
  if (!value.is_string()) {
    errors.add(path, "must be a string (got " + describe(value) + ")");
    return std::nullopt;
  }
  return value.get<std::string>();
}

std::optional<std::string> read_choice(const json& value, const JsonPointer& path,
                                       ConfigErrors& errors,
                                       std::initializer_list<std::string_view> choices) {
  return read_choice(value, path, errors, std::span(choices.begin(), choices.size()));
}

std::optional<std::string> read_choice(const json& value, const JsonPointer& path,
                                       ConfigErrors& errors,
                                       std::span<const std::string_view> choices) {
  if (!value.is_string()) {
    errors.add(path, "must be one of " + quoted_list(choices) + " (got " + describe(value) + ")");
    return std::nullopt;
  }
  const auto& text = value.get_ref<const std::string&>();
  if (std::find(choices.begin(), choices.end(), text) != choices.end()) return text;
  const auto hint = closest_match(text, std::vector<std::string>(choices.begin(), choices.end()));
  errors.add(path, "must be one of " + quoted_list(choices) + " (got " + dump(value) +
                       (hint ? "; did you mean \"" + *hint + "\"?" : "") + ")");
  return std::nullopt;
}

ObjectReader::ObjectReader(const json& value, JsonPointer path, ConfigErrors& errors)
    : object_(value.is_object() ? &value : nullptr), path_(std::move(path)), errors_(&errors) {
  if (!object_) errors.add(path_, "must be an object (got " + describe(value) + ")");
}

ObjectReader::ObjectReader(JsonPointer path, ConfigErrors& errors)
    : object_(nullptr), path_(std::move(path)), errors_(&errors) {}

JsonPointer ObjectReader::path_of(std::string_view key) const { return path_ / std::string(key); }

const json* ObjectReader::find(std::string_view key) {
  known_.emplace_back(key);
  if (!object_) return nullptr;
  const auto it = object_->find(key);
  return it == object_->end() ? nullptr : &*it;
}

const json* ObjectReader::find_required(std::string_view key) {
  const json* value = find(key);
  if (!value && object_) errors_->add(path_of(key), "is required");
  return value;
}

bool ObjectReader::has(std::string_view key) { return find(key) != nullptr; }

const json* ObjectReader::raw(std::string_view key) { return find(key); }

void ObjectReader::add_error(std::string_view key, std::string_view rule) {
  errors_->add(path_of(key), rule);
}

std::optional<double> ObjectReader::number(std::string_view key, const Range& range) {
  const json* value = find(key);
  return value ? read_number(*value, path_of(key), *errors_, range) : std::nullopt;
}

std::optional<double> ObjectReader::required_number(std::string_view key, const Range& range) {
  const json* value = find_required(key);
  return value ? read_number(*value, path_of(key), *errors_, range) : std::nullopt;
}

double ObjectReader::number_or(std::string_view key, double fallback, const Range& range) {
  return number(key, range).value_or(fallback);
}

std::optional<long> ObjectReader::integer(std::string_view key, const Range& range) {
  const json* value = find(key);
  return value ? read_integer(*value, path_of(key), *errors_, range) : std::nullopt;
}

std::optional<long> ObjectReader::required_integer(std::string_view key, const Range& range) {
  const json* value = find_required(key);
  return value ? read_integer(*value, path_of(key), *errors_, range) : std::nullopt;
}

long ObjectReader::integer_or(std::string_view key, long fallback, const Range& range) {
  return integer(key, range).value_or(fallback);
}

std::optional<bool> ObjectReader::boolean(std::string_view key) {
  const json* value = find(key);
  return value ? read_boolean(*value, path_of(key), *errors_) : std::nullopt;
}

std::optional<bool> ObjectReader::required_boolean(std::string_view key) {
  const json* value = find_required(key);
  return value ? read_boolean(*value, path_of(key), *errors_) : std::nullopt;
}

bool ObjectReader::boolean_or(std::string_view key, bool fallback) {
  return boolean(key).value_or(fallback);
}

std::optional<std::string> ObjectReader::string(std::string_view key) {
  const json* value = find(key);
  return value ? read_string(*value, path_of(key), *errors_) : std::nullopt;
}

std::optional<std::string> ObjectReader::required_string(std::string_view key) {
  const json* value = find_required(key);
  return value ? read_string(*value, path_of(key), *errors_) : std::nullopt;
}

std::string ObjectReader::string_or(std::string_view key, std::string fallback) {
  return string(key).value_or(std::move(fallback));
}

std::optional<std::string> ObjectReader::choice(std::string_view key,
                                                std::span<const std::string_view> choices) {
  const json* value = find(key);
  return value ? read_choice(*value, path_of(key), *errors_, choices) : std::nullopt;
}

std::optional<std::string> ObjectReader::required_choice(
    std::string_view key, std::span<const std::string_view> choices) {
  const json* value = find_required(key);
  return value ? read_choice(*value, path_of(key), *errors_, choices) : std::nullopt;
}

ObjectReader ObjectReader::object(std::string_view key) {
  const json* value = find(key);
  if (value) return ObjectReader(*value, path_of(key), *errors_);
  return ObjectReader(path_of(key), *errors_);
}

ObjectReader ObjectReader::required_object(std::string_view key) {
  find_required(key);
  return object(key);
}

ArrayReader ObjectReader::array(std::string_view key) {
  const json* value = find(key);
  if (value) return ArrayReader(*value, path_of(key), *errors_);
  return ArrayReader(path_of(key), *errors_);
}

ArrayReader ObjectReader::required_array(std::string_view key) {
  find_required(key);
  return array(key);
}

void ObjectReader::finish(std::string_view context) {
  if (!object_) return;
  std::vector<std::string> known = known_;
  std::sort(known.begin(), known.end());
  known.erase(std::unique(known.begin(), known.end()), known.end());
  for (const auto& [key, value] : object_->items()) {
    if (std::binary_search(known.begin(), known.end(), key)) continue;
    std::string message = "unknown key";
    if (!context.empty()) message += " " + std::string(context);
    if (const auto hint = closest_match(key, known)) {
      message += "; did you mean \"" + *hint + "\"?";
    } else if (!known.empty()) {
      message += " (known keys:";
      for (const auto& name : known) message += " " + name;
      message += ")";
    }
    errors_->add(path_of(key), message);
  }
}

ArrayReader::ArrayReader(const json& value, JsonPointer path, ConfigErrors& errors)
    : array_(value.is_array() ? &value : nullptr), path_(std::move(path)), errors_(&errors) {
  if (!array_) errors.add(path_, "must be an array (got " + describe(value) + ")");
}

ArrayReader::ArrayReader(JsonPointer path, ConfigErrors& errors)
    : array_(nullptr), path_(std::move(path)), errors_(&errors) {}

std::optional<double> ArrayReader::number(std::size_t index, const Range& range) {
  return read_number(raw(index), path_of(index), *errors_, range);
}

std::optional<long> ArrayReader::integer(std::size_t index, const Range& range) {
  return read_integer(raw(index), path_of(index), *errors_, range);
}

std::optional<std::string> ArrayReader::string(std::size_t index) {
  return read_string(raw(index), path_of(index), *errors_);
}

ObjectReader ArrayReader::object(std::size_t index) {
  return ObjectReader(raw(index), path_of(index), *errors_);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic programme: a transposition looks two rows back.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);
      }
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates) {
  const std::string lower_word = lowercase(word);
  std::optional<std::string> best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(lower_word, lowercase(candidate));
    // One edit per three letters of the candidate: "frction" finds "friction", "e" does not find
    // "g".
    if (distance < best_distance && distance <= candidate.size() / 3) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

namespace {

// Builds the document like nlohmann's parser does, and also notes where the text broke (nlohmann's
// exceptions give only a byte count) and every duplicate key (nlohmann keeps the last one
// silently).
class DocumentBuilder final : public nlohmann::json_sax<json> {
 public:
  explicit DocumentBuilder(json& root) : root_(root) {}

  bool null() override { return add(nullptr); }
  bool boolean(bool value) override { return add(value); }
  bool number_integer(number_integer_t value) override { return add(value); }
  bool number_unsigned(number_unsigned_t value) override { return add(value); }
  bool number_float(number_float_t value, const string_t& /*text*/) override { return add(value); }
  bool string(string_t& value) override { return add(std::move(value)); }
  bool binary(binary_t& value) override { return add(json::binary(std::move(value))); }
  bool start_object(std::size_t /*size*/) override { return open(json::object()); }
  bool start_array(std::size_t /*size*/) override { return open(json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& name) override {
    const Container& object = open_.back();
    if (object.value->contains(name)) duplicates_.push_back(object.path / name);
    key_ = name;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& token,
                   const json::exception& error) override {
    error_position_ = position;
    error_ = error.what();
    error_token_ = token;
    return false;
  }

  std::size_t error_position() const { return error_position_; }
  const std::string& error() const { return error_; }
  const std::string& error_token() const { return error_token_; }
  const std::vector<JsonPointer>& duplicates() const { return duplicates_; }

 private:
  struct Container {
    json* value;
    JsonPointer path;
  };

  Container place(json value) {
    if (open_.empty()) {
      root_ = std::move(value);
      return {&root_, JsonPointer{}};
    }
    const Container& parent = open_.back();
    if (parent.value->is_array()) {
      parent.value->push_back(std::move(value));
      return {&parent.value->back(), parent.path / (parent.value->size() - 1)};
    }
    json& slot = (*parent.value)[key_];
    slot = std::move(value);
    return {&slot, parent.path / key_};
  }
  bool add(json value) {
    place(std::move(value));
    return true;
  }
  bool open(json container) {
    open_.push_back(place(std::move(container)));
    return true;
  }
  bool close() {
    open_.pop_back();
    return true;
  }

  json& root_;
  std::vector<Container>
      open_;  // only the last child of each is ever added to, so these stay valid
  std::string key_;
  std::size_t error_position_ = 0;
  std::string error_;
  std::string error_token_;
  std::vector<JsonPointer> duplicates_;
};

// The offset of the bracket that opens level max_depth + 1, outside strings; none if the text
// stays within max_depth levels. One pass, no recursion: a hostile file cannot make it slow.
std::optional<std::size_t> nesting_beyond(std::string_view text, std::size_t max_depth) {
  std::size_t depth = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

// nlohmann counts the characters read up to and including the one that broke the parse; when that
// one closes a string (a key after a missing comma, say), the string's opening quote is the place.
std::size_t error_offset(std::string_view text, std::size_t characters_read) {
  const std::size_t offset = std::min(characters_read == 0 ? 0 : characters_read - 1, text.size());
  if (offset >= text.size() || text[offset] != '"') return offset;
  for (std::size_t i = offset; i-- > 0;) {
    if (text[i] == '\n') break;
    if (text[i] != '"') continue;
    std::size_t backslashes = 0;
    while (backslashes < i && text[i - 1 - backslashes] == '\\') ++backslashes;
    if (backslashes % 2 == 0) return i;
  }
  return offset;
}

std::pair<std::size_t, std::size_t> line_and_column(std::string_view text,
                                                    std::size_t characters_read) {
  const std::size_t offset = error_offset(text, characters_read);
  const std::string_view before = text.substr(0, offset);
  const std::size_t line =
      1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t newline = before.rfind('\n');
  const std::string_view current =
      newline == std::string_view::npos ? before : before.substr(newline + 1);
  // Columns count characters, not bytes: skip UTF-8 continuation bytes.
  const auto continuation = std::count_if(current.begin(), current.end(),
                                          [](unsigned char c) { return (c & 0xC0) == 0x80; });
  return {line, current.size() - static_cast<std::size_t>(continuation) + 1};
}

// "[json.exception.parse_error.101] parse error at line 2, column 8: syntax error ...; last read:
// 'TOKEN'" -> "syntax error ...; last read: 'EXCERPT'" (and "number overflow parsing 'TOKEN'"
// alike). The token is the file's own text (an unterminated string runs to the end of the file or
// of its line): only a printable excerpt of it is quoted.
std::string parse_error_reason(const std::string& what, const std::string& token) {
  std::string reason = what;
  if (const auto tag_end = reason.find("] "); tag_end != std::string::npos)
    reason.erase(0, tag_end + 2);
  if (reason.rfind("parse error", 0) == 0) {
    if (const auto colon = reason.find(": "); colon != std::string::npos)
      reason.erase(0, colon + 2);
  }
  const std::string quoted = "'" + token + "'";
  if (const auto at = reason.find(quoted); at != std::string::npos) {
    reason.replace(at, quoted.size(), "'" + printable_excerpt(token) + "'");
  }
  return reason;
}

}  // namespace

json parse_json_text(std::string_view text, const std::string& source) {
  if (const auto too_deep = nesting_beyond(text, kMaxJsonDepth)) {
    const auto [line, column] = line_and_column(text, *too_deep + 1);
    throw ConfigError({source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                       ": malformed JSON: nested deeper than " + std::to_string(kMaxJsonDepth) +
                       " levels"});
  }
  json document;
  DocumentBuilder builder(document);
  if (!json::sax_parse(text, &builder)) {
    const auto [line, column] = line_and_column(text, builder.error_position());
    throw ConfigError(
        {source + ":" + std::to_string(line) + ":" + std::to_string(column) +
         ": malformed JSON: " + parse_error_reason(builder.error(), builder.error_token())});
  }
  ConfigErrors errors(source);
  for (const auto& path : builder.duplicates()) errors.add(path, "duplicate key");
  errors.throw_if_any();
  return document;
}

json read_json_file(const std::filesystem::path& path) {
  return parse_json_text(read_input_file(path, {kMaxConfigBytes}), path.string());
}

}  // namespace blockfrag
