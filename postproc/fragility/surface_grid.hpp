// A fragility surface's data on its grid of n1 x n2 cells (the first measure's levels by the
// second's): per cell the trials, exceedances, observed probability and its Wilson interval, the
// probit surface fitted to them (fragility_surface.hpp) and how well it fits.
#pragma once

#include <cstdint>
#include <vector>

#include "postproc/fragility/fit_diagnostics.hpp"
#include "postproc/fragility/fragility_surface.hpp"

namespace blockfrag {

struct SurfaceGrid {
  std::vector<double> im1, im2;  // the axes: n1 and n2 increasing levels
  // [n1 x n2], row k1 of IM1 level k1, column k2 of IM2 level k2, row by row.
  std::vector<std::int64_t> trials, exceedances;
  std::vector<double> probability, ci_low, ci_high;  // NaN in cells without trials
  SurfaceFit fit;
  // The deviance against the saturated model (each cell's own proportion) on cells with trials - 3
  // degrees of freedom, its chi-square p-value and the largest |observed - fitted| over the cells;
  // deviance and misfit NaN, dof 0 without coefficients.
  GoodnessOfFit gof;
};

// trials and exceedances row by row, n1 x n2 = im1.size() x im2.size() of them (else
// ContractViolation).
SurfaceGrid surface_from_counts(std::vector<double> im1, std::vector<double> im2,
                                std::vector<std::int64_t> trials,
                                std::vector<std::int64_t> exceedances);

// The counts of each IM1 level summed over the IM2 levels: a surface study's curve in IM1.
std::vector<std::int64_t> summed_over_im2(const std::vector<std::int64_t>& counts, std::size_t n2);

}  // namespace blockfrag
