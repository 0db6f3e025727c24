#include "skinfem/fem/memory.hpp"

#include <fstream>
#include <string>

namespace skinfem {

double available_memory_mb() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kb = 0;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb / 1024;
  return 0;
}

}  // namespace skinfem
