// The paper's type B dam block and its seat, heel at the origin, upstream on the left, as
// docs/references.md ("The paper's type B dam block") derives them.
#pragma once

#include <array>
#include <vector>

namespace blockfrag::testing {

inline constexpr double kFoldX = 703.0 / 120.0;
inline constexpr double kToeX = 12.525, kToeY = 5.0;
inline constexpr double kBreakY = 251.0 / 30.0;
inline const std::vector<std::array<double, 2>> kTypeB = {
    {0, 0}, {kFoldX, 0}, {kToeX, kToeY}, {10, kBreakY}, {10, 21.7}, {0, 21.7}};
inline const std::vector<std::array<double, 2>> kTypeBSeat = {{0, 0}, {kFoldX, 0}, {kToeX, kToeY}};

}  // namespace blockfrag::testing
