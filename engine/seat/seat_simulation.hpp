// A scene whose block rests on a seat (engine/scene/seat.hpp): the general planar contact of
// engine/contact/planar_contact.hpp between events, its impacts at them (docs/physics.md,
// "Contact on a seat"). simulate() runs scenes with a seat here.
#pragma once

#include "engine/contact/body_load.hpp"
#include "engine/simulate.hpp"

namespace blockfrag {

// The scene must be valid and have a seat. `external`: what acts on the block besides gravity, the
// ground and the seat (engine/contact/body_load.hpp); none: the dry block.
SimulationWithHistory simulate_on_seat(const Scene& scene, double output_interval,
                                       const ExternalLoad* external = nullptr);

}  // namespace blockfrag
