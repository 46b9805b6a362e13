//! @file One 1-D sweep of one grid line in the conservative cut-cell mode (docs/tvd.md,
//! "Conservative interfaces"): every phase on its own part of the cells, Harten-Yee fluxes
//! through the faces it wets on both sides, and the interface exchange between phases applied
//! equally and oppositely, so every phase's mass and the totals are conserved to round-off.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "cut_line.hpp"
#include "eos_line.hpp"
#include "hvi/tvd/contact.hpp"
#include "hvi/tvd/harten_yee.hpp"
#include "hvi/tvd/limiter.hpp"
#include "hvi/tvd/phases.hpp"
#include "hvi/tvd/relaxation.hpp"
#include "line_kernel.hpp"
#include "strength_step.hpp"

namespace hvi::tvd::detail {

//! A phase cell smaller than this part of its largest wetted face is merged with its neighbour
//! through that face after every stage (Hu et al. 2006, section 2.5: 0.5): its own volume would
//! otherwise limit the time step.
inline constexpr double kMergeFraction = 0.5;
//! An r-z face the phase does not pair across has no face pressure (the hoop source takes the
//! cell's own); face pressures may be negative (tension), so the mark is not a number.
inline constexpr double kNoFacePressure = std::numeric_limits<double>::quiet_NaN();
//! Below this part of its fraction a phase cell is fading out of the cell within the step (a
//! trailing edge leaving it): its stage states are intermediates, not checked as physical.
inline constexpr double kLiveFraction = 0.1;

template <class Lim, bool Radial>
class CutLineSolver {
 public:
  CutLineSolver(CutLineWork& w, const LineSetup& s, const SweepContext& c, LineBudget& b)
      : W_(w), L_(s), C_(c), B_(b), n_(s.n), P_(static_cast<int>(w.phase.size())) {}

  //! Advances every phase of the line by dt (Heun); false (and `fail`) if a cell cannot be kept
  //! physical.
  bool run(LineFailure& fail) {
    prepare();
    for (auto& ph : W_.phase) {
      if (!ph.active) continue;
      fillPhaseGhosts(ph.q0);
      fillVolumeGhosts(ph.vol0);
      for (int k = 0; k < 4; ++k)
        std::copy(ph.q0[k].begin(), ph.q0[k].begin() + n_ + 4, ph.q1[k].begin());
      std::copy(ph.vol0.begin(), ph.vol0.begin() + n_ + 4, ph.vol1.begin());
    }
    if (!stage(true, fail)) return false;
    for (auto& ph : W_.phase) {
      if (!ph.active) continue;
      for (int k = 0; k < 4; ++k)
        std::copy(ph.w[k].begin() + 2, ph.w[k].begin() + n_ + 2, ph.q1[k].begin() + 2);
      std::copy(ph.volW.begin() + 2, ph.volW.begin() + n_ + 2, ph.vol1.begin() + 2);
      fillPhaseGhosts(ph.q1);
      fillVolumeGhosts(ph.vol1);
    }
    if (!stage(false, fail)) return false;
    for (int p = 0; p < P_; ++p) {
      PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
      if (!ph.active) continue;
      for (int k = 0; k < 4; ++k)
        for (int j = 2; j < n_ + 2; ++j) ph.q0[k][j] = 0.5 * (ph.q0[k][j] + ph.w[k][j]);
      for (int j = 2; j < n_ + 2; ++j) ph.vol0[j] = 0.5 * (ph.vol0[j] + ph.volW[j]);
      resetThin(p, ph.q0, ph.vol0, 1.0);
    }
    return true;
  }

 private:
  // Paired and unpaired apertures of every face (fixed during the step).
  void prepare() {
    for (auto& ph : W_.phase) {
      if (!ph.active) continue;
      ph.edgeMass = 0.0;
      ph.lo = n_ + 4;
      ph.hi = -1;
      for (int j = 0; j < n_ + 4; ++j) {
        ph.present[j] = ph.alpha[j] >= kPhaseAbsent ? 1 : 0;
        ph.virt[j] = 0;
        if (ph.present[j]) {
          ph.lo = std::min(ph.lo, j);
          ph.hi = j;
        }
      }
    }
    openFaces();
    for (auto& ph : W_.phase) {
      if (!ph.active) continue;
      for (int f = 0; f <= n_ + 2; ++f) {
        const bool l = ph.present[f] != 0, r = ph.present[f + 1] != 0;
        ph.ap[f] = l && r ? std::min(ph.gm[f], ph.gp[f]) : 0.0;
        ph.uL[f] = l ? std::max(ph.gm[f] - ph.ap[f], 0.0) : 0.0;
        ph.uR[f] = r ? std::max(ph.gp[f] - ph.ap[f], 0.0) : 0.0;
      }
    }
    W_.sharedCount = 0;
    if (P_ < 2) return;
    for (int j = 2; j <= n_ + 1; ++j) {
      int held = 0;
      for (const auto& ph : W_.phase) held += ph.active && ph.present[j] ? 1 : 0;
      if (held >= 2) W_.shared[static_cast<std::size_t>(W_.sharedCount++)] = j;
    }
  }

