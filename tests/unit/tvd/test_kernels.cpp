//! @file Kernel tests: eigen-structure for a general EOS, decomposition, limiters, fluxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "hvi/eos/eos.hpp"
#include "hvi/tvd/characteristics.hpp"
#include "hvi/tvd/contact.hpp"
#include "hvi/tvd/harten_yee.hpp"
#include "hvi/tvd/limiter.hpp"
#include "hvi/tvd/relaxation.hpp"

namespace hvi::tvd {
namespace {

using U4 = std::array<double, 4>;

CellState stateOf(const eos::Eos& eos, double rho, double u, double w, double e) {
  const eos::EosState st = eos::state(eos, rho, e);
  CellState s;
  s.rho = rho;
  s.u = u;
  s.w = w;
  s.e = e;
  s.p = st.pressure;
  s.c = st.soundSpeed;
  s.gam = st.dPdE / rho;
  s.prho = st.dPdRho;
  s.H = e + 0.5 * (u * u + w * w) + st.pressure / rho;
  return s;
}
U4 conserved(const CellState& s) {
  return {s.rho, s.rho * s.u, s.rho * s.w, s.rho * (s.e + 0.5 * (s.u * s.u + s.w * s.w))};
}
CellState fromConserved(const eos::Eos& eos, const U4& U) {
  const double u = U[1] / U[0], w = U[2] / U[0];
  return stateOf(eos, U[0], u, w, U[3] / U[0] - 0.5 * (u * u + w * w));
}
U4 flux(const eos::Eos& eos, const U4& U) {
  const CellState s = fromConserved(eos, U);
  double F[4];
  physicalFlux(U[1], U[2], U[3], s, F);
  return {F[0], F[1], F[2], F[3]};
}
// A r by central differences of the physical flux (step 1e-6 relative: truncation ~1e-12,
// rounding ~1e-10 relative, so 1e-6 tolerances are safe and still far below any O(1) error).
U4 jacobianTimes(const eos::Eos& eos, const U4& U, const U4& r) {
  double scale = 0.0;
  for (int k = 0; k < 4; ++k) scale = std::max(scale, std::abs(r[k]) / (std::abs(U[k]) + 1e-3));
  const double eps = 1e-6 / scale;
  U4 a = U, b = U;
  for (int k = 0; k < 4; ++k) {
    a[k] += eps * r[k];
    b[k] -= eps * r[k];
  }
  const U4 Fa = flux(eos, a), Fb = flux(eos, b);
  U4 out;
  for (int k = 0; k < 4; ++k) out[k] = (Fa[k] - Fb[k]) / (2 * eps);
  return out;
}
void expectEigen(const eos::Eos& eos, const CellState& s, const U4& r, double lambda,
                 const char* what) {
  const U4 Ar = jacobianTimes(eos, conserved(s), r);
  double norm = 0.0;
  for (int k = 0; k < 4; ++k) norm = std::max(norm, std::abs(lambda * r[k]) + std::abs(r[k]));
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(Ar[k], lambda * r[k], 1e-6 * norm) << what << " component " << k;
}

struct Case {
  const char* name;
  eos::Eos eos;
  double rho, e;
};
std::vector<Case> generalEosStates() {
  const eos::Tillotson al = eos::aluminiumStudy();
  return {
      {"ideal gas", eos::IdealGas{1.4, 1.0}, 0.7, 2.3},
      {"Tillotson compressed", al, 3.4, 0.02},
      {"Tillotson cold expanded", al, 2.7, 0.01},
      {"Tillotson blend", al, 2.2, 0.08},
      {"Tillotson hot expanded", al, 1.2, 0.4},
      {"Mie-Gruneisen", eos::MieGruneisen{}, 10.0, 0.01},
  };
}

// The closed-form eigenvectors hold for a general EOS through c^2 = P_rho + Gamma P / rho, not
// only for a gamma law: checked against the finite-difference flux Jacobian in every Tillotson
// region.
TEST(TvdKernels, ClosedFormEigenvectorsOfGeneralEos) {
  for (const auto& cs : generalEosStates()) {
    const double u = 0.31, w = -0.17;
    const CellState s = stateOf(cs.eos, cs.rho, u, w, cs.e);
    const double c = std::sqrt(s.prho + s.gam * s.p / s.rho);
    ASSERT_GT(c, 0.0) << cs.name;
    expectEigen(cs.eos, s, {1, u - c, w, s.H - u * c}, u - c, cs.name);
    expectEigen(cs.eos, s, {1, u + c, w, s.H + u * c}, u + c, cs.name);
    expectEigen(cs.eos, s, {0, 0, 1, w}, u, cs.name);
    // Entropy: r2 + (e - P_rho / Gamma) r5 is the textbook (1, u, w, H - c^2 / Gamma).
    expectEigen(cs.eos, s, {1, u, w, 0.5 * (u * u + w * w) + s.e - s.prho / s.gam}, u, cs.name);
  }
}

// sum_l alpha_l r_l reproduces the jump exactly for any two states, including Tillotson's
// tension cut-off (Gamma = 0) and a jump to near-vacuum density.
TEST(TvdKernels, DecompositionIsExactForAnyStates) {
  const eos::Tillotson al = eos::aluminiumStudy();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double rl = trial % 3 == 0 ? 2.79e-6 : 1.0 + 3.0 * U(rng);
    const double rr = 1.0 + 3.0 * U(rng);
    const CellState L = stateOf(al, rl, U(rng) - 0.5, U(rng) - 0.5, 0.3 * U(rng) * U(rng));
    const CellState R = stateOf(al, rr, U(rng) - 0.5, U(rng) - 0.5, 0.3 * U(rng) * U(rng));
    const U4 a = conserved(L), b = conserved(R);
    const double dU[4] = {b[0] - a[0], b[1] - a[1], b[2] - a[2], b[3] - a[3]};
    const FaceEigen f = faceEigen(L, R, dU);
    double back[4];
    applyRight(f, f.alpha, back);
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(back[k], dU[k], 1e-12 * (std::abs(a[k]) + std::abs(b[k]) + 1.0))
          << "trial " << trial << " component " << k;
  }
}

// A contact at rest (equal P and u, different rho) has no acoustic part, so the Harten-Yee
// flux is exactly (0, P, 0, 0): a cold aluminium block next to near-vacuum does not leak.
TEST(TvdKernels, ContactAtRestIsExact) {
  const eos::Tillotson al = eos::aluminiumStudy();
  const CellState L = stateOf(al, 2.79, 0.0, 0.0, 0.0);
  const CellState R = stateOf(al, 2.79e-6, 0.0, 0.0, 0.0);
  ASSERT_EQ(L.p, 0.0);
  ASSERT_EQ(R.p, 0.0);
  const U4 a = conserved(L), b = conserved(R);
  const double dU[4] = {b[0] - a[0], b[1] - a[1], b[2] - a[2], b[3] - a[3]};
  const FaceEigen f = faceEigen(L, R, dU);
  EXPECT_EQ(f.alpha[0], 0.0);
  EXPECT_EQ(f.alpha[3], 0.0);
  const double g[kFields] = {0, 0, 0, 0, 0};
  double FL[4], FR[4], F[4];
  physicalFlux(a[1], a[2], a[3], L, FL);
  physicalFlux(b[1], b[2], b[3], R, FR);
  hartenYeeFlux(f, g, g, FL, FR, 0.1 * f.c, F);
  for (double v : F) EXPECT_EQ(v, 0.0);
}

TEST(TvdKernels, FluxOfEqualStatesIsPhysicalFlux) {
  for (const auto& cs : generalEosStates()) {
    const CellState s = stateOf(cs.eos, cs.rho, 0.4, -0.2, cs.e);
    const U4 a = conserved(s);
    const double dU[4] = {0, 0, 0, 0};
    const FaceEigen f = faceEigen(s, s, dU);
    const double g[kFields] = {0, 0, 0, 0, 0};
    double F0[4], F[4];
    physicalFlux(a[1], a[2], a[3], s, F0);
    hartenYeeFlux(f, g, g, F0, F0, 0.1 * f.c, F);
    for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(F[k], F0[k]) << cs.name;
  }
}

// Mirror image of a face (states swapped, normal velocity negated, field l <-> 5 - l) gives
// the mirrored flux bit for bit: the normal-impact symmetry test relies on it.
TEST(TvdKernels, HartenYeeFluxIsMirrorSymmetricBitwise) {
  const eos::Tillotson al = eos::aluminiumStudy();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const CellState L = stateOf(al, 2.0 + U(rng), U(rng) - 0.5, U(rng) - 0.5, 0.2 * U(rng));
    const CellState R = stateOf(al, 2.0 + U(rng), U(rng) - 0.5, U(rng) - 0.5, 0.2 * U(rng));
    auto mirror = [](CellState s) {
      s.u = -s.u;
      return s;
    };
    const CellState Lm = mirror(R), Rm = mirror(L);
    const U4 a = conserved(L), b = conserved(R), am = conserved(Lm), bm = conserved(Rm);
    const double dU[4] = {b[0] - a[0], b[1] - a[1], b[2] - a[2], b[3] - a[3]};
    const double dUm[4] = {bm[0] - am[0], bm[1] - am[1], bm[2] - am[2], bm[3] - am[3]};
    const FaceEigen f = faceEigen(L, R, dU), fm = faceEigen(Lm, Rm, dUm);
    double gL[kFields], gR[kFields], gLm[kFields], gRm[kFields];
    for (int l = 0; l < kFields; ++l) {
      gL[l] = 0.3 * f.alpha[l] * U(rng);
      gR[l] = 0.3 * f.alpha[l] * U(rng);
    }
    const int swap[kFields] = {3, 1, 2, 0, 4};
    for (int l = 0; l < kFields; ++l) {
      gLm[l] = -gR[swap[l]];
      gRm[l] = -gL[swap[l]];
    }
    double FL[4], FR[4], FLm[4], FRm[4], F[4], Fm[4];
    physicalFlux(a[1], a[2], a[3], L, FL);
    physicalFlux(b[1], b[2], b[3], R, FR);
    physicalFlux(am[1], am[2], am[3], Lm, FLm);
    physicalFlux(bm[1], bm[2], bm[3], Rm, FRm);
    hartenYeeFlux(f, gL, gR, FL, FR, 0.1 * (std::abs(f.u) + f.c), F);
    hartenYeeFlux(fm, gLm, gRm, FLm, FRm, 0.1 * (std::abs(fm.u) + fm.c), Fm);
    EXPECT_EQ(Fm[0], -F[0]);
    EXPECT_EQ(Fm[1], F[1]);
    EXPECT_EQ(Fm[2], -F[2]);
    EXPECT_EQ(Fm[3], -F[3]);
  }
}

