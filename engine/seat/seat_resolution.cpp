// What happens on a seat at an event: the contacts that touch, impacts, settling or laying the
// block on its contacts, and the contact states the complementarity problem chooses.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "engine/contact/planar_impact.hpp"
#include "engine/contact/rocking_restitution.hpp"
#include "engine/errors.hpp"
#include "engine/seat/level_rest_range.hpp"
#include "engine/seat/seat_ground.hpp"
#include "engine/seat/seated_load.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

std::vector<SeatPair> SeatSimulation::touching(const BlockState& s,
                                               const EventReport& report) const {
  const double tight = kContactHeight * R_;
  std::vector<SeatPair> out;
  out.reserve(static_cast<std::size_t>(kMaxSeatContacts));
  std::optional<SeatPair> left;
  if (report.force && report.force->event == SeatEvent::leaves_end) left = report.force->pair;
  for (const SeatPair& pair :
       contacts_.touching(s, kSeatContactDrift * R_, left, report.arrived_point)) {
    const bool was_active = std::any_of(mode_.active.begin(), mode_.active.end(),
                                        [&](const ActiveContact& a) { return a.pair == pair; });
    // Another pair touches when it is closer than a new contact's tolerance, or in the seat (a
    // drifted contact can leave a vertex under the line of the segment it has just left).
    if (was_active || contacts_.pose(pair, s).gap <= tight) out.push_back(pair);
  }
  if (out.size() > static_cast<std::size_t>(kMaxSeatContacts)) {
    throw SimulationFailure("more than " + std::to_string(kMaxSeatContacts) +
                            " contacts with the seat at once at t = " + std::to_string(t_) + " s");
  }
  return out;
}

SeatSimulation::Approach SeatSimulation::fastest_approach(
    const std::vector<PlanarContact>& contacts, const BlockState& s) const {
  Approach approach{contacts, 0.0, -1};
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const double u_n = contact_velocity(contacts[i], velocity_of(s)).normal;
    if (u_n < -velocity_tol_ && u_n < approach.fastest) {
      approach.fastest = u_n;
      approach.first = static_cast<int>(i);
    }
  }
  return approach;
}

void SeatSimulation::landing_impact(BlockState& s, const Approach& approach,
                                    const BlockState& start, const BodyInertia& inertia) {
  const double mu = scene_.contact.friction;
  const std::vector<PlanarContact>& all = approach.all;
  const int first = approach.first;
  const double e =
      landing_restitution(scene_.contact.restitution, approach.fastest, settle_velocity());
  set_velocity(s, velocity_after_impact(all[static_cast<std::size_t>(first)], velocity_of(s),
                                        inertia, mu, e, R_));
  // The paper's law at the contact that hits first, as on the flat ground; when that drives
  // another touching contact into the seat (a flat landing), all take their impulses together.
  bool others_approach = false;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (static_cast<int>(i) == first) continue;
    others_approach =
        others_approach || contact_velocity(all[i], velocity_of(s)).normal < -velocity_tol_;
  }
  if (others_approach) {
    const PlanarImpact together =
        simultaneous_impact({all, velocity_of(start), inertia, mu, e, R_});
    if (together.determinacy != Determinacy::unique) ++summary_.painleve_events;
    // No consistent choice of impulses together (two pairs of one contact point, a block vertex
    // on a seat point, whose geometries differ by the contact tolerance): the first contact's
    // impact stands, and the next round takes any contact it leaves approaching.
    if (together.determinacy != Determinacy::inconsistent) {
      s = start;
      set_velocity(s, together.after);
    }
  }
}