  // An interface lying on a face (docs/tvd.md, "Interfaces on cell faces"): the phase wets
  // the face from one side and the cell across holds nothing, so no paired face flux could
  // carry the phase into that cell, and the first steps would compress the cells along the face
  // (or rarefy them at a trailing edge) until the marker step gave the next cell a fraction.
  // The empty cell is opened to the phase: it is present, the face is paired over the wetted
  // part, and until the cell holds some of the phase the face carries the donor's own state at
  // the donor's velocity, without pressure (the vacuum across does no work): exactly what
  // crosses a face behind a free surface in a cut cell. A leading edge so enters the cell as a
  // sliver; a trailing edge draws a negative part that absorbFading hands back to the donor,
  // so the edge moves into it. Only where no other phase is in the cell (or opens it too): an
  // interface between two phases on a face is the exchange's.
  void openFaces() {
    bool any = false;
    for (int p = 0; p < P_; ++p) {
      PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
      if (!ph.active) continue;
      for (int j = 2; j <= n_ + 1; ++j) {
        if (ph.present[j]) continue;
        const bool lower = ph.present[j - 1] && j - 1 >= 2 && ph.gm[j - 1] > 0.0;
        const bool upper = ph.present[j + 1] && j + 1 <= n_ + 1 && ph.gp[j] > 0.0;
        if (lower != upper) {
          ph.virt[j] = lower ? -1 : 1;
          any = true;
        }
      }
    }
    if (!any) return;  // (most lines: no interface lies on a face)
    for (int j = 2; j <= n_ + 1; ++j) {
      int claims = 0;
      for (const auto& ph : W_.phase)
        if (ph.active && (ph.present[j] || ph.virt[j])) ++claims;
      for (auto& ph : W_.phase) {
        if (!ph.active || !ph.virt[j]) continue;
        if (claims > 1) {
          ph.virt[j] = 0;
          continue;
        }
        ph.present[j] = 1;
        if (ph.virt[j] < 0)
          ph.gp[j - 1] = ph.gm[j - 1];
        else
          ph.gm[j] = ph.gp[j];
        ph.lo = std::min(ph.lo, j);
        ph.hi = std::max(ph.hi, j);
      }
    }
  }
  // An opened cell that holds none of the phase yet (its state is the donor's, by the face).
  bool unfilled(const PhaseLine& ph, int j) const {
    return ph.virt[j] != 0 && !(ph.cs[j].rho > 0.0);
  }
  // The face flux into an unfilled opened cell: the donor's state U moved at its velocity u
  // (no pressure term), and the volume it takes (u per unit aperture).
  bool openFlux(PhaseLine& ph, int f) {
    int donor = -1;
    if (ph.virt[f + 1] < 0 && unfilled(ph, f + 1)) donor = f;
    if (ph.virt[f] > 0 && unfilled(ph, f)) donor = f + 1;
    if (donor < 0 || !(ph.cs[donor].rho > 0.0)) return false;
    const double u = ph.cs[donor].u;
    for (int k = 0; k < 4; ++k) ph.flux[f][k] = u * ph.U[k][donor];
    ph.vflux[f] = u;
    return true;
  }

  void fillPhaseGhosts(std::array<std::vector<double>, 4>& q) const {
    fillGhosts(q, n_, L_.left, L_.right);
  }
  void fillVolumeGhosts(std::vector<double>& v) const {
    auto side = [&](Side s, int in0, int in1, int g0, int g1) {
      if (s == Side::Loaded) return;
      v[g0] = v[in0];
      v[g1] = v[s == Side::Reflect ? in1 : in0];
    };
    side(L_.left, 2, 3, 1, 0);
    side(L_.right, n_ + 1, n_, n_ + 2, n_ + 3);
  }

  // In-cell interface area of phase `ph` in cell j along the line (outward of the phase), in
  // line units: the divergence theorem over the phase's part of the cell, so that a uniform
  // pressure exerts no net force (planar: the aperture difference; radial: with the hoop term,
  // whose force P alpha V / r is P alpha h in line units, V = r h: so I = alpha h - faces, and
  // a full cell has none, r_R - r_L = h).
  double interfaceAlong(const PhaseLine& ph, int j) const {
    const double faces = W_.area[j] * ph.gm[j] - W_.area[j - 1] * ph.gp[j - 1];
    if constexpr (Radial) return ph.alpha[j] * W_.invR[j] / W_.invVol[j] - faces;
    return -faces;
  }
  double interfacePlanar(const PhaseLine& ph, int j) const { return ph.gp[j - 1] - ph.gm[j]; }

  bool stage(bool first, LineFailure& fail) {
    const int nb = n_ + 4;
    for (auto& ph : W_.phase)
      if (ph.active) closeFading(ph, first ? ph.q0 : ph.q1, first ? ph.vol0 : ph.vol1);
    for (int p = 0; p < P_; ++p)
      if (W_.phase[static_cast<std::size_t>(p)].active) states(p, first);
    for (int p = 0; p < P_; ++p) {
      PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
      if (!ph.active) continue;
      // Only the span the phase occupies (and the faces around it): every face flux below
      // needs both its cells to hold the phase, so nothing outside is read.
      for (int f = std::max(0, ph.lo - 1); f <= std::min(n_ + 2, ph.hi); ++f) {
        // A face carries a flux only between two cells that hold some of the phase: a cell the
        // positivity limiter emptied has no state to average with (its c would be 0).
        if (!(ph.ap[f] > 0.0) || !(ph.cs[f].rho > 0.0) || !(ph.cs[f + 1].rho > 0.0)) {
          ph.fe[f] = FaceEigen{};
          continue;
        }
        double dU[4];
        for (int k = 0; k < 4; ++k) dU[k] = ph.U[k][f + 1] - ph.U[k][f];
        ph.fe[f] = faceEigen(ph.cs[f], ph.cs[f + 1], dU, ph.sqrtRho[f], ph.sqrtRho[f + 1]);
      }
      for (int j = std::max(1, ph.lo); j <= std::min(n_ + 2, ph.hi); ++j)
        for (int l = 0; l < kFields; ++l)
          ph.g[j][l] = (l == 0 || l == 3) ? Lim::g(ph.fe[j - 1].alpha[l], ph.fe[j].alpha[l])
                                          : Superbee::g(ph.fe[j - 1].alpha[l], ph.fe[j].alpha[l]);
      for (int f = 1; f <= n_ + 1; ++f) {
        ph.vflux[f] = 0.0;
        if (!(ph.ap[f] > 0.0) || !(ph.cs[f].rho > 0.0) || !(ph.cs[f + 1].rho > 0.0)) {
          if (!(ph.ap[f] > 0.0) || !openFlux(ph, f)) ph.flux[f] = {0.0, 0.0, 0.0, 0.0};
          continue;
        }
        const FaceEigen& fe = ph.fe[f];
        const double delta = C_.entropyFix * (std::abs(fe.u) + fe.c);
        hartenYeeFlux(fe, ph.g[f].data(), ph.g[f + 1].data(), ph.F[f].data(), ph.F[f + 1].data(),
                      delta, ph.flux[f].data());
      }
      if constexpr (Radial)
        for (int f = 1; f <= n_ + 1; ++f)
          ph.pface[f] = ph.ap[f] > 0.0 && ph.cs[f].rho > 0.0 && ph.cs[f + 1].rho > 0.0
                            ? facePressure(ph.cs[f], ph.cs[f + 1], C_.contactIterations)
                            : kNoFacePressure;  // no pair across: the cell's own pressure
      wallFaces(ph);
      noReentry(ph, true);
      for (int k = 0; k < 4; ++k) std::fill(ph.ex[k].begin(), ph.ex[k].begin() + nb, 0.0);
    }
    exchange();
    for (int p = 0; p < P_; ++p) {
      PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
      if (!ph.active) continue;
      const auto& V = first ? ph.q0 : ph.q1;
      const auto& S = first ? ph.vol0 : ph.vol1;
      for (int j = 2; j <= n_ + 1; ++j) update(ph, V, S, j);
      merge(ph);
    }
    // The stiff phases' velocities relax before the positivity treatment judges the stage
    // (their explicit drag overshoots and takes internal energy into kinetic energy: the
    // fallback would then act where nothing is wrong), and again after it, before the check and
    // the floors: the fallback recomputes a phase's cells from the fluxes, and a fading cell
    // (its mass near zero, so never relaxed) hands its content, with the exchange impulse it
    // took, to its neighbour.
    relaxStiff(first, false);
    for (int p = 0; p < P_; ++p) {
      PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
      if (!ph.active) continue;
      positivity(p, first ? ph.q0 : ph.q1, first ? ph.vol0 : ph.vol1, first);
    }
    relaxStiff(first, true);
    for (int p = 0; p < P_; ++p) {
      PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
      if (!ph.active) continue;
      if (!check(p, first, fail)) return false;
      ledgerFaces(p, ph);
      if (first) resetThin(p, ph.w, ph.volW, 0.5);
      applyDry(ph);
    }
    return true;
  }

