#include "engine/water/reservoir_loads.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "engine/errors.hpp"
#include "engine/scene/block_geometry.hpp"
#include "engine/seat/turn_cache.hpp"
#include "engine/tolerances.hpp"
#include "engine/water/hydrostatic.hpp"
#include "engine/water/vertex_buffer.hpp"
#include "engine/water/wetted_face.hpp"

namespace blockfrag {

namespace {

bool same_double_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

}  // namespace

CrackPath rest_crack(const Scene& scene, const BlockOutline& outline) {
  const double tolerance = kContactHeight * scene_geometry(scene).size();
  const std::vector<Support> supports =
      scene_supports(scene, outline.rest_bottom(), outline.rest(), tolerance);
  if (supports.empty())
    throw ContractViolation("rest_crack: the block does not rest on its ground");
  return crack_under(outline.rest(), supports, tolerance);
}

ReservoirLoads::ReservoirLoads(const Scene& scene)
    : reservoir_(scene.reservoir.value()), g_(scene.g), outline_(scene) {
  crack_ = rest_crack(scene, outline_);
  crack_length_ = crack_.length();
  crack_lengths_ = segment_lengths(crack_.points);
  const double rest_head = std::max(0.0, reservoir_.level - crack_.points.front()[1]);
  unit_weight_ = reservoir_.density * g_;
  rest_mouth_pressure_ = reservoir_.uplift_area_factor * reservoir_.density * g_ * rest_head;
  added_mass_scale_ = reservoir_.hydrodynamic == Hydrodynamic::westergaard
                          ? westergaard_scale(reservoir_.density, reservoir_.depth)
                          : 0.0;
  const Vertex centre = outline_.rest_centre();
  for (Vertex& p : crack_.points) p = {p[0] - centre[0], p[1] - centre[1]};
  const std::vector<Vertex>& body = outline_.body();
  for (std::size_t i = 0; i < body.size(); ++i) {
    reach_ = std::max(reach_, std::abs(body[i][0]) + std::abs(body[i][1]));
    if (std::find(crack_.edges.begin(), crack_.edges.end(), i) != crack_.edges.end()) continue;
    const std::size_t next = i + 1 < body.size() ? i + 1 : 0;
    face_edges_.push_back({i, next, {body[next][0] - body[i][0], body[next][1] - body[i][1]}});
  }
  closed_uplifts_ = unit_uplifts(CrackOpening::closed());
  whole_uplifts_ = unit_uplifts(CrackOpening::whole());
}

ReservoirLoadSet ReservoirLoads::at(const BlockState& s, CrackOpening open) const {
  const ReservoirPose at_pose = pose(s);
  return {at_pose.hydrostatic, uplift(at_pose, open), at_pose.added.at, at_pose.added.d_dy,
          at_pose.added.d_dtheta};
}

// An edge that surely rises at the pose is dry (wetted_face.hpp): its ends are not placed; nor is
// the start of an edge whose end is at or above the surface, dry too. An end placed is the next
// edge's start.
template <class OnCut, class OnWhole>
void ReservoirLoads::visit_wetted_face(const Vertex& centre, const SineCosine& turn, OnCut&& on_cut,
                                       OnWhole&& on_whole) const {
  const double surely_rising = kSurelyRisingEdge * (std::abs(centre[1]) + reach_);
  std::size_t placed_index = outline_.body().size();
  Vertex placed{};
  for (const FaceEdge& edge : face_edges_) {
    if (edge.along[0] * turn.sin + edge.along[1] * turn.cos > surely_rising) continue;
    const bool from_placed = edge.from == placed_index;
    const Vertex previous = placed;
    placed = outline_.placed_vertex(edge.to, centre, turn);
    placed_index = edge.to;
    if (!(placed[1] < reservoir_.level)) continue;
    visit_wetted_edge_parts(
        from_placed ? previous : outline_.placed_vertex(edge.from, centre, turn), placed,
        reservoir_.level, on_cut, on_whole);
  }
}

// Every call it makes inlined: each wetted piece's push and added mass were a call apiece.
[[gnu::flatten]] ReservoirPose ReservoirLoads::pose(const BlockState& s) const {
  ReservoirPose out;
  out.turn = cached_turn(s.theta);
  out.centre = outline_.centre(s);
  const Vertex& centre = out.centre;
  // The push and the added mass in one pass over the wetted face; the added mass's pass set up
  // only under "westergaard".
  const auto add_push = [&](const WettedPiece& piece) {
    add_hydrostatic_piece(out.hydrostatic, piece, unit_weight_, centre);
  };
  if (reservoir_.hydrodynamic == Hydrodynamic::westergaard) {
    AddedMassPass added(out.added, added_mass_scale_, reservoir_.level - centre[1], centre);
    visit_wetted_face(
        centre, out.turn,
        [&](const WettedPiece& piece) {
          add_push(piece);
          added.add_cut(piece);
        },
        [&](const WettedPiece& piece) {
          add_push(piece);
          added.add_whole(piece);
        });
  } else {
    visit_wetted_face(centre, out.turn, add_push, add_push);
  }
  if (reservoir_.uplift == UpliftRule::none) return out;
  const double head = std::max(0.0, reservoir_.level - mouth_height(out));
  out.full_head = unit_weight_ * head;
  out.closed_mouth = reservoir_.uplift == UpliftRule::unchanged
                         ? rest_mouth_pressure_
                         : reservoir_.uplift_area_factor * out.full_head;
  return out;
}

WaterLoad ReservoirLoads::uplift(const ReservoirPose& at_pose, CrackOpening open) const {
  if (reservoir_.uplift == UpliftRule::none) return {};
  const auto is = [&](CrackOpening fixed) {
    return same_double_bits(open.from, fixed.from) && same_double_bits(open.to, fixed.to);
  };
  const UnitUplifts* unit = is(CrackOpening::closed())  ? &closed_uplifts_
                            : is(CrackOpening::whole()) ? &whole_uplifts_
                                                        : nullptr;
  if (unit != nullptr) {
    const WaterLoad &per_mouth = unit->per_closed_mouth, &per_head = unit->per_full_head;
    const double mouth = at_pose.closed_mouth, head = at_pose.full_head;
    const double fx = mouth * per_mouth.fx + head * per_head.fx;
    const double fy = mouth * per_mouth.fy + head * per_head.fy;
    const SineCosine& turn = at_pose.turn;
    return {turn.cos * fx - turn.sin * fy, turn.sin * fx + turn.cos * fy,
            mouth * per_mouth.moment + head * per_head.moment};
  }
  return placed_crack_uplift(at_pose, open);
}

WaterLoad ReservoirLoads::placed_crack_uplift(const ReservoirPose& at_pose,
                                              CrackOpening open) const {
  const CrackPressure pressure = crack_pressure(reservoir_.uplift, crack_length_,
                                                at_pose.closed_mouth, at_pose.full_head, open);
  VertexBuffer placed_crack(crack_.points.size());
  place_crack(crack_.points, at_pose.turn.cos, at_pose.turn.sin, at_pose.centre,
              placed_crack.vertices());
  return crack_pressure_load(placed_crack.vertices(), crack_lengths_, pressure, at_pose.centre);
}

ReservoirLoads::UnitUplifts ReservoirLoads::unit_uplifts(CrackOpening open) const {
  const auto per_unit = [&](double closed_mouth, double full_head) {
    return crack_pressure_load(
        crack_.points, crack_lengths_,
        crack_pressure(reservoir_.uplift, crack_length_, closed_mouth, full_head, open),
        {0.0, 0.0});
  };
  return {per_unit(1.0, 0.0), per_unit(0.0, 1.0)};
}

double ReservoirLoads::mouth_height(const ReservoirPose& pose) const {
  const Vertex& mouth = crack_.points.front();
  return pose.centre[1] + mouth[0] * pose.turn.sin + mouth[1] * pose.turn.cos;
}

}  // namespace blockfrag
