// The machine's available memory (MemAvailable of /proc/meminfo), for refusing work that cannot fit.
#pragma once

namespace skinfem {

double available_memory_mb();  // 0 when unknown

}  // namespace skinfem