  // Phase states U = q / alpha and their fluxes on every present cell of the buffer.
  void states(int p, bool first) {
    PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
    const auto& V = first ? ph.q0 : ph.q1;
    const auto& S = first ? ph.vol0 : ph.vol1;
    const int nb = n_ + 4;
    const double spall = C_.spall != nullptr ? C_.spall[p] : -1.0;
    const bool fracture = spall >= 0.0;
    std::visit(
        [&](const auto& eos) {
          // The occupied span and one cell either side (the faces around it check them).
          for (int j = std::max(0, ph.lo - 1); j <= std::min(nb - 1, ph.hi + 1); ++j) {
            // An opened cell (no fraction) holds a state once its part is above the absent
            // fraction itself: below, 1 / S may overflow (a plate at rest moving by round-off).
            if (!ph.present[j] || !(S[j] > kPhaseAbsent * (ph.virt[j] != 0 ? 1.0 : ph.alpha[j]))) {
              ph.cs[j] = CellState{};
              ph.sqrtRho[j] = 0.0;
              ph.F[j] = {0.0, 0.0, 0.0, 0.0};
              for (int k = 0; k < 4; ++k) ph.U[k][j] = 0.0;
              continue;
            }
            const double inv = 1.0 / S[j];
            for (int k = 0; k < 4; ++k) ph.U[k][j] = V[k][j] * inv;
            const double r = ph.U[kRho][j];
            if (!(r > 0.0)) {
              ph.cs[j] = CellState{};
              ph.sqrtRho[j] = 0.0;
              ph.F[j] = {0.0, 0.0, 0.0, 0.0};
              continue;
            }
            ph.cs[j] = cellState(eos, r, ph.U[kMn][j], ph.U[kMt][j], ph.U[kE][j]);
            // Effect fracture: the phase's tension limited where the pressure enters the
            // fluxes, the characteristic split and the interface exchange.
            if (fracture) limitTension(ph.cs[j], ph.damage[j], spall, r >= C_.rhoIntact[p]);
            ph.sqrtRho[j] = std::sqrt(r);
            physicalFlux(ph.U[kMn][j], ph.U[kMt][j], ph.U[kE][j], ph.cs[j], ph.F[j].data());
          }
        },
        (*C_.materials)[static_cast<std::size_t>(p)].eos);
  }

  void wallFaces(PhaseLine& ph) const {
    auto wall = [&](int f) {
      ph.flux[f][kRho] = 0.0;
      ph.flux[f][kMt] = 0.0;
      ph.flux[f][kE] = 0.0;
    };
    if (L_.left == Side::Reflect) wall(1);
    if (L_.right == Side::Reflect) wall(n_ + 1);
  }

  // Options::closedOutflow (the scenes' default, tvd.outflow = "auto"; docs/tvd.md "Outflow sides:
  // no re-entry"): an outflow side lets a phase out, never back in. The zero-gradient ghost copies
  // the edge cell, so where the phase there moves into the domain its face flux carries mass in
  // that no marker line holds (variant 1 at 0.0075 cm took 0.16 of its 0.28 energy in through its
  // top side). With the option such a face is a wall for the phase: no mass, tangential momentum or
  // energy, and the normal momentum of the contact pressure between the edge cell and its mirror
  // image (p at rest, falling to 0 as the material pulls away, never tension); in r-z the hoop term
  // takes the same face pressure.
  void noReentry(PhaseLine& ph, bool hoop) {
    if (!C_.closedOutflow) return;
    auto wallFlux = [&](int f, int j, bool right) {
      const bool inward = right ? ph.flux[f][kRho] < 0.0 : ph.flux[f][kRho] > 0.0;
      if (!inward || !(ph.cs[j].rho > 0.0)) return;
      CellState mirror = ph.cs[j];
      mirror.u = -mirror.u;
      const double pStar = right ? contactStar(ph.cs[j], mirror, 1.0, 0.0, C_.contactIterations).p
                                 : contactStar(mirror, ph.cs[j], 1.0, 0.0, C_.contactIterations).p;
      ph.flux[f] = {0.0, pStar, 0.0, 0.0};
      if constexpr (Radial)
        if (hoop) ph.pface[f] = pStar;
    };
    if (L_.left == Side::Outflow) wallFlux(1, 2, false);
    if (L_.right == Side::Outflow) wallFlux(n_ + 1, n_ + 1, true);
  }

