//! @file One 1-D sweep of one grid line: Heun predictor-corrector with Harten-Yee TVD fluxes.
#pragma once
#include <algorithm>
#include <cmath>

#include "eos_line.hpp"
#include "hvi/tvd/contact.hpp"
#include "hvi/tvd/harten_yee.hpp"
#include "hvi/tvd/limiter.hpp"
#include "line_work.hpp"
#include "strength_step.hpp"

namespace hvi::tvd::detail {

// Buffer layout: cells 0 and 1 are ghosts, 2..n+1 the line's cells, n+2 and n+3 ghosts; face f
// lies between cells f and f+1, so faces 1..n+1 bound the line's cells.

using State4 = std::array<std::vector<double>, 4>;

inline void fillGhosts(State4& U, int n, Side left, Side right) {
  auto side = [&](Side s, int in0, int in1, int g0, int g1) {
    if (s == Side::Loaded) return;
    for (int k = 0; k < 4; ++k) {
      U[k][g0] = U[k][in0];
      U[k][g1] = U[k][s == Side::Reflect ? in1 : in0];
    }
    if (s == Side::Reflect) {
      U[kMn][g0] = -U[kMn][g0];
      U[kMn][g1] = -U[kMn][g1];
    }
  };
  side(left, 2, 3, 1, 0);
  side(right, n + 1, n, n + 2, n + 3);
}

//! Interface normal at face f in line coordinates, oriented from cell f to f+1: the sum of the
//! two cells' marker normals (each turned to point that way); the face normal if none.
inline void faceNormal(const LineWork& W, int f, double& nn, double& nt) {
  double sn = 0.0, st = 0.0;
  for (int c = f; c <= f + 1; ++c) {
    const double a = W.nn[c], b = W.nt[c];
    const bool flip = a < 0.0 || (a == 0.0 && b < 0.0);
    sn += flip ? -a : a;
    st += flip ? -b : b;
  }
  const double len = std::sqrt(sn * sn + st * st);
  if (len < 1e-12) {
    nn = 1.0;
    nt = 0.0;
  } else {
    nn = sn / len;
    nt = st / len;
  }
}

//! Puts cell j of U at rest and cold, its mass kept, and books the momentum and energy that
//! removes (`vol`: the cell's volume in line units times the stage weight).
inline void putAtRest(State4& U, int j, double vol, int axis, Budget& floors) {
  if (U[kMn][j] == 0.0 && U[kMt][j] == 0.0 && U[kE][j] == 0.0) return;
  floors.add(0.0, -(U[kMn][j] * vol), -(U[kMt][j] * vol), -(U[kE][j] * vol), axis);
  U[kMn][j] = U[kMt][j] = U[kE][j] = 0.0;
}

//! True unless the cell has rho <= 0, a non-finite value, or an internal energy below zero by
//! more than rounding of the kinetic energy (cold material at e = 0 sits at +-1 ulp).
inline bool physical(double rho, double m, double t, double E) {
  if (!(rho > 0.0) || !std::isfinite(E) || !std::isfinite(m) || !std::isfinite(t)) return false;
  const double kin = 0.5 * (m * m + t * t) / rho;
  return E - kin >= -1e-10 * kin;
}

template <class Lim, bool Radial, bool Markers>
class LineSolver {
 public:
  LineSolver(LineWork& w, const LineSetup& s, const SweepContext& c, LineBudget& b)
      : W_(w), L_(s), C_(c), B_(b), n_(s.n) {}

