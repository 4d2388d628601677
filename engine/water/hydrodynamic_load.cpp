#include "engine/water/hydrodynamic_load.hpp"

#include <cmath>
#include <utility>

#include "engine/water/vertex_buffer.hpp"
#include "engine/water/westergaard.hpp"

namespace blockfrag {

WorldPolygon world_polygon(const std::vector<Vertex>& body, double x, double y, double theta) {
  WorldPolygon out(body.size());
  place_body(body, x, y, theta, out);
  return out;
}

void place_body(const std::vector<Vertex>& body, double x, double y, double theta,
                std::span<Vertex> out) {
  const double c = std::cos(theta), s = std::sin(theta);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vertex& v = body[i];
    out[i] = {x + c * v[0] - s * v[1], y + s * v[0] + c * v[1]};
  }
}

HydrodynamicLoad::HydrodynamicLoad(WettedBlock block, double surface, double density,
                                   double reservoir_depth)
    : block_(std::move(block)),
      surface_(surface),
      density_(density),
      reservoir_depth_(reservoir_depth) {}

LoadAddition HydrodynamicLoad::at(const BlockState& s, double lambda, double g, Footing) const {
  VertexBuffer world(block_.body.size());
  place_body(block_.body, 0.0, s.y, s.theta, world.vertices());
  return from_rates(
      westergaard_added_mass_with_rates(world.vertices(), surface_, density_, reservoir_depth_,
                                        block_.crack_edges, {0.0, s.y}),
      s, lambda, g);
}

LoadAddition HydrodynamicLoad::from_rates(const AddedMassWithRates& a, const BlockState& s,
                                          double lambda, double g) const {
  const Matrix m = per_mass(a.at);
  LoadAddition out;
  out.xx = m.xx;
  out.xtheta = m.xtheta;
  out.thetatheta = m.thetatheta;
  // The ground frame's inertial force on the added mass.
  out.force.x = m.xx * lambda * g;
  out.moment = m.xtheta * lambda * g;
  const Matrix dy = per_mass(a.d_dy), dt = per_mass(a.d_dtheta);
  const auto quadratic = [&](const Matrix& d) {
    return d.xx * s.vx * s.vx + 2.0 * d.xtheta * s.vx * s.omega + d.thetatheta * s.omega * s.omega;
  };
  // A' = dA/dy y' + dA/dtheta theta'.
  const Matrix rate{dy.xx * s.vy + dt.xx * s.omega, dy.xtheta * s.vy + dt.xtheta * s.omega,
                    dy.thetatheta * s.vy + dt.thetatheta * s.omega};
  out.force.x -= rate.xx * s.vx + rate.xtheta * s.omega;
  out.force.y += 0.5 * quadratic(dy);
  out.moment += -(rate.xtheta * s.vx + rate.thetatheta * s.omega) + 0.5 * quadratic(dt);
  return out;
}

HydrodynamicLoad::Matrix HydrodynamicLoad::per_mass(const AddedMass& a) const {
  return {a.mass / block_.mass, -a.first_moment / block_.mass, a.second_moment / block_.mass};
}

}  // namespace blockfrag
