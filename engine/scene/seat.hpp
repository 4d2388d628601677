// The ground under the block when it is not one flat line: a seat, a polyline of segments from left
// to right (the paper's type B dam block rests on a horizontal segment and an incline; a flat seat
// is one segment, or several collinear ones). Beyond the seat's ends there is no ground. What a
// seat must be for its block to rest on it, and where the block touches it at rest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/scene/polygon_properties.hpp"
#include "engine/scene/scene.hpp"

namespace blockfrag {

// Why a seat cannot carry its block; `point` is the offending seat point when one can be named,
// else -1 (the seat as a whole, or its fit with the block).
struct SeatDefect {
  int point;
  std::string rule;
};

// A contact of the block resting on its seat: the point (in the frame of the block's vertices) and
// the unit normal of the seat's push on the block there.
struct RestContact {
  Vertex point, normal;
};

// The rules, in the frame of the block's vertices (block: counter-clockwise, without polygon
// defects): at least 2 finite points with x strictly increasing (the ground is a height over x, so
// "below the seat" means something), and the block fits the seat at rest: no block vertex below
// it, no seat point inside the block, no block edge crossing a seat segment, and the weight
// carried by the seat's normal pushes at the contacts alone. Friction is not counted on: a block
// that needs friction to rest would start to slide with a smaller mu, so a scene's rest would
// depend on its inputs. `tolerance` (m): how far a vertex may miss the seat and still touch it.
std::optional<SeatDefect> seat_defect(const std::vector<Vertex>& seat,
                                      const std::vector<Vertex>& block, double tolerance);

// The contacts of the block at rest: each block vertex within `tolerance` of a seat segment (with
// that segment's upward normal; a vertex at a seat point gets both segments' normals) and each seat
// point within `tolerance` of a block edge (with the edge's inward normal). Where a block vertex
// meets a seat point (the type B block's heel and fold) this lists the normals of all four edges
// there, not all of which a contact law would use (the seat's end under the heel does not push
// on the upstream face): for the weight check a permissive reading of such a contact.
std::vector<RestContact> rest_contacts(const std::vector<Vertex>& seat,
                                       const std::vector<Vertex>& block, double tolerance);

// The tilt at which the block resting on its seat balances on its outermost support: the lesser
// of the angles that turn its centre of mass over the leftmost and over the rightmost point where
// it touches (about the leftmost counter-clockwise, about the rightmost clockwise). On a flat seat
// these are the base's corners, and the angle is the flat ground's alpha. A block that does not
// touch the seat (a scene seat_defect refuses) has no support: InvalidInput.
double seat_alpha(const std::vector<Vertex>& seat, const std::vector<Vertex>& block,
                  double tolerance);

// Where the block resting on its seat is released from when it starts tilted by theta
// (counter-clockwise > 0): turned about the leftmost point where it touches for theta > 0, the
// rightmost for theta < 0, as the flat ground releases it on the base corner the tilt lowers (flat,
// the side turning's sign says: the rightmost for turning < 0); as seat_alpha, InvalidInput for a
// block that does not touch the seat.
struct SeatTilt {
  Vertex pivot;                  // the point it turns about, in the frame of the block's vertices
  std::vector<Vertex> vertices;  // the block's vertices turned about it
  Vertex centre;                 // its centre of mass turned about it
};
SeatTilt tilt_on_seat(const std::vector<Vertex>& seat, const std::vector<Vertex>& block,
                      double theta, double tolerance, double turning = 0.0);

// Why the block resting on its seat cannot be released tilted by theta, as a rule's text: turned
// about its pivot, it would enter the seat (a vertex below it, a seat point inside the block, an
// edge crossing a segment: a face pressed into an incline next to it).
std::optional<std::string> tilt_defect(const std::vector<Vertex>& seat,
                                       const std::vector<Vertex>& block, double theta,
                                       double tolerance);

// The scene's block as vertices in its own frame: the polygon, or the rectangle's corners about
// its centre, counter-clockwise from the base's left end.
std::vector<Vertex> scene_block_vertices(const Scene& scene);
// The lowest y of those vertices: the flat ground's height in that frame.
double lowest_block_y(const Scene& scene);

}  // namespace blockfrag
