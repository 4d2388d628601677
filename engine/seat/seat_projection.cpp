// Putting a block on a seat back on its contacts after an event (their drift), laying a landing
// block on them, and the lambda range of rest.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "engine/seat/level_rest_range.hpp"
#include "engine/seat/seat_ground.hpp"
#include "engine/seat/seated_load.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

// The change dq with J dq = b that is least in the kinetic metric dq^T M dq (dx^2 + dy^2 +
// k^2 dtheta^2 for the block alone, k the radius of gyration): the change impulses at the contacts
// would make. Least in the plain (x, y, theta) norm instead, a rotation is cheap and turns the
// block about its centre, sliding every contact point along its segment (far past a fold, at the
// type B block's height). With an added mass, M = L L^T and the change is L^-T of the least z = L^T
// dq with J L^-T z = b.
Eigen::Vector3d SeatSimulation::least_kinetic_change(const Eigen::MatrixXd& j,
                                                     const Eigen::VectorXd& b,
                                                     const BodyInertia& inertia) const {
  if (inertia.coupled()) {
    const Eigen::LLT<Eigen::Matrix3d> llt(inertia.matrix());
    const Eigen::Matrix3d l_inverse_transposed = llt.matrixU().solve(Eigen::Matrix3d::Identity());
    const Eigen::MatrixXd scaled = j * l_inverse_transposed;
    return l_inverse_transposed * scaled.completeOrthogonalDecomposition().solve(b);
  }
  const double k = std::sqrt(inertia.k2);
  Eigen::MatrixXd scaled = j;
  scaled.col(2) /= k;
  Eigen::Vector3d change = scaled.completeOrthogonalDecomposition().solve(b);
  change(2) /= k;
  return change;
}

// Sets the pairs' normal velocities to zero with the least change in the kinetic metric, then,
// among the changes that leave those velocities alone, brings the pairs' slip along the seat back
// as near to what it was as they allow: on a flat seat, the flat ground's lay_flat, which keeps
// the base's slip velocity. With the kinetic metric alone (the centre's velocity kept) a block
// rocking as it slid went on at its slip plus omega times its height, 6e-5 R further than on the
// flat ground (SlidingBlockRockingAtZeroRestitutionIsLaidOnTheSeat).
void SeatSimulation::lay_on(const std::vector<SeatPair>& pairs, BlockState& s) {
  const auto k = static_cast<Eigen::Index>(pairs.size());
  Eigen::MatrixXd normal(k, 3), tangent(k, 3);
  Eigen::VectorXd u(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    const PlanarContact c = contact_of(pairs[static_cast<std::size_t>(i)], s);
    normal.row(i) = contact_row(c, c.normal);
    tangent.row(i) = contact_row(c, contact_tangent(c));
    u(i) = contact_velocity(c, velocity_of(s)).normal;
  }
  const Eigen::Vector3d least = least_kinetic_change(normal, -u, load_at(t_, s).inertia);
  Eigen::Vector3d dv = least;
  // Within the changes that keep the normal velocities, the one that takes the slip back. The
  // normals are the seat's or the block's edges' (turned by the block's tilt, within the contact
  // height over R): their rank is taken to the seat's contact drift, as pins_body takes it.
  const Eigen::Vector3d theta_over_length(1, 1, 1 / R_);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(normal * theta_over_length.asDiagonal());
  lu.setThreshold(kSeatContactDrift);
  if (lu.rank() < 3) {
    const Eigen::MatrixXd free = theta_over_length.asDiagonal() * lu.kernel();
    const Eigen::MatrixXd slip_change = tangent * free;
    dv += free * slip_change.completeOrthogonalDecomposition().solve(-tangent * dv);
  }
  // Taking the slip back can add kinetic energy; the least change never does (keeps_slip).
  const BlockState before = s;
  const auto apply = [&](const Eigen::Vector3d& change) {
    s = before;
    s.vx += change(0);
    s.vy += change(1);
    s.omega += change(2);
  };
  apply(dv);
  if (!keeps_slip(kinetic_energy(before), kinetic_energy(s))) {
    apply(least);
  }
}

