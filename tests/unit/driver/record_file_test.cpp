// Reading records: the synthetic files of tests/data/records/ (written by make_records.py) give
// back the formulas that wrote them; every file of tests/data/bad_records/ is refused with its
// file, the line to blame and the reason.
#include "mpi_driver/config/record_file.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

namespace blockfrag {
namespace {

const std::filesystem::path records =
    std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "tests/data/records";
const std::filesystem::path bad_records =
    std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "tests/data/bad_records";

TEST(RecordFile, ReadsPeerNgaAt2WithTheNgaWest2Header) {
  const Accelerogram record = read_accelerogram(records / "decaying_sine.AT2");
  ASSERT_EQ(record.times.size(), 400u);
  ASSERT_EQ(record.acceleration_g.size(), 400u);
  double peak = 0.0;
  for (std::size_t k = 0; k < 400; ++k) {
    const double t = static_cast<double>(k) * 0.005;
    EXPECT_EQ(record.times[k], t);
    const double a = 0.3 * std::exp(-t) * std::sin(4 * std::numbers::pi * t);
    peak = std::max(peak, std::abs(a));
    // %15.7E keeps 8 significant digits: at most 0.5e-7 of |a| <= 0.3, plus the parse.
    EXPECT_NEAR(record.acceleration_g[k], a, 0.5e-7 * std::abs(a) + 1e-16) << "sample " << k;
  }
  EXPECT_NEAR(peak_acceleration_g(record), peak, 0.5e-7 * peak);
}

TEST(RecordFile, ReadsTheOlderAt2HeaderLowerCaseExtensionAndDosLineEnds) {
  const Accelerogram record = read_accelerogram(records / "old_header.at2");
  ASSERT_EQ(record.times.size(), 11u);
  for (std::size_t k = 0; k < 11; ++k) {
    EXPECT_EQ(record.times[k], static_cast<double>(k) * 0.01);
    EXPECT_NEAR(record.acceleration_g[k], 0.1 - 0.005 * static_cast<double>(k), 1e-15);
  }
  EXPECT_DOUBLE_EQ(peak_acceleration_g(record), 0.1);  // |0.1 - 0.05| < 0.1 at the end
}

TEST(RecordFile, ReadsTwoColumnsSeparatedByBlanksOrCommasSkippingCommentsAndBlankLines) {
  const Accelerogram record = read_accelerogram(records / "cosine_pulse.txt");
  ASSERT_EQ(record.times.size(), 51u);
  for (std::size_t k = 0; k < 51; ++k) {
    const double t = static_cast<double>(k) * 0.01;
    EXPECT_NEAR(record.times[k], t, 1e-15);
    EXPECT_NEAR(record.acceleration_g[k], -0.4 * std::cos(2 * std::numbers::pi * t / 0.5), 0.5e-10);
  }
  EXPECT_DOUBLE_EQ(peak_acceleration_g(record), 0.4);  // at t = 0, 0.25 and 0.5, written exactly
}

struct Broken {
  std::size_t line;  // 0: the file as a whole
  std::string reason;
};

// One file per way a record can be malformed, the line a reader should be sent to, and the words.
const std::map<std::string, Broken> broken = {
    {"short_header.AT2", {3, "the file ends before header line 3 of 4"}},
    {"velocity_units.AT2",
     {3, "expected \"ACCELERATION TIME SERIES IN UNITS OF G\", got \"VELOCITY"}},
    {"no_npts.AT2", {4, "expected NPTS and DT"}},
    {"old_header_without_names.at2", {4, "expected NPTS and DT"}},
    {"zero_npts.AT2", {4, "NPTS must be a positive whole number (got \"0\")"}},
    {"one_point.AT2", {4, "a record needs at least 2 samples (NPTS = 1)"}},
    {"negative_dt.AT2", {4, "DT must be > 0 (got \"-.0050\")"}},
    {"zero_dt.AT2", {4, "DT must be > 0 (got \"0.\")"}},
    {"too_few_values.AT2", {6, "the file ends after 10 values, fewer than NPTS = 12"}},
    {"too_many_values.AT2", {6, "more values than NPTS = 8 (the extra one is \"4.0000000E-02\")"}},
    {"non_numeric.AT2", {6, "not a number: \"2.0000000E-0Z\""}},
    {"nan_value.AT2", {5, "not a finite number: \"NaN\""}},
    {"inf_value.txt", {3, "not a finite number: \"inf\""}},
    {"three_columns.txt", {1, "expected 2 numbers (time acceleration_g), found 3"}},
    {"one_column.txt", {2, "expected 2 numbers (time acceleration_g), found 1"}},
    {"header_not_a_comment.txt", {2, "not a number: \"time\""}},
    {"time_repeats.csv", {5, "times must increase strictly (0.02 follows 0.02)"}},
    {"time_goes_back.csv", {3, "times must increase strictly (0.01 follows 0.02)"}},
    {"negative_time.txt", {1, "time must be >= 0 (got -0.01)"}},
    {"one_sample.txt", {3, "a record needs at least 2 samples (found 1)"}},
    {"empty.txt", {1, "a record needs at least 2 samples (found 0)"}},
    {"hex_float.AT2", {5, "not a number: \"0x1p3\""}},
    {"nul_byte.AT2", {5, "contains a NUL byte (a record is a text file)"}},
    {"huge_dt.AT2", {4, "the record lasts (NPTS - 1) DT = inf s, more than 1e+05 s"}},
    {"huge_npts.AT2", {4, "NPTS = \"1000000000\" is more than 4000000 samples"}},
    {"time_too_late.csv", {2, "time must be <= 1e+05 s (got 2e5)"}},
};

void expect_refused(const std::filesystem::path& file, const Broken& expected) {
  try {
    read_accelerogram(file);
    ADD_FAILURE() << file << " was accepted";
  } catch (const RecordError& error) {
    const std::string where =
        file.string() + (expected.line ? ":" + std::to_string(expected.line) : "") + ": ";
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(where, 0), 0u) << message << "\ndoes not start with " << where;
    EXPECT_NE(message.find(expected.reason), std::string::npos)
        << message << "\nlacks " << expected.reason;
    EXPECT_EQ(error.file(), file.string());
    EXPECT_EQ(error.line(), expected.line);
  }
}

TEST(RecordFile, RefusesEveryBrokenFileNamingItsLineAndTheReason) {
  std::size_t seen = 0;
  for (const auto& entry : std::filesystem::directory_iterator(bad_records)) {
    const std::string name = entry.path().filename().string();
    const auto it = broken.find(name);
    if (it == broken.end()) {
      ADD_FAILURE() << "tests/data/bad_records/" << name << " has no expected line and reason here";
      continue;
    }
    SCOPED_TRACE(name);
    expect_refused(entry.path(), it->second);
    ++seen;
  }
  EXPECT_EQ(seen, broken.size()) << "a file of the table is missing from tests/data/bad_records";
}

// The project's real records (configs/records/, the USGS SLAMMER set) are read as they are: two
// comma-separated columns, '#' header lines, CRLF line ends, one with a UTF-8 byte order mark.
// Each has one sample per data line, at a uniform step from 0.
TEST(RecordFile, ReadsEveryRecordOfTheProjectsSuiteAsItIs) {
  const std::filesystem::path folder =
      std::filesystem::path(BLOCKFRAG_SOURCE_DIR) / "configs/records";
  int read = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".csv" || entry.path().filename() == "catalogue.csv") continue;
    SCOPED_TRACE(entry.path().filename().string());
    std::ifstream in(entry.path());
    std::size_t data_lines = 0;
    for (std::string line; std::getline(in, line);) {
      const auto first = line.find_first_not_of("\xEF\xBB\xBF \t\r");
      if (first != std::string::npos && line[first] != '#') ++data_lines;
    }
    const Accelerogram record = read_accelerogram(entry.path());
    ASSERT_EQ(record.times.size(), data_lines);
    ASSERT_GE(record.times.size(), 1000u);
    EXPECT_EQ(record.times.front(), 0.0);
    const double step = record.times[1] - record.times[0];
    EXPECT_NEAR(record.times.back(), step * static_cast<double>(record.times.size() - 1), 1e-6);
    ++read;
  }
  EXPECT_EQ(read, 18);
}

