#include "mpi_driver/config/adaptive_design.hpp"

namespace blockfrag {

AdaptiveDesign read_adaptive_design(ObjectReader reader) {
  AdaptiveDesign design;
  const auto base = reader.choice("base", {"latin_hypercube", "monte_carlo"});
  design.base = base == "monte_carlo" ? Design::monte_carlo : Design::latin_hypercube;
  design.limit_state = reader.string_or("limit_state", "");
  design.target_relative_width =
      reader.number_or("target_relative_width", design.target_relative_width,
                       Range::of(domain::target_relative_width));
  design.pair_probability = reader.number_or("pair_probability", design.pair_probability,
                                             Range::of(domain::pair_probability));
  design.max_samples =
      reader.required_integer("max_samples", Range::of(domain::adaptive_samples)).value_or(0);
  reader.finish();
  return design;
}

nlohmann::json adaptive_design_to_json(const AdaptiveDesign& design) {
  return {{"adaptive",
           {{"base", design.base == Design::monte_carlo ? "monte_carlo" : "latin_hypercube"},
            {"limit_state", design.limit_state},
            {"target_relative_width", design.target_relative_width},
            {"pair_probability", design.pair_probability},
            {"max_samples", design.max_samples}}}};
}

}  // namespace blockfrag
