#include "mpi_driver/config/field_table.hpp"

#include <string>

namespace blockfrag {

bool read_increasing_numbers(ObjectReader& reader, std::string_view key, const Range& range,
                             const IncreasingNumbers& rule, bool required,
                             std::vector<double>& out) {
  ArrayReader array = required ? reader.required_array(key) : reader.array(key);
  if (!array.valid()) return false;
  const std::string nouns = std::string(rule.noun) + "s";
  if (!rule.count->contains(static_cast<double>(array.size()))) {
    // Counts in digits: "100000", not the shortest form's "1e+05".
    reader.add_error(key, "must have " + std::to_string(static_cast<long long>(rule.count->low)) +
                              " to " + std::to_string(static_cast<long long>(rule.count->high)) +
                              " " + nouns + " (got " + std::to_string(array.size()) + ")");
    return false;
  }
  out.clear();
  bool valid = true;
  for (std::size_t k = 0; k < array.size(); ++k) {
    const auto value = array.number(k, range);
    if (!value) {
      valid = false;
      continue;
    }
    if (!out.empty() && *value <= out.back()) {
      reader.errors().add(array.path_of(k), "must be greater than the " + std::string(rule.noun) +
                                                " before it (" + nouns + " increase)");
      valid = false;
    }
    out.push_back(*value);
  }
  return valid;
}

}  // namespace blockfrag
