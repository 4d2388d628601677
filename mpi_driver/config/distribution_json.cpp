#include "mpi_driver/config/distribution_json.hpp"

#include <string>

namespace blockfrag {
namespace {

// Reads the law's keys; nullopt when a required one is missing or invalid.
template <class Law>
std::optional<Distribution> read_law(ObjectReader& reader) {
  Law law{};
  const FieldsRead read = read_fields<Law>(reader, DistributionKeys<Law>::fields, law);
  for (const Field<Law>& field : DistributionKeys<Law>::fields) {
    if (field.presence == Presence::required && !read.valid(field.key)) return std::nullopt;
  }
  return law;
}

template <std::size_t... index>
std::optional<Distribution> read_named_law(ObjectReader& reader, std::string_view name,
                                           std::index_sequence<index...>) {
  std::optional<Distribution> distribution;
  ((DistributionKeys<std::variant_alternative_t<index, Distribution>>::name == name
        ? void(distribution = read_law<std::variant_alternative_t<index, Distribution>>(reader))
        : void()),
   ...);
  return distribution;
}

}  // namespace

std::optional<Distribution> read_distribution(ObjectReader reader) {
  const auto kind = reader.required_choice("distribution", distribution_names);
  if (!kind) return std::nullopt;
  const auto distribution =
      read_named_law(reader, *kind, std::make_index_sequence<std::variant_size_v<Distribution>>{});
  reader.finish("for distribution \"" + *kind + "\"");
  if (!distribution) return std::nullopt;
  bool valid = true;
  for (const auto& violation : validate(*distribution)) {
    reader.errors().add(violation.field.empty() ? reader.path() : reader.path_of(violation.field),
                        violation.message);
    valid = false;
  }
  return valid ? distribution : std::nullopt;
}

nlohmann::json distribution_to_json(const Distribution& distribution) {
  return std::visit(
      [](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        nlohmann::json out = {{"distribution", std::string(DistributionKeys<Law>::name)}};
        write_fields<Law>(law, DistributionKeys<Law>::fields, out);
        return out;
      },
      distribution);
}

}  // namespace blockfrag
