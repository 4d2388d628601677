// Every tolerance, margin and budget of the engine, with its unit and why it has its value.
// Lengths are over the block's size R (its largest corner distance from the centre of mass),
// velocities over sqrt(g R), times in s unless a line says otherwise; guards are dimensionless.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace blockfrag {

// --- Contact: when a corner touches, rests, settles ---------------------------------------------
// A corner this close to the ground (over R) touches it. Above the integrators' round-off in a
// corner's height, below any lift that matters.
inline constexpr double kContactHeight = 1e-9;
// A touching corner slower than this (over sqrt(g R)) rests or slips on the ground: no impact.
inline constexpr double kRestingVelocity = 1e-9;
// An impact whose rebound would be slower than this (over sqrt(g R)) loses its bounce (e = 0), and
// one slower than this that would leave a flat block rocking or bouncing lays it flat: ends Zeno
// sequences in finite time. g is the gravity the block feels, g (1 + lambda_v). A corner leaving
// the ground at v rises v^2 / (2 g): at this speed, within the contact height, so the bounces the
// rule ends are ones whose flight no event could tell from touching. The energy left out is
// below g kContactHeight R per unit mass.
inline constexpr double kSettleVelocity = 4.47e-5;
static_assert(kSettleVelocity * kSettleVelocity / 2 <= kContactHeight);
// Impacts at one instant, one corner at a time, before the resolution gives up (a flat block's
// two corners settle in a few rounds; more means the impact law does not converge).
inline constexpr int kMaxImpactRounds = 64;
// Slide-rock ends this close to the Painleve boundary (its theta'' denominator over I/M): as it
// closes in, theta'' and V grow without bound and the contact jams into stick by a tangential
// impulse.
inline constexpr double kPainleveMargin = 1e-6;
// Relative rounding allowed in the impact laws' comparisons (energy before and after, an impulse
// on the friction cone's edge, stick needing exactly mu V): a few hundred ulps of the values
// compared, far below any physical difference.
inline constexpr double kImpactRounding = 1e-12;
// Relative to g: accelerations this close count as equal, forces this far outside their cones
// as inside, in the contact problem between events. Loose enough for the drift of an integrated
// state between events; a question asked of a state laid exactly on its contacts (where rest ends)
// can ask it tighter (kRestTolerance).
inline constexpr double kContactProblemTolerance = 1e-9;
// Consistent choices of the contact problem whose results differ by less than this many of its
// tolerances are the same motion (a statically indeterminate set's force distributions, a tie at a
// friction cone's edge).
inline constexpr double kSameContactResult = 1e3;
// Relative to the fastest contact speed: a simultaneous impact's velocities this close count as
// equal.
inline constexpr double kImpactVelocityTolerance = 1e-9;
// Halvings of the restitution coefficient that find the largest one whose simultaneous impact adds
// no kinetic energy: 2^-30 of e, below 1e-9.
inline constexpr int kRestitutionHalvings = 30;
// A pivot of the flat ground's two-contact impact (a 3 x 3 elimination) this small: the system has
// no unique solution.
inline constexpr double kSingularPivot = 1e-300;
// Gravity in the ground's frame (over g, 1 + lambda_v) where it is exactly zero: the contact has
// lost its load there, and any tiny value of the right sign gives the same guard outcome without
// dividing by zero.
inline constexpr double kLostLoadGravityFactor = 1e-300;

// --- A seat: contacts that drift, blocks that fall ----------------------------------------------
// An active contact on a seat whose gap has drifted this far (over R) while its mode was
// integrated still touches at the next event, where it is projected back: the seat's modes
// integrate x, y and theta with the contacts held at the acceleration level only.
inline constexpr double kSeatContactDrift = 1e-6;
// A block past a seat's end whose lowest vertex has dropped this far (over R) below that end has
// fallen off the seat: nothing under it can catch it.
inline constexpr double kFallDepth = 0.5;
// Where rest on a seat ends: lambda is searched up to this (in g) for the thresholds; rest that
// holds beyond it holds for any lambda.
inline constexpr double kRestSearchLimit = 1024.0;
// The flat ground under a reservoir runs as a seat of one segment this many block sizes either side
// of the block (engine/water/reservoir_load.cpp): far past any slide a ground motion gives.
inline constexpr double kFlatSeatHalfLength = 1e4;
// A seat's simulation watches each block vertex and seat point not in contact for touching, one
// guard each in a fixed array (engine/seat/seat_system.hpp): a scene on a seat has at most this
// many together.
inline constexpr int kMaxSeatClearances = 38;

