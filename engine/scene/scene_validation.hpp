// The engine's own check of a scene (configs are validated with JSON paths before they get here;
// this keeps a library caller from running a scene the physics does not define).
#pragma once

#include "engine/scene/scene.hpp"

namespace blockfrag {

// Throws InvalidInput naming the first rule broken.
void validate_scene(const Scene& scene);

}  // namespace blockfrag