TEST(TvdKernels, LimitersAreSymmetricOddAndInTheTvdRegion) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int t = 0; t < 1000; ++t) {
    const double a = U(rng), b = U(rng);
    for (auto g : {&Minmod::g, &VanLeer::g, &Superbee::g}) {
      EXPECT_EQ(g(a, b), g(b, a));
      EXPECT_EQ(g(-a, -b), -g(a, b));
      if (a * b <= 0.0)
        EXPECT_EQ(g(a, b), 0.0);
      else {
        // Sweby's region: 0 <= g/b <= min(2, 2 a/b) in ratio form, and g between the jumps
        // for minmod.
        const double r = a / b, phi = g(a, b) / b;
        EXPECT_GE(phi, 0.0);
        EXPECT_LE(phi, std::min(2.0, 2.0 * r) + 1e-14);
      }
    }
  }
  EXPECT_EQ(Minmod::g(1.0, 3.0), 1.0);
  EXPECT_EQ(VanLeer::g(1.0, 3.0), 1.5);
  EXPECT_EQ(Superbee::g(1.0, 3.0), 2.0);
  EXPECT_EQ(Superbee::g(1.0, 1.5), 1.5);
}

TEST(TvdKernels, EntropyFixIsContinuousAndPositive) {
  const double d = 0.2;
  EXPECT_DOUBLE_EQ(entropyFixedAbs(d, d), d);
  EXPECT_DOUBLE_EQ(entropyFixedAbs(0.0, d), d / 2);
  EXPECT_DOUBLE_EQ(entropyFixedAbs(-0.5, d), 0.5);
}

