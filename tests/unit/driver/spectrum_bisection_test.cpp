// The spectrum's pieces without MPI: a record's verdict; the brackets of a column (every change of
// "overturned", islands too, never across a failed point); bisection to the tolerance with the
// number of steps the halving needs, a failed midpoint stopping its bracket, the iteration cap;
// and the bisection state file: a round trip of every bit, damage of any kind refused.
#include "mpi_driver/study/spectrum_bisection.hpp"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mpi_driver/parallel/bisection_state.hpp"
#include "mpi_driver/parallel/checkpoint.hpp"

namespace blockfrag {
namespace {

using V = SpectrumVerdict;

SampleRecord record_of(std::int64_t status, bool overturned, std::int64_t impacts, bool settled) {
  SampleRecord record;
  record.index = 0;
  record.status = status;
  record.overturned = overturned;
  record.impacts = impacts;
  record.settled = settled;
  return record;
}

TEST(SpectrumVerdict, ClassifiesRecords) {
  EXPECT_EQ(spectrum_verdict(record_of(0, false, 12, true)), V::stands);
  EXPECT_EQ(spectrum_verdict(record_of(0, true, 0, true)), V::overturns_no_impact);
  EXPECT_EQ(spectrum_verdict(record_of(0, true, 1, true)), V::overturns_one_impact);
  EXPECT_EQ(spectrum_verdict(record_of(0, true, 7, true)), V::overturns_more_impacts);
  EXPECT_EQ(spectrum_verdict(record_of(0, false, 7, false)), V::still_moving);
  EXPECT_EQ(spectrum_verdict(record_of(1, false, 0, false)), V::failed);
  EXPECT_EQ(spectrum_verdict(record_of(2, false, 0, false)), V::rejected);
  EXPECT_FALSE(overturned(V::still_moving));
  EXPECT_TRUE(decided(V::still_moving));
  EXPECT_FALSE(decided(V::failed));
}

TEST(SpectrumBisection, ColumnBracketsEveryCrossingIslandsToo) {
  const std::vector<double> amplitude{1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<V> verdicts{
      V::stands,       V::overturns_more_impacts, V::overturns_more_impacts,
      V::stands,       V::overturns_one_impact,   V::failed,
      V::still_moving, V::overturns_no_impact};
  const auto brackets = column_brackets(3, amplitude, verdicts, 1e-7);
  // 1-2 onset, 3-4 end, 4-5 onset; 5-6 and 6-7 touch the failed point; 7-8 onset.
  ASSERT_EQ(brackets.size(), 4u);
  const double lows[] = {1, 3, 4, 7};
  const int directions[] = {+1, -1, +1, +1};
  for (std::size_t k = 0; k < brackets.size(); ++k) {
    EXPECT_EQ(brackets[k].frequency_index, 3);
    EXPECT_EQ(brackets[k].low, lows[k]);
    EXPECT_EQ(brackets[k].high, lows[k] + 1);
    EXPECT_EQ(brackets[k].direction(), directions[k]);
    EXPECT_TRUE(brackets[k].is_open());
  }
  EXPECT_EQ(brackets[1].verdict_low, static_cast<std::int64_t>(V::overturns_more_impacts));
  EXPECT_EQ(brackets[1].verdict_high, static_cast<std::int64_t>(V::stands));
  // A neighbour pair already within the tolerance is converged from the start.
  const std::vector<double> close{1.0, 1.0 + 1e-9};
  const auto done =
      column_brackets(0, close, std::vector<V>{V::stands, V::overturns_no_impact}, 1e-7);
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0].state, static_cast<std::int64_t>(BracketState::converged));
}

TEST(SpectrumBisection, ConvergesOnTheThresholdInTheStepsHalvingNeeds) {
  const double threshold = 1.2345678901;
  const double tolerance = 1e-9;
  for (const bool onset : {true, false}) {
    const auto verdict = [&](double a) {
      return (a >= threshold) == onset ? V::overturns_one_impact : V::stands;
    };
    SpectrumBracket bracket = column_brackets(
        0, std::vector<double>{1.0, 1.5}, std::vector<V>{verdict(1.0), verdict(1.5)}, tolerance)[0];
    while (bracket.is_open()) narrow(bracket, verdict(bracket.midpoint()), tolerance, 60);
    EXPECT_EQ(bracket.state, static_cast<std::int64_t>(BracketState::converged));
    EXPECT_LE(bracket.low, threshold);
    EXPECT_GT(bracket.high, threshold);
    EXPECT_LE(bracket.high - bracket.low, tolerance * bracket.high);
    // 0.5 halved until within 1e-9 x 1.23: ceil(log2(0.5 / 1.23e-9)) = 29 steps.
    EXPECT_EQ(bracket.iterations, 29);
    EXPECT_EQ(bracket.direction(), onset ? +1 : -1);
    EXPECT_EQ(overturned(static_cast<V>(bracket.verdict_high)), onset);
  }
}

TEST(SpectrumBisection, StopsAtAFailedMidpointOrTheCap) {
  SpectrumBracket bracket = column_brackets(
      0, std::vector<double>{1.0, 2.0}, std::vector<V>{V::stands, V::overturns_no_impact}, 1e-9)[0];
  narrow(bracket, V::stands, 1e-9, 60);
  EXPECT_EQ(bracket.low, 1.5);
  narrow(bracket, V::failed, 1e-9, 60);
  EXPECT_EQ(bracket.state, static_cast<std::int64_t>(BracketState::failed));
  EXPECT_EQ(bracket.low, 1.5);
  EXPECT_EQ(bracket.high, 2.0);
  EXPECT_THROW(narrow(bracket, V::stands, 1e-9, 60), ContractViolation);

  SpectrumBracket capped = column_brackets(
      0, std::vector<double>{1.0, 2.0}, std::vector<V>{V::stands, V::overturns_no_impact}, 1e-9)[0];
  for (int k = 0; k < 3; ++k) narrow(capped, V::stands, 1e-9, 3);
  EXPECT_EQ(capped.state, static_cast<std::int64_t>(BracketState::capped));
  EXPECT_EQ(capped.iterations, 3);
  EXPECT_EQ(capped.low, 1.875);
}

BisectionState some_bisection_state() {
  BisectionState state;
  state.config_hash = 0x0123456789abcdefULL;
  state.round = 7;
  for (std::int64_t k = 0; k < 5; ++k) {
    SpectrumBracket bracket;
    bracket.frequency_index = k % 3;
    bracket.low = 1.0 + 0.1 * static_cast<double>(k) + 1e-17;
    bracket.high = bracket.low + std::ldexp(1.0, -40);
    bracket.verdict_low = k % 2 == 0 ? 0 : 3;
    bracket.verdict_high = k % 2 == 0 ? 2 : 4;
    bracket.iterations = 10 + k;
    bracket.state = k % 4;
    state.brackets.push_back(bracket);
  }
  return state;
}

TEST(BisectionState, RoundTripsEveryBit) {
  const BisectionState state = some_bisection_state();
  const BisectionState back =
      decode_bisection_state(encode_bisection_state(state), "s.bisection", 100, 3);
  EXPECT_EQ(back.config_hash, state.config_hash);
  EXPECT_EQ(back.round, state.round);
  ASSERT_EQ(back.brackets.size(), state.brackets.size());
  EXPECT_EQ(std::memcmp(back.brackets.data(), state.brackets.data(),
                        state.brackets.size() * sizeof(SpectrumBracket)),
            0);
  BisectionState empty;
  EXPECT_TRUE(decode_bisection_state(encode_bisection_state(empty), "e", 100, 3).brackets.empty());
}

TEST(BisectionState, RefusesDamage) {
  const std::string good = encode_bisection_state(some_bisection_state());
  const auto refused = [](const std::string& bytes, std::int64_t max_brackets = 100,
                          std::int64_t frequencies = 3) {
    try {
      decode_bisection_state(bytes, "s.bisection", max_brackets, frequencies);
    } catch (const CheckpointError& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refused(good), "(accepted)");
  for (std::size_t at : {std::size_t{0}, std::size_t{9}, std::size_t{40}, good.size() - 1}) {
    std::string damaged = good;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    EXPECT_NE(refused(damaged), "(accepted)") << "byte " << at;
  }
  EXPECT_NE(refused(good.substr(0, good.size() - 9)), "(accepted)");
  EXPECT_NE(refused(""), "(accepted)");
  EXPECT_NE(refused(good, 4), "(accepted)");       // more brackets than allowed
  EXPECT_NE(refused(good, 100, 2), "(accepted)");  // a frequency index outside the map
  // A consistent file (checksum and all) with an impossible bracket is refused too.
  BisectionState odd = some_bisection_state();
  odd.brackets[2].high = odd.brackets[2].low;
  EXPECT_NE(refused(encode_bisection_state(odd)), "(accepted)");
  odd = some_bisection_state();
  odd.brackets[1].verdict_low = 9;
  EXPECT_NE(refused(encode_bisection_state(odd)), "(accepted)");
  EXPECT_NE(refused(good).find("(accepted)"), std::string::npos);
  EXPECT_NE(refused(std::string(good).replace(0, 8, "BFCKPT02")).find("wrong header"),
            std::string::npos);
}

}  // namespace
}  // namespace blockfrag