bool SeatSimulation::resolve_impacts(BlockState& s, const std::vector<SeatPair>& pairs,
                                     bool& impacted) {
  const double mu = scene_.contact.friction;
  // An impact changes the velocity alone, so the pairs' contacts are posed once for every round;
  // laying the block, which moves it, ends the rounds.
  std::vector<PlanarContact> contacts;
  contacts.reserve(pairs.size());
  for (const SeatPair& pair : pairs) contacts.push_back(contact_of(pair, s));
  for (int round = 0; round < kMaxImpactRounds; ++round) {
    const Approach approach = fastest_approach(contacts, s);
    const double fastest = approach.fastest;
    const int first = approach.first;
    if (first < 0) return true;
    impacted = true;
    if (round == 0) {
      ++summary_.impacts;
      if (!summary_.first_impact_time) summary_.first_impact_time = t_;
    }
    const double before = kinetic_energy(s);
    const BlockState start = s;
    const BodyInertia inertia = load_at(t_, s).inertia;
    // A landing slower than the settling speed while another contact touches lays the block on
    // its contacts, their slip kept: the flat ground's rule for a corner landing that slowly while
    // the other touches (it lays the block flat). Taken as an impact, the landing is plastic and
    // the other contact, turning about it, can leave faster than the settling speed: a chain of
    // ever smaller bounces that the flat ground ends would go on.
    const bool laid = pairs.size() >= 2 && -fastest < settle_velocity();
    // A rocking impact takes the scene's rocking restitution where it sets one, as on the flat
    // ground (engine/contact/rocking_restitution.hpp).
    const auto& rocking_restitution = scene_.contact.rocking_restitution;
    const auto rocking =
        laid || !rocking_restitution
            ? std::nullopt
            : rocking_impact({approach.all, static_cast<std::size_t>(first), velocity_of(s),
                              inertia.k2, mu, velocity_tol_, *rocking_restitution});
    if (laid) {
      lay_on(pairs, s);
    } else if (rocking) {
      set_velocity(s, rocking->after);
    } else {
      landing_impact(s, approach, start, inertia);
    }
    const double after = kinetic_energy(s);
    if (before > 0) {
      summary_.max_impact_energy_gain =
          std::max(summary_.max_impact_energy_gain, (after - before) / before);
    }
    if (log_impacts_) {
      impact_log_.push_back({t_, start.omega, s.omega, before, after, ModeKind::flight});
    }
    if (laid) return true;
  }
  return false;
}

// Whether the fastest of the pairs that approach the seat lands plastically (none approaching: no):
// where it would bounce off slower than the settling speed (settling.hpp), as on the flat ground. A
// fold vertex of the type B block, sliding and turning in flight, bounced at e = 0.3 in flights of
// 2e-6 s, was found 1e-11 m inside the seat after each and landed again as fast as before, without
// end (record suite sample 116). A rocking impact under the scene's rocking restitution also
// leaves its landing point still, whatever e is.
bool SeatSimulation::plastic_landing(const std::vector<SeatPair>& pairs) {
  double fastest = 0.0;
  std::vector<PlanarContact> contacts;
  std::size_t landing = 0;
  for (const SeatPair& pair : pairs) {
    contacts.push_back(contact_of(pair, state_));
    const double u_n = contact_velocity(contacts.back(), velocity_of(state_)).normal;
    if (u_n < fastest) {
      fastest = u_n;
      landing = contacts.size() - 1;
    }
  }
  if (!(fastest < -velocity_tol_)) return false;
  if (lands_plastically(scene_.contact.restitution, fastest, settle_velocity())) return true;
  const auto& rocking = scene_.contact.rocking_restitution;
  return rocking &&
         rocking_impact({contacts, landing, velocity_of(state_), geometry_.inertia_per_mass(),
                         scene_.contact.friction, velocity_tol_, *rocking});
}

