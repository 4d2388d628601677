// Samples of the type B block's record suite study (configs/dam_type_b_record_suite.json) that ran
// into the seat's budgets (docs/validation.md, "Type A against type B over a record suite"). No
// excitation is left after a record ends, and the impacts and friction take energy: the block must
// end at rest on its seat or off it, never in a storm of contact changes.
#include <cstdint>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

// Samples that ran into the budgets (100,000 contact changes within 1e-6 s, or 1,000,000 events):
// 118 at 0.8 g, 242 at 1.4 g, 271 at 1.6 g. Their blocks' bounces on the seat end now that a
// contact whose rebound would be slower than the settling speed stays on the seat (a fold vertex
// bounced at e = 0.3 in flights of 2e-6 s and landed each time as fast as before).
TEST(DamTypeBRecordSuite, SamplesThatRanOutOfTheBudgetsComeToRest) {
  const StudyConfig config = read_study_config(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) /
                                               "configs/dam_type_b_record_suite.json");
  StudySampler sampler(config);
  for (const std::int64_t index : {118, 242, 271}) {
    SCOPED_TRACE("sample " + std::to_string(index));
    const Summary s = simulate(sampler.draw(index).scene);
    ASSERT_EQ(s.status, Status::ok) << s.status_reason;
    EXPECT_TRUE(s.settled);
    EXPECT_FALSE(s.overturned);
    EXPECT_EQ(s.modes.back().mode, ModeKind::rest);
    // Slid upstream, it rests on the seat's horizontal part: theta 0, to rounding.
    EXPECT_NEAR(s.final_theta, 0.0, 1e-12);
  }
}

// Samples 116 and 127 (0.8 g): the block's heel slides 8e-8 m past the seat's upstream end, and as
// the block turns about its fold the heel comes down on it. Taken as a contact on the upstream
// face, not on the base the heel lies on, the seat's end let the face's horizontal normal carry
// the block, and the contact state changed 100,000 times 4e-11 s apart (at t = 4.914 s and 6.129
// s; tests/unit/engine/seat_contacts_test.cpp). Taken on the base, the block rocks on and rests.
TEST(DamTypeBRecordSuite, SamplesWhoseHeelCameDownOnTheSeatsEndComeToRest) {
  const StudyConfig config = read_study_config(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) /
                                               "configs/dam_type_b_record_suite.json");
  StudySampler sampler(config);
  for (const std::int64_t index : {116, 127}) {
    SCOPED_TRACE("sample " + std::to_string(index));
    const Summary s = simulate(sampler.draw(index).scene);
    ASSERT_EQ(s.status, Status::ok) << s.status_reason;
    EXPECT_TRUE(s.settled);
    EXPECT_FALSE(s.overturned);
    EXPECT_FALSE(s.fell);
    EXPECT_EQ(s.modes.back().mode, ModeKind::rest);
    EXPECT_NEAR(s.final_theta, 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace blockfrag
