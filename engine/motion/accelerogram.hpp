// A recorded ground acceleration: samples of a(t) in g, read from a PEER NGA .AT2 file or a
// two-column text file. The one I/O the engine does: a scene names a record, and nothing but the
// engine knows what a record's samples mean.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace blockfrag {

// a(t_k) = acceleration_g[k] at strictly increasing times_k >= 0 (s); linear in between.
struct Accelerogram {
  std::vector<double> times;
  std::vector<double> acceleration_g;
};

// A record file that cannot be used. what() is "<file>:<line>: <reason>", or "<file>: <reason>" when
// no line is to blame (a file that cannot be opened); the file is named as the caller gave it.
class RecordError : public std::runtime_error {
 public:
  RecordError(const std::string& file, std::size_t line, const std::string& reason);
  const std::string& file() const noexcept { return file_; }
  std::size_t line() const noexcept { return line_; }  // 1-based; 0 for the whole file
  const std::string& reason() const noexcept { return reason_; }

 private:
  std::string file_, reason_;
  std::size_t line_;
};

// Reads a record, choosing the format by the extension: ".AT2" (any case) is PEER NGA (4 header
// lines, the 4th giving NPTS and DT, then NPTS values in g, any number per line, sample k at k DT);
// anything else is two columns "time acceleration_g" per line, separated by whitespace or commas,
// blank lines and lines starting with '#' ignored. Throws RecordError for every malformed input.
Accelerogram read_accelerogram(const std::filesystem::path& file);

// Refuses (std::invalid_argument) fewer than 2 samples, non-finite values, negative or
// non-increasing times, or columns of different lengths.
void check_accelerogram(const Accelerogram& record);

// max |a| in g: the peak ground acceleration.
double peak_acceleration_g(const Accelerogram& record);

// Whether every sample time is a multiple of step, to a relative 1e-9.
bool on_step_grid(const Accelerogram& record, double step);

// The record's piecewise-linear a(t) (zero before the first sample) sampled at k step for every
// k step up to the last sample time: a record that fits a fixed-step integrator's grid. What lies
// past the last grid point (less than one step) is dropped, as the motion ends there.
Accelerogram resample(const Accelerogram& record, double step);

}  // namespace blockfrag
