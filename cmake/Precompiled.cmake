# Precompiled headers. Eigen's dense and sparse modules with the standard headers most files use take about 1.5 s
# of processor time to parse, in each of some two hundred source files; precompiled once per set of flags, each file
# loads them in a fraction of that. CI compiles the tree twice (Release, then the sanitizers' build), so this is
# several minutes of its time. The library's files have a header of their own (their flag -fno-math-errno changes
# what <cmath> defines); the chapter programs share one; the tests' adds doctest. The library is left out when
# clang-tidy is to read this build's compile_commands.json (the default, as .ci/run does): clang-tidy cannot read
# GCC's precompiled header and would report it as an error. -DCLOTH_PCH=OFF compiles every file from its headers.
# Under ccache (-DCMAKE_CXX_COMPILER_LAUNCHER=ccache) it is off by default: ccache compiles a file that uses a
# precompiled header without caching it (unless its sloppiness settings allow it), and a file it has cached costs
# nothing to compile anyway.
if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache")
  set(cloth_pch_default OFF)
else()
  set(cloth_pch_default ON)
endif()
option(CLOTH_PCH "Precompile Eigen's and the standard library's headers (and doctest's for the tests)"
       ${cloth_pch_default})
option(CLOTH_PCH_LIBRARY "Also precompile them for the library's own files (clang-tidy cannot then read src/)" OFF)

set(CLOTH_PCH_HEADERS <Eigen/Dense> <Eigen/Sparse> <algorithm> <array> <cmath> <cstdio> <functional> <limits>
    <map> <memory> <optional> <sstream> <stdexcept> <string> <utility> <vector>)

# cloth_precompile_programs(target...): the chapter programs' and tools' shared header, compiled once (for the
# first target) and reused by the others, whose flags are the same.
function(cloth_precompile_programs)
  if(NOT CLOTH_PCH)
    return()
  endif()
  get_property(owner GLOBAL PROPERTY CLOTH_PCH_PROGRAM_OWNER)
  foreach(target IN LISTS ARGN)
    if(NOT owner)
      target_precompile_headers(${target} PRIVATE ${CLOTH_PCH_HEADERS})
      set(owner ${target})
      set_property(GLOBAL PROPERTY CLOTH_PCH_PROGRAM_OWNER ${owner})
    else()
      target_precompile_headers(${target} REUSE_FROM ${owner})
    endif()
  endforeach()
endfunction()
