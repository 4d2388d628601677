#include "engine/seat/seat_system.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "engine/contact/contact_lcp.hpp"

namespace blockfrag {

namespace {

constexpr int kMaxUnknowns = 2 * kMaxSeatContacts;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxUnknowns, kMaxUnknowns>;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxUnknowns, 1>;

}  // namespace

FixedStateForces fixed_state_forces(std::span<const PlanarContact> contacts,
                                    std::span<const ContactState> states, const BlockState& s,
                                    Vec2 applied, double inertia_per_mass, double mu) {
  FixedStateForces out;
  const BodyAcceleration free{applied.x, applied.y, 0.0};
  out.acceleration = free;
  if (contacts.empty()) return out;
  const RigidVelocity v{s.vx, s.vy, s.omega};
  const Eigen::Vector3d inverse_mass(1.0, 1.0, 1.0 / inertia_per_mass);
  // Rows: each contact's normal acceleration, and a sticking one's tangential. Unknowns: each
  // contact's normal force, and a sticking one's friction (a slipping one's follows the normal).
  std::array<Eigen::RowVector3d, kMaxUnknowns> rows{};
  std::array<Eigen::Vector3d, kMaxUnknowns> columns{};
  std::array<double, kMaxUnknowns> rhs{};
  int k = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const PlanarContact& c = contacts[i];
    const Vec2 t = contact_tangent(c);
    const Eigen::RowVector3d jn = contact_row(c, c.normal), jt = contact_row(c, t);
    const ContactAcceleration y = contact_acceleration(c, v, free);
    const int slip = slip_sign(states[i]);
    rows[static_cast<std::size_t>(k)] = jn;
    rhs[static_cast<std::size_t>(k)] = -y.normal;
    columns[static_cast<std::size_t>(k)] = (jn - slip * mu * jt).transpose();
    ++k;
    if (slip == 0) {
      rows[static_cast<std::size_t>(k)] = jt;
      rhs[static_cast<std::size_t>(k)] = -y.tangent;
      columns[static_cast<std::size_t>(k)] = jt.transpose();
      ++k;
    }
  }
  Matrix a(k, k);
  Vector d(k);
  for (int r = 0; r < k; ++r) {
    const Eigen::RowVector3d weighted =
        rows[static_cast<std::size_t>(r)].cwiseProduct(inverse_mass.transpose());
    for (int col = 0; col < k; ++col)
      a(r, col) = weighted.dot(columns[static_cast<std::size_t>(col)]);
    d(r) = rhs[static_cast<std::size_t>(r)];
  }
  // Redundant contacts (collinear supports) leave the system singular: the accelerations are then
  // still determined, and the forces taken are the smallest that give them.
  const Eigen::FullPivLU<Matrix> lu(a);
  const Vector amounts = lu.isInvertible() ? Vector(lu.solve(d))
                                           : Vector(a.completeOrthogonalDecomposition().solve(d));
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  int col = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const int slip = slip_sign(states[i]);
    const double normal = amounts(col++);
    const double tangent = slip == 0 ? amounts(col++) : -slip * mu * normal;
    out.normal[i] = normal;
    out.tangent[i] = tangent;
    const PlanarContact& c = contacts[i];
    const Vec2 t = contact_tangent(c);
    const Vec2 f{normal * c.normal.x + tangent * t.x, normal * c.normal.y + tangent * t.y};
    out.total.x += f.x;
    out.total.y += f.y;
    force +=
        normal * contact_row(c, c.normal).transpose() + tangent * contact_row(c, t).transpose();
  }
  const Eigen::Vector3d change = inverse_mass.cwiseProduct(force);
  out.acceleration = {free.x_dd + change(0), free.y_dd + change(1), free.theta_dd + change(2)};
  return out;
}