// Gauss-Newton iterations that put the active contacts' gaps back to zero after an event.
inline constexpr int kProjectionIterations = 4;
// Halvings of the lambda interval that bracket where rest on a seat ends.
inline constexpr int kRestThresholdHalvings = 64;
// Relative to g: the contact problem's tolerance (a force outside its cone, an acceleration taken
// for none) where rest's lambda range is found, a tenth of the margin by which rest ends past it.
// The block at rest is laid exactly on its contacts, so the problem's forces there are exact to
// rounding (a few 1e-16 g); at its tolerance between events, 1e-9 g, rest held past its range by
// 3e-9 of lambda (the block pivoting with an acceleration below 1e-9 g counted as still), and the
// block started to rock a few 1e-9 s after the flat ground's closed-form onset, which is
// kOnsetMargin past its threshold.
inline constexpr double kRestTolerance = 1e-13;
// How far inside the flat ground's rest range (in lambda) a still block on a level line is taken
// to rest without the contact problem: well past where its tolerance (kContactProblemTolerance)
// could choose otherwise.
inline constexpr double kLevelRestInside = 1e-6;
// A contact problem's column subset solved by its solve matrix rather than its QR (to skip the
// subsets that surely fail): only where the columns' condition is at most kMaxScreenedCondition
// (the type B block's are below 340), and trusted where its answer fails a check by more than
// kClearlyFailing of its size, some 450 times the two solves' difference at that condition.
inline constexpr double kMaxScreenedCondition = 1e4;
// Relative room for rounding in the seat's geometric shortcuts: a point beside an edge's ends, or
// a seat point or end beyond the block's reach, by more than this fraction of the sizes compared
// is beside or beyond it without the exact test (many ulps, far below any contact height).
inline constexpr double kGeometryRounding = 1e-9;
inline constexpr double kClearlyFailing = 1e-9;
// Two seat segments whose directions' cross product is within this of zero (and whose lines are
// within the contact height) are on one line: a flat seat given as a polyline rounds to 1e-16.
inline constexpr double kCollinearSine = 1e-12;
// Two block edges at a vertex whose normals' nearness to the seat's upward direction differs by
// less than this (times that direction's length) are equally near it: a tilt of the block by about
// this much (rad) would swap them.
inline constexpr double kEdgeNormalTie = 1e-6;
// A block vertex whose direction from a vertex carrying the block on a line is within this sine of
// a hull edge's there (or of the carrying chain's) is watched for touching although that edge's far
// end is (engine/seat/hull_watch.hpp): on that edge (a non-convex block's vertex there) or nearly,
// it touches at the instant the far end does, or within the carrying contacts' drift
// (kSeatContactDrift) of it, and rounding would choose which of the two a step finds first.
inline constexpr double kHullEdgeSine = 1e-3;
// A seat point's rates along the two block edges at a vertex, below this fraction of the sum of the
// contact velocities there, are the velocities' rounding: they say nothing about where it goes.
inline constexpr double kSeatPointRateRounding = 1e-9;
// A vertex this close to a seat's end (over R) may pass it, where its clearance becomes its
// distance from the end.
inline constexpr double kSeatEndMargin = 1e-9;
// A seat point this close to a block edge's line (over R) may be on the edge: its distance's
// sinusoid is not told from zero.
inline constexpr double kSeatLineMargin = 1e-12;
// A step's range of theta is widened by this (rad) either way where it asks whether a sinusoid's
// minimum lies in it: rounding moves where the slope changes sign by a few ulps.
inline constexpr double kThetaStepMarginRad = 1e-9;
// A seat carries the block's weight at rest when a combination of its contacts' wrenches with
// non-negative weights matches the weight to this, relative to the weight; two of its contacts'
// unit normals this close (the sum of their components' differences) are one direction.
inline constexpr double kCarriedWeightResidual = 1e-9;
inline constexpr double kSameSeatNormal = 1e-12;
// Two supports' unit normals this close (the length of their difference) are one direction where
// the block's statics under water look for the lines it can slide along.
inline constexpr double kSameSupportDirection = 1e-9;

