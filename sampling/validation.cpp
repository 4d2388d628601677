#include "sampling/validation.hpp"

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

}  // namespace blockfrag
