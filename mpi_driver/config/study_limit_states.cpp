#include "mpi_driver/config/study_limit_states.hpp"

#include <cctype>
#include <span>

#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {
namespace {

// The table of the threshold's key the kind selects (none for overturning).
std::span<const Field<LimitState>> threshold_fields(LimitStateKind kind) {
  switch (kind) {
    case LimitStateKind::overturning: break;
    case LimitStateKind::max_rotation: return study_fields::max_rotation;
    case LimitStateKind::residual_slide: return study_fields::residual_slide;
    case LimitStateKind::post_earthquake_unstable: return study_fields::post_earthquake_unstable;
  }
  return {};
}

void check_limit_state_name(ObjectReader& reader, const std::optional<std::string>& name,
                            const StudyConfig& config) {
  if (name && !valid_limit_state_name(*name)) {
    reader.add_error(
        "name",
        "must start with a letter, digit or '_', then letters, digits, '_', '-' or '.' (got \"" +
            printable_excerpt(*name) + "\")");
  }
  for (const auto& other : config.limit_states) {
    if (name && other.name == *name)
      reader.add_error("name", "\"" + *name + "\" is used by another limit state");
  }
}

}  // namespace

// An HDF5 group name of its own: starts with a letter, digit or '_' ("." and ".." name the group
// itself and its parent), then letters, digits, '_', '-' and '.'.
bool valid_limit_state_name(const std::string& name) {
  if (name.empty() || !(std::isalnum(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    return false;
  for (const char c : name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      return false;
  }
  return true;
}

const char* limit_state_kind_name(LimitStateKind kind) {
  return limit_state_kind_names.name(kind).data();
}

void read_limit_states(ArrayReader array, ObjectReader& root, StudyConfig& config,
                       bool scene_valid) {
  if (array.valid() && array.size() == 0)
    root.add_error("limit_states", "must name at least one limit state");
  for (std::size_t k = 0; k < array.size(); ++k) {
    ObjectReader reader = array.object(k);
    if (!reader.valid()) continue;
    LimitState state;
    const bool named =
        read_fields<LimitState>(reader, study_fields::limit_state_name, state).valid("name");
    const auto name = named ? std::optional(state.name) : std::nullopt;
    check_limit_state_name(reader, name, config);
    const bool typed =
        read_fields<LimitState>(reader, study_fields::limit_state_type, state).valid("type");
    const auto kind = typed ? std::optional(state.kind) : std::nullopt;
    if (kind == LimitStateKind::post_earthquake_unstable) state.threshold = 1.0;
    if (kind) read_fields<LimitState>(reader, threshold_fields(*kind), state);
    if (kind == LimitStateKind::post_earthquake_unstable && scene_valid &&
        !config.base_scene.reservoir) {
      reader.add_error("type",
                       "\"post_earthquake_unstable\" needs a reservoir in /scene (the safety "
                       "factors after the earthquake are the reservoir's)");
    }
    if (kind != LimitStateKind::overturning) {
      read_fields<LimitState>(reader, study_fields::overturned_exceeds, state);
    }
    reader.finish(kind ? "for type \"" + std::string(limit_state_kind_name(*kind)) + "\""
                       : std::string{});
    if (named) config.limit_states.push_back(state);
  }
}

nlohmann::json limit_state_to_json(const LimitState& state) {
  nlohmann::json out = nlohmann::json::object();
  write_fields<LimitState>(state, study_fields::limit_state_name, out);
  write_fields<LimitState>(state, study_fields::limit_state_type, out);
  write_fields<LimitState>(state, threshold_fields(state.kind), out);
  if (state.kind != LimitStateKind::overturning)
    write_fields<LimitState>(state, study_fields::overturned_exceeds, out);
  return out;
}

}  // namespace blockfrag