// Puts the contacts' gaps back to zero: the least change of the pose.
void SeatSimulation::project_positions(const std::vector<ActiveContact>& active,
                                       BlockState& s) const {
  if (active.empty()) return;
  // A sticking vertex goes back to where it stuck, too: held by its velocity alone, it crept
  // along the seat by the integrator's error (a block rocking on its corner at an adaptive
  // tolerance of 1e-8 came to rest 1e-8 to 1e-7 R from the flat ground's place, where the
  // flat ground's pivot does not move).
  std::vector<std::pair<SeatPair, double>> anchored;
  for (const ActiveContact& a : active) {
    if (a.state != ContactState::stick) continue;
    if (const auto place = anchor_of(a.pair)) anchored.emplace_back(a.pair, *place);
  }
  const auto k = static_cast<Eigen::Index>(active.size());
  const auto rows = k + static_cast<Eigen::Index>(anchored.size());
  for (int iteration = 0; iteration < kProjectionIterations; ++iteration) {
    Eigen::MatrixXd j(rows, 3);
    Eigen::VectorXd gap(rows);
    for (Eigen::Index i = 0; i < k; ++i) {
      const PairPose p = contacts_.pose(active[static_cast<std::size_t>(i)].pair, s);
      j.row(i) = contact_row(p.contact, p.contact.normal);
      gap(i) = p.gap;
    }
    for (std::size_t a = 0; a < anchored.size(); ++a) {
      const PairPose p = contacts_.pose(anchored[a].first, s);
      const auto i = k + static_cast<Eigen::Index>(a);
      j.row(i) = contact_row(p.contact, contact_tangent(p.contact));
      gap(i) = p.along - anchored[a].second;
    }
    if (gap.cwiseAbs().maxCoeff() <= std::numeric_limits<double>::epsilon() * R_) break;
    const Eigen::Vector3d dq = least_kinetic_change(j, -gap, geometry_.inertia_per_mass());
    s.x += dq(0);
    s.y += dq(1);
    s.theta += dq(2);
  }
}

// The tilt is read with every touching contact put back on the seat: the active ones have drifted
// (by the integrator's error, far more than 1e-9 rad at an adaptive tolerance of 1e-8), and a
// pivot sunk into the seat lets the face's far corner touch before the tilt is reached.
bool SeatSimulation::lies_overturned(const BlockState& s,
                                     const std::vector<SeatPair>& touching) const {
  std::vector<ActiveContact> landed;
  landed.reserve(touching.size());
  for (const SeatPair& pair : touching) landed.push_back({pair, ContactState::stick});
  BlockState on_seat = s;
  project_positions(landed, on_seat);
  return contacts_.overturn_margin(geometry_, on_seat.theta) <= kContactHeight;
}

// Puts the active contacts' gaps back to zero (the least change) and their normal
// velocities (and a sticking one's tangential velocity) too.
void SeatSimulation::project(const SeatMode& mode) {
  if (mode.active.empty()) return;
  project_positions(mode.active, state_);
  // A chart that holds the contacts takes only the rates they leave free (the flat ground's modes
  // too: a rock takes theta' and drops a stopped slide's residual slip). Projected, that residual
  // would go into theta', the rock would start turning at a rounding's speed where the flat
  // ground's starts at 0, and the adaptive stepper's first step, scaled by the state over its
  // derivative, would underflow (ARockFromAStoppedSlideStartsAtRestAsOnTheFlatGround).
  if (mode.rest || !std::holds_alternative<FreeChart>(chart_of(mode))) return;
  std::vector<Eigen::RowVector3d> rows;
  std::vector<double> velocities;
  for (const ActiveContact& a : mode.active) {
    const PlanarContact c = contact_of(a.pair, state_);
    const ContactVelocity u = contact_velocity(c, velocity_of(state_));
    rows.push_back(contact_row(c, c.normal));
    velocities.push_back(u.normal);
    if (a.state == ContactState::stick) {
      rows.push_back(contact_row(c, contact_tangent(c)));
      velocities.push_back(u.tangent);
    }
  }
  Eigen::MatrixXd j(static_cast<Eigen::Index>(rows.size()), 3);
  Eigen::VectorXd u(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    j.row(static_cast<Eigen::Index>(i)) = rows[i];
    u(static_cast<Eigen::Index>(i)) = velocities[i];
  }
  const Eigen::Vector3d dv = least_kinetic_change(j, -u, load_at(t_, state_).inertia);
  state_.vx += dv(0);
  state_.vy += dv(1);
  state_.omega += dv(2);
}

