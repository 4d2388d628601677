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

// The rates of the added mass against central differences of the added mass itself, for the
// type A dam block's outline tilted, lifted and cut by the surface.
TEST(HydrodynamicLoad, TheAddedMassRatesAreItsDerivatives) {
  const std::vector<Vertex> body{{-5.0, -7.0}, {7.55, -7.0}, {5.0, -3.6}, {5.0, 9.7}, {-5.0, 9.7}};
  const std::vector<std::size_t> base{0};
  for (const double theta : {0.0, 0.07, -0.04}) {
    for (const double surface : {9.7, 3.0}) {
      SCOPED_TRACE(theta);
      SCOPED_TRACE(surface);
      const double y = 0.3;
      const auto added = [&](double yy, double tt) {
        return westergaard_added_mass(world_polygon(body, 0.0, yy, tt), surface, 1000.0, 100.0,
                                      base, yy);
      };
      const AddedMassWithRates a = westergaard_added_mass_with_rates(
          world_polygon(body, 0.0, y, theta), surface, 1000.0, 100.0, base, {0.0, y});
      const double h = 1e-5;
      const AddedMass up = added(y + h, theta), down = added(y - h, theta);
      const AddedMass turned = added(y, theta + h), back = added(y, theta - h);
      const auto near = [](double exact, double difference) {
        EXPECT_NEAR(exact, difference, 1e-6 * std::max(1.0, std::abs(difference)));
      };
      near(a.d_dy.mass, (up.mass - down.mass) / (2 * h));
      near(a.d_dy.first_moment, (up.first_moment - down.first_moment) / (2 * h));
      near(a.d_dy.second_moment, (up.second_moment - down.second_moment) / (2 * h));
      near(a.d_dtheta.mass, (turned.mass - back.mass) / (2 * h));
      near(a.d_dtheta.first_moment, (turned.first_moment - back.first_moment) / (2 * h));
      near(a.d_dtheta.second_moment, (turned.second_moment - back.second_moment) / (2 * h));
      EXPECT_GT(std::abs(a.d_dtheta.second_moment), 1.0);
    }
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
