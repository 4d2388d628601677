// The paper's block and gravity, which most physics tests share: a rectangle of half-width
// a = 0.5 m and half-height b = 1 m (R = sqrt(1.25) m) under g = 9.81 m/s^2, the scenes' default.
// Their names are long so that a test's own a, b and g (the paper's letters) never hide them.
#pragma once

#include <numbers>

#include "engine/scene/block_geometry.hpp"

namespace blockfrag::testing {

inline constexpr double kGravity = 9.81;
inline constexpr double kPaperHalfWidth = 0.5;
inline constexpr double kPaperHalfHeight = 1.0;
inline constexpr double pi = std::numbers::pi;
// A fresh geometry per call: a geometry remembers the last angle it turned the block by, so each
// test holds its own.
inline BlockGeometry paper_block() {
  return BlockGeometry(RectangularBlock{kPaperHalfWidth, kPaperHalfHeight, 1.0});
}

}  // namespace blockfrag::testing
