// Which build measured a number: the compiler, the flags that change speed and rounding, and the processor, in
// the one line the book prints under every measured table (program/fragment.hpp).
#pragma once

#include <string>

namespace cloth {

/// The compiler and its version, as it names itself: "GCC 12.2.0", "Clang 15.0.6".
std::string compiler_description();

/// The flags the library was compiled with that change speed or rounding (optimisation, instruction set,
/// floating-point contraction), as CMake passed them in: "-O3 -march=native -mno-avx512f -ffp-contract=off".
std::string compiler_flags();

/// The widest vector instructions those flags let the compiler use, and FMA if it may: "AVX2, FMA", "SSE2".
std::string vector_instructions();

/// The processor's model name (from /proc/cpuinfo), or "an unnamed processor" where the system does not say.
std::string processor_description();

/// All three in one line: "GCC 12.2.0 -O3 -march=native ... (AVX2, FMA) on AMD EPYC 7763 64-Core Processor".
std::string build_description();

}  // namespace cloth
