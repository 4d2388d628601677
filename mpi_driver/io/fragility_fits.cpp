#include "mpi_driver/io/fragility_fits.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <set>

#include <sys/stat.h>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/config/adaptive_design.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/io/hdf5_reader.hpp"

namespace blockfrag {
namespace {

constexpr const char* not_an_output = "not a blockfrag study output";

// Only a regular file is handed to HDF5: a FIFO or a device could block or never end.
void require_regular_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  const int fd = ::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT) throw InvalidInput(name + ": no such file");
    throw InvalidInput(name + ": cannot be opened for reading (" + std::strerror(error) + ")");
  }
  struct stat status {};
  const bool examined = ::fstat(fd, &status) == 0;
  ::close(fd);
  if (!examined) throw InvalidInput(name + ": cannot be examined");
  if (S_ISDIR(status.st_mode)) throw InvalidInput(name + ": is a folder, " + not_an_output);
  if (!S_ISREG(status.st_mode)) {
    throw InvalidInput(name + ": is not a regular file, so " + not_an_output);
  }
}

// A study's levels: at most 1,000,000 given (mpi_driver/config/intensity_measure.cpp), and an
// adaptive study adds two per batch. A dataset declaring more is not a blockfrag output's, and is
// refused before memory is allocated for it.
constexpr std::size_t max_levels = 1'000'000 + 2 * static_cast<std::size_t>(kMaxAdaptiveBatches);
// The longest texts read, well above what blockfrag writes: a word (config_hash, im_name,
// im_units, a limit state's type), a label (im_label, fit_status), a list of limit-state names
// (severity_order, crossing_pairs).
constexpr std::size_t max_word = 64;
constexpr std::size_t max_label = 120;
constexpr std::size_t max_name_list = 1 << 20;

// What an exported fit's median (in the measure's unit) and beta may be: outside, OpenQuake's
// mean and stddev overflow or underflow (beta 40 makes the mean inf, a denormal beta its stddev
// 0), and no study of a block has such a curve.
constexpr double min_median = 1e-6;
constexpr double max_median = 1e6;
constexpr double min_beta = 1e-6;
constexpr double max_beta = 10.0;

bool printable_ascii(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte >= 0x20 && byte < 0x7f;
  });
}

