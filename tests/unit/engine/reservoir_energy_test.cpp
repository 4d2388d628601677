// Free rocking under a reservoir keeps its energy between impacts: the block's and the added
// mass's kinetic energy (1/2 q'^T (M + A) q', A from Westergaard's added mass at each pose), the
// block's weight's potential energy, and the water's static loads' potential along the rocking:
// on one degree of freedom (theta about the fixed pivot) every force has one,
//   V(theta) = -integral from theta0 to theta of Q(theta') dtheta',
// Q the static loads' moment about the pivot (the hydrostatic push at each pose and the uplift
// that stays on the block, engine/water/reservoir_loads.hpp), integrated here by Simpson's rule.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "engine/simulate.hpp"
#include "engine/water/reservoir_loads.hpp"
#include "engine/water/westergaard.hpp"

namespace blockfrag {
namespace {

// A concrete slice 1 m wide and 2 m high (4,800 kg/m) on a flat seat, released tilted about its
// upstream heel at (-0.5, -1), a 100 m reservoir up to its top.
constexpr double kEnergyA = 0.5, kEnergyB = 1.0, kEnergyMass = 4800.0, kEnergyTheta0 = 0.2;

Scene wet_slice() {
  Scene scene;
  scene.block = {kEnergyA, kEnergyB, kEnergyMass};
  scene.contact = {2.0, 0.0};
  scene.seat = Seat{{{-50.0, -kEnergyB}, {50.0, -kEnergyB}}};
  scene.reservoir =
      Reservoir{kEnergyB, 100.0, 1000.0, Hydrodynamic::westergaard, UpliftRule::unchanged, 1.0};
  scene.initial.theta = kEnergyTheta0;
  scene.duration = 1.5;
  scene.solver.tolerance = 1e-11;
  return scene;
}

// The pose turned by theta about the heel.
BlockState about_heel(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {-kEnergyA + c * kEnergyA - s * kEnergyB, -kEnergyB + s * kEnergyA + c * kEnergyB, theta};
}

// The static loads' moment about the heel, per unit mass.
double moment_about_heel(const ReservoirLoads& loads, double theta) {
  const BlockState pose = about_heel(theta);
  const ReservoirLoadSet set = loads.at(pose, CrackOpening::whole());
  const double fx = set.hydrostatic.fx + set.uplift.fx, fy = set.hydrostatic.fy + set.uplift.fy;
  const double rx = pose.x + kEnergyA, ry = pose.y + kEnergyB;
  return (set.hydrostatic.moment + set.uplift.moment + rx * fy - ry * fx) / kEnergyMass;
}

double water_potential(const ReservoirLoads& loads, double theta) {
  const int n = 400;
  const double h = (theta - kEnergyTheta0) / n;
  double sum = moment_about_heel(loads, kEnergyTheta0) + moment_about_heel(loads, theta);
  for (int i = 1; i < n; ++i) {
    sum += (i % 2 == 1 ? 4.0 : 2.0) * moment_about_heel(loads, kEnergyTheta0 + i * h);
  }
  return -sum * h / 3.0;
}

double energy(const Scene& scene, const ReservoirLoads& loads, const HistoryRow& r) {
  const std::vector<Vertex> body{
      {-kEnergyA, -kEnergyB}, {kEnergyA, -kEnergyB}, {kEnergyA, kEnergyB}, {-kEnergyA, kEnergyB}};
  WorldPolygon world;
  for (const Vertex& v : body) {
    world.push_back({r.x + std::cos(r.theta) * v[0] - std::sin(r.theta) * v[1],
                     r.y + std::sin(r.theta) * v[0] + std::cos(r.theta) * v[1]});
  }
  const AddedMass a = westergaard_added_mass(world, scene.reservoir->level, 1000.0, 100.0,
                                             loads.crack().edges, r.y);
  const double k2 = (kEnergyA * kEnergyA + kEnergyB * kEnergyB) / 3.0;
  const double block = r.vx * r.vx + r.vy * r.vy + k2 * r.omega * r.omega;
  const double water = (a.mass * r.vx * r.vx - 2.0 * a.first_moment * r.vx * r.omega +
                        a.second_moment * r.omega * r.omega) /
                       kEnergyMass;
  return 0.5 * (block + water) + scene.g * r.y + water_potential(loads, r.theta);
}

TEST(ReservoirEnergy, FreeRockingKeepsKineticGravityAndWaterEnergy) {
  const Scene scene = wet_slice();
  const ReservoirLoads loads(scene);
  const SimulationWithHistory run = simulate_with_history(scene, 0.01);
  ASSERT_EQ(run.summary.status, Status::ok);
  ASSERT_TRUE(run.summary.first_impact_time.has_value());
  const double start = energy(scene, loads, run.history.front());
  const double drop = scene.g * std::hypot(kEnergyA, kEnergyB) *
                      (std::cos(std::atan(kEnergyA / kEnergyB) - kEnergyTheta0) -
                       std::cos(std::atan(kEnergyA / kEnergyB)));
  double largest = 0.0, turned = 0.0;
  int checked = 0;
  for (const HistoryRow& r : run.history) {
    if (r.t >= *run.summary.first_impact_time) break;
    largest = std::max(largest, std::abs(energy(scene, loads, r) - start));
    turned = std::max(turned, std::abs(water_potential(loads, r.theta)));
    ++checked;
  }
  EXPECT_GT(checked, 10);
  EXPECT_GT(turned, 0.05 * drop);  // the water's part is not negligible
  EXPECT_LT(largest, 1e-7 * drop);
}

}  // namespace
}  // namespace blockfrag
