#include "postproc/fragility/surface_grid.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include <gsl/gsl_cdf.h>

#include "engine/errors.hpp"
#include "postproc/fragility/binomial_interval.hpp"

namespace blockfrag {

SurfaceGrid surface_from_counts(std::vector<double> im1, std::vector<double> im2,
                                std::vector<std::int64_t> trials,
                                std::vector<std::int64_t> exceedances) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t cells = im1.size() * im2.size();
  if (trials.size() != cells || exceedances.size() != cells)
    throw ContractViolation("a surface of " + std::to_string(im1.size()) + " x " +
                            std::to_string(im2.size()) + " cells needs as many counts");
  SurfaceGrid grid;
  std::vector<double> cell_im1, cell_im2;  // each cell's coordinates, for the fit
  for (std::size_t c = 0; c < cells; ++c) {
    const auto n = trials[c], z = exceedances[c];
    grid.probability.push_back(n > 0 ? static_cast<double>(z) / static_cast<double>(n) : nan);
    const auto interval = n > 0 ? wilson_interval(z, n, 0.95) : ProportionInterval{nan, nan};
    grid.ci_low.push_back(interval.low);
    grid.ci_high.push_back(interval.high);
    cell_im1.push_back(im1[c / im2.size()]);
    cell_im2.push_back(im2[c % im2.size()]);
  }
  grid.fit = fit_fragility_surface(cell_im1, cell_im2, trials, exceedances);
  grid.gof = {nan, 0, nan, nan};
  if (grid.fit.status == SurfaceFitStatus::ok ||
      grid.fit.status == SurfaceFitStatus::not_increasing) {
    std::vector<double> expected;
    for (std::size_t c = 0; c < cells; ++c) {
      expected.push_back(static_cast<double>(trials[c]) *
                         grid.fit.probability(cell_im1[c], cell_im2[c]));
    }
    // The curves' deviance with the surface's expected counts; a surface has three parameters,
    // not two.
    grid.gof = goodness_of_fit(cell_im1, trials, exceedances, 1.0, 1.0, expected);
    grid.gof.dof = std::max(grid.gof.dof - 1, 0);
    grid.gof.p_value = grid.gof.dof >= 1 ? gsl_cdf_chisq_Q(grid.gof.deviance, grid.gof.dof) : nan;
  }
  grid.im1 = std::move(im1);
  grid.im2 = std::move(im2);
  grid.trials = std::move(trials);
  grid.exceedances = std::move(exceedances);
  return grid;
}

std::vector<std::int64_t> summed_over_im2(const std::vector<std::int64_t>& counts, std::size_t n2) {
  std::vector<std::int64_t> sums(counts.size() / n2, 0);
  for (std::size_t c = 0; c < counts.size(); ++c) sums[c / n2] += counts[c];
  return sums;
}

}  // namespace blockfrag
