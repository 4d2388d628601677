#include "mpi_driver/config/ground_motion_json.hpp"

#include <array>
#include <cstddef>
#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "engine/number_text.hpp"
#include "engine/tolerances.hpp"
#include "mpi_driver/config/record_file.hpp"
#include "mpi_driver/config/scene_fields.hpp"

namespace blockfrag {

namespace {

using nlohmann::json;

template <std::size_t... index>
constexpr auto motion_types(std::index_sequence<index...>) {
  return std::array<std::string_view, sizeof...(index)>{
      MotionKeys<std::variant_alternative_t<index, GroundMotion>>::type...};
}
constexpr auto kMotionTypes =
    motion_types(std::make_index_sequence<std::variant_size_v<GroundMotion>>{});

// The samples are read here, so a record that cannot be used is refused with the scene, at
// /ground_motion/file, with the reader's "<file>:<line>: <reason>". The table has read the file's
// name and the scale.
void read_record(RecordedMotion& motion, ObjectReader& reader, const FieldsRead& read,
                 const std::filesystem::path& base_folder) {
  RecordTarget target;
  read_fields<RecordTarget>(reader, scene_fields::record_target, target);
  if (read.valid("scale") && target.target_pga_g)
    reader.add_error("target_pga_g", "give either scale or target_pga_g, not both");
  if (read.valid("file") && motion.file.empty()) reader.add_error("file", "must not be empty");
  if (motion.file.empty()) return;
  const std::filesystem::path path = base_folder / motion.file;  // an absolute file replaces it
  try {
    motion.record = std::make_shared<const Accelerogram>(read_accelerogram(path));
  } catch (const RecordError& error) {
    reader.add_error("file", error.what());
    return;
  }
  if (target.target_pga_g) {
    const double peak = peak_acceleration_g(*motion.record);
    if (peak > 0) {
      motion.scale = *target.target_pga_g / peak;
    } else {
      reader.add_error("target_pga_g",
                       "cannot scale " + path.string() + " to a peak: its accelerations are all 0");
    }
  }
}

// The rules a motion's table cannot say.
template <class Motion>
void read_beyond_table(Motion&, ObjectReader&, const FieldsRead&, const std::filesystem::path&) {}

void read_beyond_table(RecordedMotion& motion, ObjectReader& reader, const FieldsRead& read,
                       const std::filesystem::path& base_folder) {
  read_record(motion, reader, read, base_folder);
}

void read_beyond_table(MavroeidisPapageorgiouPulse& pulse, ObjectReader& reader,
                       const FieldsRead& read, const std::filesystem::path&) {
  if (pulse.t0 && read.valid("period") && read.valid("gamma") &&
      *pulse.t0 < (1.0 - kGridRounding) * pulse.half_width()) {
    reader.add_error("t0", "must be >= gamma period / 2 = " + format_number(pulse.half_width()) +
                               " (the pulse starts at t >= 0) (got " + format_number(*pulse.t0) +
                               ")");
  }
}

template <std::size_t index>
GroundMotion read_motion(ObjectReader& reader, const std::filesystem::path& base_folder) {
  using Motion = std::variant_alternative_t<index, GroundMotion>;
  Motion motion;
  FieldsRead read;
  // A motion without keys ("none") instantiates no table code.
  if constexpr (std::size(MotionKeys<Motion>::fields) > 0) {
    read = read_fields<Motion>(reader, MotionKeys<Motion>::fields, motion);
  }
  read_beyond_table(motion, reader, read, base_folder);
  return motion;
}

using MotionReader = GroundMotion (*)(ObjectReader&, const std::filesystem::path&);
template <std::size_t... index>
constexpr auto motion_readers(std::index_sequence<index...>) {
  return std::array<MotionReader, sizeof...(index)>{&read_motion<index>...};
}

}  // namespace

std::vector<std::string_view> ground_motion_types() {
  return {kMotionTypes.begin(), kMotionTypes.end()};
}

GroundMotion read_ground_motion(ObjectReader reader, const std::filesystem::path& base_folder) {
  const auto type = reader.required_choice("type", kMotionTypes);
  // Without a valid type nobody knows which keys belong here: report nothing more.
  if (!type) return NoMotion{};
  static constexpr auto readers =
      motion_readers(std::make_index_sequence<std::variant_size_v<GroundMotion>>{});
  std::size_t index = 0;
  while (kMotionTypes[index] != *type) ++index;
  GroundMotion motion = readers[index](reader, base_folder);
  reader.finish("for type \"" + *type + "\"");
  return motion;
}

json ground_motion_to_json(const GroundMotion& motion) {
  return std::visit(
      [](const auto& given) {
        using Motion = std::decay_t<decltype(given)>;
        json out = {{"type", MotionKeys<Motion>::type}};
        if constexpr (std::size(MotionKeys<Motion>::fields) > 0) {
          write_fields<Motion>(given, MotionKeys<Motion>::fields, out);
        }
        return out;
      },
      motion);
}

}  // namespace blockfrag