// At an event: the contacts that touch are put back where the drift left them, impacts while one
// approaches, the block settled or laid on its contacts, then the contact states of the
// complementarity problem over those that carry force.
SeatMode SeatSimulation::resolve(const EventReport& report) {
  std::vector<SeatPair> found;
  if (!report.touching) found = touching(state_, report);
  const std::vector<SeatPair>& pairs = report.touching ? *report.touching : found;
  put_back_on_held_contacts(pairs);
  const std::size_t logged = impact_log_.size();
  BlockState s = state_;
  bool impacted = false;
  if (!resolve_impacts(s, pairs, impacted)) {
    throw SimulationFailure("impacts on the seat do not end at t = " + std::to_string(t_) + " s");
  }
  settle_or_lay(s, pairs, impacted);
  state_ = s;
  SeatMode mode = contact_states(pairs, report, logged);
  if (!report.force || report.force->event != SeatEvent::leaves_end) return mode;
  // Where a block vertex on a seat point left the seat through one pair's end, the other pair
  // there touches within the drift's tolerance; slipping on past its own end, it would leave at
  // once, the first pair touch again, and the block swap between the two every 1e-8 s without
  // moving (the type B block slipping off the seat's upstream end as it turns about its heel).
  const auto leaving = std::find_if(mode.active.begin(), mode.active.end(), [&](const auto& a) {
    return contacts_.leaves_with(report.force->pair, a.pair, slip_sign(a.state), state_);
  });
  if (leaving == mode.active.end()) return mode;
  std::vector<SeatPair> staying = pairs;
  std::erase(staying, leaving->pair);
  return contact_states(staying, report, logged);
}

// The contact states over the touching pairs that carry force, from the complementarity problem
// at state_.
SeatMode SeatSimulation::contact_states(const std::vector<SeatPair>& pairs,
                                        const EventReport& report, std::size_t logged) {
  const BlockState& s = state_;
  CarryingContacts carrying = carrying_contacts(pairs);
  if (carrying.pairs.empty()) return logged_mode(SeatMode{}, logged);
  const bool still = std::abs(s.vx) <= velocity_tol_ && std::abs(s.vy) <= velocity_tol_ &&
                     R_ * std::abs(s.omega) <= velocity_tol_;
  if (still && !report.force && !report.rest_ended && rests_inside_level_range(carrying.problem)) {
    return logged_mode(rest_on(carrying.pairs), logged);
  }
  PlanarForces forces = resolve_contact_forces(carrying.problem);
  if (forces.determinacy != Determinacy::unique) ++summary_.painleve_events;
  // Just past a lift-off or slip-start guard, or where rest ended, the block cannot stay put,
  // whatever the tolerance of the contact problem lets it choose: rest's range is of lambda over
  // the gravity factor 1 + lambda_v, the problem's tolerance of the accelerations, and under a
  // factor below 1 the problem can still find rest just past the range's end
  // (RestEndingUnderAVerticalPulseStartsASlideAsOnTheFlatGround).
  if (still && holds_at_rest(forces, carrying.problem.tolerance) && !report.force &&
      !report.rest_ended) {
    return logged_mode(rest_on(carrying.pairs), logged);
  }
  if (still && pins_body(fixed_rows(carrying.pairs, forces.states, s), R_)) {
    forces = choice_that_moves(carrying.problem, report, forces);
  }
  SeatMode mode = states_after_guard(carrying.pairs, forces, report);
  // Each guard's state brings back the other's in a statically indeterminate set (a block nested
  // in the seat on four pairs: the heel's lift-off and the fold's friction limit took turns every
  // 1e-10 s while lambda crept on): rest is decided over all the pairs at once, as at rest's start.
  if (still && swaps_back(mode, report)) {
    LcpDecompositions decompositions;
    if (rest_holds(carrying.pairs, motion_.lambda(t_) / gravity_factor(t_), decompositions)) {
      return logged_mode(rest_on(carrying.pairs), logged);
    }
  }
  mode.pinned = pins_body(fixed_rows(mode), R_);
  return logged_mode(mode, logged);
}

bool SeatSimulation::swaps_back(const SeatMode& resolved, const EventReport& report) const {
  if (!report.force || (report.force->event != SeatEvent::lift_off &&
                        report.force->event != SeatEvent::friction_limit)) {
    return false;
  }
  const BlockState& s = state_;
  const BlockState& p = last_event_pose_;
  if (s.x != p.x || s.y != p.y || s.theta != p.theta) return false;
  if (resolved.active.size() != left_at_last_event_.size()) return false;
  return std::all_of(resolved.active.begin(), resolved.active.end(), [&](const ActiveContact& a) {
    return std::find(left_at_last_event_.begin(), left_at_last_event_.end(), a.pair) !=
           left_at_last_event_.end();
  });
}