// Symmetric collision of cold ideal gas: the two-shock contact solver is exact in the
// strong-shock limit, P* = rho (gamma + 1)/2 u^2, u* = 0.
TEST(TvdKernels, ContactStarStrongShockLimit) {
  const eos::IdealGas gas{1.4, 1.0};
  const CellState L = stateOf(gas, 1.0, 2.0, 0.3, 0.0), R = stateOf(gas, 1.0, -2.0, -0.1, 0.0);
  const ContactStar s = contactStar(L, R, 1.0, 0.0);
  EXPECT_NEAR(s.uL, 0.0, 1e-12);
  EXPECT_EQ(s.uL, s.uR);
  EXPECT_NEAR(s.p, 1.0 * 1.2 * 4.0, 1e-9);
}

// Two objects moving apart separate: no tension across an interface.
TEST(TvdKernels, ContactSeparates) {
  const eos::Tillotson al = eos::aluminiumStudy();
  const CellState L = stateOf(al, 2.79, -0.5, 0.0, 0.0), R = stateOf(al, 2.79, 0.5, 0.0, 0.0);
  const ContactStar s = contactStar(L, R, 1.0, 0.0);
  EXPECT_EQ(s.p, 0.0);
  EXPECT_DOUBLE_EQ(s.uL, -0.5);
  EXPECT_DOUBLE_EQ(s.uR, 0.5);
}