  // Momentum and energy that pass between phases: (a) where the interface lies on a face (the
  // phase on one side only, another phase across it), through the face's normal; (b) inside a
  // cell both phases occupy, along the interface normal (the phases' interface area vectors).
  // Each is a two-shock contact Riemann problem (contactStar) whose p* and u* act on both sides
  // with opposite signs; a separating contact (p* = 0) exchanges nothing. No mass crosses.
  void exchange() {
    for (int f = 1; f <= n_ + 1; ++f) {
      for (int p = 0; p < P_; ++p) {
        PhaseLine& a = W_.phase[static_cast<std::size_t>(p)];
        if (!a.active || !(a.uL[f] > 0.0)) continue;
        double left = a.uL[f];
        for (int q = 0; q < P_ && left > 0.0; ++q) {
          if (q == p) continue;
          PhaseLine& b = W_.phase[static_cast<std::size_t>(q)];
          if (!b.active || !(b.uR[f] > 0.0)) continue;
          const double s = std::min(left, b.uR[f]) * W_.area[f];
          left -= s / W_.area[f];
          if (!(a.cs[f].rho > 0.0) || !(b.cs[f + 1].rho > 0.0)) continue;
          const ContactStar st = contactStar(a.cs[f], b.cs[f + 1], 1.0, 0.0, C_.contactIterations);
          if (!(st.p > 0.0)) continue;
          a.ex[kMn][f] -= st.p * s;
          a.ex[kE][f] -= st.p * st.uL * s;
          b.ex[kMn][f + 1] += st.p * s;
          b.ex[kE][f + 1] += st.p * st.uL * s;
        }
      }
    }
    if (P_ < 2) return;
    for (int ix = 0; ix < W_.sharedCount; ++ix) {
      const int j = W_.shared[static_cast<std::size_t>(ix)];
      // The pair's shared area, component by component: where a's outward area and b's inward
      // area agree in sign, the smaller of the two. Exact where the two fill the cell (I_b =
      // -I_a); with vacuum in the cell it never gives a phase more interface than it has, so a
      // sliver with no area along the line gets no push along it.
      auto shared = [](double ia, double ib) {
        const double jb = -ib;
        if (ia > 0.0 && jb > 0.0) return std::min(ia, jb);
        if (ia < 0.0 && jb < 0.0) return std::max(ia, jb);
        return 0.0;
      };
      for (int p = 0; p < P_; ++p) {
        PhaseLine& a = W_.phase[static_cast<std::size_t>(p)];
        if (!a.active || !a.present[j] || !(a.cs[j].rho > 0.0)) continue;
        for (int q = p + 1; q < P_; ++q) {
          PhaseLine& b = W_.phase[static_cast<std::size_t>(q)];
          if (!b.active || !b.present[j] || !(b.cs[j].rho > 0.0)) continue;
          const double sn = shared(interfacePlanar(a, j), interfacePlanar(b, j));
          const double st = shared(a.It[j], b.It[j]);
          const double len = std::sqrt(sn * sn + st * st);
          if (!(len > 1e-12)) continue;
          const double nn = sn / len, nt = st / len;
          const ContactStar cst = contactStar(a.cs[j], b.cs[j], nn, nt, C_.contactIterations);
          if (!(cst.p > 0.0)) continue;
          const double s = shared(interfaceAlong(a, j), interfaceAlong(b, j));
          a.ex[kMn][j] -= cst.p * s;
          a.ex[kE][j] -= cst.p * cst.uL * nn * s;
          b.ex[kMn][j] += cst.p * s;
          b.ex[kE][j] += cst.p * cst.uL * nn * s;
        }
      }
    }
  }

  // Velocity relaxation of stiff phases (docs/tvd.md, "The thin film: velocity relaxation").
  // A phase of fraction alpha exchanges momentum with the cell's other phases through at most
  // two interfaces of a cell's width: linearised, p* = p0 + Z (ua - ub) with Z <= Za = rho c,
  // so its velocity relaxes in tau >= alpha h / (2 c), the time its own sound needs to cross
  // its part of the cell, and in the same time its own pressure acts on its interface (a film
  // behind a separating contact is pushed by it alone). The mass that takes the exchange is
  // the cell's and, through the merge, its paired neighbour's along the line (a sliver of a
  // full body is not stiff; a film is thin in its neighbours too). An explicit stage with
  // dt > tau overshoots (Heun amplifies the error for dt > 2 tau; a film: tau ~ 1e-4 dt), so
  // where tau < dt the cell's phases take their common velocity (the limit tau -> 0, Saurel and
  // Abgrall 1999), momentum and total energy exact (relaxVelocities). Applied to the state the
  // stage is judged by: the predictor's result, the corrector's Heun average.
  void relaxStiff(bool first, bool final) {
    if (P_ < 2) return;
    double* m = W_.relax.data();
    double* mn = m + P_;
    double* mt = mn + P_;
    double* E = mt + P_;
    double* old = E + P_;  // 3 per phase: the judged momenta and energy before
    const double weight = first ? 1.0 : 2.0;  // the corrector's result changes twice its average
    for (int ix = 0; ix < W_.sharedCount; ++ix) {
      const int j = W_.shared[static_cast<std::size_t>(ix)];
      int held = 0;
      bool stiff = false;
      for (int p = 0; p < P_; ++p) {
        const PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
        m[p] = 0.0;
        if (!ph.active || !ph.present[j]) continue;
        const double r = judged(ph, kRho, j, first);
        // A part the stage moved out (negative working volume: an edge left the cell, and what
        // is left is round-off mass next to momentum that is not) has no velocity to relax:
        // pooled, its momentum over its mass gave the cell a common velocity of 1e10 cm/us and
        // its phases energies of +-1e3 (variant 1 at 0.0075 cm, docs/tvd.md "Robustness").
        if (!(r > 0.0) || !(judgedVolume(ph, j, first) > 0.0)) continue;
        m[p] = r;
        ++held;
        const double c = ph.cs[j].c;
        if (!(c > 0.0)) continue;
        const double partner = std::max(ph.ap[j - 1] > 0.0 ? ph.alpha[j - 1] : 0.0,
                                        ph.ap[j] > 0.0 ? ph.alpha[j + 1] : 0.0);
        if ((ph.alpha[j] + partner) * C_.h < 2.0 * c * C_.dt) stiff = true;
      }
      if (!stiff || held < 2) continue;
      for (int p = 0; p < P_; ++p) {
        if (!(m[p] > 0.0)) continue;
        const PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
        old[3 * p] = mn[p] = judged(ph, kMn, j, first);
        old[3 * p + 1] = mt[p] = judged(ph, kMt, j, first);
        old[3 * p + 2] = E[p] = judged(ph, kE, j, first);
      }
      relaxVelocities(P_, m, mn, mt, E);
      // Booked in the exchange as well: the positivity fallback recomputes a phase's cells from
      // the fluxes and the exchange, and so keeps the impulses the other phases took.
      const double toExchange = final ? 0.0 : 1.0 / (C_.dt * W_.invVol[j]);
      for (int p = 0; p < P_; ++p) {
        if (!(m[p] > 0.0)) continue;
        PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
        const double d[3] = {weight * (mn[p] - old[3 * p]), weight * (mt[p] - old[3 * p + 1]),
                             weight * (E[p] - old[3 * p + 2])};
        ph.w[kMn][j] += d[0];
        ph.w[kMt][j] += d[1];
        ph.w[kE][j] += d[2];
        ph.ex[kMn][j] += d[0] * toExchange;
        ph.ex[kMt][j] += d[1] * toExchange;
        ph.ex[kE][j] += d[2] * toExchange;
      }
      if (final) ++B_.relaxed;
    }
  }