  //! Advances the line by dt; false (and `fail` filled) if a cell cannot be kept physical.
  bool run(LineFailure& fail) {
    fillGhosts(W_.u0, n_, L_.left, L_.right);
    for (int k = 0; k < 4; ++k)  // loaded ghost cells (vacuum) keep their values
      std::copy(W_.u0[k].begin(), W_.u0[k].begin() + n_ + 4, W_.u1[k].begin());
    if (!stage(W_.u0, fail)) return false;
    for (int k = 0; k < 4; ++k)
      std::copy(W_.w[k].begin() + 2, W_.w[k].begin() + n_ + 2, W_.u1[k].begin() + 2);
    resetThin(W_.u1, 0.5);
    fillGhosts(W_.u1, n_, L_.left, L_.right);
    if (!stage(W_.u1, fail)) return false;
    for (int k = 0; k < 4; ++k) {
      double* u = W_.u0[k].data();
      const double* w = W_.w[k].data();
      for (int j = 2; j < n_ + 2; ++j) u[j] = 0.5 * (u[j] + w[j]);
    }
    resetThin(W_.u0, 1.0);
    return true;
  }

 private:
  bool isVacuum(int j) const { return Markers && W_.mat[j] < 0; }

  // W = V + dt L(V) on cells 2..n+1, with the ledger of this stage weighted by 1/2 (Heun).
  bool stage(State4& V, LineFailure& fail) {
    const int nb = n_ + 4;
    primitiveStates(*C_.materials, C_.singleMaterial, Markers ? W_.mat.data() : nullptr, 0, nb,
                    V[kRho].data(), V[kMn].data(), V[kMt].data(), V[kE].data(), W_.cs.data());
    // Effect fracture (one material): its tension limited where the pressure enters the fluxes.
    // A cell beside one below the intact density along the line (vacuum, a free surface's partly
    // filled cell, torn material) carries none: without marker lines the partly filled cell of a
    // free surface reads as stretched solid, and would pull its neighbour across the surface.
    if (!Markers && C_.spall != nullptr) {
      const double spall = C_.spall[C_.singleMaterial];
      const double intact = C_.rhoIntact[C_.singleMaterial];
      const double* r = V[kRho].data();
      for (int j = 0; j < nb; ++j)
        limitTension(W_.cs[j], W_.damage[j], spall,
                     r[j] >= intact && (j == 0 || r[j - 1] >= intact) &&
                         (j == nb - 1 || r[j + 1] >= intact));
    }
    const CellState* cs = W_.cs.data();
    for (int j = 0; j < nb; ++j) {
      if (isVacuum(j)) continue;
      W_.sqrtRho[j] = std::sqrt(V[kRho][j]);
      physicalFlux(V[kMn][j], V[kMt][j], V[kE][j], cs[j], W_.F[j].data());
    }
    for (int f = 0; f <= n_ + 2; ++f) {
      if (Markers && W_.kind[f] != FaceKind::Regular) {
        W_.fe[f] = FaceEigen{};
        continue;
      }
      double dU[4];
      for (int k = 0; k < 4; ++k) dU[k] = V[k][f + 1] - V[k][f];
      W_.fe[f] = faceEigen(cs[f], cs[f + 1], dU, W_.sqrtRho[f], W_.sqrtRho[f + 1]);
    }
    for (int j = 1; j <= n_ + 2; ++j)
      for (int l = 0; l < kFields; ++l)
        // The scene's limiter on the two acoustic (genuinely nonlinear) fields; the compressive
        // superbee on the linearly degenerate ones (entropy, shear), whose discontinuities no
        // characteristic convergence steepens, so contacts stay 2-3 cells wide instead of
        // spreading as t^(1/3) (Yee 1989, section 4.6).
        W_.g[j][l] = (l == 0 || l == 3) ? Lim::g(W_.fe[j - 1].alpha[l], W_.fe[j].alpha[l])
                                        : Superbee::g(W_.fe[j - 1].alpha[l], W_.fe[j].alpha[l]);
    for (int f = 1; f <= n_ + 1; ++f) faceFlux(f);
    if constexpr (Radial) facePressures();
    wallFaces();
    for (int j = 2; j <= n_ + 1; ++j) update(V, j);

    // Positivity: recompute with the Rusanov flux the regular faces of any cell the TVD flux
    // leaves unphysical, then floor what is left of a negative internal energy.
    bool any = false;
    for (int j = 2; j <= n_ + 1; ++j) {
      if (isVacuum(j)) continue;
      if (!physical(W_.w[kRho][j], W_.w[kMn][j], W_.w[kMt][j], W_.w[kE][j])) {
        W_.fallback[j - 1] = W_.fallback[j] = 1;
        any = true;
      }
    }
    if (any) {
      for (int f = 1; f <= n_ + 1; ++f)
        if (W_.fallback[f] && (!Markers || W_.kind[f] == FaceKind::Regular)) rusanov(V, f);
      wallFaces();
      for (int j = 2; j <= n_ + 1; ++j)
        if (W_.fallback[j - 1] || W_.fallback[j]) update(V, j);
      std::fill(W_.fallback.begin(), W_.fallback.begin() + n_ + 4, 0);
      if (!rescued_ && resetFastThinNeighbours(V)) {
        // Once per stage: the stage again from its corrected input (nothing booked yet).
        rescued_ = true;
        const bool ok = stage(V, fail);
        rescued_ = false;
        return ok;
      }
      for (int j = 2; j <= n_ + 1; ++j) {
        if (isVacuum(j)) continue;
        const int mat = Markers ? W_.mat[j] : C_.singleMaterial;
        const double r = W_.w[kRho][j], m = W_.w[kMn][j], t = W_.w[kMt][j], E = W_.w[kE][j];
        const bool thin = V[kRho][j] < C_.rhoThin[mat];
        if (!(r > 0.0) || !std::isfinite(E) || !std::isfinite(m) || !std::isfinite(t)) {
          if (!thin) {
            fail.j = j;
            fail.rho = r;
            fail.e = E / r - 0.5 * (m * m + t * t) / (r * r);
            fail.what = "density not positive or state not finite after the positivity fallback";
            return false;
          }
          // A nearly empty cell that even the first-order flux empties (the wave speeds grew
          // within the step): it becomes vacuum at rest, the change booked in the ledger.
          const double fill = 0.5 * C_.rhoCut[mat];
          const double vol = 0.5 / W_.invVol[j];
          const double rho0 = std::isfinite(r) ? r : V[kRho][j];
          const double m0 = std::isfinite(m) ? m : V[kMn][j];
          const double t0 = std::isfinite(t) ? t : V[kMt][j];
          const double E0 = std::isfinite(E) ? E : V[kE][j];
          B_.floors.add(vol * (fill - rho0), -(vol * m0), -(vol * t0), -(vol * E0), C_.axis);
          W_.w[kRho][j] = fill;
          W_.w[kMn][j] = W_.w[kMt][j] = W_.w[kE][j] = 0.0;
          continue;
        }
        const double kin = 0.5 * (m * m + t * t) / r;
        if (E < kin) {
          if (thin) {  // nearly empty: drop the velocity rather than invent kinetic energy
            const double vol = 0.5 / W_.invVol[j];
            B_.floors.add(0.0, -(vol * m), -(vol * t), -(vol * E), C_.axis);
            W_.w[kMn][j] = W_.w[kMt][j] = W_.w[kE][j] = 0.0;
          } else {
            B_.floors.energy += 0.5 * (kin - E) / W_.invVol[j];
            W_.w[kE][j] = kin;
          }
        }
      }
    }
    ledgerFaces();
    return true;
  }