// The face pressure inside one material (the r-z hoop source's): contactStar's p* where neither
// cell is in tension, bit for bit (the tension cut-off and gases are unchanged by it); the
// tension itself where the cells carry it (copper at 0.99 rho0: P = -0.0141 Mbar), so that a
// uniform state in tension has the hoop source its flux difference needs; never below the
// cells' own tension (two cells in tension moving apart).
TEST(TvdKernels, FacePressureCarriesTheCellsTension) {
  const eos::MieGruneisen cu{};
  const CellState A = stateOf(cu, 9.0, 0.01, 0.0, 1e-4), B = stateOf(cu, 9.1, -0.02, 0.0, 2e-4);
  ASSERT_GT(A.p, 0.0);
  EXPECT_EQ(facePressure(A, B, 2), contactStar(A, B, 1.0, 0.0, 2).p);
  const CellState T = stateOf(cu, 0.99 * 8.93, 0.0, 0.0, 0.0);
  ASSERT_LT(T.p, -0.01);
  EXPECT_EQ(contactStar(T, T, 1.0, 0.0, 2).p, 0.0);  // an interface separates ...
  EXPECT_DOUBLE_EQ(facePressure(T, T, 2), T.p);      // ... a body in tension does not
  const CellState L = stateOf(cu, 0.99 * 8.93, -0.01, 0.0, 0.0);
  const CellState R = stateOf(cu, 0.995 * 8.93, 0.01, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(facePressure(L, R, 2), std::min(L.p, R.p));
}

// With the star state equal to the cell state the two-sided flux is the physical flux, and
// the tangential velocity is untouched by the interface whatever its orientation (slip).
TEST(TvdKernels, StarFluxConsistencyAndSlip) {
  const eos::Tillotson al = eos::aluminiumStudy();
  const CellState K = stateOf(al, 3.0, 0.3, 0.7, 0.02);
  const double nn = 0.6, nt = 0.8;
  double F[4], F0[4];
  starFlux(K, K.p, K.u * nn + K.w * nt, nn, nt, F);
  const U4 U = conserved(K);
  physicalFlux(U[1], U[2], U[3], K, F0);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(F[k], F0[k], 1e-14 * (std::abs(F0[k]) + 1));
  // Change only the normal velocity: the tangential velocity (along (-nt, nn)) is kept.
  starFlux(K, K.p, 0.0, nn, nt, F);
  const double vn = F[1] - K.p, vt = F[2];  // rho vn^2, rho vn vt
  ASSERT_NE(F[0], 0.0);
  const double un = F[0] / K.rho, ut = vt / F[0];
  EXPECT_NEAR(un * nn + ut * nt, 0.0, 1e-14);
  EXPECT_NEAR(-un * nt + ut * nn, -K.u * nt + K.w * nn, 1e-14);
  EXPECT_NEAR(vn, K.rho * un * un, 1e-14);
}

// Free surface: the material's own flux without the pressure; zero for material at rest.
TEST(TvdKernels, FreeSurfaceFlux) {
  const eos::Tillotson al = eos::aluminiumStudy();
  double F[4];
  freeSurfaceFlux(stateOf(al, 2.79, 0.0, 0.3, 0.0), F);
  for (double v : F) EXPECT_EQ(v, 0.0);
  const CellState K = stateOf(al, 3.1, 0.2, 0.3, 0.01);
  ASSERT_GT(K.p, 0.0);
  freeSurfaceFlux(K, F);
  const U4 U = conserved(K);
  double F0[4];
  physicalFlux(U[1], U[2], U[3], K, F0);
  EXPECT_DOUBLE_EQ(F[0], F0[0]);
  EXPECT_DOUBLE_EQ(F[1], F0[1] - K.p);
  EXPECT_DOUBLE_EQ(F[2], F0[2]);
  EXPECT_DOUBLE_EQ(F[3], F0[3] - K.p * K.u);
}


// Instantaneous velocity relaxation of a cell's phases (hvi/tvd/relaxation.hpp; docs/tvd.md "The
// thin film"; Saurel and Abgrall, J. Comput. Phys. 150 (1999) 425): the exact two-phase
// equilibrium of a drag that conserves momentum is the centre-of-mass velocity
// (m1 u1 + m2 u2) / (m1 + m2); the interface work at that velocity conserves total energy, and
// each phase's internal energy rises by its kinetic energy relative to it.
TEST(TvdRelaxation, TwoPhasesReachTheExactEquilibrium) {
  // A thin film (1e-3 of the dense phase's mass) moving at 40 cm/us across a dense phase at
  // 0.3 cm/us, with a transverse slip: the case the explicit exchange overshoots.
  const double m[2] = {2.7, 2.7e-3};
  const double u[2][2] = {{0.3, -0.05}, {40.0, 7.0}};  // (along, across)
  const double e[2] = {0.02, 0.5};                    // specific internal energies
  double mn[2], mt[2], E[2];
  for (int k = 0; k < 2; ++k) {
    mn[k] = m[k] * u[k][0];
    mt[k] = m[k] * u[k][1];
    E[k] = m[k] * (e[k] + 0.5 * (u[k][0] * u[k][0] + u[k][1] * u[k][1]));
  }
  const double P0n = mn[0] + mn[1], P0t = mt[0] + mt[1], E0 = E[0] + E[1];
  const double m0[2] = {m[0], m[1]};
  relaxVelocities(2, m, mn, mt, E);
  // Mass untouched (bit for bit: not an argument it writes).
  EXPECT_EQ(m[0], m0[0]);
  EXPECT_EQ(m[1], m0[1]);
  // Momentum and total energy to round-off (a few ulp of the largest term).
  EXPECT_NEAR(mn[0] + mn[1], P0n, 4e-16 * (std::abs(m[0] * u[0][0]) + std::abs(m[1] * u[1][0])));
  EXPECT_NEAR(mt[0] + mt[1], P0t, 4e-16 * (std::abs(m[0] * u[0][1]) + std::abs(m[1] * u[1][1])));
  EXPECT_NEAR(E[0] + E[1], E0, 4e-16 * E0);
  // The exact equilibrium: both phases at the centre-of-mass velocity.
  const double un = (m[0] * u[0][0] + m[1] * u[1][0]) / (m[0] + m[1]);
  const double ut = (m[0] * u[0][1] + m[1] * u[1][1]) / (m[0] + m[1]);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(mn[k] / m[k], un, 1e-15);
    EXPECT_NEAR(mt[k] / m[k], ut, 1e-15);
    // Each phase's internal energy rises by its own kinetic energy relative to the equilibrium.
    const double du = u[k][0] - un, dt = u[k][1] - ut;
    const double eAfter = E[k] / m[k] - 0.5 * (un * un + ut * ut);
    EXPECT_NEAR(eAfter, e[k] + 0.5 * (du * du + dt * dt), 1e-12 * (1.0 + eAfter));
    EXPECT_GE(eAfter, e[k]);
  }
  // The fraction-weighted (here mass-weighted) velocity is what it was: the relaxation is
  // internal to the cell. A phase with no mass takes no part.
  double mz[3] = {1.0, 0.0, 2.0}, an[3] = {1.0, 5.0, 4.0}, at[3] = {0.0, 0.0, 0.0},
         Ez[3] = {1.0, 3.0, 5.0};
  relaxVelocities(3, mz, an, at, Ez);
  EXPECT_EQ(an[1], 5.0);
  EXPECT_EQ(Ez[1], 3.0);
  EXPECT_NEAR(an[0] / mz[0], 5.0 / 3.0, 1e-15);
  EXPECT_NEAR(an[2] / mz[2], 5.0 / 3.0, 1e-15);
  EXPECT_NEAR(Ez[0] + Ez[2], 6.0, 1e-15);
}

}  // namespace
}  // namespace hvi::tvd
