// A sampled input's distribution: {"distribution": "fixed" | "uniform" | "normal" | "lognormal",
// ...the keys of its DistributionKeys table}. The name selects the table; validate()
// (sampling/validation.hpp) checks what no table can (min < max, a positive std_dev, ...).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/config_reader.hpp"
#include "mpi_driver/config/field_table.hpp"
#include "sampling/distributions.hpp"

namespace blockfrag {

// One specialisation per alternative of Distribution: its "distribution" name and its keys. A
// parameter may be any number here: the study checks the distribution's support against its
// input's domain after.
template <class Law>
struct DistributionKeys;

template <>
struct DistributionKeys<Fixed> {
  static constexpr std::string_view name = "fixed";
  static constexpr Field<Fixed> fields[] = {
      {"value", &Fixed::value, &domain::distribution_parameter, Presence::required}};
};
template <>
struct DistributionKeys<Uniform> {
  static constexpr std::string_view name = "uniform";
  static constexpr Field<Uniform> fields[] = {
      {"min", &Uniform::min, &domain::distribution_parameter, Presence::required},
      {"max", &Uniform::max, &domain::distribution_parameter, Presence::required}};
};
template <>
struct DistributionKeys<Normal> {
  static constexpr std::string_view name = "normal";
  static constexpr Field<Normal> fields[] = {
      {"mean", &Normal::mean, &domain::distribution_parameter, Presence::required},
      {"std_dev", &Normal::std_dev, &domain::distribution_parameter, Presence::required},
      {"lower", &Normal::lower, &domain::distribution_parameter},
      {"upper", &Normal::upper, &domain::distribution_parameter}};
};
template <>
struct DistributionKeys<LogNormal> {
  static constexpr std::string_view name = "lognormal";
  static constexpr Field<LogNormal> fields[] = {
      {"median", &LogNormal::median, &domain::distribution_parameter, Presence::required},
      {"beta", &LogNormal::beta, &domain::distribution_parameter, Presence::required},
      {"lower", &LogNormal::lower, &domain::distribution_parameter},
      {"upper", &LogNormal::upper, &domain::distribution_parameter}};
};

// The "distribution" names, in Distribution's order.
inline constexpr std::array<std::string_view, 4> distribution_names{
    DistributionKeys<Fixed>::name, DistributionKeys<Uniform>::name, DistributionKeys<Normal>::name,
    DistributionKeys<LogNormal>::name};

// The distribution of the reader's object, when it is complete and valid (the errors recorded
// otherwise). The reader is finished.
std::optional<Distribution> read_distribution(ObjectReader reader);
nlohmann::json distribution_to_json(const Distribution& distribution);

}  // namespace blockfrag