  void update(PhaseLine& ph, const std::array<std::vector<double>, 4>& V,
              const std::vector<double>& S, int j) {
    if (!ph.present[j]) {
      for (int k = 0; k < 4; ++k) ph.w[k][j] = 0.0;
      ph.volW[j] = 0.0;
      return;
    }
    // The phase's part of the cell grows or shrinks as its interface moves with it (the
    // interface area times the phase's velocity along the line); a full cell has no interface.
    const double lam = C_.dt * W_.invVol[j];
    const double aR = W_.area[j] * ph.ap[j], aL = W_.area[j - 1] * ph.ap[j - 1];
    if (unfilled(ph, j))  // its part grows by the volume the donor's face moved in
      ph.volW[j] = S[j] + lam * (aL * ph.vflux[j - 1] - aR * ph.vflux[j]);
    else
      ph.volW[j] = S[j] + lam * ph.cs[j].u * interfaceAlong(ph, j);
    const double* FR = ph.flux[j].data();
    const double* FL = ph.flux[j - 1].data();
    for (int k = 0; k < 4; ++k)
      ph.w[k][j] = V[k][j] - lam * (aR * FR[k] - aL * FL[k] - ph.ex[k][j]);
    if constexpr (Radial) {
      // Hoop source over the phase's part of the cell; a face the phase does not pair across
      // contributes the cell's own pressure (what its interface area in the closure assumes).
      const double pl = ph.ap[j - 1] > 0.0 && !std::isnan(ph.pface[j - 1]) ? ph.pface[j - 1] : ph.cs[j].p;
      const double pr = ph.ap[j] > 0.0 && !std::isnan(ph.pface[j]) ? ph.pface[j] : ph.cs[j].p;
      ph.w[kMn][j] += C_.dt * 0.5 * (pl + pr) * S[j] * W_.invR[j];
    }
  }

  // What a stage is judged by: the predictor's result itself, and for the corrector the Heun
  // average it leads to (the corrector's own result is only an intermediate: at a trailing
  // edge it is negative, volume and mass alike, while the average is the exact remainder).
  double judged(const PhaseLine& ph, int k, int j, bool first) const {
    return first ? ph.w[k][j] : 0.5 * (ph.q0[k][j] + ph.w[k][j]);
  }
  double judgedVolume(const PhaseLine& ph, int j, bool first) const {
    return first ? ph.volW[j] : 0.5 * (ph.vol0[j] + ph.volW[j]);
  }
  // A cell keeps a state worth checking while its part is not a fading sliver.
  bool live(const PhaseLine& ph, int j, bool first) const {
    const double v = judgedVolume(ph, j, first);
    if (ph.virt[j] != 0 && !(v > 0.0)) return false;  // opened, still empty
    return v >= kLiveFraction * ph.alpha[j];
  }

  // As the whole-cell kernel: faces of a live cell the TVD flux leaves unphysical are
  // recomputed with the Rusanov flux. Mass is never removed: a positivity flux limiter keeps
  // every cell's mass (as judged) from going below zero. What is left is check's: the floors of
  // negative internal energy (booked), and the stop of a live cell that cannot be kept physical.
  void positivity(int p, const std::array<std::vector<double>, 4>& V, const std::vector<double>& S,
                  bool first) {
    PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
    auto physicalAt = [&](int j) {
      return physical(judged(ph, kRho, j, first), judged(ph, kMn, j, first),
                      judged(ph, kMt, j, first), judged(ph, kE, j, first));
    };
    bool any = false;
    for (int j = 2; j <= n_ + 1; ++j) {
      if (!ph.present[j] || !live(ph, j, first) || physicalAt(j)) continue;
      ph.fallback[j - 1] = ph.fallback[j] = 1;
      any = true;
    }
    if (any) {
      for (int f = 1; f <= n_ + 1; ++f) {
        if (!ph.fallback[f] || !(ph.ap[f] > 0.0) || !(ph.cs[f].rho > 0.0) ||
            !(ph.cs[f + 1].rho > 0.0))
          continue;
        const CellState& a = ph.cs[f];
        const CellState& b = ph.cs[f + 1];
        double UL[4], UR[4];
        for (int k = 0; k < 4; ++k) {
          UL[k] = ph.U[k][f];
          UR[k] = ph.U[k][f + 1];
        }
        const double smax = std::max(std::abs(a.u) + a.c, std::abs(b.u) + b.c);
        rusanovFlux(UL, UR, ph.F[f].data(), ph.F[f + 1].data(), smax, ph.flux[f].data());
      }
      wallFaces(ph);
      noReentry(ph, false);
      std::fill(ph.fallback.begin(), ph.fallback.begin() + n_ + 4, 0);
      // Every cell again (not only those next to a recomputed face): the merges pooled pairs
      // of cells, and redoing one of a pair would count its partner's share twice.
      for (int j = 2; j <= n_ + 1; ++j) update(ph, V, S, j);
      merge(ph);
    }
    // A cut cell can still lose more than it holds (its faces are large for its volume): the
    // faces that carry its mass out are scaled down until it keeps none to spare (a
    // positivity-preserving flux limiter in the sense of Hu, Adams and Shu, J. Comput. Phys.
    // 242 (2013) 169). A face flux is shared by its two cells, so this stays conservative.
    const bool absorbed = absorbFading(ph);
    for (int pass = 0; pass < 8; ++pass) {
      bool short_ = false;
      for (int j = 2; j <= n_ + 1; ++j) {
        if (!ph.present[j]) continue;
        // judged mass >= 0: the predictor's result, the corrector's average
        const double floor = first ? 0.0 : -ph.q0[kRho][j];
        const double deficit = floor - ph.w[kRho][j];
        if (!(deficit > 0.0)) continue;
        const double lam = C_.dt * W_.invVol[j];
        const double outL =
            lam * W_.area[j - 1] * ph.ap[j - 1] * std::max(-ph.flux[j - 1][kRho], 0.0);
        const double outR = lam * W_.area[j] * ph.ap[j] * std::max(ph.flux[j][kRho], 0.0);
        const double out = outL + outR;
        if (!(out > 0.0)) continue;
        const double theta = std::max(0.0, 1.0 - deficit / out * (1.0 + 1e-12));
        for (int f : {j - 1, j}) {
          const bool leaving = f == j ? ph.flux[f][kRho] > 0.0 : ph.flux[f][kRho] < 0.0;
          if (!leaving) continue;
          // The face's two cells take the change directly (a full update would undo the
          // absorbed fading cells).
          const double s = W_.area[f] * ph.ap[f] * (1.0 - theta);
          for (int k = 0; k < 4; ++k) {
            const double d = s * ph.flux[f][k];
            if (f >= 2) ph.w[k][f] += C_.dt * W_.invVol[f] * d;
            if (f + 1 <= n_ + 1) ph.w[k][f + 1] -= C_.dt * W_.invVol[f + 1] * d;
            ph.flux[f][k] *= theta;
          }
        }
        short_ = true;
      }
      if (!short_) break;
    }
    if (absorbed) settleAbsorbed(ph);
  }