// Between events the contacts hold only at the acceleration level: the integrator lets their gaps
// and velocities drift, to its tolerance, and the contact problem reads contact velocities against
// 1e-9 sqrt(g R), well below an adaptive solver's drift. So the state is put back on the contacts
// that were active and still touch before it is read: a drifted pivot does not count as leaving.
// A plastic landing while another contact holds is taken with every touching contact put back on
// the seat (positions only): the event's crossing leaves the landing corner a little inside the
// seat, and at e = 0 the potential energy each landing gave back from there kept landings going
// just above the settling speed without end (RockingLandingsAtZeroRestitutionEndAsOnTheFlatGround).
// A bouncing block is left where it is: raised out of the seat at every bounce, it would gain that
// energy.
void SeatSimulation::put_back_on_held_contacts(const std::vector<SeatPair>& pairs) {
  SeatMode holding;
  holding.rest = mode_.rest;
  for (const ActiveContact& a : mode_.active) {
    if (std::find(pairs.begin(), pairs.end(), a.pair) != pairs.end()) holding.active.push_back(a);
  }
  project(holding);
  if (!holding.active.empty() && plastic_landing(pairs)) {
    std::vector<ActiveContact> on_seat;
    for (const SeatPair& pair : pairs) on_seat.push_back({pair, ContactState::stick});
    project_positions(on_seat, state_);
  }
}

// An impact where two contacts or more touch, after which none of them moves faster than the
// settling speed, lays the block at rest (the flat ground's rule for a corner landing, or leaving
// after the impact, slower than that speed): it ends a Zeno sequence of ever smaller bounces in
// finite time, whatever the landing's speed, since a landing just faster than the settling speed
// that leaves the other contact slower would rock on in swings too small for the touch guard to
// see. A block that still slides along the seat is laid on its contacts instead, keeping its slip
// where that adds no kinetic energy (lay_on): laid at rest, a sliding block rocking from corner
// to corner in ever smaller swings would make an impact every microsecond without end
// (SlidingBlockRockingAtZeroRestitutionIsLaidOnTheSeat); left as it was, a block whose other
// corner lifts slower than the settling speed would rock on where the flat ground slides
// (ASlidingBlockLandingSlowlyIsLaidOnItsContactsWhateverItsRestitution).
void SeatSimulation::settle_or_lay(BlockState& s, const std::vector<SeatPair>& pairs,
                                   bool impacted) {
  bool landed = impacted && pairs.size() >= 2, sliding = false;
  const double settle = settle_velocity();
  for (const SeatPair& pair : pairs) {
    const ContactVelocity u = contact_velocity(contact_of(pair, s), velocity_of(s));
    landed = landed && std::abs(u.normal) <= settle;
    sliding = sliding || std::abs(u.tangent) > settle;
  }
  if (landed && !sliding) s.vx = s.vy = s.omega = 0.0;
  if (landed && sliding) {
    const double before = kinetic_energy(s);
    lay_on(pairs, s);
    if (before > 0) {
      summary_.max_impact_energy_gain =
          std::max(summary_.max_impact_energy_gain, (kinetic_energy(s) - before) / before);
    }
  }
}