bool is_config_hash(const std::string& text) {
  return text.size() == 16 && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

// Reads the schema: any missing or malformed object is the input's fault, named with the file and
// the object; a text is quoted only as a short printable excerpt.
class FitsReader {
 public:
  explicit FitsReader(const Hdf5Reader& file) : file_(file) {}

  // A text attribute of printable ASCII (it goes into the exported files and the messages).
  std::string text(const std::string& object, const std::string& name,
                   std::size_t max_length) const {
    require(object, name);
    std::string value = file_.string_attribute(object, name, max_length);
    if (!printable_ascii(value)) {
      throw malformed("attribute " + name + " of " + object +
                      " holds a control character or a byte outside printable ASCII (\"" +
                      printable_excerpt(value) + "\")");
    }
    return value;
  }

  double number(const std::string& object, const std::string& name) const {
    require(object, name);
    return file_.number_attribute(object, name);
  }

  std::optional<double> optional_number(const std::string& object, const std::string& name) const {
    if (!file_.has_attribute(object, name)) return std::nullopt;
    return number(object, name);
  }

  std::vector<double> optional_interval(const std::string& object, const std::string& name) const {
    if (!file_.has_attribute(object, name)) return {};
    const std::vector<double> values = file_.number_array_attribute(object, name, 2);
    if (values.size() != 2) {
      throw malformed(object + " attribute " + name + " holds " + std::to_string(values.size()) +
                      " values, not 2");
    }
    return values;
  }

  // The levels: finite and positive.
  std::vector<double> levels(const std::string& path) const {
    if (!file_.has_object(path)) throw malformed(path + " is missing");
    std::vector<double> values = file_.number_dataset(path, max_levels);
    for (const double level : values) {
      if (!(std::isfinite(level) && level > 0.0)) {
        throw malformed(path + " holds the level " + format_number(level) +
                        " (levels are finite and > 0)");
      }
    }
    return values;
  }

  InvalidInput malformed(const std::string& what) const {
    return InvalidInput(file_.name() + ": " + what +
                        " (not the fragility layout blockfrag writes)");
  }

 private:
  void require(const std::string& object, const std::string& name) const {
    if (!file_.has_attribute(object, name)) {
      throw malformed(object + " has no attribute " + name);
    }
  }

  const Hdf5Reader& file_;
};

void check_fit(const FitsReader& reader, const FragilityFit& fit, const std::string& group) {
  const bool usable = fit.median >= min_median && fit.median <= max_median &&
                      fit.beta >= min_beta && fit.beta <= max_beta;
  if (!usable) {
    throw reader.malformed(group + " has fit_status \"ok\" but median " +
                           format_number(fit.median) + " and beta " + format_number(fit.beta) +
                           " (an exported fit has a median in [" + format_number(min_median) +
                           ", " + format_number(max_median) +
                           "] of the measure's unit and a beta in [" + format_number(min_beta) +
                           ", " + format_number(max_beta) + "])");
  }
}

FragilityFit read_fit(const FitsReader& reader, const std::string& name) {
  const std::string group = "/fragility/" + name;
  FragilityFit fit;
  fit.name = name;
  fit.type = reader.text(group, "type", max_word);
  if (fit.type != "overturning" && fit.type != "max_rotation" && fit.type != "residual_slide" &&
      fit.type != "post_earthquake_unstable") {
    throw reader.malformed(group + " has an unknown type \"" + printable_excerpt(fit.type) + "\"");
  }
  fit.threshold = reader.number(group, "threshold");
  if (fit.type != "overturning" && !(std::isfinite(fit.threshold) && fit.threshold > 0.0)) {
    throw reader.malformed(group + " has the threshold " + format_number(fit.threshold) + " (a " +
                           fit.type + "'s is finite and > 0)");
  }
  fit.median = reader.number(group, "median");
  fit.beta = reader.number(group, "beta");
  fit.fit_status = reader.text(group, "fit_status", max_label);
  fit.median_ci = reader.optional_interval(group, "median_ci");
  fit.beta_ci = reader.optional_interval(group, "beta_ci");
  fit.deviance = reader.optional_number(group, "deviance");
  fit.gof_p_value = reader.optional_number(group, "gof_p_value");
  const auto overturned = reader.optional_number(group, "overturned_exceeds");
  fit.overturned_exceeds = overturned ? *overturned != 0.0 : fit.type != "residual_slide";
  fit.im = reader.levels(group + "/im");
  if (fit.fitted()) check_fit(reader, fit, group);
  const auto nested = reader.optional_number(group, "nested_median");
  if (nested && !std::isnan(*nested)) {
    if (!(*nested >= min_median && *nested <= max_median)) {
      throw reader.malformed(group + " has the nested_median " + format_number(*nested) +
                             " (a median is in [" + format_number(min_median) + ", " +
                             format_number(max_median) + "] of the measure's unit)");
    }
    fit.nested_median = *nested;
  }
  return fit;
}

std::vector<std::string> split_names(const std::string& text, char separator = ',') {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(separator, start), text.size());
    std::string name = text.substr(start, end - start);
    const auto first = name.find_first_not_of(" \t");
    const auto last = name.find_last_not_of(" \t");
    name = first == std::string::npos ? "" : name.substr(first, last - first + 1);
    if (!name.empty()) names.push_back(name);
    start = end + 1;
  }
  return names;
}

// The limit states' groups, each name checked against the study's rule before it is used in a
// path, a message or an exported file (a space or a newline in one would split it in two).
std::vector<std::string> state_groups(const Hdf5Reader& file, const FitsReader& reader) {
  std::vector<std::string> groups;
  for (const auto& member : file.member_names("/fragility")) {
    if (!valid_limit_state_name(member)) {
      throw reader.malformed("/fragility has a member \"" + printable_excerpt(member) +
                             "\", not a limit state name (a letter, digit or '_', then letters, "
                             "digits, '_', '-' or '.')");
    }
    if (file.is_group("/fragility/" + member)) groups.push_back(member);
  }
  return groups;
}

