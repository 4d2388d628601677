// Westergaard's added mass in the equations of motion (engine/water/hydrodynamic_load.hpp): in
// free motion the block's and the water's kinetic energy plus gravity's potential energy stay
// constant between events, the water's being 1/2 q'^T A(y, theta) q' with A from the wetted face
// at each pose (engine/water/westergaard.hpp); and the added mass slows the rocking.
#include "engine/water/hydrodynamic_load.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "engine/seat/seat_simulation.hpp"
#include "engine/water/westergaard.hpp"

namespace blockfrag {
namespace {

// A concrete slice 1 m wide and 2 m high (2,400 kg/m^3) in a 100 m reservoir whose surface is at
// its top: the added mass, about 16,500 kg/m, is several times the block's 4,800 kg/m.
constexpr double kSliceHalfWidth = 0.5, kSliceHalfHeight = 1.0, kSliceMass = 4800.0;
constexpr double kWaterDensity = 1000.0, kReservoirDepth = 100.0, kSurface = 1.0;

WettedBlock wetted_slice() {
  return {{{-kSliceHalfWidth, -kSliceHalfHeight},
           {kSliceHalfWidth, -kSliceHalfHeight},
           {kSliceHalfWidth, kSliceHalfHeight},
           {-kSliceHalfWidth, kSliceHalfHeight}},
          {0},
          kSliceMass,
          std::hypot(kSliceHalfWidth, kSliceHalfHeight)};
}

Scene released_slice(double theta0) {
  Scene scene;
  scene.block = {kSliceHalfWidth, kSliceHalfHeight, kSliceMass};
  scene.contact = {2.0, 0.0};
  scene.seat = Seat{{{-50.0, -kSliceHalfHeight}, {50.0, -kSliceHalfHeight}}};
  scene.initial.theta = theta0;
  scene.duration = 1.5;
  scene.solver.tolerance = 1e-10;
  return scene;
}

// Per unit of the block's mass.
double energy(const HistoryRow& r, double g) {
  const WettedBlock slice = wetted_slice();
  const AddedMass a =
      westergaard_added_mass(world_polygon(slice.body, r.x, r.y, r.theta), kSurface, kWaterDensity,
                             kReservoirDepth, slice.crack_edges, r.y);
  const double k2 = (kSliceHalfWidth * kSliceHalfWidth + kSliceHalfHeight * kSliceHalfHeight) / 3;
  const double block = r.vx * r.vx + r.vy * r.vy + k2 * r.omega * r.omega;
  const double water = (a.mass * r.vx * r.vx - 2.0 * a.first_moment * r.vx * r.omega +
                        a.second_moment * r.omega * r.omega) /
                       kSliceMass;
  return 0.5 * (block + water) + g * r.y;
}

TEST(HydrodynamicLoad, FreeRockingKeepsBlockWaterAndGravityEnergy) {
  for (const double theta0 : {0.2, -0.2}) {  // about the upstream heel, then the downstream toe
    SCOPED_TRACE(theta0);
    const Scene scene = released_slice(theta0);
    const HydrodynamicLoad water(wetted_slice(), kSurface, kWaterDensity, kReservoirDepth);
    const SimulationWithHistory run = simulate_on_seat(scene, 0.01, &water);
    ASSERT_EQ(run.summary.status, Status::ok);
    ASSERT_TRUE(run.summary.first_impact_time.has_value());
    const double start = energy(run.history.front(), scene.g);
    const double drop =
        scene.g * std::hypot(kSliceHalfWidth, kSliceHalfHeight) *
        (std::cos(std::atan(kSliceHalfWidth / kSliceHalfHeight) - std::abs(theta0)) -
         std::cos(std::atan(kSliceHalfWidth / kSliceHalfHeight)));
    int checked = 0;
    double largest = 0.0;
    for (const HistoryRow& r : run.history) {
      if (r.t >= *run.summary.first_impact_time) break;
      largest = std::max(largest, std::abs(energy(r, scene.g) - start));
      ++checked;
    }
    EXPECT_GT(checked, 10);
    EXPECT_LT(largest, 1e-7 * drop);
  }
}

TEST(HydrodynamicLoad, TheAddedMassSlowsTheRocking) {
  const Scene scene = released_slice(0.2);
  const HydrodynamicLoad water(wetted_slice(), kSurface, kWaterDensity, kReservoirDepth);
  const Summary wet = simulate_on_seat(scene, 0.0, &water).summary;
  const Summary dry = simulate_on_seat(scene, 0.0).summary;
  ASSERT_TRUE(wet.first_impact_time && dry.first_impact_time);
  EXPECT_GT(*wet.first_impact_time, 1.2 * *dry.first_impact_time);
}

}  // namespace
}  // namespace blockfrag
