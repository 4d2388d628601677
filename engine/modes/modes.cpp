#include "engine/modes/modes.hpp"

namespace blockfrag {

const char* mode_name(ModeKind mode) {
  switch (mode) {
    case ModeKind::rest: return "rest";
    case ModeKind::slide: return "slide";
    case ModeKind::rock: return "rock";
    case ModeKind::slide_rock: return "slide_rock";
    case ModeKind::flight: return "flight";
  }
  return "unknown";
}

}  // namespace blockfrag
