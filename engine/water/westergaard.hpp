// Westergaard's (1933, Trans. ASCE 98) added mass of the reservoir on the block's wetted upstream
// face: a rigid vertical face moving horizontally with acceleration a in incompressible water of
// depth H feels the pressure -(7/8) rho_w sqrt(H y_d) a at depth y_d, so the water adds the mass
//   m_w(y_d) = (7/8) rho_w sqrt(H y_d)   per unit area of the face,
// on horizontal motion only. Over the wetted face, with z a point's height above a reference,
//   M_a = integral m_w dA,   S_a = integral m_w z dA,   I_a = integral m_w z^2 dA,
// the face's added mass and its first and second moments, which couple the block's sliding and
// rocking (the face at height z moves horizontally by -z dtheta). For a vertical face wetted to
// depth d, about its foot: M_a = (7/12) rho_w sqrt(H) d^(3/2), acting 0.4 d above the foot,
// S_a = (7/30) rho_w sqrt(H) d^(5/2), I_a = (2/15) rho_w sqrt(H) d^(7/2).
//
// An inclined edge counts by its projected height (dA = |dy| per metre of dam): the pressure is
// taken as the vertical face's at the same depth, acting along the edge's normal, so its
// horizontal part on a length ds is p |n_x| ds = p |dy|. This is a simplification for sloping
// faces (Zangar 1952 gives their pressure; CADAM3D offers cos^2 and Corns et al. 1988 corrections),
// exact for a vertical face; the pressure's vertical part on an inclined face is left out.
//
// The integrals over each wetted piece are exact closed forms in the depth u = y_d, with
// Z = y_w - y_ref the surface's height above the reference:
//   integral sqrt(u) du = 2/3 u^(3/2),
//   integral sqrt(u) (Z - u) du = 2/3 Z u^(3/2) - 2/5 u^(5/2),
//   integral sqrt(u) (Z - u)^2 du = 2/3 Z^2 u^(3/2) - 4/5 Z u^(5/2) + 2/7 u^(7/2).
#pragma once

#include <cstddef>
#include <span>

#include "engine/water/water_load.hpp"
#include "engine/water/wetted_face.hpp"

namespace blockfrag {

struct AddedMass {
  double mass = 0.0;           // M_a, kg/m
  double first_moment = 0.0;   // S_a, kg m/m
  double second_moment = 0.0;  // I_a, kg m^2/m
};

// `reservoir_depth` H > 0 (the reservoir's depth at the dam, surface to bottom); the moments are
// about the height `reference_y` (the block's centre of mass, or its base). `crack_edges` as for
// the hydrostatic load (engine/water/wetted_face.hpp).
AddedMass westergaard_added_mass(std::span<const Vertex> polygon, double surface, double density,
                                 double reservoir_depth, std::span<const std::size_t> crack_edges,
                                 double reference_y);

// The added mass about the centre of mass `centre` (its y the reference), and how it changes as
// the block rises (d/dy: every depth and the surface's height above the centre fall by dy) and
// turns about its centre (d/dtheta: a point's depth falls by its x from the centre times dtheta).
// A piece's integrals depend on its ends' depths alone, and their derivative in a depth is the
// integrand there, which is zero at the surface: where a piece is cut by the surface, its cut end
// counts nothing.
struct AddedMassWithRates {
  AddedMass at, d_dy, d_dtheta;
};
AddedMassWithRates westergaard_added_mass_with_rates(std::span<const Vertex> polygon,
                                                     double surface, double density,
                                                     double reservoir_depth,
                                                     std::span<const std::size_t> crack_edges,
                                                     const Vertex& centre);

// Westergaard's added mass per unit area over the square root of the depth, (7/8) rho_w sqrt(H).
// Throws ContractViolation for H <= 0.
double westergaard_scale(double density, double reservoir_depth);

// The added mass and its rates about `centre` summed into `sums`, which must start at zero, over
// one pose's wetted pieces, each piece's terms added as add_added_mass_piece_in_full adds them, to
// the same bits: `scale` from westergaard_scale, `z` the surface's height above the centre.
class AddedMassPass {
 public:
  AddedMassPass(AddedMassWithRates& sums, double scale, double z, const Vertex& centre);
  // A piece whose b is at least as deep as its a, as visit_wetted_edge's are, cut by the surface
  // where its depth_a is zero.
  void add(const WettedPiece& piece);
  // The same for a piece known to be cut by the surface, or known to be wetted whole
  // (visit_wetted_edge_parts's).
  void add_cut(const WettedPiece& piece);
  void add_whole(const WettedPiece& piece);

 private:
  // At one end: the antiderivatives, the integrands and the antiderivatives' derivatives in Z
  // (whose M_a part is zero).
  struct EndTerms {
    AddedMass at, integrand;
    double dz_first, dz_second;
  };
  EndTerms end_terms(double depth) const;
  void add_cut_terms(const EndTerms& deep, double deep_x);
  void add_whole_terms(const EndTerms& deep, const EndTerms& shallow, double deep_x,
                       double shallow_x);

  AddedMassWithRates& out_;
  double scale_, z_, centre_x_;
  // z's products every end's terms take, found once a pose: (2/3) z, (2/3) z^2, (4/5) z, (4/3) z.
  double z23_, z23z_, z45_, z43_;
};

// One wetted piece's added mass and rates with both ends' terms whatever the depths, added to
// `out`: the plain sum AddedMassPass shortcuts.
void add_added_mass_piece_in_full(AddedMassWithRates& out, const WettedPiece& piece, double scale,
                                  double z, const Vertex& centre);

}  // namespace blockfrag