// --- Events: where a mode ends -------------------------------------------------------------------
// A guard this close to zero when a mode starts is armed only once it has moved away: the event
// that started the mode left it there.
inline constexpr double kArmingMargin = 1e-12;
// A guard that starts below -kArmingMargin must fall this much further (relative to its start)
// before it fires: the event that ended the last mode left it there.
inline constexpr double kUnarmedFurtherDrop = 1e-9;
// Guards within this of zero at either end of a step are looked at inside it, at this many
// equally spaced samples: a corner can dip below the ground and come back within one step.
inline constexpr double kNearZero = 0.05;
inline constexpr int kInteriorSamples = 16;
// Event times are located to this relative accuracy (of 1 + t): a few ulps of t.
inline constexpr double kEventTimeTolerance = 1e-15;
// A time within this relative distance (of max(1, |end|)) of the end of a stretch has reached it:
// a step that short cannot advance t.
inline constexpr double kReachedEnd = 1e-14;
inline bool reached(double t, double end) {
  return end - t <= kReachedEnd * std::max(1.0, std::abs(end));
}
// Rest ends where lambda is past a threshold by this much (in units of lambda), so the modes it
// leads to see an unambiguous sign; a pulse that only grazes a threshold leaves the block at rest.
inline constexpr double kOnsetMargin = 1e-12;
// A search for a guard's crossing or a corner's landing stops after this many steps with the
// bracket it has: a safeguard for a bracket that stops narrowing (a guard noisy at the tolerance).
inline constexpr int kMaxBracketSteps = 200;
// A corner's landing in closed-form flight is located to this relative accuracy (of 1 + its time
// from the flight's start, s): two ulps, since its height is exact to rounding.
inline constexpr double kLandingTimeTolerance = 4e-16;
// An extremum of theta or x inside a step is located to this fraction of the step: they are flat
// there, so a time error dt changes them by O(dt^2).
inline constexpr double kStateExtremumTimeTolerance = 1e-8;
// A fixed-step method that crosses an event retakes the step, ending this fraction of the
// remainder past the located event.
inline constexpr double kRetakeOvershoot = 0.01;

// --- Steps ---------------------------------------------------------------------------------------
// No step is longer than 1/16 of a motion piece's time scale (a pulse's quarter period, a record's
// sample interval): the dense output then resolves the motion's shape between events.
inline constexpr double kStepsPerPieceTimeScale = 16.0;
// Rest under vertical motion looks at the thresholds every 1/64 of the faster piece's time scale.
inline constexpr double kRestChecksPerTimeScale = 64.0;
// No step is longer than half the block's time scale sqrt(R/g).
inline constexpr double kMaxStepOverBlockTime = 0.5;
// The adaptive stepper fails a step shorter than this many ulps of t (it cannot usefully be
// shorter) or after this many consecutive rejections (each shrinks the step by at least 10%: a
// controller that needs more is not converging).
inline constexpr double kMinStepUlps = 16.0;
inline constexpr int kMaxConsecutiveRejections = 100;
// The closed-form landing search in flight steps at least this (over sqrt(R/g)).
inline constexpr double kFlightMinStep = 1e-4;
// A corner that starts a flight at the ground may sink this far (over R) before it is seen landing
// (the guards' arming margin).
inline constexpr double kLandingSinkAllowance = 1e-12;

// --- Ground motion: where a pulse's lambda has its extremes --------------------------------------
// Extremes without a closed form (the Mavroeidis-Papageorgiou pulse) are searched in cells of 1/64
// of the fastest period, each proved empty or searched by the bound on the slope's derivative; a
// maximum and minimum this close in lambda (over the pulse's scale) are one flat point, far below
// the onset margin above; a zero of the slope is located to this fraction of the slope's largest
// change over a cell.
inline constexpr double kExtremumCellsPerPeriod = 64.0;
inline constexpr double kNegligibleExtremumPair = 1e-15;
inline constexpr double kSlopeZeroTolerance = 1e-12;
// A cell is proved empty of zeros only where its ends' values exceed by this factor (beside their
// round-off) what the slope's bound lets them reach: a bound that is attained must not prove too
// much.
inline constexpr double kSlopeBoundFactor = 1.001;
// A dam's crest history has this many nodes per period of the fastest thing it carries (the
// foundation's oscillation or the dam's own ringing): a sinusoid drawn linearly between nodes h
// apart errs by at most (omega h)^2 / 8 of its amplitude, 5e-4 at 100 nodes per period. The same
// bound covers sampling a smooth foundation piece as linear segments for the filter.
inline constexpr double kCrestNodesPerPeriod = 100.0;

