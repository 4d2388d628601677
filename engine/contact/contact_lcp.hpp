// The complementarity problem that both the contact forces (engine/contact/planar_contact.hpp)
// and the simultaneous impacts (engine/contact/planar_impact.hpp) solve, in one form: contact
// values y (accelerations or velocities, along each contact's n and t) affine in the contact
// forces (or impulses) lambda, y = free + J Minv J^T lambda, with per contact either
//   stick:  y_n = target_n, y_t = 0, |lambda_t| <= mu lambda_n
//   slip s: y_n = target_n, lambda_t = -s mu lambda_n, s y_t >= 0 (> 0 when starting to slip)
//   off:    lambda = 0, y_n >= target_n
// with lambda_n >= 0. Solved by trying each choice of states: small sets of contacts (a block
// touches a seat at a few points) make this exact and let every consistent choice be seen.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "engine/contact/body_load.hpp"
#include "engine/contact/planar_contact.hpp"

namespace blockfrag {

struct LcpContact {
  Eigen::RowVector3d jn, jt;  // d(y_n)/d(q') and d(y_t)/d(q'), q = (x, y, theta)
  double free_n, free_t;      // y without contact forces
  double target_n;            // y_n of an active contact
  // The contact slips with this sign and may not stick (forces on a slipping contact); 0: free.
  int forced_slip = 0;
  // A slip from stick must accelerate its way strictly (forces), or may end at rest (impacts).
  bool strict_slip_start = true;
};

struct LcpProblem {
  std::vector<LcpContact> contacts;
  BodyInertia inertia;  // the mass matrix per unit mass
  double friction;
  double tolerance;  // absolute, in y's units
  double length;     // R: a theta component is compared through R times it
  // Skip the choices whose fixed contact values leave the body no freedom (pins_body): a body
  // that may not stay put (its rest has ended) must move, and is given the first choice that lets
  // it.
  bool must_move = false;
};

struct LcpSolution {
  std::vector<ContactState> states;
  std::vector<double> normal, tangent;  // lambda at each contact
  Eigen::Vector3d change;               // Minv J^T lambda: the body's accelerations or jump
  Determinacy determinacy = Determinacy::inconsistent;
  // The consistent choices seen: the search stops at the second that disagrees with the first.
  int consistent_choices = 0;
};

// What solve_contact_lcp decomposes for each choice of states (its rows' least-squares reach, its
// square system's LU, the LUs' column subsets) depends on the contacts' rows, the inertia, the
// friction and the forced slips, not on the free accelerations or targets. A series of problems
// that differ in those alone (the rest range's search over the ground's acceleration at one state)
// keeps them here and decomposes each choice once, with the same solutions to the bit. A problem
// of another shape starts it afresh.
class LcpDecompositions {
 public:
  LcpDecompositions();
  ~LcpDecompositions();
  LcpDecompositions(const LcpDecompositions&) = delete;
  LcpDecompositions& operator=(const LcpDecompositions&) = delete;

  struct Kept;

 private:
  friend LcpSolution solve_contact_lcp(const LcpProblem&, LcpSearch, LcpDecompositions*);
  friend bool first_consistent_is_still(const LcpProblem&,
                                        const std::function<bool(const LcpSolution&)>&,
                                        LcpDecompositions*);
  std::unique_ptr<Kept> kept_;
};

LcpSolution solve_contact_lcp(const LcpProblem& problem, LcpSearch search = LcpSearch::every_choice,
                              LcpDecompositions* decompositions = nullptr);

// Whether the choice solve_contact_lcp takes first (LcpSearch::first_consistent; no forces where
// none is consistent) has no slipping contact and passes `still`: whether a body stays at rest.
// Found with fewer choices tried: those without a slip first, those with one only before the
// first consistent choice without, and only where that one passes `still` (a block past the end of
// its rest range pivots on one contact, a choice that comes after most of those with a slip).
bool first_consistent_is_still(const LcpProblem& problem,
                               const std::function<bool(const LcpSolution&)>& still,
                               LcpDecompositions* decompositions = nullptr);

// The solution of a x = d as solve_contact_lcp's FullPivLU gives it for a 1 x 1 system, to the
// bit, or none where that LU finds the system singular: a choice with one slipping contact and
// every other off, decided without decomposing.
std::optional<double> solve_single(double a, double d);

// Likewise for an invertible 2 x 2 system (a[row][column]): one sticking contact, or two slipping.
// None where that LU finds it singular, or where it is not finite: left to the LU.
std::optional<std::array<double, 2>> solve_pair(const std::array<std::array<double, 2>, 2>& a,
                                                const std::array<double, 2>& d);

// y_n and y_t rows of a contact for q' = (x', y', theta'): n . u and t . u of the material point.
// Inline: every right-hand side on a seat asks for it several times per contact.
inline Eigen::RowVector3d contact_row(const PlanarContact& c, Vec2 direction) {
  // u = (x' - theta' r_y, y' + theta' r_x): d . u = d_x x' + d_y y' + (r x d) theta'.
  return {direction.x, direction.y, c.r.x * direction.y - c.r.y * direction.x};
}

// Whether these rows (contact_row's, each held at a fixed value) leave the body no freedom: rank 3,
// theta's column taken through `length` (R) so that the rank test compares like with like, to the
// seat's contact drift (engine/tolerances.hpp).
bool pins_body(const std::vector<Eigen::RowVector3d>& rows, double length);

}  // namespace blockfrag
