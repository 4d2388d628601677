// The reservoir's loads on the scene's block at any pose: what the dynamics add to the block's
// equations of motion, evaluated in one call. Per metre of dam (the block is a slice of unit
// thickness: its mass is per metre too), in the scene's frame (engine/scene/reservoir.hpp).
//   hydrostatic: rho_w g (level - y) over the wetted upstream face at the pose
//     (engine/water/hydrostatic.hpp);
//   uplift: the crack's water under the scene's rule, the crack closed or opened as the caller
//     says (engine/water/crack_pressure.hpp);
//   added mass: Westergaard's on the wetted face and its rates, "westergaard" only
//     (engine/water/westergaard.hpp).
// The crack is the block's at rest (engine/water/crack_path.hpp): on the flat ground its base, on a
// seat its outline between the outermost points where the seat holds it. It moves with the block:
// the pressure acts on the block's own base, along its normals, whatever the pose.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/scene/block_state.hpp"
#include "engine/water/block_outline.hpp"
#include "engine/water/crack_path.hpp"
#include "engine/water/crack_pressure.hpp"
#include "engine/water/westergaard.hpp"

namespace blockfrag {

struct ReservoirLoadSet {
  WaterLoad hydrostatic;  // force and moment about the centre of mass
  WaterLoad uplift;       // force and moment about the centre of mass
  AddedMass added_mass;   // M_a, and S_a, I_a about the centre of mass's height
  // How added_mass changes as the block rises and turns (westergaard_added_mass_with_rates).
  AddedMass added_mass_d_dy, added_mass_d_dtheta;
};

// What the loads at a pose share whatever the crack's opening: the hydrostatic push, the added mass
// with its rates, and the crack's pressures at the mouth.
struct ReservoirPose {
  Vertex centre;    // the centre of mass
  SineCosine turn;  // the block's tilt
  WaterLoad hydrostatic;
  AddedMassWithRates added;
  double closed_mouth = 0.0, full_head = 0.0;  // crack_pressure's, "none" aside
};

class ReservoirLoads {
 public:
  // The scene must be valid and have a reservoir.
  explicit ReservoirLoads(const Scene& scene);

  // The water rises above the block's lowest point at rest: without that, every load is zero at
  // rest and a scene is the dry scene's.
  bool wets() const { return reservoir_.level > outline_.rest_bottom(); }
  // The crack at rest about the centre of mass, unturned (its points), and the block's edges along
  // it.
  const CrackPath& crack() const { return crack_; }
  UpliftRule uplift_rule() const { return reservoir_.uplift; }

  // The loads at pose s (BlockState in the ground's frame: engine/water/block_outline.hpp), the
  // crack's part [open.from, open.to] opened (closed at rest and sliding, whole when rocking about
  // either end of the base or in flight). The head at the crack's mouth is the mouth's depth below
  // the surface at the pose, but under "unchanged", which keeps the pre-earthquake head and
  // pressure on the block.
  ReservoirLoadSet at(const BlockState& s, CrackOpening open) const;
  // The same in two parts, for a caller that tries several openings at one pose: the pose's and
  // the uplift at an opening.
  ReservoirPose pose(const BlockState& s) const;
  WaterLoad uplift(const ReservoirPose& pose, CrackOpening open) const;

 private:
  // Calls on_cut and on_whole (visit_wetted_edge_parts) with each wetted piece of the face at the
  // pose whose centre of mass is `centre`.
  template <class OnCut, class OnWhole>
  void visit_wetted_face(const Vertex& centre, const SineCosine& turn, OnCut&& on_cut,
                         OnWhole&& on_whole) const;
  // The height of the crack's mouth at the pose: a mouth on a vertex to the bits of the vertex
  // placed there (its point at rest is the vertex's).
  double mouth_height(const ReservoirPose& pose) const;

  Reservoir reservoir_;
  double g_;
  BlockOutline outline_;
  CrackPath crack_;
  double crack_length_;
  std::vector<double> crack_lengths_;  // of its straight pieces, at rest
  // The outline's edges the reservoir may wet (all but the crack's), from vertex `from` to vertex
  // `to`, and the edge at rest (to less from), unturned.
  struct FaceEdge {
    std::size_t from, to;
    Vertex along;
  };
  std::vector<FaceEdge> face_edges_;
  double reach_ = 0.0;  // the most |x| + |y| of a vertex from the centre of mass, unturned
  // The closed crack's and the whole open crack's uplift (a seated and a lifted block's: every
  // right-hand side asks for one of them) on the unturned block about its centre of mass, per unit
  // of each pressure crack_pressure takes: linear in both, the uplift at a pose is their sum
  // turned with the block (the moment about the centre unchanged).
  struct UnitUplifts {
    WaterLoad per_closed_mouth, per_full_head;
  };
  UnitUplifts unit_uplifts(CrackOpening open) const;
  // The uplift at any other opening: the crack placed at the pose and its pressure integrated.
  WaterLoad placed_crack_uplift(const ReservoirPose& pose, CrackOpening open) const;
  UnitUplifts closed_uplifts_, whole_uplifts_;
  double unit_weight_;          // rho_w g
  double rest_mouth_pressure_;  // c rho_w g h at rest
  double added_mass_scale_;     // westergaard_scale, "westergaard" only
};

// The crack of the scene's block at rest, in the scene's frame.
CrackPath rest_crack(const Scene& scene, const BlockOutline& outline);

}  // namespace blockfrag
