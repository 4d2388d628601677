#include "mpi_driver/config/record_suite.hpp"

#include "mpi_driver/config/record_file.hpp"
#include "mpi_driver/config/study_fields.hpp"
#include "mpi_driver/config/study_hash.hpp"

namespace blockfrag {
namespace {

// Reads one record file; a problem is reported at `path` (the entry, or its "file" or "vertical").
std::shared_ptr<const Accelerogram> read_file(const std::string& file, const JsonPointer& path,
                                              ConfigErrors& errors,
                                              const std::filesystem::path& base_folder) {
  if (file.empty()) {
    errors.add(path, "must not be empty");
    return nullptr;
  }
  try {
    auto record = std::make_shared<const Accelerogram>(read_accelerogram(base_folder / file));
    check_accelerogram(*record);
    return record;
  } catch (const InvalidInput& error) {
    errors.add(path, error.what());
    return nullptr;
  }
}

}  // namespace

std::uint64_t record_content_hash(const Accelerogram& record) {
  std::string bytes;
  for (const auto* column : {&record.times, &record.acceleration_g}) {
    bytes.append(reinterpret_cast<const char*>(column->data()), column->size() * sizeof(double));
  }
  return fnv1a64(bytes);
}

std::size_t RecordSuite::record_of(std::uint32_t member, std::uint32_t per_level) const {
  double total = 0.0;
  for (const auto& r : records) total += r.weight;
  const double u = (static_cast<double>(member) + 0.5) / static_cast<double>(per_level) * total;
  double cumulative = 0.0;
  for (std::size_t k = 0; k < records.size(); ++k) {
    cumulative += records[k].weight;
    if (u < cumulative) return k;
  }
  return records.size() - 1;  // u = total by rounding
}

std::optional<RecordSuite> read_record_suite(ObjectReader& reader,
                                             const std::filesystem::path& base_folder,
                                             std::size_t max_samples) {
  ArrayReader array = reader.required_array("records");
  if (!array.valid()) return std::nullopt;
  if (array.size() == 0 || array.size() > kMaxSuiteRecords) {
    reader.add_error("records", "must list 1 to " + std::to_string(kMaxSuiteRecords) +
                                    " records (got " + std::to_string(array.size()) + ")");
    return std::nullopt;
  }
  const std::size_t errors_before = reader.errors().size();
  RecordSuite suite;
  std::size_t samples = 0;
  for (std::size_t k = 0; k < array.size(); ++k) {
    SuiteRecord record;
    const nlohmann::json& raw = array.raw(k);
    ConfigErrors& errors = reader.errors();
    JsonPointer file_path = array.path_of(k);
    if (raw.is_string()) {
      record.file = raw.get<std::string>();
    } else if (raw.is_object()) {
      ObjectReader entry = array.object(k);
      const FieldsRead read =
          read_fields<SuiteRecord>(entry, study_fields::suite_record_files, record);
      if (!read.valid("file")) continue;
      file_path = entry.path_of("file");
      if (read.valid("vertical")) {
        record.vertical =
            read_file(record.vertical_file, entry.path_of("vertical"), errors, base_folder);
      }
      read_fields<SuiteRecord>(entry, study_fields::suite_record, record);
      entry.finish();
    } else {
      errors.add(array.path_of(k),
                 "must be a record file name or an object {\"file\", \"vertical\", \"weight\"}");
      continue;
    }
    record.record = read_file(record.file, file_path, errors, base_folder);
    if (!record.record || (!record.vertical_file.empty() && !record.vertical)) continue;
    samples += record.record->times.size() + (record.vertical ? record.vertical->times.size() : 0);
    if (samples > max_samples) {
      errors.add(file_path, "the suite's records up to this one hold " + std::to_string(samples) +
                                " samples, more than the " + std::to_string(max_samples) +
                                " a suite may hold");
      return std::nullopt;
    }
    record.content_hash = record_content_hash(*record.record);
    if (record.vertical) {
      record.content_hash ^= record_content_hash(*record.vertical) * 0x9E3779B97F4A7C15ULL;
    }
    suite.records.push_back(std::move(record));
  }
  if (reader.errors().size() != errors_before) return std::nullopt;
  return suite;
}

nlohmann::json record_suite_to_json(const RecordSuite& suite) {
  nlohmann::json records = nlohmann::json::array();
  for (const auto& r : suite.records) {
    nlohmann::json entry = {{"content_hash", hash_to_hex(r.content_hash)}};
    write_fields<SuiteRecord>(r, study_fields::suite_record_files, entry);
    write_fields<SuiteRecord>(r, study_fields::suite_record, entry);
    records.push_back(std::move(entry));
  }
  return {{"type", "record_suite"}, {"records", records}};
}

}  // namespace blockfrag
