#include "sampling/validation.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <utility>

namespace blockfrag {
namespace {

std::string join(const std::vector<Violation>& violations) {
  std::string text;
  for (const auto& violation : violations) {
    if (!text.empty()) text += "; ";
    text +=
        violation.field.empty() ? violation.message : violation.field + ": " + violation.message;
  }
  return text;
}

}  // namespace

SamplingError::SamplingError(std::vector<Violation> violations)
    : InvalidInput(join(violations)), violations_(std::move(violations)) {}

std::string format_number(double value) {
  // to_chars spells these "nan", "-nan", "inf"; a sign on a NaN means nothing to a reader.
  if (std::isnan(value)) return "nan";
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace blockfrag