// The groups in severity_order's order, then any it does not name; without severity_order, by
// fitted median, the unfitted ones last.
std::vector<FragilityFit> read_states(const Hdf5Reader& file, const FitsReader& reader,
                                      const std::vector<std::string>& groups) {
  std::vector<FragilityFit> states;
  if (file.has_attribute("/fragility", "severity_order")) {
    std::set<std::string> named;
    for (const auto& name :
         split_names(reader.text("/fragility", "severity_order", max_name_list))) {
      if (std::find(groups.begin(), groups.end(), name) == groups.end()) {
        throw reader.malformed("severity_order names \"" + printable_excerpt(name) +
                               "\" but there is no group /fragility/" + printable_excerpt(name));
      }
      if (!named.insert(name).second) {
        throw reader.malformed("severity_order names \"" + name + "\" twice");
      }
      states.push_back(read_fit(reader, name));
    }
    for (const auto& name : groups) {
      if (named.count(name) == 0) states.push_back(read_fit(reader, name));
    }
  } else {
    for (const auto& name : groups) states.push_back(read_fit(reader, name));
    std::stable_sort(states.begin(), states.end(), [](const auto& a, const auto& b) {
      if (a.fitted() != b.fitted()) return a.fitted();
      return a.fitted() && a.median < b.median;
    });
  }
  if (states.empty()) throw reader.malformed("/fragility holds no limit state");
  return states;
}

}  // namespace

FragilityFits read_fragility_fits(const std::filesystem::path& path) {
  require_regular_file(path);
  const std::string name = path.string();
  if (!Hdf5Reader::is_hdf5(path)) {
    throw InvalidInput(name + ": not an HDF5 file, so " + not_an_output);
  }
  const Hdf5Reader file(path);
  if (!file.has_attribute("/", "config_hash") || !file.has_attribute("/", "config")) {
    throw InvalidInput(name + ": " + not_an_output +
                       " (its root has no config and config_hash attributes)");
  }
  if (!file.is_group("/fragility")) {
    throw InvalidInput(name + ": has no /fragility group, so no fragility fits to export");
  }
  const FitsReader reader(file);
  FragilityFits fits;
  fits.source = name;
  fits.config_hash = reader.text("/", "config_hash", max_word);
  if (!is_config_hash(fits.config_hash)) {
    throw reader.malformed("attribute config_hash of / is \"" +
                           printable_excerpt(fits.config_hash) +
                           "\", not a config hash (16 hexadecimal digits)");
  }
  fits.im_name = reader.text("/fragility", "im_name", max_word);
  fits.im_units = reader.text("/fragility", "im_units", max_word);
  fits.im_label = reader.text("/fragility", "im_label", max_label);
  fits.im_period_s = reader.optional_number("/fragility", "im_period_s");
  fits.im_damping = reader.optional_number("/fragility", "im_damping");
  const std::vector<std::string> groups = state_groups(file, reader);
  fits.states = read_states(file, reader, groups);
  if (file.has_attribute("/fragility", "nested_status")) {
    fits.nested_status = reader.text("/fragility", "nested_status", max_label);
    fits.nested_beta = reader.number("/fragility", "nested_beta");
    if (fits.nested_status == "ok" &&
        !(fits.nested_beta >= min_beta && fits.nested_beta <= max_beta)) {
      throw reader.malformed("/fragility has nested_status \"ok\" but nested_beta " +
                             format_number(fits.nested_beta) + " (a beta is in [" +
                             format_number(min_beta) + ", " + format_number(max_beta) + "])");
    }
  }
  if (file.has_attribute("/fragility", "crossing_pairs")) {
    for (const auto& pair :
         split_names(reader.text("/fragility", "crossing_pairs", max_name_list), ';')) {
      const auto names = split_names(pair);
      const auto known = [&](const std::string& state) {
        return std::find(groups.begin(), groups.end(), state) != groups.end();
      };
      if (names.size() != 2 || !known(names[0]) || !known(names[1])) {
        throw reader.malformed("crossing_pairs holds \"" + printable_excerpt(pair) +
                               "\", not two of its limit states");
      }
      fits.crossing_pairs.emplace_back(names[0], names[1]);
    }
  }
  return fits;
}

}  // namespace blockfrag
