//! @file Pressure and sound speed of every particle from its material's EOS.
#pragma once
#include <cstddef>
#include <vector>

#include "hvi/eos/eos.hpp"

namespace hvi::sph::detail {

//! p_i, c_i = EOS_{mat_i}(rho_i, e_i) for i < n. One std::visit per material; the particle loop
//! inside sees the concrete EOS type.
void evaluateEos(const std::vector<eos::Eos>& materials, const int* mat, const double* rho,
                 const double* e, double* p, double* c, std::size_t n);

}  // namespace hvi::sph::detail