// The dam's modal oscillator steps by a third-order Taylor series below this omega h: there the
// closed-form coefficients lose more digits to cancellation (terms of size 1 / (omega^2 h) cancel
// down to h) than the Taylor step loses to truncation ((omega h)^3): about 2e-12 against 2e-13 of
// the state's scale.
inline constexpr double kTaylorBelow = 1e-4;

// --- Intensity measures (engine/motion/intensity_measures.hpp) -----------------------------------
// The D5-95 crossings are located to this fraction of their piece's length (a cubic or a closed
// form bisected): below any sampling interval of a record or period of a pulse.
inline constexpr double kDurationCrossingTolerance = 1e-12;
// An extremum of the oscillator's u inside a step is located to this fraction of the step: u is
// flat there, so a time off by delta changes u by |u''| delta^2 / 2, with |u''| = |a + omega^2 u|
// at the extremum: at most 2e-21 (1 + PGA / Sa) of |u| with h = T / 100.
inline constexpr double kSpectrumExtremumTimeTolerance = 1e-9;
// A maximum and a minimum of the ground velocity this close (over the pulse's velocity scale,
// peak |lambda| g / omega) are one flat point: far below every other error here.
inline constexpr double kNegligibleVelocityPair = 1e-15;

// --- Rounding: comparisons of values computed two ways -------------------------------------------
// A history row due at time t belongs to the step that ends within this relative distance of t.
inline constexpr double kOutputTimeRounding = 1e-15;
// A record resampled onto a step grid keeps a last sample within this relative distance of a grid
// point; a given pulse start t0 within this of its lower bound is at the bound.
inline constexpr double kGridRounding = 1e-12;
// A record's sample time within this relative distance (of the larger of it and the step) of a
// multiple of a fixed step is on that step's grid: the times' decimal digits carry rounding, and
// RK4 steps the record without resampling it.
inline constexpr double kStepGridRounding = 1e-9;
// The reservoir's pass at a pose skips an edge whose rise (its turned y, before the block's
// height is added) is above this fraction of the centre of mass's height plus the outline's
// reach: placing a vertex errs by a few units in the last place of those (~1e-16 of them), so
// such an edge's placed ends rise too and it is dry where the full pass would find it dry.
inline constexpr double kSurelyRisingEdge = 1e-12;

// --- Settling: the run without a duration -------------------------------------------------------
// A run that has not settled stops this long after the last excitation ends (unless the scene
// gives max_duration): a rocking block with e < 1 settles within seconds; one with e = 1 never
// does.
inline constexpr double kSettleAllowance = 60.0;  // s
// The dam's ringing has ended once the crest's acceleration is below this (in g): a thousand times
// below any friction or tipping threshold of a real block.
inline constexpr double kRingingEndAccelerationG = 1e-6;

// --- Budgets: what stops a scene that does not end -----------------------------------------------
// The defaults of a scene's max_steps and max_events: far above any real scene (a 600 s record with
// 20,000 impacts takes under 2 million steps), so only a pathology reaches them.
inline constexpr long kDefaultMaxSteps = 50'000'000;
inline constexpr long kDefaultMaxEvents = 1'000'000;
// The step budget is checked every this many steps (and at every event): a power of two minus
// one, masked.
inline constexpr long kBudgetCheckMask = 1023;
// Sa's steps (period / 100 each) before it refuses a motion (InvalidInput): a few seconds of work.
// A 10 ms oscillator under a 100 s record takes a million.
inline constexpr long kMaxSpectrumSteps = 200'000'000;
// Too many nodes would exhaust memory before the block moves: a dam period far shorter than the
// scene's duration (period / 100 per node) is refused with InvalidInput.
inline constexpr std::size_t kMaxCrestNodes = 2'000'000;
// Contact changes within this (s, relative to 1 + t) are at one instant: a block held by several
// contacts, whose forces the contact problem cannot tell apart, can flip between its equally valid
// force distributions 4e-11 s apart, each a new time, at a millisecond of CPU each. Most such
// storms end within a few thousand changes; kMaxInstantEvents fails the scene ("no progress") at
// 100 s of CPU at most (engine/no_progress.hpp).
inline constexpr double kInstant = 1e-6;
inline constexpr int kMaxInstantEvents = 100'000;
// Events that leave the block at one pose, to the bit, in a row: a still block whose guards hand
// it back and forth between contact sets 1e-10 s apart spreads its changes wider than an instant
// as lambda creeps on, at 3 ms of CPU each (the contact problem over five pairs). This fails it
// within a minute, well before the event budget.
inline constexpr int kMaxStandstillEvents = 10'000;

}  // namespace blockfrag
