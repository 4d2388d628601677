#include "engine/water/hydrodynamic_load.hpp"

#include <cmath>
#include <utility>

#include "engine/water/westergaard.hpp"

namespace blockfrag {

namespace {

constexpr double kLengthStep = 1e-4;  // of the block's size
constexpr double kAngleStep = 1e-4;   // rad

}  // namespace

WorldPolygon world_polygon(const std::vector<Vertex>& body, double x, double y, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  WorldPolygon out;
  out.reserve(body.size());
  for (const Vertex& v : body) out.push_back({x + c * v[0] - s * v[1], y + s * v[0] + c * v[1]});
  return out;
}

HydrodynamicLoad::HydrodynamicLoad(WettedBlock block, double surface, double density,
                                   double reservoir_depth)
    : block_(std::move(block)),
      surface_(surface),
      density_(density),
      reservoir_depth_(reservoir_depth) {}

HydrodynamicLoad::Matrix HydrodynamicLoad::added(double y, double theta) const {
  const AddedMass a = westergaard_added_mass(world_polygon(block_.body, 0.0, y, theta), surface_,
                                             density_, reservoir_depth_, block_.crack_edges, y);
  return {a.mass / block_.mass, -a.first_moment / block_.mass, a.second_moment / block_.mass};
}

LoadAddition HydrodynamicLoad::at(const BlockState& s, double lambda, double g, Footing) const {
  const Matrix a = added(s.y, s.theta);
  LoadAddition out;
  out.xx = a.xx;
  out.xtheta = a.xtheta;
  out.thetatheta = a.thetatheta;
  // The ground frame's inertial force on the added mass.
  out.force.x = a.xx * lambda * g;
  out.moment = a.xtheta * lambda * g;
  if (s.vx == 0.0 && s.vy == 0.0 && s.omega == 0.0) return out;
  const double hy = kLengthStep * block_.size, ht = kAngleStep;
  const Matrix up = added(s.y + hy, s.theta), down = added(s.y - hy, s.theta);
  const Matrix turned = added(s.y, s.theta + ht), back = added(s.y, s.theta - ht);
  const Matrix dy{(up.xx - down.xx) / (2 * hy), (up.xtheta - down.xtheta) / (2 * hy),
                  (up.thetatheta - down.thetatheta) / (2 * hy)};
  const Matrix dt{(turned.xx - back.xx) / (2 * ht), (turned.xtheta - back.xtheta) / (2 * ht),
                  (turned.thetatheta - back.thetatheta) / (2 * ht)};
  const auto quadratic = [&](const Matrix& m) {
    return m.xx * s.vx * s.vx + 2.0 * m.xtheta * s.vx * s.omega + m.thetatheta * s.omega * s.omega;
  };
  // A' = dA/dy y' + dA/dtheta theta'.
  const Matrix rate{dy.xx * s.vy + dt.xx * s.omega, dy.xtheta * s.vy + dt.xtheta * s.omega,
                    dy.thetatheta * s.vy + dt.thetatheta * s.omega};
  out.force.x -= rate.xx * s.vx + rate.xtheta * s.omega;
  out.force.y += 0.5 * quadratic(dy);
  out.moment += -(rate.xtheta * s.vx + rate.thetatheta * s.omega) + 0.5 * quadratic(dt);
  return out;
}

}  // namespace blockfrag
