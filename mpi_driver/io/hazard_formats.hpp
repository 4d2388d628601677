// The three hazard-file parsers behind read_hazard_file (hazard_file.hpp) and what they share:
// the text split in lines, numbers read strictly, and the raw curve turned into a HazardCurve.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "mpi_driver/io/hazard_file.hpp"

namespace blockfrag {

// The most levels a curve may have (OpenQuake's and the USGS service's have about 20).
inline constexpr std::size_t kMaxHazardLevels = 10'000;

// A file's levels and rates as read, before the ends are trimmed: rates may be +inf (OpenQuake's
// poe = 1) and 0.
struct RawHazard {
  std::vector<double> im;
  std::vector<double> rate;
};

// `where(i)` names level i in a message ("line 3, column poe-0.1000000").
using LevelName = std::function<std::string(std::size_t)>;

// Leaves out leading infinite rates and levels after the first zero, checks the rest
// (non-increasing rates, at least two levels) and converts the intensities by `unit`.
SiteHazard finish_hazard(const std::string& file, RawHazard raw, const LevelName& where,
                         double unit);

// The lines of a text, without their '\n' or "\r\n".
std::vector<std::string_view> split_lines(std::string_view text);
// Fields separated by commas (no quoting: no hazard file puts a comma in a number).
std::vector<std::string_view> split_fields(std::string_view line);
// A whole field as a finite number (spaces around it allowed); false otherwise.
bool read_field_number(std::string_view field, double& value);

// Throws InvalidInput: "FILE: <what> A, the study's intensity measure is B: ...", `what` saying
// where A comes from ("its curves are of", "--imt names").
[[noreturn]] void refuse_imt(const std::string& file, const std::string& what,
                             const HazardImt& file_imt, const HazardImt& study);

SiteHazard read_openquake_curve(const std::string& file, std::string_view text,
                                const HazardRequest& request);
SiteHazard read_usgs_curve(const std::string& file, std::string_view text,
                           const HazardRequest& request);
SiteHazard read_table_curve(const std::string& file, std::string_view text,
                            const HazardRequest& request);

}  // namespace blockfrag
