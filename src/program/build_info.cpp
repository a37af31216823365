// The compiler and the flags are fixed when this file is compiled; the processor is read when the program runs,
// since a binary built for one machine may be run on another.
#include "program/build_info.hpp"

#include <fstream>

#ifndef CLOTH_BUILD_FLAGS
#define CLOTH_BUILD_FLAGS ""  // set by src/CMakeLists.txt; empty when this file is compiled some other way
#endif

namespace cloth {

std::string compiler_description() {
#if defined(__clang__)
  return "Clang " + std::string(__clang_version__).substr(0, std::string(__clang_version__).find(' '));
#elif defined(__GNUC__)
  return "GCC " + std::string(__VERSION__).substr(0, std::string(__VERSION__).find(' '));
#else
  return "an unnamed compiler";
#endif
}

std::string compiler_flags() { return CLOTH_BUILD_FLAGS; }

std::string vector_instructions() {
  std::string vector_units;
#if defined(__AVX512F__)
  vector_units = "AVX-512";
#elif defined(__AVX2__)
  vector_units = "AVX2";
#elif defined(__AVX__)
  vector_units = "AVX";
#elif defined(__SSE2__)
  vector_units = "SSE2";
#endif
#if defined(__FMA__)
  vector_units += ", FMA";
#endif
  return vector_units;
}

std::string processor_description() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  const std::string key = "model name";
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.compare(0, key.size(), key) != 0) continue;
    const auto colon = line.find(':');
    const auto start = line.find_first_not_of(" \t", colon == std::string::npos ? line.size() : colon + 1);
    if (start != std::string::npos) return line.substr(start);
  }
  return "an unnamed processor";
}

std::string build_description() {
  return compiler_description() + " " + compiler_flags() + " (" + vector_instructions() + ") on " +
         processor_description();
}

}  // namespace cloth
