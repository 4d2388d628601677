// What the block's equations of motion take besides its contacts (docs/physics.md, "Equations in
// one general form"): a mass matrix and a generalized applied force, both per unit of the block's
// own mass M, in the coordinates q = (x, y, theta) of its centre of mass:
//   M(q) q'' = Q + J^T lambda.
// Without water the matrix is diag(1, 1, k^2) and Q = (lambda g, -g (1 + lambda_v), 0). A mass that
// follows the block's horizontal motion only (the reservoir's added mass on its upstream face),
// whose face points sit at heights z above the centre of mass, feels the face's horizontal
// acceleration x'' - z theta'' (plus the ground's): it adds
//   [  a   0  -s ]      a = M_a / M,  s = S_a / M,  i = I_a / M,
//   [  0   0   0 ]      M_a its mass, S_a and I_a the first and second moments of z over it,
//   [ -s   0   i ]
// which is positive semi-definite (s^2 <= a i by Cauchy-Schwarz): x and theta are coupled.
#pragma once

#include <Eigen/Dense>

#include "engine/contact/crack_seating.hpp"
#include "engine/contact/impact.hpp"
#include "engine/scene/block_state.hpp"

namespace blockfrag {

struct BodyInertia {
  double k2;  // I / M, m^2
  // The added parts of the matrix's x-x, x-theta and theta-theta entries.
  double xx = 0.0, xtheta = 0.0, thetatheta = 0.0;

  // A block alone (implicit: most of the engine knows the block by its k^2 alone).
  BodyInertia(double inertia_per_mass) : k2(inertia_per_mass) {}
  BodyInertia(double inertia_per_mass, double added_xx, double added_xtheta,
              double added_thetatheta)
      : k2(inertia_per_mass), xx(added_xx), xtheta(added_xtheta), thetatheta(added_thetatheta) {}

  bool coupled() const { return xx != 0.0 || xtheta != 0.0 || thetatheta != 0.0; }

  // M^-1 v. Uncoupled, the diagonal's products exactly as a diagonal matrix gives them; coupled, y
  // apart and the (x, theta) block's 2x2 inverse.
  Eigen::Vector3d inverse_times(const Eigen::Vector3d& v) const {
    if (!coupled()) return {v(0), v(1), v(2) * (1.0 / k2)};
    const double mxx = 1.0 + xx, mtt = k2 + thetatheta;
    const double det = mxx * mtt - xtheta * xtheta;
    return {(mtt * v(0) - xtheta * v(2)) / det, v(1), (mxx * v(2) - xtheta * v(0)) / det};
  }

  Eigen::Matrix3d matrix() const {
    Eigen::Matrix3d m;
    m << 1.0 + xx, 0.0, xtheta, 0.0, 1.0, 0.0, xtheta, 0.0, k2 + thetatheta;
    return m;
  }

  // Twice the kinetic energy per unit mass, q'^T M q'.
  double twice_kinetic(const RigidVelocity& v) const {
    const double block = v.vx * v.vx + v.vy * v.vy + k2 * v.omega * v.omega;
    if (!coupled()) return block;
    return block + xx * v.vx * v.vx + 2.0 * xtheta * v.vx * v.omega +
           thetatheta * v.omega * v.omega;
  }
};

// The generalized applied force per unit mass: a force at the centre of mass and a moment about
// it; and the mass matrix it drives.
struct BodyLoad {
  Vec2 force;
  double moment = 0.0;
  BodyInertia inertia;

  // M^-1 Q: the accelerations without contact forces.
  Eigen::Vector3d free_acceleration() const {
    return inertia.inverse_times({force.x, force.y, moment});
  }
};

// What acts on the block besides gravity, the ground's inertia on its own mass and its contacts
// (the reservoir), per unit of the block's mass, at a state of the block under the ground's
// horizontal acceleration -lambda g: added to the dry load.
struct LoadAddition {
  Vec2 force{0.0, 0.0};
  double moment = 0.0;
  double xx = 0.0, xtheta = 0.0, thetatheta = 0.0;
};

// How the block stands on its ground, for a load that depends on it (the water in the crack under
// its base): seated on its base (at rest, or sliding on two contacts or more), or lifted from it
// (rocking on one contact, or in flight). It changes only at events.
enum class Footing { seated, lifted };

// How the load on a seated block changes as the crack under its base opens: not at all, or the
// reservoir's uplift drained from the opened part ("zero_in_gap") or the full head filling it
// ("full_head_in_gap").
enum class SeatedCrack { unaffected, drains, fills };

// A seated block's loads at one state for the openings of the crack under its base that a search
// tries (ExternalLoad::search_openings): what does not depend on the opening is found once.
class CrackOpenings {
 public:
  virtual LoadAddition opened(LiftingSide side, double fraction) const = 0;