  // The stage's result must be physical where the cell is live: a state the fallback and the
  // limiter could not keep positive stops the run, and what is left of a negative internal
  // energy is floored (booked). A cold compressed state (e ~ 0, P > 0: Tillotson's or
  // Mie-Gruneisen's A mu) leaves the set e >= 0 under any flux with a finite wave speed (the
  // Lax-Friedrichs state U + F(U)/s has rho e = -P^2 / (2 s^2 rho (1 + u/s)) < 0 at e = 0), so
  // the floor there makes energy (+10 % on the Whipple d = 1 cm debris striking the wall).
  // Options::keepColdStates (off: it destabilises thin cells, docs/tvd.md "The energy floor
  // in cold compressed cells") keeps such a state where the EOS takes it.
  bool check(int p, bool first, LineFailure& fail) {
    PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
    mixDeficits(ph, first);
    for (int j = 2; j <= n_ + 1; ++j) {
      if (!ph.present[j] || !live(ph, j, first)) continue;
      const double r = judged(ph, kRho, j, first), m = judged(ph, kMn, j, first);
      const double t = judged(ph, kMt, j, first), E = judged(ph, kE, j, first);
      if (!(r > 0.0) || !std::isfinite(E) || !std::isfinite(m) || !std::isfinite(t)) {
        fail.j = j;
        fail.rho = r / judgedVolume(ph, j, first);
        fail.e = E / r - 0.5 * (m * m + t * t) / (r * r);
        fail.what = "phase density not positive or state not finite after the positivity fallback";
        return false;
      }
      // Below the vacuum density resetThin puts the cell at rest and cold right after this
      // check (the same judged state, first stage, or its average, second): a floor here would
      // only be taken back there. With round-off mass beside momentum the two bookings were
      // each of the order of the whole problem's energy, hiding the net the reset removes.
      const double vol = judgedVolume(ph, j, first);
      if (!(r >= C_.rhoCut[p] * vol)) continue;
      const double kin = 0.5 * (m * m + t * t) / r;
      if (E < kin && C_.keepColdStates && admissible(p, r, m, t, E, vol)) continue;
      if (E < kin) {  // raise the judged energy to the kinetic energy (e = 0), booked
        const double add = (kin - E) * (first ? 1.0 : 2.0);
        B_.floors.energy += 0.5 * add / W_.invVol[j];  // the final state changes by add / 2
        ph.w[kE][j] += add;
      }
    }
    return true;
  }

  // The EOS takes the phase state (partial integrals r, m, t, E over its part `vol` of the
  // cell): a finite, non-negative pressure and a positive, finite sound speed.
  bool admissible(int p, double r, double m, double t, double E, double vol) const {
    if (!(vol > 0.0)) return false;
    return std::visit(
        [&](const auto& eos) {
          const CellState s = cellState(eos, r / vol, m / vol, t / vol, E / vol);
          return std::isfinite(s.p) && s.p >= 0.0 && std::isfinite(s.c) && s.c > 0.0;
        },
        (*C_.materials)[static_cast<std::size_t>(p)].eos);
  }

  // A live cell the limiter left without positive mass: its deficit was not made by its own
  // outflows (the limiter would have scaled them) but handed to it by a fading neighbour
  // (absorbFading), so no flux is left to scale. As the last resort before the run stops, the
  // cell mixes with the neighbour along the line that holds the most of the phase (Hu et al.
  // 2006's mixing: the judged integrals pooled and shared by judged volume, a convex share of
  // a positive total): conservative, and a no-op wherever the run would have gone on anyway.
  void mixDeficits(PhaseLine& ph, bool first) {
    for (int j = 2; j <= n_ + 1; ++j) {
      if (!ph.present[j] || !live(ph, j, first) || judged(ph, kRho, j, first) > 0.0) continue;
      const double vj = 1.0 / W_.invVol[j];
      int t = -1;
      double best = 0.0;
      for (int n : {j - 1, j + 1}) {
        if (n < 2 || n > n_ + 1 || !ph.present[n] || !(judgedVolume(ph, n, first) > 0.0)) continue;
        const double mass = judged(ph, kRho, n, first) / W_.invVol[n];
        if (mass > best) {
          best = mass;
          t = n;
        }
      }
      if (t < 0 || !(judged(ph, kRho, j, first) * vj + best > 0.0)) {
        mixWider(ph, j, first);
        continue;
      }
      const double vt = 1.0 / W_.invVol[t];
      const double sj = judgedVolume(ph, j, first) * vj, st = judgedVolume(ph, t, first) * vt;
      const double weight = first ? 1.0 : 2.0;  // the corrector's result changes twice its average
      for (int k = 0; k < 4; ++k) {
        const double aj = judged(ph, k, j, first), at = judged(ph, k, t, first);
        const double u = (aj * vj + at * vt) / (sj + st);
        ph.w[k][j] += weight * (u * sj * W_.invVol[j] - aj);
        ph.w[k][t] += weight * (u * st * W_.invVol[t] - at);
      }
      ++B_.mixed;
    }
  }

  // The deficit exceeds either neighbour's mass (variant 1 at 0.0075 cm, step 5467, in a
  // vapour of 1e-5 g/cm^3: a fading cell's overdraw, 8.6 times its content, handed to a cell
  // that kept little of the inflow it paid for; docs/tvd.md, "Robustness"): the cells around it
  // along the line are pooled with it, one more on each side at a time up to kMixReach, until
  // the pooled judged mass is positive, and share by judged volume (the same convex mixing over
  // more cells; cells of no positive judged volume are left out). Only where the run would
  // otherwise stop; exactly conservative.
  static constexpr int kMixReach = 4;
  void mixWider(PhaseLine& ph, int j, bool first) {
    for (int reach = 1; reach <= kMixReach; ++reach) {
      const int lo = std::max(2, j - reach), hi = std::min(n_ + 1, j + reach);
      double mass = 0.0, vol = 0.0;
      for (int c = lo; c <= hi; ++c) {
        if (!ph.present[c] || !(judgedVolume(ph, c, first) > 0.0)) continue;
        mass += judged(ph, kRho, c, first) / W_.invVol[c];
        vol += judgedVolume(ph, c, first) / W_.invVol[c];
      }
      if (!(mass > 0.0) || !(vol > 0.0)) continue;
      const double weight = first ? 1.0 : 2.0;  // the corrector's result changes twice its average
      for (int k = 0; k < 4; ++k) {
        double total = 0.0;
        for (int c = lo; c <= hi; ++c)
          if (ph.present[c] && judgedVolume(ph, c, first) > 0.0)
            total += judged(ph, k, c, first) / W_.invVol[c];
        const double u = total / vol;
        for (int c = lo; c <= hi; ++c)
          if (ph.present[c] && judgedVolume(ph, c, first) > 0.0)
            ph.w[k][c] += weight * (u * judgedVolume(ph, c, first) - judged(ph, k, c, first));
      }
      ++B_.mixed;
      return;
    }
  }