  void faceFlux(int f) {
    const CellState* cs = W_.cs.data();
    double* FL = W_.fluxL[f].data();
    double* FR = W_.fluxR[f].data();
    const FaceKind kind = Markers ? W_.kind[f] : FaceKind::Regular;
    switch (kind) {
      case FaceKind::Regular: {
        const FaceEigen& fe = W_.fe[f];
        const double delta = C_.entropyFix * (std::abs(fe.u) + fe.c);
        hartenYeeFlux(fe, W_.g[f].data(), W_.g[f + 1].data(), W_.F[f].data(), W_.F[f + 1].data(),
                      delta, FL);
        for (int k = 0; k < 4; ++k) FR[k] = FL[k];
        return;
      }
      case FaceKind::Contact: {
        double nn, nt;
        faceNormal(W_, f, nn, nt);
        const ContactStar s = contactStar(cs[f], cs[f + 1], nn, nt, C_.contactIterations);
        starFlux(cs[f], s.p, s.uL, nn, nt, FL);
        starFlux(cs[f + 1], s.p, s.uR, nn, nt, FR);
        return;
      }
      case FaceKind::VacuumRight:
        freeSurfaceFlux(cs[f], FL);
        for (int k = 0; k < 4; ++k) FR[k] = 0.0;
        return;
      case FaceKind::VacuumLeft:
        freeSurfaceFlux(cs[f + 1], FR);
        for (int k = 0; k < 4; ++k) FL[k] = 0.0;
        return;
      case FaceKind::Void:
        for (int k = 0; k < 4; ++k) FL[k] = FR[k] = 0.0;
        return;
    }
  }

