# Precompiled headers. About half of a translation unit's compile time went to parsing the standard library,
# Eigen and nlohmann-json again (g++ -fsyntax-only on a test: 5.3 of 10 s); each library and the command parse
# them once instead, and every test reuses one parse (tests/CMakeLists.txt). Only third-party headers are
# precompiled, so editing a skinfem header rebuilds what includes it and nothing more. -Winvalid-pch warns if
# GCC ever ignores a precompiled header (a flag that differs between the owner and a reuser).
option(SKINFEM_PCH "precompile the standard, Eigen and nlohmann-json headers" ON)
set(skinfem_pch_std <algorithm> <array> <cmath> <cstdio> <functional> <map> <memory> <optional> <sstream>
  <stdexcept> <string> <vector>)
set(skinfem_pch_eigen <Eigen/Dense> <Eigen/Sparse>)
set(skinfem_pch_json <nlohmann/json.hpp>)

# skinfem_precompile(target [headers...]): the standard headers and those given, precompiled for target.
function(skinfem_precompile target)
  if(SKINFEM_PCH)
    target_precompile_headers(${target} PRIVATE ${skinfem_pch_std} ${ARGN})
    target_compile_options(${target} PRIVATE -Winvalid-pch)
  endif()
endfunction()

# skinfem_reuse_precompiled(target owner): target compiles against owner's precompiled headers (same flags).
function(skinfem_reuse_precompiled target owner)
  if(SKINFEM_PCH)
    target_precompile_headers(${target} REUSE_FROM ${owner})
    target_compile_options(${target} PRIVATE -Winvalid-pch)
  endif()
endfunction()
