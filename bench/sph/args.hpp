//! @file Positional arguments of the SPH bench programs: a number that does not parse whole,
//! or lies outside its range, stops the program with a message naming the argument (instead of
//! atof's silent 0 or an uncaught exception from the solver).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace hvi::bench {

//! Argument `index` of argv (1-based) as a number in [lo, hi], or `fallback` where absent.
inline double numberArg(int argc, char** argv, int index, const char* name, double fallback,
                        double lo, double hi) {
  if (index >= argc) return fallback;
  const char* text = argv[index];
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) {
    char range[64];
    std::snprintf(range, sizeof range, "[%g, %g]", lo, hi);
    throw std::invalid_argument("argument " + std::to_string(index) + " (" + name + ") = '" + text +
                                "': expected a number in " + range);
  }
  return v;
}

}  // namespace hvi::bench
