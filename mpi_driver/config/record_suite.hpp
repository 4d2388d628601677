// A suite of recorded ground motions for a study: the base scene's
//   "ground_motion": {"type": "record_suite",
//                     "records": ["a.AT2", {"file": "b.csv", "vertical": "b_up.csv", "weight": 2}]}
// (files relative to the study file's folder). Each sample runs one record of the suite, chosen by
// its place in its level (record_of): a pure function of the sample's index, so any rank, chunk or
// restart runs the same record.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/motion/accelerogram.hpp"
#include "engine/motion/intensity_measures.hpp"
#include "mpi_driver/config/config_reader.hpp"

namespace blockfrag {

struct SuiteRecord {
  std::string file;  // as the config gives it
  std::shared_ptr<const Accelerogram> record;
  std::string vertical_file;  // empty: no vertical companion
  std::shared_ptr<const Accelerogram> vertical;
  double weight = 1.0;
  // FNV-1a 64 of the samples (both components): a study's identity includes what its records hold.
  std::uint64_t content_hash = 0;
  // The horizontal record's measures as recorded (Sa at the study's period, if it asks for it).
  IntensityMeasures measures;
};

struct RecordSuite {
  std::vector<SuiteRecord> records;

  // The record of member `member` (0-based) of a level of `per_level` samples: systematic sampling
  // over the cumulative weights, u = (member + 1/2) / per_level falls in record k's share. Every
  // level sees each record in proportion to its weight: with equal weights and per_level a
  // multiple of the suite's size, each record exactly per_level / size times, in blocks.
  std::size_t record_of(std::uint32_t member, std::uint32_t per_level) const;
};

// FNV-1a 64 of a record's samples (times and accelerations).
std::uint64_t record_content_hash(const Accelerogram& record);

// A suite has at most this many records; each weight is in (0, 1e6].
inline constexpr std::size_t kMaxSuiteRecords = 10'000;
// Every rank holds every record of its suite (16 bytes a sample): together at most this many
// samples, 1.6 GB, ten thousand records of 40 s at 250 Hz.
inline constexpr std::size_t kMaxSuiteSamples = 100'000'000;

// Reads the suite at reader's object (the "records" array and "type"); errors name
// /.../records/K and the record's file and line. nullopt after an error, and at the first record
// that takes the suite past max_samples samples (its vertical companions counted).
std::optional<RecordSuite> read_record_suite(ObjectReader& reader,
                                             const std::filesystem::path& base_folder,
                                             std::size_t max_samples = kMaxSuiteSamples);

// The canonical form: each record as {"file", "vertical" (when given), "weight", "content_hash"}.
nlohmann::json record_suite_to_json(const RecordSuite& suite);

}  // namespace blockfrag