 protected:
  ~CrackOpenings() = default;
};

// What searches them (engine/seat/seated_load.cpp).
class CrackOpeningSearch {
 public:
  virtual void search(const CrackOpenings& openings) = 0;

 protected:
  ~CrackOpeningSearch() = default;
};

class ExternalLoad {
 public:
  virtual ~ExternalLoad() = default;
  virtual LoadAddition at(const BlockState& s, double lambda, double g, Footing footing) const = 0;
  // Whether and how the load on a seated block depends on how far the crack under its base has
  // opened: the engine then opens it from a lifting outermost contact's side just far enough to
  // keep that contact's normal force from going negative (engine/seat/seated_load.hpp).
  virtual SeatedCrack seated_crack() const { return SeatedCrack::unaffected; }
  // The load on the seated block with the crack opened over `fraction` of its length from `side`.
  virtual LoadAddition seated_opened(const BlockState& s, double lambda, double g, LiftingSide,
                                     double) const {
    return at(s, lambda, g, Footing::seated);
  }
  // Runs `search` on the loads seated_opened gives at the state s, each to the bit.
  virtual void search_openings(const BlockState& s, double lambda, double g,
                               CrackOpeningSearch& search) const;
};

// The openings ExternalLoad::search_openings runs a search on unless a load finds them faster:
// seated_opened's, each anew.
class OpenedAnew final : public CrackOpenings {
 public:
  OpenedAnew(const ExternalLoad& load, const BlockState& s, double lambda, double g)
      : load_(&load), s_(&s), lambda_(lambda), g_(g) {}
  LoadAddition opened(LiftingSide side, double fraction) const override {
    return load_->seated_opened(*s_, lambda_, g_, side, fraction);
  }

 private:
  const ExternalLoad* load_;
  const BlockState* s_;
  double lambda_, g_;
};

inline void ExternalLoad::search_openings(const BlockState& s, double lambda, double g,
                                          CrackOpeningSearch& search) const {
  search.search(OpenedAnew(*this, s, lambda, g));
}

inline BodyLoad with_addition(BodyLoad load, double inertia_per_mass, const LoadAddition& add) {
  load.force.x += add.force.x;
  load.force.y += add.force.y;
  load.moment += add.moment;
  load.inertia = {inertia_per_mass, add.xx, add.xtheta, add.thetatheta};
  return load;
}

// The load on a dry block of k^2 = I/M under lambda and lambda_v: gravity and the ground's inertia
// alone, which do not depend on the block's state.
inline BodyLoad dry_body_load(double inertia_per_mass, double lambda, double lambda_v, double g) {
  return {{lambda * g, -g * (1.0 + lambda_v)}, 0.0, inertia_per_mass};
}

// The load on a block of k^2 = I/M under lambda, lambda_v and an external load (none: dry), the
// block standing as `footing` says.
inline BodyLoad body_load(double inertia_per_mass, double lambda, double lambda_v, double g,
                          const ExternalLoad* external, const BlockState& s, Footing footing) {
  const BodyLoad load = dry_body_load(inertia_per_mass, lambda, lambda_v, g);
  if (external == nullptr) return load;
  return with_addition(load, inertia_per_mass, external->at(s, lambda, g, footing));
}

// The same for a seated block whose crack is opened over `fraction` of its length from `side`
// (ExternalLoad::seated_opened, or one of ExternalLoad::search_openings).
inline BodyLoad seated_body_load(double inertia_per_mass, double lambda, double lambda_v, double g,
                                 const CrackOpenings& openings, LiftingSide side, double fraction) {
  return with_addition(dry_body_load(inertia_per_mass, lambda, lambda_v, g), inertia_per_mass,
                       openings.opened(side, fraction));
}

}  // namespace blockfrag
