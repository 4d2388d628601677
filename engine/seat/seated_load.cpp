#include "engine/seat/seated_load.hpp"

#include <algorithm>
#include <cstddef>

#include "engine/contact/crack_seating.hpp"
#include "engine/seat/fixed_state_forces.hpp"

namespace blockfrag {

namespace {

// The loads' counter-clockwise moment about the contact's point, per unit mass.
double moment_about(const BodyLoad& load, const PlanarContact& c) {
  return load.moment - (c.r.x * load.force.y - c.r.y * load.force.x);
}

// The outermost contact that lifts and the one the block would turn about.
struct Lifting {
  LiftingSide side;
  std::size_t corner, pivot;
  double sense;  // the pivot's moment times sense presses the corner down where it is >= 0
};

Lifting lifting_at(bool heel_lifts, std::size_t upstream, std::size_t downstream) {
  return heel_lifts ? Lifting{LiftingSide::upstream, upstream, downstream, 1.0}
                    : Lifting{LiftingSide::downstream, downstream, upstream, -1.0};
}

// The load with the crack opened as far as the lifting corner needs, found on the openings the
// external load gives at the state (ExternalLoad::search_openings).
class OpeningSearch final : public CrackOpeningSearch {
 public:
  OpeningSearch(const SeatedLoadInput& in, const BlockState& s,
                std::span<const PlanarContact> contacts, std::span<const ContactState> states,
                Lifting lifting, bool held, SeatedCrack crack)
      : in_(in),
        s_(s),
        contacts_(contacts),
        states_(states),
        lifting_(lifting),
        held_(held),
        crack_(crack),
        found_{{0.0, 0.0}, 0.0, in.inertia_per_mass} {}

  void search(const CrackOpenings& openings) override {
    const auto opened = [&](double fraction) {
      return seated_body_load(in_.inertia_per_mass, in_.lambda, in_.lambda_v, in_.g, openings,
                              lifting_.side, fraction);
    };
    const auto quasi_static = [&] {
      return seating_opening([&](double f) {
        return lifting_.sense * moment_about(opened(f), contacts_[lifting_.pivot]);
      });
    };
    if (held_) {
      found_ = opened(quasi_static());
      return;
    }
    const auto corner_force = [&](double fraction) {
      return fixed_state_forces(contacts_, states_, s_, opened(fraction), in_.mu)
          .normal[lifting_.corner];
    };
    // Filled with the full head, the opening lifts the corner further at rest, and seats a
    // slipping one only where it lightens the friction that tips the block onto its other corner:
    // the least opening that seats it is looked for over the whole crack.
    const double reach = crack_ == SeatedCrack::fills ? 1.0 : quasi_static();
    found_ =
        !(corner_force(reach) >= 0.0)
            ? opened(reach)
            : opened(reach * seating_opening([&](double x) { return corner_force(x * reach); }));
  }
  const BodyLoad& found() const { return found_; }

 private:
  const SeatedLoadInput& in_;
  const BlockState& s_;
  std::span<const PlanarContact> contacts_;
  std::span<const ContactState> states_;
  Lifting lifting_;
  bool held_;
  SeatedCrack crack_;
  BodyLoad found_;
};

}  // namespace

BodyLoad seated_load(const SeatedLoadInput& in, const BlockState& s,
                     std::span<const PlanarContact> contacts,
                     std::span<const ContactState> states) {
  const BodyLoad closed =
      body_load(in.inertia_per_mass, in.lambda, in.lambda_v, in.g, in.external, s, Footing::seated);
  const SeatedCrack crack =
      in.external == nullptr ? SeatedCrack::unaffected : in.external->seated_crack();
  if (crack == SeatedCrack::unaffected || contacts.size() < 2) {
    return closed;
  }
  std::size_t upstream = 0, downstream = 0;
  for (std::size_t i = 1; i < contacts.size(); ++i) {
    if (contacts[i].r.x < contacts[upstream].r.x) upstream = i;
    if (contacts[i].r.x > contacts[downstream].r.x) downstream = i;
  }
  const bool held = std::all_of(states.begin(), states.end(),
                                [](ContactState c) { return c == ContactState::stick; });
  Lifting lifting{};
  if (held) {
    // At rest the forces of three contacts or more are not unique: a corner lifts where the loads
    // turn the block about the other outermost contact, as in the statics.
    const bool heel_lifts = moment_about(closed, contacts[downstream]) < 0.0;
    if (!heel_lifts && !(moment_about(closed, contacts[upstream]) > 0.0)) return closed;
    lifting = lifting_at(heel_lifts, upstream, downstream);
  } else {
    const FixedStateForces forces = fixed_state_forces(contacts, states, s, closed, in.mu);
    const double heel = forces.normal[upstream], toe = forces.normal[downstream];
    if (heel >= 0.0 && toe >= 0.0) return closed;
    lifting = lifting_at(heel <= toe, upstream, downstream);
  }
  OpeningSearch search(in, s, contacts, states, lifting, held, crack);
  in.external->search_openings(s, in.lambda, in.g, search);
  return search.found();
}

}  // namespace blockfrag
