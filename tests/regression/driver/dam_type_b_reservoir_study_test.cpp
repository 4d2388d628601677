// Sample 342 of the type B block's reservoir study (configs/dam_type_b_reservoir_study.json: the
// Loma Prieta HSP-000 record at 5.40 times, friction 0.952, restitution 0.0079, reservoir at
// 17.98 m). At t = 3.2753 s the block lands from a rock on its heel, its toe on the incline's top
// point, and bounces off it by 4e-8 m; in the flight that follows the toe comes down 8e-9 m past
// the seat's end, under the incline's line. Its clearance was its distance from the seat's end (a
// vertex past an end's x was taken as off the seat), and the seat's end stayed outside the block,
// just beside its downstream face: neither guard fired, and the toe's base went on into the
// incline (0.35 R deep at 12 s), where the contact state changed 1,000,000 times by t = 14.5 s.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/block_geometry.hpp"
#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/seat.hpp"
#include "engine/seat/seat_contacts.hpp"
#include "engine/simulate.hpp"
#include "engine/tolerances.hpp"
#include "mpi_driver/config/study_config.hpp"
#include "mpi_driver/study/study_sample.hpp"

namespace blockfrag {
namespace {

// Each block vertex's gap over each seat segment its projection falls on, at a history row: the
// least of them (< 0: under the segment).
double reservoir_study_lowest_gap(const SeatContacts& contacts, double x0, const HistoryRow& row) {
  const BlockState s{x0 + row.x, row.y, row.theta, row.vx, row.vy, row.omega};
  double lowest = 1.0;
  for (int i = 0; i < contacts.vertex_count(); ++i) {
    for (int k = 0; k + 1 < contacts.point_count(); ++k) {
      const PairPose p = contacts.pose({ContactKind::block_vertex, i, k}, s);
      if (p.along >= 0 && p.along <= p.length && p.gap < lowest) lowest = p.gap;
    }
  }
  return lowest;
}

TEST(DamTypeBReservoirStudy, ToeLandingPastTheInclinesTopStaysOutOfTheSeat) {
  const StudyConfig config = read_study_config(std::filesystem::path(BLOCKFRAG_SOURCE_DIR) /
                                               "configs/dam_type_b_reservoir_study.json");
  StudySampler sampler(config);
  Scene scene = sampler.draw(342).scene;
  // Past the landing at 3.2753 s: the toe was 4.7e-4 m under the incline by 3.286 s.
  scene.duration = 3.4;
  const SimulationWithHistory run = simulate_with_history(scene, 1e-4);
  ASSERT_EQ(run.summary.status, Status::ok) << run.summary.status_reason;

  const std::vector<Vertex> block = scene_block_vertices(scene);
  const SeatContacts contacts(block, scene.seat->points);
  const double R = scene_geometry(scene).size();
  const double x0 = polygon_properties(block).centroid[0];
  const double drift = kSeatContactDrift * R;
  EXPECT_LE(run.summary.max_penetration, kSeatContactDrift);
  for (const HistoryRow& row : run.history) {
    SCOPED_TRACE("t = " + std::to_string(row.t) + " s");
    ASSERT_GE(reservoir_study_lowest_gap(contacts, x0, row), -drift);
  }
}

}  // namespace
}  // namespace blockfrag
