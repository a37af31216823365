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

# cloth_precompile_programs(target...): the chapter programs' and tools' shared header, compiled once by a target
# of its own (cloth_pch_programs, an empty file with the programs' flags, which needs nothing else built first, so
# that its header is compiled beside the library's files) and reused by the programs.
function(cloth_precompile_programs)
  if(NOT CLOTH_PCH)
    return()
  endif()
  if(NOT TARGET cloth_pch_programs)
    set(empty ${CMAKE_BINARY_DIR}/cloth_pch_programs.cpp)
    file(CONFIGURE OUTPUT ${empty} CONTENT "// The chapter programs' precompiled header (cmake/Precompiled.cmake).\n")
    add_library(cloth_pch_programs OBJECT ${empty})
    target_link_libraries(cloth_pch_programs PRIVATE Eigen3::Eigen)
    target_precompile_headers(cloth_pch_programs PRIVATE ${CLOTH_PCH_HEADERS})
  endif()
  foreach(target IN LISTS ARGN)
    target_precompile_headers(${target} REUSE_FROM cloth_pch_programs)
  endforeach()
endfunction()
