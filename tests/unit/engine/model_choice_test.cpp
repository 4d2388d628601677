// Which model a scene runs, against the rules of docs/physics.md ("Effects: which model runs"):
// each set of effects names its model or is refused; "auto" prunes to at_rest where |lambda|
// never reaches min(mu, the tip thresholds), to Newmark's sliding where friction is below both
// tip thresholds and the flat-sliding limit (Shenton), and otherwise runs in full; vertical motion
// always runs full_vertical.
#include "engine/contact/model_choice.hpp"

#include <gtest/gtest.h>

#include "engine/errors.hpp"
#include "tests/support/contact_states.hpp"

namespace blockfrag {
namespace {

Effects named(bool rocking, bool sliding, bool impact, bool flight, bool vertical = false) {
  return {false, rocking, sliding, impact, flight, vertical};
}

TEST(ModelNamedBy, EachModelsEffectsNameIt) {
  EXPECT_EQ(model_named_by(Effects{}), Model::full);  // "auto" before pruning
  EXPECT_EQ(model_named_by(named(true, true, true, true)), Model::full);
  EXPECT_EQ(model_named_by(named(true, false, true, false)), Model::housner_rocking);
  EXPECT_EQ(model_named_by(named(true, false, false, false)), Model::housner_rocking);
  EXPECT_EQ(model_named_by(named(false, true, false, false)), Model::newmark_sliding);
}

TEST(ModelNamedBy, RefusesSetsThatNameNoModel) {
  const Effects refused[] = {
      named(false, false, false, false),       // nothing
      named(false, false, true, false),        // impact alone
      named(false, false, false, true),        // flight alone
      named(true, true, false, false),         // rocking and sliding without impact and flight
      named(true, true, true, false),          // all but flight
      named(true, false, true, true),          // rocking with flight but no sliding
      named(false, true, true, false),         // sliding with impact
      named(false, true, false, true),         // sliding with flight
      named(true, false, true, false, true),   // vertical with Housner's model
      named(false, true, false, false, true),  // vertical with Newmark's
  };
  for (const Effects& e : refused) {
    EXPECT_THROW(model_named_by(e), InvalidInput)
        << "rocking " << e.rocking << " sliding " << e.sliding << " impact " << e.impact
        << " flight " << e.flight << " vertical " << e.vertical;
  }
}

// The paper's block (a/b = 0.5 both ways) with friction mu under a rectangular pulse of
// amplitude A: its peak |lambda| is A.
Model chosen(double mu, double A, const Effects& effects = Effects{}) {
  Scene scene;
  scene.block = {0.5, 1.0, 1.0};
  scene.contact.friction = mu;
  scene.ground_motion = RectangularPulse{A, 1.0};
  scene.effects = effects;
  return choose_model(scene, GroundMotionPieces(scene.ground_motion), BlockGeometry(scene.block));
}

TEST(ChooseModel, AGroundThatNeverReachesFrictionOrTheTipThresholdLeavesTheBlockAtRest) {
  // min(mu, a/b): 0.5 for mu = 0.6, 0.3 for mu = 0.3. Just below it: at rest; just above: not.
  EXPECT_EQ(chosen(0.6, 0.49), Model::at_rest);
  EXPECT_EQ(chosen(0.6, 0.51), Model::full);
  EXPECT_EQ(chosen(0.3, 0.29), Model::at_rest);
  EXPECT_EQ(chosen(0.3, 0.31), Model::newmark_sliding);
  EXPECT_EQ(chosen(0.6, -0.49), Model::at_rest);
  EXPECT_EQ(chosen(0.6, -0.51), Model::full);
}

TEST(ChooseModel, FrictionBelowTheTipThresholdsCanOnlySlide) {
  // mu < a/b = 0.5: Newmark's model is exact, however strong the ground (Shenton).
  for (const double A : {0.31, 0.5, 2.0, -3.0}) EXPECT_EQ(chosen(0.3, A), Model::newmark_sliding);
  EXPECT_EQ(chosen(0.0, 0.1), Model::newmark_sliding);
  // mu = a/b is not below it, and mu above it can rock: full.
  EXPECT_EQ(chosen(0.5, 0.8), Model::full);
  EXPECT_EQ(chosen(0.7, 0.8), Model::full);
  // Friction above the peak lambda does not rule out sliding: still full once past a/b.
  EXPECT_EQ(chosen(2.0, 0.8), Model::full);
}

TEST(ChooseModel, APolygonPrunesByItsEasierCorner) {
  // docs/references.md, "Polygon blocks": the right triangle with legs 3 and 4 has tip thresholds
  // 0.75 (left) and 1.5 (right), and flat-sliding limit min = 0.75. mu = 0.6 < 0.75: only slides
  // once |lambda| > 0.6; mu = 1 lies between the thresholds and can rock about the left corner.
  Scene scene;
  scene.polygon = PolygonBlock{{{0, 0}, {3, 0}, {0, 4}}, 1.0};
  const auto choose = [&](double mu, double A) {
    scene.contact.friction = mu;
    scene.ground_motion = RectangularPulse{A, 1.0};
    return choose_model(scene, GroundMotionPieces(scene.ground_motion), scene_geometry(scene));
  };
  EXPECT_EQ(choose(0.6, 0.59), Model::at_rest);
  EXPECT_EQ(choose(0.6, 0.7), Model::newmark_sliding);
  EXPECT_EQ(choose(0.6, -2.0), Model::newmark_sliding);
  EXPECT_EQ(choose(1.0, 0.74), Model::at_rest);
  EXPECT_EQ(choose(1.0, 0.76), Model::full);
}

TEST(ChooseModel, ABlockReleasedTiltedIsAlreadyRocking) {
  Scene scene;
  scene.initial.theta = -0.1;
  scene.contact.friction = 0.3;  // would be Newmark's from rest under a pulse, at_rest without
  for (const GroundMotion& motion :
       {GroundMotion{NoMotion{}}, GroundMotion{RectangularPulse{0.4, 1.0}}}) {
    scene.ground_motion = motion;
    EXPECT_EQ(choose_model(scene, GroundMotionPieces(motion), BlockGeometry(scene.block)),
              Model::full);
  }
}

TEST(ChooseModel, NamedEffectsAreTakenAsTheyAre) {
  // No pruning: Housner's model at lambda below a/b, the full model where Newmark's would do.
  EXPECT_EQ(chosen(0.6, 0.1, named(true, false, true, false)), Model::housner_rocking);
  EXPECT_EQ(chosen(0.3, 0.4, named(true, true, true, true)), Model::full);
  EXPECT_EQ(chosen(0.6, 0.1, named(false, true, false, false)), Model::newmark_sliding);
  EXPECT_THROW(chosen(0.6, 0.1, named(true, true, false, false)), InvalidInput);
}

TEST(ChooseModel, VerticalMotionRunsTheFullVerticalModel) {
  // Even where the horizontal motion alone would leave the block at rest or only sliding.
  for (const double mu : {0.6, 0.3}) {
    Scene scene;
    scene.contact.friction = mu;
    scene.ground_motion = RectangularPulse{0.1, 1.0};
    scene.vertical_motion = SinePulse{0.2, 1.0, 1.0};
    scene.effects = named(true, true, true, true, true);
    EXPECT_EQ(
        choose_model(scene, GroundMotionPieces(scene.ground_motion), BlockGeometry(scene.block)),
        Model::full_vertical)
        << "mu = " << mu;
    scene.effects = Effects{};
    EXPECT_EQ(
        choose_model(scene, GroundMotionPieces(scene.ground_motion), BlockGeometry(scene.block)),
        Model::full_vertical)
        << "mu = " << mu;
  }
}

}  // namespace
}  // namespace blockfrag
