#include "mpi_driver/config/spectrum_fields.hpp"

#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {

std::vector<KeyTable> spectrum_key_tables() {
  using namespace spectrum_fields;
  return {{"block.", describe_fields<BlockShape>(block_shape)},
          {"pulse.", describe_fields<PulseFamily>(pulse_type)},
          {"pulse.", describe_fields<PulseFamily>(periodic_family)},
          {"pulse.", describe_fields<PulseFamily>(makris_c_family)},
          {"frequency_ratio.", describe_fields<AxisValues>(frequency_values)},
          {"frequency_ratio.", describe_fields<AxisRange>(axis_range)},
          {"amplitude_ratio.", describe_fields<AxisValues>(amplitude_values)},
          {"amplitude_ratio.", describe_fields<AxisRange>(axis_range)},
          {"bisection.", describe_fields<SpectrumConfig>(bisection)},
          {"minimum_overturning.",
           describe_fields<MinimumOverturningSettings>(study_fields::minimum_overturning)},
          {"", describe_fields<SpectrumConfig>(settle)},
          {"", describe_fields<SpectrumConfig>(output)},
          {"", describe_fields<SpectrumConfig>(checkpoint)}};
}

}  // namespace blockfrag