// The touching contacts that can carry force (not leaving), and their contact problem at state_.
SeatSimulation::CarryingContacts SeatSimulation::carrying_contacts(
    const std::vector<SeatPair>& pairs) {
  std::vector<SeatPair> carrying_pairs;
  std::vector<PlanarContact> contacts;
  for (const SeatPair& pair : pairs) {
    const PlanarContact c = contact_of(pair, state_);
    if (contact_velocity(c, velocity_of(state_)).normal > velocity_tol_) continue;
    carrying_pairs.push_back(pair);
    contacts.push_back(c);
  }
  // A load that opens the seated crack opens it for the contacts that carry the block now (a
  // landing block's crack was open while it rocked), as at rest.
  const bool reseats = external_ != nullptr &&
                       external_->seated_crack() != SeatedCrack::unaffected && contacts.size() >= 2;
  const BodyLoad load =
      reseats ? seated_load({geometry_.inertia_per_mass(), motion_.lambda(t_), vertical_.lambda(t_),
                             scene_.g, scene_.contact.friction, external_},
                            state_, contacts,
                            std::vector<ContactState>(contacts.size(), ContactState::stick))
              : load_at(t_, state_);
  CarryingContacts carrying{std::move(carrying_pairs),
                            {std::move(contacts), velocity_of(state_), load.inertia, load.force,
                             scene_.contact.friction, velocity_tol_, scene_.g, R_}};
  carrying.problem.applied_moment = load.moment;
  return carrying;
}

// At rest every touching contact is kept: where rest ends is found on all of them.
SeatMode SeatSimulation::rest_on(const std::vector<SeatPair>& carrying) {
  SeatMode mode;
  mode.rest = true;
  for (const SeatPair& pair : carrying) mode.active.push_back({pair, ContactState::stick});
  state_.vx = state_.vy = state_.omega = 0.0;
  return mode;
}

// A still block that may not stay put (its rest has just ended, or a guard said a contact's force
// left its cone) moves the way the first choice that lets it says. The contact problem's tolerance
// also accepts choices that pin it, with forces a tolerance outside their cones; held there, the
// individual forces of a statically indeterminate set (two corners sticking on a flat seat) are
// not unique, the guards would follow one arbitrary distribution, and the block would swap which
// corner slips at every event without moving. Where rest ended the block is still laid exactly on
// its contacts, lambda kOnsetMargin past the end of rest's range: the choice is made at the
// tolerance that range was found at, since at the problem's own tolerance a block with mu = b / h
// exactly would take a rock its sticking pivot's friction cannot hold, 1e-12 g outside its cone,
// where the flat ground's closed forms slide it
// (RestEndingAtATieOfThresholdsSlidesAsOnTheFlatGround).
PlanarForces SeatSimulation::choice_that_moves(PlanarForcesInput problem, const EventReport& report,
                                               const PlanarForces& pinned) const {
  problem.must_move = true;
  if (report.rest_ended) problem.tolerance = kRestTolerance;
  PlanarForces moving = resolve_contact_forces(problem);
  if (moving.determinacy == Determinacy::inconsistent && report.rest_ended) {
    problem.tolerance = kContactProblemTolerance;
    moving = resolve_contact_forces(problem);
  }
  return moving.determinacy != Determinacy::inconsistent ? moving : pinned;
}

// The contact problem accepts forces a tolerance outside their cone (1e-9 g): just past the guard
// that said a contact's force left it, it can still choose the old state. The guard's crossing
// decides then, as the flat ground's closed forms do: the contact lifts off, or slips against its
// friction.
SeatMode SeatSimulation::states_after_guard(const std::vector<SeatPair>& carrying,
                                            const PlanarForces& forces,
                                            const EventReport& report) const {
  SeatMode mode;
  for (std::size_t i = 0; i < carrying.size(); ++i) {
    ContactState state = forces.states[i];
    if (report.force && report.force->pair == carrying[i]) {
      const auto before =
          std::find_if(mode_.active.begin(), mode_.active.end(),
                       [&](const ActiveContact& a) { return a.pair == carrying[i]; });
      if (before != mode_.active.end() && before->state == state) {
        if (report.force->event == SeatEvent::lift_off) {
          state = ContactState::off;
        } else if (state == ContactState::stick) {
          state = forces.tangent[i] > 0 ? ContactState::slip_negative : ContactState::slip_positive;
        }
      }
    }
    if (state != ContactState::off) mode.active.push_back({carrying[i], state});
  }
  return mode;
}

// The rows of the mode's fixed contact values: pinned where they leave the block no freedom.
std::vector<Eigen::RowVector3d> SeatSimulation::fixed_rows(const SeatMode& mode) const {
  std::vector<ContactState> states;
  std::vector<SeatPair> active;
  for (const ActiveContact& a : mode.active) {
    active.push_back(a.pair);
    states.push_back(a.state);
  }
  return fixed_rows(active, states, state_);
}

