#include "engine/seat/fixed_state_forces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

#include <Eigen/Dense>

#include "engine/contact/contact_lcp.hpp"

namespace blockfrag {

namespace {

constexpr int kMaxUnknowns = 2 * kMaxSeatContacts;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxUnknowns, kMaxUnknowns>;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxUnknowns, 1>;

// A row of contact_row's, and Eigen's sum order for a dot product of three.
struct Row3 {
  double x, y, z;
};
Row3 row_of(const PlanarContact& c, Vec2 d) { return {d.x, d.y, c.r.x * d.y - c.r.y * d.x}; }
double dot(Row3 a, Row3 b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }

// The solution of a x = d by Eigen's FullPivLU, step by step: the pivot is the first largest
// entry in column-major order; nothing where the rank falls short. Inlined into its callers: a
// call passed its system through memory, an eighth of a rocking block's contact guards.
[[gnu::always_inline]] inline std::optional<std::array<double, 2>> full_pivot_solve(
    std::array<std::array<double, 2>, 2> a, std::array<double, 2> d) {
  const std::array<double, 4> score{std::abs(a[0][0]), std::abs(a[1][0]), std::abs(a[0][1]),
                                    std::abs(a[1][1])};
  int best = 0;
  for (int k = 1; k < 4; ++k) {
    if (score[static_cast<std::size_t>(k)] > score[static_cast<std::size_t>(best)]) best = k;
  }
  if (score[static_cast<std::size_t>(best)] == 0.0) return std::nullopt;
  const bool swap_rows = best % 2 == 1, swap_columns = best >= 2;
  if (swap_rows) {
    std::swap(a[0], a[1]);
    std::swap(d[0], d[1]);
  }
  if (swap_columns) {
    std::swap(a[0][0], a[0][1]);
    std::swap(a[1][0], a[1][1]);
  }
  const double l = a[1][0] / a[0][0];
  const double u11 = a[1][1] - l * a[0][1];
  const double max_pivot = std::max(std::abs(a[0][0]), std::abs(u11));
  const double threshold = 2.0 * std::numeric_limits<double>::epsilon() * max_pivot;
  if (!(std::abs(a[0][0]) > threshold && std::abs(u11) > threshold)) return std::nullopt;
  const double c1 = (d[1] - d[0] * l) / u11;
  const double c0 = (d[0] - c1 * a[0][1]) / a[0][0];
  return swap_columns ? std::array<double, 2>{c1, c0} : std::array<double, 2>{c0, c1};
}

// A contact's rows of the system: its normal's and tangent's, the normal force's column (a slipping
// contact's friction follows its normal force) and the right-hand sides.
struct ContactRows {
  Eigen::RowVector3d jn, jt;
  Eigen::Vector3d normal_column;
  double normal_rhs, tangent_rhs;
  int slip;
};

// Inlined: returned through memory, its copies were 0.4 % of the wet type A block's run.
[[gnu::always_inline]] inline ContactRows contact_rows(const PlanarContact& c, ContactState state,
                                                       const RigidVelocity& v,
                                                       const BodyAcceleration& free, double mu) {
  const Vec2 t = contact_tangent(c);
  const Eigen::RowVector3d jn = contact_row(c, c.normal), jt = contact_row(c, t);
  const ContactAcceleration y = contact_acceleration(c, v, free);
  const int slip = slip_sign(state);
  return {jn, jt, (jn - slip * mu * jt).transpose(), -y.normal, -y.tangent, slip};
}

BodyAcceleration free_acceleration_of(const BodyLoad& load) {
  const Eigen::Vector3d free_q = load.free_acceleration();
  return {free_q(0), free_q(1), free_q(2)};
}

// The forces and accelerations of the amounts solved (per contact its normal force, and a sticking
// one's friction after it).
FixedStateForces forces_of_amounts(std::span<const PlanarContact> contacts,
                                   std::span<const ContactState> states, const BodyLoad& load,
                                   const BodyAcceleration& free, double mu,
                                   std::span<const double> amounts) {
  FixedStateForces out;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  std::size_t col = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const int slip = slip_sign(states[i]);
    const double normal = amounts[col++];
    const double tangent = slip == 0 ? amounts[col++] : -slip * mu * normal;
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
  const Eigen::Vector3d change = load.inertia.inverse_times(force);
  out.acceleration = {free.x_dd + change(0), free.y_dd + change(1), free.theta_dd + change(2)};
  return out;
}

}  // namespace

FixedStateForces no_contact_forces(const BodyLoad& load) {
  FixedStateForces out;
  out.acceleration = free_acceleration_of(load);
  return out;
}

FixedStateForces general_fixed_state_forces(std::span<const PlanarContact> contacts,
                                            std::span<const ContactState> states,
                                            const BlockState& s, const BodyLoad& load, double mu) {
  if (contacts.empty()) return no_contact_forces(load);
  const BodyAcceleration free = free_acceleration_of(load);
  const RigidVelocity v{s.vx, s.vy, s.omega};
  // Rows: each contact's normal acceleration, and a sticking one's tangential. Unknowns: each
  // contact's normal force, and a sticking one's friction (a slipping one's follows the normal).
  std::array<Eigen::RowVector3d, kMaxUnknowns> rows{};
  std::array<Eigen::Vector3d, kMaxUnknowns> columns{};
  std::array<double, kMaxUnknowns> rhs{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactRows c = contact_rows(contacts[i], states[i], v, free, mu);
    rows[k] = c.jn;
    rhs[k] = c.normal_rhs;
    columns[k] = c.normal_column;
    ++k;
    if (c.slip == 0) {
      rows[k] = c.jt;
      rhs[k] = c.tangent_rhs;
      columns[k] = c.jt.transpose();
      ++k;
    }
  }
  const auto size = static_cast<Eigen::Index>(k);
  Matrix a(size, size);
  Vector d(size);
  for (Eigen::Index r = 0; r < size; ++r) {
    const auto row = static_cast<std::size_t>(r);
    const Eigen::RowVector3d weighted =
        load.inertia.inverse_times(rows[row].transpose()).transpose();
    for (Eigen::Index col = 0; col < size; ++col)
      a(r, col) = weighted.dot(columns[static_cast<std::size_t>(col)]);
    d(r) = rhs[row];
  }
  // Redundant contacts (collinear supports) leave the system singular: the accelerations are then
  // still determined, and the forces taken are the smallest that give them.
  const Eigen::FullPivLU<Matrix> lu(a);
  const Vector amounts = lu.isInvertible() ? Vector(lu.solve(d))
                                           : Vector(a.completeOrthogonalDecomposition().solve(d));
  return forces_of_amounts(contacts, states, load, free, mu,
                           std::span(amounts.data(), static_cast<std::size_t>(amounts.size())));
}

std::optional<FixedStateForces> two_slipping_contacts_forces(
    std::span<const PlanarContact> contacts, std::span<const ContactState> states,
    const BlockState& s, const BodyLoad& load, double mu) {
  if (contacts.size() != 2 || slip_sign(states[0]) == 0 || slip_sign(states[1]) == 0) {
    return std::nullopt;
  }
  const BodyAcceleration free = free_acceleration_of(load);
  const RigidVelocity v{s.vx, s.vy, s.omega};
  const std::array<ContactRows, 2> c{contact_rows(contacts[0], states[0], v, free, mu),
                                     contact_rows(contacts[1], states[1], v, free, mu)};
  std::array<std::array<double, 2>, 2> a{};
  for (std::size_t r = 0; r < 2; ++r) {
    const Eigen::RowVector3d weighted = load.inertia.inverse_times(c[r].jn.transpose()).transpose();
    for (std::size_t col = 0; col < 2; ++col) a[r][col] = weighted.dot(c[col].normal_column);
  }
  const auto amounts = full_pivot_solve(a, {c[0].normal_rhs, c[1].normal_rhs});
  if (!amounts) return std::nullopt;
  return forces_of_amounts(contacts, states, load, free, mu, *amounts);
}

FixedStateForces fixed_state_forces(std::span<const PlanarContact> contacts,
                                    std::span<const ContactState> states, const BlockState& s,
                                    const BodyLoad& load, double mu) {
  const auto two = two_slipping_contacts_forces(contacts, states, s, load, mu);
  return two ? *two : general_fixed_state_forces(contacts, states, s, load, mu);
}

namespace {

// One contact under a coupled mass matrix (the reservoir's added mass): the same 2x2 or 1x1
// system with M^-1 applied to each row in full.
bool coupled_one_contact_forces(const PlanarContact& c, ContactState state, const BlockState& s,
                                const BodyLoad& load, double mu, FixedStateForces& out) {
  const Eigen::Vector3d free_q = load.free_acceleration();
  const RigidVelocity v{s.vx, s.vy, s.omega};
  const Vec2 t = contact_tangent(c);
  const Row3 jn = row_of(c, c.normal), jt = row_of(c, t);
  const Eigen::Vector3d wn = load.inertia.inverse_times({jn.x, jn.y, jn.z});
  const Eigen::Vector3d wt = load.inertia.inverse_times({jt.x, jt.y, jt.z});
  const auto dot_w = [](Row3 r, const Eigen::Vector3d& w) {
    return (r.x * w(0) + r.y * w(1)) + r.z * w(2);
  };
  const ContactAcceleration y =
      contact_acceleration(c, v, BodyAcceleration{free_q(0), free_q(1), free_q(2)});
  const int slip = slip_sign(state);
  double normal = 0.0, tangent = 0.0;
  if (slip == 0) {
    const auto amounts =
        full_pivot_solve({{{dot_w(jn, wn), dot_w(jn, wt)}, {dot_w(jt, wn), dot_w(jt, wt)}}},
                         {-y.normal, -y.tangent});
    if (!amounts) return false;
    normal = (*amounts)[0];
    tangent = (*amounts)[1];
  } else {
    const double a = dot_w(jn, wn) - slip * mu * dot_w(jn, wt);
    if (a == 0.0) return false;
    normal = -y.normal / a;
    tangent = -slip * mu * normal;
  }
  out.normal[0] = normal;
  out.tangent[0] = tangent;
  out.total = {normal * c.normal.x + tangent * t.x, normal * c.normal.y + tangent * t.y};
  const Eigen::Vector3d change = normal * wn + tangent * wt;
  out.acceleration = {free_q(0) + change(0), free_q(1) + change(1), free_q(2) + change(2)};
  return true;
}

}  // namespace

bool one_contact_forces(const PlanarContact& c, ContactState state, const BlockState& s,
                        const BodyLoad& load, double mu, FixedStateForces& out) {
  if (load.inertia.coupled()) return coupled_one_contact_forces(c, state, s, load, mu, out);
  const Eigen::Vector3d free_q = load.free_acceleration();
  const BodyAcceleration free{free_q(0), free_q(1), free_q(2)};
  const RigidVelocity v{s.vx, s.vy, s.omega};
  const double inverse_inertia = 1.0 / load.inertia.k2;
  const Vec2 t = contact_tangent(c);
  const Row3 jn = row_of(c, c.normal), jt = row_of(c, t);
  const Row3 wn{jn.x, jn.y, jn.z * inverse_inertia};
  const ContactAcceleration y = contact_acceleration(c, v, free);
  const int slip = slip_sign(state);
  double normal = 0.0, tangent = 0.0;
  if (slip == 0) {
    const Row3 wt{jt.x, jt.y, jt.z * inverse_inertia};
    const auto amounts = full_pivot_solve(
        {{{dot(wn, jn), dot(wn, jt)}, {dot(wt, jn), dot(wt, jt)}}}, {-y.normal, -y.tangent});
    if (!amounts) return false;
    normal = (*amounts)[0];
    tangent = (*amounts)[1];
  } else {
    const double s_mu = slip * mu;
    const double a = dot(wn, {jn.x - s_mu * jt.x, jn.y - s_mu * jt.y, jn.z - s_mu * jt.z});
    if (a == 0.0) return false;
    normal = -y.normal / a;
    tangent = -slip * mu * normal;
  }
  out.normal[0] = normal;
  out.tangent[0] = tangent;
  // The general solve's sums, from zero.
  out.total.x = 0.0 + (normal * c.normal.x + tangent * t.x);
  out.total.y = 0.0 + (normal * c.normal.y + tangent * t.y);
  const Row3 force{0.0 + (normal * jn.x + tangent * jt.x), 0.0 + (normal * jn.y + tangent * jt.y),
                   0.0 + (normal * jn.z + tangent * jt.z)};
  out.acceleration = {free.x_dd + force.x, free.y_dd + force.y,
                      free.theta_dd + inverse_inertia * force.z};
  return true;
}

std::optional<FixedStateForces> one_contact_forces(const PlanarContact& c, ContactState state,
                                                   const BlockState& s, const BodyLoad& load,
                                                   double mu) {
  FixedStateForces out;
  if (!one_contact_forces(c, state, s, load, mu, out)) return std::nullopt;
  return out;
}

}  // namespace blockfrag