TEST(RecordFile, RefusesAMissingFileAndAFolderWithoutALine) {
  expect_refused(bad_records / "no_such_record.AT2", {0, "no such file"});
  expect_refused(records, {0, "is a folder"});
}

// A FIFO would block the read forever and a device never ends: both are refused before any read.
TEST(RecordFile, RefusesAFifoAndADeviceWithoutReadingThem) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("blockfrag_fifo_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::filesystem::path fifo = folder / "record.txt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(fifo, {0, "is a FIFO, not a regular file"});
  std::filesystem::remove_all(folder);
  expect_refused("/dev/zero", {0, "is a character device, not a regular file"});
}

// A message quotes at most a short printable excerpt of the file: a record that is really a
// secret, or a binary, or a 10 MB line, is not echoed.
TEST(RecordFile, QuotesAtMostSixtyPrintableCharactersOfTheFile) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("blockfrag_long_line_" + std::to_string(::getpid()) + ".txt");
  {
    std::ofstream out(file);
    out << "0.0 0.1\n0.01 secret\x01" << std::string(10'000'000, 'x') << "\n";
  }
  try {
    read_accelerogram(file);
    ADD_FAILURE() << "accepted";
  } catch (const RecordError& error) {
    const std::string message = error.what();
    EXPECT_LT(message.size(), file.string().size() + 120) << message.substr(0, 200);
    EXPECT_NE(message.find("not a number: \"secret?xxxx"), std::string::npos)
        << message.substr(0, 200);
    EXPECT_NE(message.find("...\""), std::string::npos);
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace blockfrag
