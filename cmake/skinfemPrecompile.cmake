# Build speed: precompiled headers, unity builds, the sanitizer build's front ends at -O1 and its suites
# without UndefinedBehaviorSanitizer.
#
# Precompiled headers. About half of a translation unit's compile time went to parsing the standard library,
# Eigen and nlohmann-json again (g++ -fsyntax-only on a test: 5.3 of 10 s); each library and the command parse
# them once instead, and every test reuses one parse (tests/CMakeLists.txt). Only third-party headers are
# precompiled, so editing a skinfem header rebuilds what includes it and nothing more. -Winvalid-pch warns if
# GCC ever ignores a precompiled header (a flag that differs between the owner and a reuser).
option(SKINFEM_PCH "precompile the standard, Eigen and nlohmann-json headers" ON)
# Unity builds: each library compiles its sources in batches of 8, one translation unit a batch, so the Eigen
# kernels several sources share are instantiated and optimised once per batch instead of once per source
# (the sanitizer build: 610 s one source at a time, 507 s in batches, on 2 cores).
# Names in anonymous namespaces must therefore be unique within a library.
option(SKINFEM_UNITY "compile each library's sources in batches (unity build)" ON)
set(skinfem_pch_std <algorithm> <array> <cmath> <cstdio> <functional> <map> <memory> <optional> <sstream>
  <stdexcept> <string> <vector>)
set(skinfem_pch_eigen <Eigen/Dense> <Eigen/Sparse>)
set(skinfem_pch_json <nlohmann/json.hpp>)

# skinfem_fast_compile(target [headers...]): the standard headers and those given, precompiled for target; its
# sources compiled in unity batches.
function(skinfem_fast_compile target)
  if(SKINFEM_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
    # In a batch each source is an included file, so GCC takes a class of an anonymous namespace held by a
    # pimpl (mesh/locate.cpp, fem/base_traction.cpp) for one declared in a header.
    target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
  endif()
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

# skinfem_front_end(target [ALWAYS]): target compiles at -O1 under the sanitizers (SKINFEM_SANITIZE), with ALWAYS
# in every build, instead of the build type's -O2 or -O3. For the command and the Python module (under the
# sanitizers) and the test suites (always): their own code sets up, sequences and checks calls into the
# libraries, which keep the build's level and do the numerical work, so their compile time falls by about a
# third under the sanitizers while the passes run as long (tests/README.md, "Time budget"). A precompiled
# header keeps the level it was made with, so the targets that share one (tests/CMakeLists.txt) all take the same.
function(skinfem_front_end target)
  if(SKINFEM_SANITIZE OR "ALWAYS" IN_LIST ARGN)
    target_compile_options(${target} PRIVATE -O1)
  endif()
endfunction()

# skinfem_test_sanitizers(target): under the sanitizers a test suite keeps AddressSanitizer and leaves out
# UndefinedBehaviorSanitizer. The suites set up, sequence and check calls into the libraries, which keep both
# (all the numerical code is theirs); UBSan's checks in the suites' own code doubled their compile time
# (tests/contact/test_lcp.cpp: 33 s with both, 18 s with AddressSanitizer alone), about 2 min of CI's
# sanitizer build. The runtime is linked as before, for the libraries.
function(skinfem_test_sanitizers target)
  if(SKINFEM_SANITIZE)
    target_compile_options(${target} PRIVATE -fno-sanitize=undefined)
  endif()
endfunction()
