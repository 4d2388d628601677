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

// Reads the schema: any missing or malformed object is the input's fault, named with the file.
class FitsReader {
 public:
  explicit FitsReader(const Hdf5Reader& file) : file_(file) {}

  std::string text(const std::string& object, const std::string& name) const {
    require(object, name);
    try {
      return file_.string_attribute(object, name);
    } catch (const Hdf5Error& error) {
      throw malformed(error.what());
    }
  }

  double number(const std::string& object, const std::string& name) const {
    require(object, name);
    try {
      return file_.number_attribute(object, name);
    } catch (const Hdf5Error& error) {
      throw malformed(error.what());
    }
  }

  std::optional<double> optional_number(const std::string& object, const std::string& name) const {
    if (!file_.has_attribute(object, name)) return std::nullopt;
    return number(object, name);
  }

  std::vector<double> optional_interval(const std::string& object, const std::string& name) const {
    if (!file_.has_attribute(object, name)) return {};
    std::vector<double> values;
    try {
      values = file_.number_array_attribute(object, name);
    } catch (const Hdf5Error& error) {
      throw malformed(error.what());
    }
    if (values.size() != 2) {
      throw malformed(object + " attribute " + name + " holds " + std::to_string(values.size()) +
                      " values, not 2");
    }
    return values;
  }

  std::vector<double> dataset(const std::string& path) const {
    if (!file_.has_object(path)) throw malformed(path + " is missing");
    try {
      return file_.number_dataset(path);
    } catch (const Hdf5Error& error) {
      throw malformed(error.what());
    }
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

FragilityFit read_fit(const FitsReader& reader, const std::string& name) {
  const std::string group = "/fragility/" + name;
  FragilityFit fit;
  fit.name = name;
  fit.type = reader.text(group, "type");
  if (fit.type != "overturning" && fit.type != "max_rotation" && fit.type != "residual_slide") {
    throw reader.malformed(group + " has an unknown type \"" + fit.type + "\"");
  }
  fit.threshold = reader.number(group, "threshold");
  fit.median = reader.number(group, "median");
  fit.beta = reader.number(group, "beta");
  fit.fit_status = reader.text(group, "fit_status");
  fit.median_ci = reader.optional_interval(group, "median_ci");
  fit.beta_ci = reader.optional_interval(group, "beta_ci");
  fit.deviance = reader.optional_number(group, "deviance");
  fit.gof_p_value = reader.optional_number(group, "gof_p_value");
  const auto overturned = reader.optional_number(group, "overturned_exceeds");
  fit.overturned_exceeds = overturned ? *overturned != 0.0 : fit.type != "residual_slide";
  fit.im = reader.dataset(group + "/im");
  if (fit.fitted()) {
    const bool usable =
        std::isfinite(fit.median) && fit.median > 0.0 && std::isfinite(fit.beta) && fit.beta > 0.0;
    if (!usable) {
      throw reader.malformed(group + " has fit_status \"ok\" but median " +
                             std::to_string(fit.median) + " and beta " + std::to_string(fit.beta) +
                             " (both must be finite and > 0)");
    }
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

// The groups in severity_order's order, then any it does not name; without severity_order, by
// fitted median, the unfitted ones last.
std::vector<FragilityFit> read_states(const Hdf5Reader& file, const FitsReader& reader) {
  std::vector<std::string> groups;
  for (const auto& member : file.member_names("/fragility")) {
    if (file.is_group("/fragility/" + member)) groups.push_back(member);
  }
  std::vector<FragilityFit> states;
  if (file.has_attribute("/fragility", "severity_order")) {
    std::set<std::string> named;
    for (const auto& name : split_names(reader.text("/fragility", "severity_order"))) {
      if (std::find(groups.begin(), groups.end(), name) == groups.end()) {
        throw reader.malformed("severity_order names \"" + name +
                               "\" but there is no group /fragility/" + name);
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
  fits.config_hash = reader.text("/", "config_hash");
  fits.im_name = reader.text("/fragility", "im_name");
  fits.im_units = reader.text("/fragility", "im_units");
  fits.im_label = reader.text("/fragility", "im_label");
  fits.im_period_s = reader.optional_number("/fragility", "im_period_s");
  fits.im_damping = reader.optional_number("/fragility", "im_damping");
  fits.states = read_states(file, reader);
  if (file.has_attribute("/fragility", "crossing_pairs")) {
    for (const auto& pair : split_names(reader.text("/fragility", "crossing_pairs"), ';')) {
      const auto names = split_names(pair);
      if (names.size() != 2) {
        throw reader.malformed("crossing_pairs holds \"" + pair + "\", not two names");
      }
      fits.crossing_pairs.emplace_back(names[0], names[1]);
    }
  }
  return fits;
}

}  // namespace blockfrag