SeatSystem::SeatSystem(const SeatSystemContext& c, const std::vector<ActiveContact>& active,
                       const std::vector<int>& watched_vertices,
                       const std::vector<int>& watched_points)
    : c_(c), watched_vertices_(watched_vertices), watched_points_(watched_points) {
  count_ = static_cast<int>(active.size());
  std::copy(active.begin(), active.end(), active_.begin());
  events_.fill(SeatEvent::none);
  events_[0] = SeatEvent::overturns;
  events_[1] = SeatEvent::falls;
  for (int i = 0; i < count_; ++i) {
    const auto base = static_cast<std::size_t>(2 + kSeatContactGuards * i);
    events_[base] = SeatEvent::lift_off;
    events_[base + 1] = active_[static_cast<std::size_t>(i)].state == ContactState::stick
                            ? SeatEvent::friction_limit
                            : SeatEvent::slip_stops;
    // A sticking contact's point does not move along its segment or edge (the type B block
    // rocking on its toe sticks at the seat's end): only slipping ones can leave it.
    if (active_[static_cast<std::size_t>(i)].state != ContactState::stick) {
      events_[base + 2] = SeatEvent::leaves_end;
      events_[base + 3] = SeatEvent::leaves_end;
    }
  }
  const std::size_t watched = watched_vertices_.size() + watched_points_.size();
  for (std::size_t i = 0; i < watched; ++i) {
    events_[static_cast<std::size_t>(kFirstClearanceGuard) + i] = SeatEvent::touches;
  }
}

FixedStateForces SeatSystem::solve(double t, const BlockState& s) const {
  std::array<PlanarContact, kMaxSeatContacts> contacts{};
  std::array<ContactState, kMaxSeatContacts> states{};
  for (int i = 0; i < count_; ++i) {
    const auto at = static_cast<std::size_t>(i);
    contacts[at] = c_.contacts->pose(active_[at].pair, s).contact;
    states[at] = active_[at].state;
  }
  const auto n = static_cast<std::size_t>(count_);
  const Vec2 applied{c_.piece->lambda(t) * c_.g, -c_.g * (1.0 + c_.vertical->lambda(t))};
  return fixed_state_forces(std::span(contacts).first(n), std::span(states).first(n), s, applied,
                            c_.geometry->inertia_per_mass(), c_.mu);
}

std::array<double, SeatSystem::kGuards> SeatSystem::guards(double t, const BlockState& s) const {
  std::array<double, kGuards> out;
  out.fill(1.0);
  const double R = c_.geometry->size();
  // Lying on another face is overturning over the seat; past its ends the block falls instead.
  const bool over_seat = s.x >= c_.contacts->seat_point(0).x &&
                         s.x <= c_.contacts->seat_point(c_.contacts->point_count() - 1).x;
  out[0] = over_seat ? c_.contacts->overturn_margin(*c_.geometry, s.theta) : 1.0;
  std::array<Vec2, kMaxSeatClearances> world{};
  c_.contacts->world_vertices(s, world);
  out[1] = c_.contacts->height_over_fall(s, world, c_.fall_depth) / R;

  if (count_ > 0) {
    const FixedStateForces f = solve(t, s);
    const RigidVelocity v{s.vx, s.vy, s.omega};
    const double velocity_scale = std::sqrt(c_.g * R);
    for (int i = 0; i < count_; ++i) {
      const auto at = static_cast<std::size_t>(i);
      const auto base = static_cast<std::size_t>(2 + kSeatContactGuards * i);
      const PairPose p = c_.contacts->pose(active_[at].pair, s);
      out[base] = f.normal[at] / c_.g;
      const int slip = slip_sign(active_[at].state);
      out[base + 1] = slip == 0 ? (c_.mu * f.normal[at] - std::abs(f.tangent[at])) / c_.g
                                : slip * contact_velocity(p.contact, v).tangent / velocity_scale;
      if (slip != 0 && active_[at].pair.kind == ContactKind::block_vertex) {
        const SeatContacts::RunPlace run = c_.contacts->place_on_run(
            active_[at].pair.seat, {s.x + p.contact.r.x, s.y + p.contact.r.y});
        out[base + 2] = run.along / R;
        out[base + 3] = (run.length - run.along) / R;
      } else if (slip != 0) {
        out[base + 2] = p.along / R;
        out[base + 3] = (p.length - p.along) / R;
      }
    }
  }
  std::size_t g = static_cast<std::size_t>(kFirstClearanceGuard);
  for (const int i : watched_vertices_) {
    out[g++] = c_.contacts->clearance_at(world[static_cast<std::size_t>(i)]) / R;
  }
  for (const int k : watched_points_) out[g++] = c_.contacts->point_clearance(k, world) / R;
  return out;
}

ContactForces SeatSystem::forces(double t, const BlockState& s) const {
  const FixedStateForces f = solve(t, s);
  return {f.total.x, f.total.y};
}

}  // namespace blockfrag