// Whether the block at rest on its active contacts stays at rest under lambda (with g).
bool SeatSimulation::rest_holds(double lambda, LcpDecompositions& decompositions) const {
  std::vector<SeatPair> pairs;
  for (const ActiveContact& a : mode_.active) pairs.push_back(a.pair);
  return rest_holds(pairs, lambda, decompositions);
}

bool SeatSimulation::rest_holds(const std::vector<SeatPair>& pairs, double lambda,
                                LcpDecompositions& decompositions) const {
  std::vector<PlanarContact> contacts;
  for (const SeatPair& pair : pairs) contacts.push_back(contact_of(pair, state_));
  const BodyLoad load = seated_load(
      {geometry_.inertia_per_mass(), lambda, 0.0, scene_.g, scene_.contact.friction, external_},
      state_, contacts, std::vector<ContactState>(contacts.size(), ContactState::stick));
  PlanarForcesInput in{std::move(contacts),     {0.0, 0.0, 0.0}, load.inertia, load.force,
                       scene_.contact.friction, velocity_tol_,   scene_.g,     R_};
  in.tolerance = kRestTolerance;
  in.applied_moment = load.moment;
  // The first consistent choice decides rest; whether others disagree does not matter here.
  return first_consistent_forces_are_still(
      in, [&](const PlanarForces& f) { return holds_at_rest(f, in.tolerance); }, &decompositions);
}

// The lambda range of rest: in closed form for a dry block on a level line (level_rest_range);
// else, as rest holds on an interval of lambda (the contact forces that balance the load, affine
// in lambda, form a convex cone), found by doubling then halving each way from lambda = 0, or,
// where a load pushes the block (the reservoir's) so that it rests only under the ground's help,
// from the lambda it came to rest under.
void SeatSimulation::set_rest_thresholds(SeatMode& mode) {
  if (external_ == nullptr) {
    std::vector<PlanarContact> contacts;
    for (const ActiveContact& a : mode.active) contacts.push_back(contact_of(a.pair, state_));
    if (const std::optional<RestRange> range =
            level_rest_range(contacts, scene_.contact.friction)) {
      mode.rest_low = range->low;
      mode.rest_high = range->high;
      return;
    }
  }
  LcpDecompositions decompositions;
  const auto holds = [&](double lambda) { return rest_holds(lambda, decompositions); };
  const double start =
      external_ == nullptr || holds(0.0) ? 0.0 : motion_.lambda(t_) / gravity_factor(t_);
  const auto edge = [&](double direction) {
    double inside = start, step = direction, outside = start + step;
    while (holds(outside)) {
      inside = outside;
      if (std::abs(outside) >= kRestSearchLimit)
        return direction * std::numeric_limits<double>::infinity();
      step *= 2.0;
      outside = start + step;
    }
    for (int i = 0; i < kRestThresholdHalvings && std::abs(outside - inside) > 0.0; ++i) {
      const double middle = 0.5 * (inside + outside);
      if (middle == inside || middle == outside) break;
      (holds(middle) ? inside : outside) = middle;
    }
    return inside;
  };
  mode.rest_high = edge(1.0);
  mode.rest_low = edge(-1.0);
}

double SeatSimulation::rest_margin(double t, MotionPiece& piece, MotionPiece& vertical) const {
  const double lambda = piece.lambda(t), factor = 1.0 + vertical.lambda(t);
  return kOnsetMargin +
         std::min({mode_.rest_high * factor - lambda, lambda - mode_.rest_low * factor, factor});
}

}  // namespace blockfrag
