//! @file Instantaneous velocity relaxation of the phases of one cell (docs/tvd.md, "The thin
//! film: velocity relaxation"): the limit of the interface drag for a phase whose exchange
//! relaxation time is shorter than the step (Saurel and Abgrall, J. Comput. Phys. 150 (1999)
//! 425, section 3.2; CTH and Autodyn give a mixed cell one velocity).
#pragma once

namespace hvi::tvd {

//! Brings the phases k = 0..n-1 of one cell to their common (centre-of-mass) velocity
//! u* = sum(m_k u_k) / sum(m_k), in place, on the conserved state per unit cell volume: mass m_k
//! untouched, momenta (mn_k, mt_k) -> m_k u*, and total energy E_k -> E_k + u* . (m_k u* - mom_k),
//! the work of the relaxation impulse at the interface velocity u_I = u* (Saurel and Abgrall's
//! choice, u_I the mixture velocity, which the relaxation leaves unchanged). So the momentum and
//! the total energy of the cell are conserved (the impulses sum to zero and all act at one
//! velocity), and each phase's internal energy rises by its own kinetic energy relative to u*,
//! m_k |u_k - u*|^2 / 2 >= 0: the kinetic energy the relaxation removes heats the phase that
//! carried it, and no phase's internal energy falls. Phases with m_k <= 0 take no part.
inline void relaxVelocities(int n, const double* m, double* mn, double* mt, double* E) {
  double M = 0.0, Pn = 0.0, Pt = 0.0;
  for (int k = 0; k < n; ++k) {
    if (!(m[k] > 0.0)) continue;
    M += m[k];
    Pn += mn[k];
    Pt += mt[k];
  }
  if (!(M > 0.0)) return;
  const double un = Pn / M, ut = Pt / M;
  for (int k = 0; k < n; ++k) {
    if (!(m[k] > 0.0)) continue;
    const double n1 = m[k] * un, t1 = m[k] * ut;
    E[k] += un * (n1 - mn[k]) + ut * (t1 - mt[k]);
    mn[k] = n1;
    mt[k] = t1;
  }
}

}  // namespace hvi::tvd
