//! @file Primitive states of a line's cells, one EOS dispatch per material and line.
#pragma once
#include <variant>
#include <vector>

#include "hvi/cases/scene.hpp"
#include "hvi/tvd/characteristics.hpp"

namespace hvi::tvd::detail {

//! Primitive state and EOS response of a cell with conserved (rho, m, t, E), rho > 0.
template <class Eos>
inline CellState cellState(const Eos& eos, double rho, double m, double t, double E) {
  CellState s;
  const double inv = 1.0 / rho;
  s.rho = rho;
  s.u = m * inv;
  s.w = t * inv;
  s.e = E * inv - 0.5 * (s.u * s.u + s.w * s.w);
  const eos::EosState st = eos.state(rho, s.e);
  s.p = st.pressure;
  s.c = st.soundSpeed;
  s.gam = st.dPdE * inv;
  s.prho = st.dPdRho;
  s.H = (E + st.pressure) * inv;
  return s;
}

//! Fills cs[j0..j1) from the conserved arrays. With `mat` null every cell is of material
//! `single`; otherwise each material's cells are done in one pass with the concrete EOS type
//! (std::visit once per material, not per cell) and vacuum cells (mat < 0) get a zero state.
inline void primitiveStates(const std::vector<cases::Material>& materials, int single,
                            const int* mat, int j0, int j1, const double* r, const double* m,
                            const double* t, const double* E, CellState* cs) {
  if (mat == nullptr) {
    std::visit(
        [&](const auto& eos) {
          for (int j = j0; j < j1; ++j) cs[j] = cellState(eos, r[j], m[j], t[j], E[j]);
        },
        materials[single].eos);
    return;
  }
  for (int j = j0; j < j1; ++j)
    if (mat[j] < 0) cs[j] = CellState{};
  for (int id = 0; id < static_cast<int>(materials.size()); ++id) {
    std::visit(
        [&](const auto& eos) {
          for (int j = j0; j < j1; ++j)
            if (mat[j] == id) cs[j] = cellState(eos, r[j], m[j], t[j], E[j]);
        },
        materials[id].eos);
  }
}

}  // namespace hvi::tvd::detail
