#include "engine/modes/modes.hpp"

namespace blockfrag {

ModeKind mode_kind(const Mode& mode) {
  switch (mode.index()) {
    case 0: return ModeKind::rest;
    case 1: return ModeKind::slide;
    case 2: return ModeKind::rock;
    case 3: return ModeKind::slide_rock;
    default: return ModeKind::flight;
  }
}

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
