//! @file Per-particle EOS pass, dispatched once per material.
#include "detail/eos_pass.hpp"
#include "detail/parallel.hpp"

namespace hvi::sph::detail {

void evaluateEos(const std::vector<eos::Eos>& materials, const int* mat, const double* rho,
                 const double* e, double* p, double* c, std::size_t n) {
  const long nl = static_cast<long>(n);
  for (std::size_t k = 0; k < materials.size(); ++k) {
    const int kk = static_cast<int>(k);
    std::visit(
        [&](const auto& eos) {
#pragma omp parallel for schedule(static) if (nl > kParallelPairs)
          for (long i = 0; i < nl; ++i) {
            if (mat[i] != kk) continue;
            const eos::EosState s = eos.state(rho[i], e[i]);
            p[i] = s.pressure;
            c[i] = s.soundSpeed;
          }
        },
        materials[k]);
  }
}

}  // namespace hvi::sph::detail
