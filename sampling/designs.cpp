#include "sampling/designs.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "engine/errors.hpp"
#include "sampling/philox_stream.hpp"

namespace blockfrag {
namespace {

void require_samples(std::uint32_t n) {
  // Positions k < n are counted in the draw word below its reserved bit.
  if (n == 0 || n > reserved_draw_flag) {
    throw ContractViolation("samples per level must be in [1, 2^31] (got " + std::to_string(n) +
                            ")");
  }
}

}  // namespace

double monte_carlo_uniform(std::uint64_t seed, std::uint32_t stream, std::uint64_t index) {
  return uniform_open01(seed, stream, index);
}

std::vector<std::uint32_t> latin_hypercube_permutation(std::uint64_t seed, std::uint32_t stream,
                                                       std::uint64_t level, std::uint32_t n) {
  require_samples(n);
  std::vector<std::uint32_t> permutation(n);
  std::iota(permutation.begin(), permutation.end(), 0u);
  for (std::uint32_t k = n - 1; k > 0; --k) {
    const std::uint64_t bits = random_bits(seed, stream, level, reserved_draw_flag | k);
    std::swap(permutation[k], permutation[index_below(bits, k + 1)]);
  }
  return permutation;
}

double latin_hypercube_uniform_in_stratum(std::uint64_t seed, std::uint32_t stream,
                                          std::uint64_t index, std::uint32_t stratum,
                                          std::uint32_t n) {
  const double u = (stratum + uniform_open01(seed, stream, index)) / n;
  // stratum + v rounds up to stratum + 1 when v is within an ulp of 1; in the top stratum that
  // would give exactly 1, which no inverse CDF accepts.
  return std::min(u, max_open01);
}

double latin_hypercube_uniform(std::uint64_t seed, std::uint32_t stream, std::uint64_t level,
                               std::uint32_t n, std::uint32_t j) {
  if (j >= n)
    throw ContractViolation("sample " + std::to_string(j) + " of a level of " + std::to_string(n));
  const auto permutation = latin_hypercube_permutation(seed, stream, level, n);
  return latin_hypercube_uniform_in_stratum(seed, stream, level * n + j, permutation[j], n);
}

double design_uniform(Design design, std::uint64_t seed, std::uint32_t stream,
                      std::uint32_t samples_per_level, std::uint64_t index) {
  switch (design) {
    case Design::monte_carlo: return monte_carlo_uniform(seed, stream, index);
    case Design::latin_hypercube:
      require_samples(samples_per_level);
      return latin_hypercube_uniform(seed, stream, index / samples_per_level, samples_per_level,
                                     static_cast<std::uint32_t>(index % samples_per_level));
  }
  throw ContractViolation("unknown sampling design");
}

LatinHypercubeLevel::LatinHypercubeLevel(std::uint64_t seed, std::vector<std::uint32_t> streams,
                                         std::uint64_t level, std::uint32_t samples_per_level)
    : seed_(seed),
      streams_(std::move(streams)),
      level_(level),
      samples_per_level_(samples_per_level) {
  require_samples(samples_per_level_);
  strata_.reserve(streams_.size() * samples_per_level_);
  for (const std::uint32_t stream : streams_) {
    const auto permutation = latin_hypercube_permutation(seed_, stream, level_, samples_per_level_);
    strata_.insert(strata_.end(), permutation.begin(), permutation.end());
  }
}

std::uint32_t LatinHypercubeLevel::stratum(std::size_t dimension, std::uint32_t j) const {
  if (dimension >= streams_.size() || j >= samples_per_level_) {
    throw ContractViolation("Latin hypercube dimension " + std::to_string(dimension) + ", sample " +
                            std::to_string(j) + " out of range");
  }
  return strata_[dimension * samples_per_level_ + j];
}

double LatinHypercubeLevel::uniform(std::size_t dimension, std::uint32_t j) const {
  // stratum() checks dimension and j, so it runs before streams_ is indexed (the order in which a
  // call's arguments are evaluated is the compiler's).
  const std::uint32_t in_stratum = stratum(dimension, j);
  return latin_hypercube_uniform_in_stratum(
      seed_, streams_[dimension], level_ * samples_per_level_ + j, in_stratum, samples_per_level_);
}

}  // namespace blockfrag
