#include "mpi_driver/config/intensity_measure.hpp"

#include <cstdio>
#include <span>

#include "engine/scene/parameter_domains.hpp"
#include "mpi_driver/config/study_fields.hpp"

namespace blockfrag {
namespace {

// The tables of the levels of one domain: their list's and their range's.
struct LevelTables {
  std::span<const Field<LevelList>> list;
  std::span<const Field<LevelRange>> range;
};

template <const Domain& level>
constexpr LevelTables level_tables{study_fields::level_list<level>,
                                   study_fields::level_range<level>};

// The levels' tables in the measure's unit: far past any earthquake, finite.
LevelTables measure_level_tables(ImType type) {
  if (type == ImType::pgv) return level_tables<domain::pgv_level>;
  return level_tables<domain::intensity_g>;
}

}  // namespace

double largest_level(ImType type) {
  return type == ImType::pgv ? domain::pgv_level.high : domain::intensity_g.high;
}

namespace {

// "levels", or "from", "to" and "count".
std::vector<double> read_levels(ObjectReader& reader, const LevelTables& tables) {
  if (reader.has("levels")) {
    bool range_given = false;
    for (const Field<LevelRange>& field : tables.range) range_given |= reader.has(field.key);
    if (range_given) reader.add_error("levels", "give either levels or from/to/count, not both");
    LevelList list;
    read_fields<LevelList>(reader, tables.list, list);
    return list.levels;
  }
  std::vector<double> levels;
  LevelRange grid;
  const FieldsRead read = read_fields<LevelRange>(reader, tables.range, grid);
  const double from = grid.from, to = grid.to;
  if (!read.valid("from") || !read.valid("to")) return levels;
  if (to <= from) {
    reader.add_error("to", "must be greater than from (" + format_number(from) + ")");
    return levels;
  }
  if (!read.valid("count")) return levels;
  const double intervals = static_cast<double>(grid.count - 1);
  for (long k = 0; k < grid.count; ++k) {
    levels.push_back(k == grid.count - 1 ? to
                                         : from + (to - from) * static_cast<double>(k) / intervals);
  }
  return levels;
}

// {"type": "pulse_period", "levels": [...]} or from/to/count: the periods of a surface's grid.
void read_second_axis(ObjectReader reader, IntensityMeasure& measure) {
  if (!reader.valid()) return;
  reader.required_choice("type", {"pulse_period"});
  if (measure.cloud) {
    reader.add_error("type", "makes a grid of stripes: a cloud (\"scaling\": \"none\") has none");
    return;
  }
  measure.periods = read_levels(reader, level_tables<domain::pulse_period>);
  const std::size_t cells = measure.levels.size() * measure.periods.size();
  if (cells > kMaxSurfaceCells) {
    reader.add_error(reader.has("levels") ? "levels" : "count",
                     "makes a grid of " + std::to_string(measure.levels.size()) + " x " +
                         std::to_string(measure.periods.size()) + " = " + std::to_string(cells) +
                         " cells, more than " + std::to_string(kMaxSurfaceCells) +
                         " (the surface fit's separation check is cubic in them)");
  }
  reader.finish("for type \"pulse_period\"");
}

}  // namespace

const char* im_type_name(ImType type) { return im_type_names.name(type).data(); }

const char* im_unit(ImType type) {
  switch (type) {
    case ImType::pgv: return "m/s";
    case ImType::pga_over_g_tan_alpha: return "1";
    default: return "g";
  }
}

std::string im_label(const IntensityMeasure& measure) {
  switch (measure.type) {
    case ImType::pulse_amplitude: return "pulse amplitude";
    case ImType::pga: return "PGA";
    case ImType::pgv: return "PGV";
    case ImType::pga_over_g_tan_alpha: return "PGA/(g tan alpha)";
    case ImType::sa: {
      char text[64];
      std::snprintf(text, sizeof text, "Sa(%g s, %g %%)", measure.period, 100 * measure.damping);
      return text;
    }
  }
  return "";
}

IntensityMeasure read_intensity_measure(ObjectReader reader, ImType default_type) {
  IntensityMeasure measure;
  measure.type = default_type;
  read_fields<IntensityMeasure>(reader, study_fields::measure_type, measure);
  if (measure.type == ImType::sa) read_fields<IntensityMeasure>(reader, study_fields::sa, measure);
  read_fields<IntensityMeasure>(reader, study_fields::scaling, measure);
  if (measure.cloud) {
    read_fields<IntensityMeasure>(reader, study_fields::cloud, measure);
    for (const char* key : {"levels", "from", "to", "count"}) {
      if (reader.has(key)) reader.add_error(key, "a cloud (\"scaling\": \"none\") has no levels");
    }
  } else {
    measure.levels = read_levels(reader, measure_level_tables(measure.type));
  }
  if (reader.has("second")) read_second_axis(reader.required_object("second"), measure);
  reader.finish(measure.type == ImType::sa ? "for type \"sa\"" : std::string{});
  return measure;
}

nlohmann::json intensity_measure_to_json(const IntensityMeasure& measure) {
  nlohmann::json out = nlohmann::json::object();
  write_fields<IntensityMeasure>(measure, study_fields::measure_type, out);
  if (measure.type == ImType::sa) write_fields<IntensityMeasure>(measure, study_fields::sa, out);
  write_fields<IntensityMeasure>(measure, study_fields::scaling, out);
  if (measure.cloud) {
    write_fields<IntensityMeasure>(measure, study_fields::cloud, out);
  } else {
    write_fields<LevelList>({measure.levels}, measure_level_tables(measure.type).list, out);
  }
  // Only a surface has the key: the canonical config (and hash) of every other study is unchanged.
  if (measure.surface()) {
    out["second"] = {{"type", "pulse_period"}};
    write_fields<LevelList>({measure.periods}, level_tables<domain::pulse_period>.list,
                            out["second"]);
  }
  return out;
}

}  // namespace blockfrag
