// The block at rest under its reservoir, as a dam engineer checks it first (USACE EM 1110-2-2100,
// 2005, Stability Analysis of Concrete Structures; FERC's Engineering Guidelines chapter III,
// Gravity Dams): its loads, the constant ground accelerations at which it starts to slide or rock
// either way, and its safety factors, pseudo-static (a seismic coefficient K) and after the
// earthquake (full uplift, no seismic load). Per metre of dam, x downstream, the reservoir
// upstream.
//
// The loads at rest: the weight W = M g at the centre of mass; the hydrostatic push on the wetted
// upstream face; the crack's uplift, closed (engine/water/crack_pressure.hpp: c rho_w g h at the
// mouth falling linearly to zero at the end; none under the rule "none"); under a horizontal
// ground acceleration a (+x downstream), the block's inertia -M a at its centre of mass and
// Westergaard's hydrodynamic force -M_a a at the added mass's centroid (S_a / M_a above the
// centre of mass), M_a = 0 with "hydrodynamic": "none".
//
// The ground holds the block at its supports (engine/water/block_supports.hpp). It slides along a
// line of supports (the flat ground; a seat's segment) in a direction that lifts it off every other
// support, when the load's component along the line reaches mu times its push into it; it rocks
// about its downstream (upstream) outermost support when the loads' moment about it turns
// clockwise (counter-clockwise).
#pragma once

#include "engine/scene/block_state.hpp"
#include "engine/summary.hpp"
#include "engine/water/block_supports.hpp"

namespace blockfrag {

// The constant ground acceleration, in g, at which the block at rest starts each motion: sliding
// or rocking downstream needs the ground to accelerate upstream by this much (the inertia then
// pushes downstream), and the other way round. Closed forms: on a flat base, sliding
//   downstream (mu N0 - F0) / ((M + M_a) g),   upstream (mu N0 + F0) / ((M + M_a) g),
// with N0 = W - U - V the base's push (V: the water's vertical push on the face, + down) and F0 the
// static horizontal load (the hydrostatic push); rocking about a support P at height h_P below the
// centre of mass
//   M_P / (((M + M_a) h_P + S_a) g),
// M_P the static loads' resisting moment about P. Dry, on a flat base: mu, and b/a-type tip
// thresholds (x_G - x_P) / h_P. A negative value: the block moves without shaking. Infinite
// (+inf): no horizontal acceleration that way starts it (no line to slide along that way).
struct YieldAccelerations {
  double slide_downstream, slide_upstream, rock_downstream, rock_upstream;
};

// Resisting over driving, downstream: sliding mu N / T along the easiest line of supports the block
// can slide downstream on (the flat ground: mu (W - U + V) / H, H the horizontal loads), and
// overturning about the downstream support, the loads' counter-clockwise moments over their
// clockwise ones, each load's horizontal and vertical parts counted apart (the hydrostatic push
// overturns, the water's weight on an inclined face resists). +inf: nothing drives.
struct SafetyFactors {
  double sliding, overturning;
};

struct BlockStatics {
  double weight;                        // W = M g, N/m
  double hydrostatic_x, hydrostatic_y;  // N/m, + downstream and + up
  double uplift_x, uplift_y;            // N/m; uplift_y > 0 lifts
  double added_mass;                    // M_a, kg/m
  YieldAccelerations yield;
};

// The scene's block at rest (dry without a reservoir). The scene must be valid.
BlockStatics block_statics(const Scene& scene);

// Pseudo-static, at rest: the seismic coefficient K >= 0 puts K W at the centre of mass and
// K g M_a at the added mass's centroid, both downstream (the ground accelerating upstream by K g).
// Under "zero_in_gap" the crack opens from the heel as far as the heel needs under those loads.
SafetyFactors pseudo_static_safety_factors(const Scene& scene, double coefficient);

// After the earthquake: the block at rest at pose `final_pose` (engine/water/block_outline.hpp),
// held where it was held at rest (its supports and crack carried with it: a block back in its seat,
// or displaced by a slide small next to the block), under its reservoir with full uplift over its
// crack (the head at the mouth falling linearly to zero, effective area 1, whatever the scene's
// uplift rule and area factor) and no seismic load. The scene must be valid and have a reservoir.
SafetyFactors post_earthquake_safety_factors(const Scene& scene, const BlockState& final_pose);

// The summary's post-earthquake check of a run that ended at `final_pose`; `standing_at_rest`: the
// run succeeded and the block neither overturned nor fell, and rests at the end.
PostEarthquakeCheck post_earthquake_check(const Scene& scene, const BlockState& final_pose,
                                          bool standing_at_rest);

}  // namespace blockfrag