  // r-z: the hoop-stress source P/r of the radial momentum takes the mean of the pressures on
  // the cell's two faces, each from the two-shock Riemann problem between its cells. With the
  // flux difference this is the gradient form -dP/dr, exact for a uniform pressure, and on the
  // axis cell the axis face's pressure is that of the flow colliding with its mirror image:
  // without it nothing stops cold gas at r = 0 (the axis face has zero area), and the
  // cylindrical Noh shock never forms.
  void facePressures() {
    const CellState* cs = W_.cs.data();
    for (int f = 1; f <= n_ + 1; ++f) {
      const FaceKind kind = Markers ? W_.kind[f] : FaceKind::Regular;
      W_.pface[f] = (kind == FaceKind::Regular || kind == FaceKind::Contact)
                        ? contactStar(cs[f], cs[f + 1], 1.0, 0.0, C_.contactIterations).p
                        : 0.0;
    }
  }

  void rusanov(const State4& V, int f) {
    const CellState& a = W_.cs[f];
    const CellState& b = W_.cs[f + 1];
    const double* Fa = W_.F[f].data();
    const double* Fb = W_.F[f + 1].data();
    double UL[4], UR[4];
    for (int k = 0; k < 4; ++k) {
      UL[k] = V[k][f];
      UR[k] = V[k][f + 1];
    }
    const double smax = std::max(std::abs(a.u) + a.c, std::abs(b.u) + b.c);
    rusanovFlux(UL, UR, Fa, Fb, smax, W_.fluxL[f].data());
    W_.fluxR[f] = W_.fluxL[f];
  }

  // A reflecting boundary passes only the normal momentum (pressure): mass, tangential
  // momentum and energy fluxes are zero there exactly, not only to rounding.
  void wallFaces() {
    auto wall = [&](int f) {
      for (auto* F : {&W_.fluxL[f], &W_.fluxR[f]}) {
        (*F)[kRho] = 0.0;
        (*F)[kMt] = 0.0;
        (*F)[kE] = 0.0;
      }
    };
    if (L_.left == Side::Reflect) wall(1);
    if (L_.right == Side::Reflect) wall(n_ + 1);
  }

  void update(const State4& V, int j) {
    if (isVacuum(j)) {
      for (int k = 0; k < 4; ++k) W_.w[k][j] = 0.0;
      return;
    }
    const double lam = C_.dt * W_.invVol[j];
    const double aR = W_.area[j], aL = W_.area[j - 1];
    const double* FR = W_.fluxL[j].data();      // leaving through the right face
    const double* FL = W_.fluxR[j - 1].data();  // entering through the left face
    for (int k = 0; k < 4; ++k) W_.w[k][j] = V[k][j] - lam * (aR * FR[k] - aL * FL[k]);
    if constexpr (Radial)
      W_.w[kMn][j] += C_.dt * 0.5 * (W_.pface[j - 1] + W_.pface[j]) * W_.invR[j];
  }