  // A cell whose part the stage moved out entirely (a trailing edge crossing its face: the
  // working volume went below zero, and with it, consistently, its mass) hands what it overdrew
  // to the neighbour through the face it drained by, and that face is dry for the rest of the
  // step: the edge now lies in the neighbour, whose part shrinks from the next stage on. True if
  // any cell was absorbed.
  bool absorbFading(PhaseLine& ph) {
    bool any = false;
    for (int j = 2; j <= n_ + 1; ++j) {
      if (!ph.present[j] || !(ph.volW[j] < 0.0)) continue;
      const double outR =
          ph.ap[j] > 0.0 && j + 1 <= n_ + 1 ? W_.area[j] * ph.ap[j] * ph.flux[j][kRho] : 0.0;
      const double outL = ph.ap[j - 1] > 0.0 && j - 1 >= 2
                              ? -W_.area[j - 1] * ph.ap[j - 1] * ph.flux[j - 1][kRho]
                              : 0.0;
      int t = -1, f = -1;
      if (outR > 0.0 && outR >= outL) {
        t = j + 1;
        f = j;
      } else if (outL > 0.0) {
        t = j - 1;
        f = j - 1;
      }
      if (t < 0) continue;
      handOver(ph, j, t);
      const double vj = 1.0 / W_.invVol[j], vt = 1.0 / W_.invVol[t];
      ph.volW[t] += ph.volW[j] * vj / vt;
      ph.volW[j] = 0.0;
      ph.dry[f] = 1;
      ph.into[j] = t;
      any = true;
    }
    return any;
  }
  // What the positivity limiter moved through the faces of a cell absorbFading emptied belongs
  // to the cell that absorbed it (the edge now lies there). The limiter scales a chain of faces
  // by their mass flux alone, so left in the emptied cell it was round-off mass beside momentum
  // and energy that are not: a state of no volume, which closeFading then handed to a neighbour
  // as empty as itself, at 1e10 cm/us (variant 1 at 0.0075 cm, step 4324; docs/tvd.md
  // "Robustness"). Moved as absorbFading moves, exactly conservative.
  void settleAbsorbed(PhaseLine& ph) {
    for (int j = 2; j <= n_ + 1; ++j) {
      const int t = ph.into[j];
      if (t < 0) continue;
      ph.into[j] = -1;
      handOver(ph, j, t);
    }
  }
  // Cell j's stage result joins cell t's (integrals: per cell volume times the volume ratio).
  void handOver(PhaseLine& ph, int j, int t) {
    const double vj = 1.0 / W_.invVol[j], vt = 1.0 / W_.invVol[t];
    for (int k = 0; k < 4; ++k) {
      ph.w[k][t] += ph.w[k][j] * vj / vt;
      ph.w[k][j] = 0.0;
    }
  }
  // A cell whose working part has faded below kLiveFraction of its fraction (an edge leaving
  // it) closes before the stage: its content joins the neighbour through its wetter paired
  // face and its faces are dry for the rest of the step. Left open, the face's aperture (that
  // of the start of the step) would carry a flux no longer in proportion to what the cell holds.
  void closeFading(PhaseLine& ph, std::array<std::vector<double>, 4>& q, std::vector<double>& S) {
    for (int j = 2; j <= n_ + 1; ++j) {
      if (!ph.present[j] || !(S[j] < kLiveFraction * ph.alpha[j])) continue;
      if (S[j] == 0.0 && q[kRho][j] == 0.0 && !(ph.ap[j - 1] > 0.0) && !(ph.ap[j] > 0.0))
        continue;  // closed already
      const double aR = j + 1 <= n_ + 1 ? W_.area[j] * ph.ap[j] : 0.0;
      const double aL = j - 1 >= 2 ? W_.area[j - 1] * ph.ap[j - 1] : 0.0;
      const int t = aR >= aL ? (aR > 0.0 ? j + 1 : -1) : j - 1;
      if (t < 0) continue;
      const double vj = 1.0 / W_.invVol[j], vt = 1.0 / W_.invVol[t];
      if (!(q[kRho][t] * vt + q[kRho][j] * vj > 0.0)) continue;
      for (int k = 0; k < 4; ++k) {
        q[k][t] += q[k][j] * vj / vt;
        q[k][j] = 0.0;
      }
      S[t] += S[j] * vj / vt;
      S[j] = 0.0;
      for (int f : {j - 1, j}) ph.ap[f] = ph.uL[f] = ph.uR[f] = ph.gm[f] = ph.gp[f] = 0.0;
    }
  }

  void applyDry(PhaseLine& ph) {
    for (int f = 1; f <= n_ + 1; ++f) {
      if (!ph.dry[f]) continue;
      ph.dry[f] = 0;
      ph.ap[f] = ph.uL[f] = ph.uR[f] = ph.gm[f] = ph.gp[f] = 0.0;
    }
  }

  // Small phase cells share one state with their neighbour through the larger wetted face: the
  // integrals are pooled and redistributed by phase volume, exactly conservative.
  void merge(PhaseLine& ph) {
    for (int j = 2; j <= n_ + 1; ++j) {
      // Only cells of positive working volume pool, so that the shares volW / pooled are convex
      // (Hu et al. 2006 share by volume). A cell whose part went below zero (a trailing edge
      // left it) is absorbFading's: pooled with it, the shares lay outside [0, 1] and grew
      // without bound as the pooled volume went to zero (the Whipple debris cloud, docs/tvd.md
      // "Robustness").
      if (!ph.present[j] || !(ph.volW[j] > 0.0)) continue;
      const double vol = ph.volW[j] / W_.invVol[j];
      const double fl = W_.area[j - 1] * ph.gp[j - 1], fr = W_.area[j] * ph.gm[j];
      const double face = std::max(fl, fr) * C_.h;
      // Also a cell the stage left without positive mass: pooled, it takes its partner's state.
      if (!(vol < kMergeFraction * face) && ph.w[kRho][j] > 0.0) continue;
      const double al = W_.area[j - 1] * ph.ap[j - 1], ar = W_.area[j] * ph.ap[j];
      int t = -1;
      if (ar > 0.0 && ar >= al && j + 1 <= n_ + 1)
        t = j + 1;
      else if (al > 0.0 && j - 1 >= 2)
        t = j - 1;
      else if (ar > 0.0 && j + 1 <= n_ + 1)
        t = j + 1;
      if (t < 0 || !(ph.volW[t] > 0.0)) continue;
      const double vj = 1.0 / W_.invVol[j], vt = 1.0 / W_.invVol[t];
      // Pooling a deficit would only spread it: the positivity limiter treats it first.
      if (!(ph.w[kRho][j] * vj + ph.w[kRho][t] * vt > 0.0)) continue;
      const double pv = ph.volW[j] * vj + ph.volW[t] * vt;
      if (!(pv > 0.0)) continue;
      for (int k = 0; k < 4; ++k) {
        const double total = ph.w[k][j] * vj + ph.w[k][t] * vt;
        const double u = total / pv;
        ph.w[k][j] = ph.volW[j] * u;
        ph.w[k][t] = ph.volW[t] * u;
      }
    }
  }

