// Numbers into the sentences the verdicts print (every sentence is built from the numbers it states).
#pragma once

#include <cstdio>
#include <string>

namespace skinfem::validation {

// One value through a printf format with a single conversion, e.g. fmt("%.2f", 1.234) = "1.23".
inline std::string fmt(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

}  // namespace skinfem::validation
