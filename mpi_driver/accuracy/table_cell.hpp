// Numbers in the accuracy study's Markdown tables.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace blockfrag {

// x in a printf format ("%.3g", "%.2e"); an infinite error (a setting that gave no result) reads
// "inf" whatever its sign.
inline std::string table_cell(double x, const char* format) {
  if (std::isinf(x)) return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

}  // namespace blockfrag