// The rows of the contact values held fixed in these states at the pose: each carrying contact's
// normal velocity, and a sticking one's tangential velocity.
std::vector<Eigen::RowVector3d> SeatSimulation::fixed_rows(const std::vector<SeatPair>& pairs,
                                                           const std::vector<ContactState>& states,
                                                           const BlockState& s) const {
  std::vector<Eigen::RowVector3d> rows;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (states[i] == ContactState::off) continue;
    const PlanarContact c = contact_of(pairs[i], s);
    rows.push_back(contact_row(c, c.normal));
    if (states[i] == ContactState::stick) rows.push_back(contact_row(c, contact_tangent(c)));
  }
  return rows;
}

SeatMode SeatSimulation::logged_mode(const SeatMode& mode, std::size_t logged) {
  for (std::size_t i = logged; i < impact_log_.size(); ++i)
    impact_log_[i].mode_after = kind_of(mode);
  return mode;
}

// Well inside the flat ground's rest range (level_rest_range) the contact problem's first
// consistent choice is every contact sticking, the block still: the rest it finds, without the
// problem's solves (a study's every scene starts so, and a settled one ends so). Near the range's
// ends the problem decides, at its own tolerance.
bool SeatSimulation::rests_inside_level_range(const PlanarForcesInput& problem) {
  if (external_ != nullptr) return false;
  const std::optional<RestRange> range = level_rest_range(problem.contacts, problem.friction);
  if (!range) return false;
  const double factor = gravity_factor(t_);
  const double lambda = motion_.lambda(t_) / factor;
  return factor > 0 && lambda > range->low + kLevelRestInside &&
         lambda < range->high - kLevelRestInside;
}

// No contact slips and the block does not accelerate (to the contact problem's tolerance, relative
// to g): the one test of rest, at an event and where rest's lambda range ends.
bool SeatSimulation::holds_at_rest(const PlanarForces& f, double relative_tolerance) const {
  const double tolerance = relative_tolerance * scene_.g;
  return std::none_of(f.states.begin(), f.states.end(), is_slip) &&
         std::abs(f.acceleration.x_dd) <= tolerance && std::abs(f.acceleration.y_dd) <= tolerance &&
         R_ * std::abs(f.acceleration.theta_dd) <= tolerance;
}

void SeatSimulation::enter(const SeatMode& next, const EventReport& report) {
  const bool first = summary_.modes.empty();
  const ModeKind before = kind_of(mode_);
  left_at_last_event_.clear();
  for (const ActiveContact& a : mode_.active) left_at_last_event_.push_back(a.pair);
  last_event_pose_ = state_;
  mode_ = next;
  project(mode_);
  if (mode_.rest) {
    // Laid on its contacts, a resting block can touch the seat where it did not at the event (a
    // corner a few 1e-9 R above it while the block was turned;
    // ACornerThatTouchesOnceTheBlockIsLaidAtRestCarriesItsRest).
    // Rest's range is found on every contact it rests on: found without one, it would end where
    // lambda changes sign, and the contacts, pinned, would swap which one slips without end.
    for (const SeatPair& pair : touching(state_, report)) {
      const bool active = std::any_of(mode_.active.begin(), mode_.active.end(),
                                      [&](const ActiveContact& a) { return a.pair == pair; });
      if (!active) mode_.active.push_back({pair, ContactState::stick});
    }
    set_rest_thresholds(mode_);
  }
  std::vector<std::pair<SeatPair, double>> anchors;
  for (const ActiveContact& a : mode_.active) {
    if (a.state != ContactState::stick || a.pair.kind != ContactKind::block_vertex) continue;
    anchors.emplace_back(a.pair, anchor_of(a.pair).value_or(contacts_.pose(a.pair, state_).along));
  }
  anchors_ = std::move(anchors);
  entered(before, kind_of(mode_), first, false);
}

}  // namespace blockfrag
