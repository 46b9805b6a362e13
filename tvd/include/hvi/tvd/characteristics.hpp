//! @file Characteristic decomposition of a conserved jump for a general EOS P(rho, e).
#pragma once
#include <algorithm>
#include <cmath>

namespace hvi::tvd {

// Conserved variables of one 1-D sweep, in line coordinates: U = (rho, m, t, E) with m the
// momentum normal to the faces, t the tangential momentum, E = rho (e + |v|^2 / 2).
//
// Eigen-structure of dF/dU for a general EOS, Gamma = P_e / rho, c^2 = P_rho + Gamma P / rho:
// eigenvalues u - c, u, u, u + c, right eigenvectors (closed form)
//   r1 = (1, u - c, w, H - u c),  r4 = (1, u + c, w, H + u c)     acoustic
//   r3 = (0, 0, 1, w)                                             shear
//   entropy: density part r2 = (1, u, w, q^2/2), internal-energy part r5 = (0, 0, 0, 1)
// and the characteristic variables ("Riemann invariants of the local state", the rows of the
// left eigenvector matrix applied to the jump):
//   alpha1,4 = (dP -+ c rho du) / (2 c^2),   alpha3 = rho dw,
//   alpha2   = drho - dP / c^2,              alpha5 = d(rho e) - h dP / c^2,
// with h = H - q^2/2 the specific enthalpy. Two choices make this hold for any EOS:
//  - dP is the ACTUAL pressure jump P_R - P_L, not its linearisation P_rho drho + P_e de with
//    averaged derivatives (which fails for strongly nonlinear EOS: a cold aluminium block next
//    to vacuum, both at P = 0, would see a spurious acoustic jump and start to leak). Using the
//    actual jump is what a Roe average for a general EOS (Glaister's condition
//    dP = chi drho + kappa d(rho e)) achieves; the entropy wave's internal-energy content, which
//    the textbook vector (1, u, w, H - c^2/Gamma) fixes through Gamma (singular at Gamma = 0,
//    e.g. Tillotson's tension cut-off), is carried exactly as alpha5 instead.
//  - rho du = dm - u drho and d(rho e) = dE - u dm - w dt + q^2/2 drho are exact for
//    sqrt(rho)-weighted (Roe) velocities.
// Hence alpha1 r1 + alpha2 r2 + alpha3 r3 + alpha4 r4 + alpha5 r5 = dU EXACTLY for any c > 0:
// no matrix is built or inverted, and c (from the averaged P_rho and Gamma) only sets wave
// speeds and the split between the acoustic and entropy parts.

//! Primitive state of one cell in line coordinates, with the EOS response.
struct CellState {
  double rho = 0.0;   //!< g/cm^3
  double u = 0.0;     //!< normal velocity, cm/us
  double w = 0.0;     //!< tangential velocity, cm/us
  double e = 0.0;     //!< specific internal energy, cm^2/us^2
  double p = 0.0;     //!< Mbar
  double c = 0.0;     //!< sound speed from the EOS (floored there), cm/us
  double gam = 0.0;   //!< Gamma = (dP/de)_rho / rho
  double prho = 0.0;  //!< (dP/drho)_e, cm^2/us^2
  double H = 0.0;     //!< total specific enthalpy (E + P) / rho
};

inline constexpr int kFields = 5;

//! Averaged state at a face and the characteristic variables of the jump across it.
struct FaceEigen {
  double u = 0.0, w = 0.0, H = 0.0, c = 0.0;
  double q2h = 0.0;                                   //!< |v|^2 / 2 of the averaged velocity
  double alpha[kFields] = {0.0, 0.0, 0.0, 0.0, 0.0};  //!< alpha1, alpha2, alpha3, alpha4, alpha5
};

//! Characteristic speed of field l (0-based) at a face.
inline double waveSpeed(const FaceEigen& f, int l) {
  return l == 0 ? f.u - f.c : (l == 3 ? f.u + f.c : f.u);
}

//! Relative floor of c^2 against q^2 + P/rho: keeps the acoustic variables finite in cold
//! (P = 0, c = 0) gas, e.g. the Noh inflow. 1e-8 gives c >= 1e-4 |v|, far below any physical
//! wave speed, so it adds no visible dissipation.
inline constexpr double kRelativeSoundFloor2 = 1e-8;

//! Roe-weighted (sqrt(rho)) averages of u, w, H, e, Gamma and P_rho; c^2 = P_rho + Gamma P/rho
//! of the average, never below the smaller of the two cells' (floored) c^2. dU = U_R - U_L;
//! sL, sR = sqrt(rho_L), sqrt(rho_R) (computed once per cell by the sweep).
inline FaceEigen faceEigen(const CellState& L, const CellState& R, const double dU[4], double sL,
                           double sR) {
  const double inv = 1.0 / (sL + sR);
  const double wL = sL * inv, wR = sR * inv;  // computed alike so that L <-> R is exact
  FaceEigen f;
  f.u = wL * L.u + wR * R.u;
  f.w = wL * L.w + wR * R.w;
  f.H = wL * L.H + wR * R.H;
  const double e = wL * L.e + wR * R.e;
  const double gam = wL * L.gam + wR * R.gam;
  const double prho = wL * L.prho + wR * R.prho;
  f.q2h = 0.5 * (f.u * f.u + f.w * f.w);
  const double h = f.H - f.q2h;  // specific enthalpy of the average
  const double pOverRho = std::max(h - e, 0.0);
  double c2 = prho + gam * pOverRho;
  c2 = std::max(c2, std::min(L.c * L.c, R.c * R.c));
  c2 = std::max(c2, kRelativeSoundFloor2 * (2.0 * f.q2h + pOverRho) + 1e-300);
  f.c = std::sqrt(c2);
  const double dp = R.p - L.p;
  const double dmu = dU[1] - f.u * dU[0];  // rho du
  const double uw = f.u * dU[1] + f.w * dU[2];
  const double deps = (dU[3] - uw) + f.q2h * dU[0];  // d(rho e)
  // One division: 0.5 / c2 = 0.5 (1 / c2) exactly; dp / c2 as dp (1 / c2) (issue 17).
  const double invc2 = 1.0 / c2;
  const double inv2c2 = 0.5 * invc2;
  const double dpc2 = dp * invc2;
  f.alpha[0] = (dp - f.c * dmu) * inv2c2;
  f.alpha[1] = dU[0] - dpc2;
  f.alpha[2] = dU[2] - f.w * dU[0];
  f.alpha[3] = (dp + f.c * dmu) * inv2c2;
  f.alpha[4] = deps - h * dpc2;
  return f;
}

inline FaceEigen faceEigen(const CellState& L, const CellState& R, const double dU[4]) {
  return faceEigen(L, R, dU, std::sqrt(L.rho), std::sqrt(R.rho));
}

//! out = sum over fields l of r_l * phi[l] (acoustic pair summed first: exact mirror symmetry).
[[gnu::always_inline]] inline void applyRight(const FaceEigen& f, const double phi[kFields],
                                             double out[4]) {
  const double sum = phi[0] + phi[3], diff = phi[3] - phi[0];
  out[0] = sum + phi[1];
  out[1] = (f.u * sum + f.c * diff) + f.u * phi[1];
  out[2] = (f.w * sum + f.w * phi[1]) + phi[2];
  out[3] = (f.H * sum + (f.u * f.c) * diff) + ((f.q2h * phi[1] + f.w * phi[2]) + phi[4]);
}

//! Physical flux of the conserved variables (m, t, E) of a cell through a face normal to the
//! line.
inline void physicalFlux(double m, double t, double E, const CellState& s, double F[4]) {
  F[0] = m;
  F[1] = m * s.u + s.p;
  F[2] = t * s.u;
  F[3] = (E + s.p) * s.u;
}

}  // namespace hvi::tvd