  void ledgerFaces() {
    const double h = 0.5 * C_.dt;  // Heun weight of a stage
    for (int f = 1; f <= n_ + 1; ++f) {
      const double s = h * W_.area[f];
      if (f == 1 && L_.leftEdge) {
        const double* F = W_.fluxR[f].data();
        B_.edge[0].add(s * F[kRho], s * F[kMn], s * F[kMt], s * F[kE], C_.axis);
      } else if (f == n_ + 1 && L_.rightEdge) {
        const double* F = W_.fluxL[f].data();
        B_.edge[1].add(-(s * F[kRho]), -(s * F[kMn]), -(s * F[kMt]), -(s * F[kE]), C_.axis);
      } else if (Markers && W_.kind[f] != FaceKind::Regular) {
        const double* R = W_.fluxR[f].data();
        const double* L = W_.fluxL[f].data();
        B_.interfaces.add(s * (R[kRho] - L[kRho]), s * (R[kMn] - L[kMn]), s * (R[kMt] - L[kMt]),
                          s * (R[kE] - L[kE]), C_.axis);
      }
    }
  }

  // Below the vacuum density a cell is vacuum: it keeps its mass but is set at rest and cold
  // (P = 0). Left alone, the few ulps of momentum and energy that the fluxes of dense
  // neighbours leave in it become huge velocities and sound speeds that set the time step.
  // The Rusanov flux keeps a cell positive only while dt (|u| + c) / h <= 1/2 on both sides
  // of its faces. The step's CFL condition ensures that for the step's start, not for the
  // predictor's result: there a nearly empty (thin) cell can hold a few ulps of mass with a
  // finite energy, so huge specific energy, sound speed and velocity, and its face then
  // diffuses more mass out of its dense neighbour than that holds (docs/tvd.md, "Positivity
  // fallback and vacuum": variant 1 coarse with strength, step 247). Only where the fallback
  // has left a cell that is not thin unphysical (the run would stop otherwise, so every run
  // that went on before is unchanged): each thin neighbour of such a cell whose signal speed
  // breaks that bound is put at rest and cold in the stage's input, its mass kept, the change
  // booked under floors, as a cell below the vacuum density is. True if any was.
  bool resetFastThinNeighbours(State4& V) {
    const double weight = &V == &W_.u0 ? 1.0 : 0.5;  // the stage input's share of the result
    bool reset = false;
    for (int j = 2; j <= n_ + 1; ++j) {
      if (isVacuum(j)) continue;
      const int mat = Markers ? W_.mat[j] : C_.singleMaterial;
      const double r = W_.w[kRho][j];
      const bool bad = !(r > 0.0) || !std::isfinite(W_.w[kE][j]) || !std::isfinite(W_.w[kMn][j]) ||
                       !std::isfinite(W_.w[kMt][j]);
      if (!bad || V[kRho][j] < C_.rhoThin[mat]) continue;
      for (int nb : {j - 1, j + 1}) {
        if (nb < 2 || nb > n_ + 1 || isVacuum(nb)) continue;
        const int mn = Markers ? W_.mat[nb] : C_.singleMaterial;
        if (!(V[kRho][nb] < C_.rhoThin[mn])) continue;
        const CellState& c = W_.cs[nb];
        const double reach = C_.dt * W_.invVol[nb] * std::max(W_.area[nb - 1], W_.area[nb]);
        if (!(reach * (std::abs(c.u) + c.c) > 0.5)) continue;
        putAtRest(V, nb, weight / W_.invVol[nb], C_.axis, B_.floors);
        reset = true;
      }
    }
    return reset;
  }

  void resetThin(State4& U, double weight) {
    for (int j = 2; j <= n_ + 1; ++j) {
      if (isVacuum(j)) continue;
      const int m = Markers ? W_.mat[j] : C_.singleMaterial;
      if (!(U[kRho][j] >= C_.rhoCut[m])) putAtRest(U, j, weight / W_.invVol[j], C_.axis, B_.floors);
    }
  }

  LineWork& W_;
  const LineSetup& L_;
  const SweepContext& C_;
  LineBudget& B_;
  const int n_;
  bool rescued_ = false;  // resetFastThinNeighbours has acted in this stage
};

}  // namespace hvi::tvd::detail
