// A scene whose block rests on a seat (engine/scene/seat.hpp): the general planar contact of
// engine/contact/planar_contact.hpp between events, its impacts at them (docs/physics.md,
// "Contact on a seat"). simulate() runs scenes with a seat here.
#pragma once

#include "engine/simulate.hpp"

namespace blockfrag {

// The scene must be valid and have a seat.
SimulationWithHistory simulate_on_seat(const Scene& scene, double output_interval);

}  // namespace blockfrag
