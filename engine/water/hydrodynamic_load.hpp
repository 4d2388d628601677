// Westergaard's added mass (engine/water/westergaard.hpp) in the block's equations of motion
// (engine/contact/body_load.hpp). The water's kinetic energy in the ground's frame is
//   T_w = 1/2 q'^T A(y, theta) q',  A = [[M_a, 0, -S_a], [0, 0, 0], [-S_a, 0, I_a]],
// with M_a, S_a, I_a the wetted face's added mass and its first and second moments of the height
// z above the centre of mass: the face at z moves horizontally at x' - z theta'. A depends on the
// pose (the face's depths change as the block lifts and tilts), so Lagrange's equations give,
// besides A q'' in the mass matrix, the generalized force
//   -A' q' + 1/2 (0, q'^T dA/dy q', q'^T dA/dtheta q'),  A' = dA/dy y' + dA/dtheta theta',
// which keeps block, water and gravity's energy constant in free motion (for a fixed face it is
// the centripetal part of the face's acceleration, -omega^2 times its lever). The ground's
// acceleration -lambda g drives the water as it drives the block: the ground frame's inertial
// force lambda g on the added mass, (M_a lambda g, 0, -S_a lambda g). The derivatives of A are
// exact (engine/water/westergaard.hpp, westergaard_added_mass_with_rates).
//
// Left out, as Westergaard's model leaves them out: the water's compressibility (the reservoir's
// resonance), cavitation where the pressure would fall below zero, the surface's waves, and the
// flow into an opening crack.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/contact/body_load.hpp"
#include "engine/water/water_load.hpp"
#include "engine/water/westergaard.hpp"

namespace blockfrag {

struct WettedBlock {
  std::vector<Vertex> body;  // the block's vertices from its centre of mass, unturned, ccw
  std::vector<std::size_t> crack_edges;  // never wetted by the reservoir (wetted_face.hpp)
  double mass;                           // the block's, kg (per metre of dam)
  double size;                           // R, m
};

// The block's outline at the pose (x, y, theta) of its centre of mass.
WorldPolygon world_polygon(const std::vector<Vertex>& body, double x, double y, double theta);
// The same into `out` (as many as body).
void place_body(const std::vector<Vertex>& body, double x, double y, double theta,
                std::span<Vertex> out);

class HydrodynamicLoad : public ExternalLoad {
 public:
  // `surface`: the water's y; `reservoir_depth`: H, > 0.
  HydrodynamicLoad(WettedBlock block, double surface, double density, double reservoir_depth);

  // The added mass's part of the load per unit of the block's mass at s under lambda.
  LoadAddition at(const BlockState& s, double lambda, double g, Footing) const override;
  // The same from the added mass and its rates at s found by the caller (ReservoirLoads, which
  // places the block once for all the reservoir's loads).
  LoadAddition from_rates(const AddedMassWithRates& a, const BlockState& s, double lambda,
                          double g) const;

 private:
  struct Matrix {  // A's three entries, per unit mass
    double xx, xtheta, thetatheta;
  };
  Matrix per_mass(const AddedMass& a) const;

  WettedBlock block_;
  double surface_, density_, reservoir_depth_;
};

}  // namespace blockfrag