  // What the stage moved through the domain's edge faces, for the ledger and per phase (the
  // same numbers, so every phase's mass in the domain plus what it lost closes exactly; the
  // phase's own edgeMass feeds its strength state's advection).
  void ledgerFaces(int p, PhaseLine& ph) {
    const double h = 0.5 * C_.dt;
    if (L_.leftEdge) {
      const double s = h * W_.area[1] * ph.ap[1];
      const double* F = ph.flux[1].data();
      ph.edgeMass += s * F[kRho];
      B_.edge[0].add(s * F[kRho], s * F[kMn], s * F[kMt], s * F[kE], C_.axis);
      W_.edgeMass[2 * static_cast<std::size_t>(p)] += s * F[kRho];
    }
    if (L_.rightEdge) {
      const double s = h * W_.area[n_ + 1] * ph.ap[n_ + 1];
      const double* F = ph.flux[n_ + 1].data();
      B_.edge[1].add(-(s * F[kRho]), -(s * F[kMn]), -(s * F[kMt]), -(s * F[kE]), C_.axis);
      W_.edgeMass[2 * static_cast<std::size_t>(p) + 1] -= s * F[kRho];
    }
  }

  // A phase cell below the vacuum density (docs/tvd.md, "The vacuum cut-off: pooled, not
  // discarded") mixes with the neighbour along the line that holds the most of the phase, as
  // Hu et al. (2006) mix small cells: the integrals pooled and shared by phase volume, so that
  // both end at the pooled density, above the cut-off; exactly conservative. Where the pair
  // stays below the cut-off, a wider run of the phase's cells is pooled (poolWider). Only where
  // nothing lifts it (no neighbour holds the phase, or the phase is below the cut-off over the
  // whole reach) is it put at rest and cold, booked, as the whole-cell kernel treats every such
  // cell.
  void resetThin(int p, std::array<std::vector<double>, 4>& q, const std::vector<double>& S,
                 double weight) {
    PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
    for (int j = 2; j <= n_ + 1; ++j) {
      if (!ph.present[j] || q[kRho][j] >= C_.rhoCut[p] * S[j]) continue;
      if (S[j] > 0.0 && (poolPair(p, q, S, j) || poolWider(p, q, S, j))) {
        ++B_.pooled;
        continue;
      }
      putAtRest(q, j, weight / W_.invVol[j], C_.axis, B_.floors);
    }
  }

  // Cell j pooled with the line neighbour that holds the most of the phase, if the pair's
  // density reaches the cut-off; false (nothing changed) otherwise.
  bool poolPair(int p, std::array<std::vector<double>, 4>& q, const std::vector<double>& S, int j) {
    PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
    int t = -1;
    double best = 0.0;
    for (int n : {j - 1, j + 1}) {
      if (n < 2 || n > n_ + 1 || !ph.present[n] || !(S[n] > 0.0)) continue;
      const double mass = q[kRho][n] / W_.invVol[n];
      if (mass > best) {
        best = mass;
        t = n;
      }
    }
    if (t < 0) return false;
    const double vj = 1.0 / W_.invVol[j], vt = 1.0 / W_.invVol[t];
    const double sj = S[j] * vj, st = S[t] * vt;
    if (!(q[kRho][j] * vj + best >= C_.rhoCut[p] * (sj + st))) return false;
    for (int k = 0; k < 4; ++k) {
      const double u = (q[k][j] * vj + q[k][t] * vt) / (sj + st);
      q[k][j] = u * S[j];
      q[k][t] = u * S[t];
    }
    return true;
  }

  // The pair cannot reach the cut-off (vapour beside vapour): the run of the phase's cells
  // around j along the line (present, of positive part, contiguous) is pooled one more cell on
  // each side at a time, up to kMixReach, until its density reaches the cut-off, and shared by
  // phase volume, as mixWider pools a deficit. False (nothing changed) if it never does: then
  // the phase is below the vacuum density over the whole reach.
  bool poolWider(int p, std::array<std::vector<double>, 4>& q, const std::vector<double>& S,
                 int j) {
    PhaseLine& ph = W_.phase[static_cast<std::size_t>(p)];
    auto in = [&](int c) { return c >= 2 && c <= n_ + 1 && ph.present[c] && S[c] > 0.0; };
    int lo = j, hi = j;
    double mass = q[kRho][j] / W_.invVol[j], vol = S[j] / W_.invVol[j];
    for (int reach = 1; reach <= kMixReach; ++reach) {
      bool grew = false;
      if (lo == j - reach + 1 && in(j - reach)) {
        --lo;
        mass += q[kRho][lo] / W_.invVol[lo];
        vol += S[lo] / W_.invVol[lo];
        grew = true;
      }
      if (hi == j + reach - 1 && in(j + reach)) {
        ++hi;
        mass += q[kRho][hi] / W_.invVol[hi];
        vol += S[hi] / W_.invVol[hi];
        grew = true;
      }
      if (!grew) return false;
      if (!(mass >= C_.rhoCut[p] * vol)) continue;
      for (int k = 0; k < 4; ++k) {
        double total = 0.0;
        for (int c = lo; c <= hi; ++c) total += q[k][c] / W_.invVol[c];
        const double u = total / vol;
        for (int c = lo; c <= hi; ++c) q[k][c] = u * S[c];
      }
      return true;
    }
    return false;
  }

  CutLineWork& W_;
  const LineSetup& L_;
  const SweepContext& C_;
  LineBudget& B_;
  const int n_;
  const int P_;
};

}  // namespace hvi::tvd::detail
