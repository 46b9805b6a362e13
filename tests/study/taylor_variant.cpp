//! @file The Taylor anvil (docs/strength.md, "Taylor anvil") with scene overrides from the
//! command line, for the measurements of that section (not a test: it prints the final shape).
//! Usage: hvi_taylor_variant SPACING_CM [key=value ...]
//! e.g.   hvi_taylor_variant 0.0381 'sph.viscosity_switch="morris_monaghan"'
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hvi/test/taylor.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SPACING_CM [key=value ...]\n", argv[0]);
    return 2;
  }
  const double dx = std::atof(argv[1]);
  std::vector<std::string> overrides(argv + 2, argv + argc);
  const hvi::sph::test::TaylorShape t = hvi::sph::test::taylorAnvil(dx, overrides);
  hvi::sph::test::printTaylor(dx, t);
  return 0;
}
