// What sampling's validators report: every broken rule at once, each tied to the field it concerns,
// so a config reader can prefix its own JSON path ("/inputs/mu/std_dev: must be > 0 (got -1)").
#pragma once

#include <string>
#include <vector>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"  // format_number, for the messages

namespace blockfrag {

struct Violation {
  std::string field;    // a member name ("std_dev") or a path inside a plan ("inputs/2/name");
                        // empty when the rule concerns the whole object
  std::string message;  // "must be > 0 (got -1)"
};

// Thrown by sampling code handed invalid input; what() lists every violation as "field: message".
class SamplingError : public InvalidInput {
 public:
  explicit SamplingError(std::vector<Violation> violations);
  const std::vector<Violation>& violations() const { return violations_; }

 private:
  std::vector<Violation> violations_;
};

}  // namespace blockfrag
