// A recorded ground acceleration: samples of a(t) in g. The engine gets the samples; reading them
// from a record file is the config layer's (mpi_driver/config/record_file.hpp).
#pragma once

#include <vector>

namespace blockfrag {

// a(t_k) = acceleration_g[k] at strictly increasing times_k >= 0 (s); linear in between.
struct Accelerogram {
  std::vector<double> times;
  std::vector<double> acceleration_g;
};

// Refuses (InvalidInput) fewer than 2 samples, non-finite values, negative or non-increasing
// times, or columns of different lengths.
void check_accelerogram(const Accelerogram& record);

// max |a| in g: the peak ground acceleration.
double peak_acceleration_g(const Accelerogram& record);

// Whether every sample time is a multiple of step, to a relative kStepGridRounding.
bool on_step_grid(const Accelerogram& record, double step);

// The record's piecewise-linear a(t) (zero before the first sample) sampled at k step for every
// k step up to the last sample time: a record that fits a fixed-step integrator's grid. What lies
// past the last grid point (less than one step) is dropped, as the motion ends there.
Accelerogram resample(const Accelerogram& record, double step);

}  // namespace blockfrag
