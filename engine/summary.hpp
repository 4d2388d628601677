// One simulation's outputs: what users judge a scene by, and what it cost.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace blockfrag {

enum class ModeKind { rest, slide, rock, slide_rock, flight };

const char* mode_name(ModeKind mode);

struct ModeChange {
  double time;
  ModeKind mode;
};

enum class Status { ok, failed };

// The model a scene ran: what its effects asked for, or what "auto" kept. at_rest: the ground never
// reaches a threshold, answered without integrating. full_vertical: the full model with vertical
// ground motion.
enum class Model { at_rest, newmark_sliding, housner_rocking, full, full_vertical };

const char* model_name(Model model);
// The effects the model simulates, e.g. {"rocking", "impact"}.
std::vector<const char*> model_effects(Model model);

// A scene with a reservoir: the block's static safety factors after the earthquake, at its final
// pose under full uplift over its crack (engine/water/block_statics.hpp); none when the block does
// not stand at rest at the end (it overturned, fell, failed, or still moves when a fixed duration
// ends); +inf when nothing drives it.
struct PostEarthquakeCheck {
  std::optional<double> sliding_safety_factor;
  std::optional<double> overturning_safety_factor;
};

struct Summary {
  Status status = Status::ok;
  std::string status_reason;  // empty when ok
  Model model = Model::full;

  bool overturned = false;
  std::optional<double> overturn_time;
  // The block went off a seat's end and dropped below it (engine/seat/seat_simulation.hpp);
  // never on the flat ground, which has no ends. Ends the run, as overturning does.
  bool fell = false;
  std::optional<double> fell_time;
  double max_abs_theta = 0.0;  // rad
  double final_theta = 0.0;    // rad
  double final_slide = 0.0;    // m, centre of mass relative to the ground, end minus start
  double max_abs_slide = 0.0;  // m
  std::optional<double> rock_start_time;   // first time a corner lifts
  std::optional<double> slide_start_time;  // first time a contact point slips
  std::optional<double> first_impact_time;
  long impacts = 0;
  std::vector<ModeChange> modes;
  // s, where the simulation stopped (duration, settling, overturning, falling)
  double end_time = 0.0;
  // The block's fate is final at the end: every excitation has ended and it rests on its base, or
  // it has overturned or fallen. settle_time: since when it rests for good (0 if it never moved),
  // or the overturning or falling time; none when not settled.
  bool settled = false;
  std::optional<double> settle_time;

  long steps = 0;
  long rhs_evaluations = 0;
  long events = 0;
  // The largest kinetic-energy gain over any impact, relative to the energy before it (<= 0 is
  // right).
  double max_impact_energy_gain = 0.0;
  // The largest breach of the contact laws at any step, per weight: max(-V, |F| - mu V) / (M g);
  // 0 when the contact force stayed in Coulomb's cone with V >= 0 throughout.
  double max_contact_violation = 0.0;
  // The deepest any corner of the block went below the ground at a step's end or at an extreme of
  // theta or x, over R: at most about the contact tolerance (1e-9), which lets a corner put on the
  // ground leave the other that far under.
  double max_penetration = 0.0;
  long painleve_events = 0;  // jams resolved by a tangential impulse, singular points passed
  std::optional<PostEarthquakeCheck> post_earthquake;  // with a reservoir only
};

// One impact event (all the corner impulses of one instant), for the history's impact log.
struct ImpactRecord {
  double time;
  double omega_before, omega_after;                    // rad/s
  double kinetic_energy_before, kinetic_energy_after;  // per unit mass, J/kg
  ModeKind mode_after;
};

// One row of the time history: the centre of mass relative to the ground, and the contact forces
// divided by the block's weight M g.
struct HistoryRow {
  double t, x, y, theta, vx, vy, omega;
  ModeKind mode;
  double friction_per_weight, normal_per_weight;
};

}  // namespace blockfrag
