#include "engine/water/westergaard.hpp"

#include <algorithm>
#include <cmath>

#include "engine/errors.hpp"

namespace blockfrag {

namespace {

// A depth u's square root and its powers u^(3/2), u^(5/2), u^(7/2): one square root per depth for
// its antiderivatives, integrands and derivatives in Z alike.
struct DepthPowers {
  double root, u32, u52, u72;
};
DepthPowers depth_powers(double u) {
  const double root = std::sqrt(u);
  const double u32 = u * root, u52 = u32 * u;
  return {root, u32, u52, u52 * u};
}

// The antiderivatives in the depth u of sqrt(u), sqrt(u) (Z - u) and sqrt(u) (Z - u)^2.
AddedMass depth_antiderivatives(const DepthPowers& p, double z) {
  return {2.0 / 3.0 * p.u32, 2.0 / 3.0 * z * p.u32 - 2.0 / 5.0 * p.u52,
          2.0 / 3.0 * z * z * p.u32 - 4.0 / 5.0 * z * p.u52 + 2.0 / 7.0 * p.u72};
}

// The integrands: the antiderivatives' derivatives in u, and in Z.
AddedMass depth_integrands(double u, const DepthPowers& p, double z) {
  return {p.root, p.root * (z - u), p.root * (z - u) * (z - u)};
}
AddedMass surface_height_derivatives(const DepthPowers& p, double z) {
  return {0.0, 2.0 / 3.0 * p.u32, 4.0 / 3.0 * z * p.u32 - 4.0 / 5.0 * p.u52};
}

void add_scaled(AddedMass& total, double scale, const AddedMass& a) {
  total.mass += scale * a.mass;
  total.first_moment += scale * a.first_moment;
  total.second_moment += scale * a.second_moment;
}

}  // namespace

double westergaard_scale(double density, double reservoir_depth) {
  if (!(reservoir_depth > 0.0)) {
    throw ContractViolation("westergaard_added_mass: the reservoir's depth must be > 0");
  }
  return 7.0 / 8.0 * density * std::sqrt(reservoir_depth);
}

AddedMassPass::AddedMassPass(AddedMassWithRates& sums, double scale, double z, const Vertex& centre)
    : out_(sums),
      scale_(scale),
      z_(z),
      centre_x_(centre[0]),
      z23_(2.0 / 3.0 * z),
      z23z_(z23_ * z),
      z45_(4.0 / 5.0 * z),
      z43_(4.0 / 3.0 * z) {}

// depth_powers, depth_antiderivatives, depth_integrands and surface_height_derivatives, with z's
// products found once a pose.
AddedMassPass::EndTerms AddedMassPass::end_terms(double depth) const {
  const DepthPowers p = depth_powers(depth);
  const double below = z_ - depth;
  const double first = p.root * below;
  return {{2.0 / 3.0 * p.u32, z23_ * p.u32 - 2.0 / 5.0 * p.u52,
           z23z_ * p.u32 - z45_ * p.u52 + 2.0 / 7.0 * p.u72},
          {p.root, first, first * below},
          2.0 / 3.0 * p.u32,
          z43_ * p.u32 - 4.0 / 5.0 * p.u52};
}

void AddedMassPass::add(const WettedPiece& piece) {
  if (piece.depth_a == 0.0) {
    add_cut(piece);
  } else {
    add_whole(piece);
  }
}

void AddedMassPass::add_cut(const WettedPiece& piece) {
  add_cut_terms(end_terms(piece.depth_b), piece.b[0] - centre_x_);
}

void AddedMassPass::add_whole(const WettedPiece& piece) {
  add_whole_terms(end_terms(piece.depth_b), end_terms(piece.depth_a), piece.b[0] - centre_x_,
                  piece.a[0] - centre_x_);
}

// A piece cut by the surface: its shallow end's antiderivatives, integrands and derivatives are
// zeros (of either sign), and a zero added to a sum that started at +0 leaves it as it was (in
// round-to-nearest such a sum is never -0), so the deep end's terms alone give the full sums'
// bits. The derivatives in Z add their M_a part, zero, to no effect for the same reason.
void AddedMassPass::add_cut_terms(const EndTerms& deep, double deep_x) {
  out_.at.mass += scale_ * deep.at.mass;
  out_.at.first_moment += scale_ * deep.at.first_moment;
  out_.at.second_moment += scale_ * deep.at.second_moment;
  add_scaled(out_.d_dy, -scale_, deep.integrand);
  out_.d_dy.first_moment += -scale_ * deep.dz_first;
  out_.d_dy.second_moment += -scale_ * deep.dz_second;
  add_scaled(out_.d_dtheta, -scale_ * deep_x, deep.integrand);
}

void AddedMassPass::add_whole_terms(const EndTerms& deep, const EndTerms& shallow, double deep_x,
                                    double shallow_x) {
  out_.at.mass += scale_ * (deep.at.mass - shallow.at.mass);
  out_.at.first_moment += scale_ * (deep.at.first_moment - shallow.at.first_moment);
  out_.at.second_moment += scale_ * (deep.at.second_moment - shallow.at.second_moment);
  add_scaled(out_.d_dy, -scale_, deep.integrand);
  add_scaled(out_.d_dy, scale_, shallow.integrand);
  out_.d_dy.first_moment += -scale_ * deep.dz_first;
  out_.d_dy.second_moment += -scale_ * deep.dz_second;
  out_.d_dy.first_moment += scale_ * shallow.dz_first;
  out_.d_dy.second_moment += scale_ * shallow.dz_second;
  add_scaled(out_.d_dtheta, -scale_ * deep_x, deep.integrand);
  add_scaled(out_.d_dtheta, scale_ * shallow_x, shallow.integrand);
}

void add_added_mass_piece_in_full(AddedMassWithRates& out, const WettedPiece& piece, double scale,
                                  double z, const Vertex& centre) {
  const bool a_deeper = piece.depth_a > piece.depth_b;
  const double deep = a_deeper ? piece.depth_a : piece.depth_b;
  const double shallow = a_deeper ? piece.depth_b : piece.depth_a;
  const double deep_x = (a_deeper ? piece.a : piece.b)[0] - centre[0];
  const double shallow_x = (a_deeper ? piece.b : piece.a)[0] - centre[0];
  const DepthPowers p_deep = depth_powers(deep), p_shallow = depth_powers(shallow);
  const AddedMass at_deep = depth_antiderivatives(p_deep, z);
  const AddedMass at_shallow = depth_antiderivatives(p_shallow, z);
  out.at.mass += scale * (at_deep.mass - at_shallow.mass);
  out.at.first_moment += scale * (at_deep.first_moment - at_shallow.first_moment);
  out.at.second_moment += scale * (at_deep.second_moment - at_shallow.second_moment);
  const AddedMass f_deep = depth_integrands(deep, p_deep, z);
  const AddedMass f_shallow = depth_integrands(shallow, p_shallow, z);
  // Rising by dy: both depths and Z fall by dy.
  add_scaled(out.d_dy, -scale, f_deep);
  add_scaled(out.d_dy, scale, f_shallow);
  add_scaled(out.d_dy, -scale, surface_height_derivatives(p_deep, z));
  add_scaled(out.d_dy, scale, surface_height_derivatives(p_shallow, z));
  // Turning by dtheta: a point at x from the centre rises by x dtheta.
  add_scaled(out.d_dtheta, -scale * deep_x, f_deep);
  add_scaled(out.d_dtheta, scale * shallow_x, f_shallow);
}

AddedMassWithRates westergaard_added_mass_with_rates(std::span<const Vertex> polygon,
                                                     double surface, double density,
                                                     double reservoir_depth,
                                                     std::span<const std::size_t> crack_edges,
                                                     const Vertex& centre) {
  const double scale = westergaard_scale(density, reservoir_depth);
  const double z = surface - centre[1];
  AddedMassWithRates out;
  AddedMassPass pass(out, scale, z, centre);
  for_each_wetted_piece(polygon, surface, crack_edges,
                        [&](const WettedPiece& piece) { pass.add(piece); });
  return out;
}

AddedMass westergaard_added_mass(std::span<const Vertex> polygon, double surface, double density,
                                 double reservoir_depth, std::span<const std::size_t> crack_edges,
                                 double reference_y) {
  const double scale = westergaard_scale(density, reservoir_depth);
  const double z = surface - reference_y;  // the surface's height above the reference
  AddedMass total;
  for_each_wetted_piece(polygon, surface, crack_edges, [&](const WettedPiece& piece) {
    // Over the piece's projected height, from its shallow end to its deep end.
    const AddedMass shallow =
        depth_antiderivatives(depth_powers(std::min(piece.depth_a, piece.depth_b)), z);
    const AddedMass deep =
        depth_antiderivatives(depth_powers(std::max(piece.depth_a, piece.depth_b)), z);
    total.mass += scale * (deep.mass - shallow.mass);
    total.first_moment += scale * (deep.first_moment - shallow.first_moment);
    total.second_moment += scale * (deep.second_moment - shallow.second_moment);
  });
  return total;
}

}  // namespace blockfrag
