//! @file Diagnostic (issue 14, item 1): which term of the r-z momentum equation accelerates the
//! first column next to the axis along the impact in variant 1. Runs a scene, and for every
//! real particle within `rmax` of the axis recomputes, from the state at the start of each step,
//! the axial acceleration split into the pair sum's self part (-(1/r_i) sum mu_j q_i dW/dz),
//! its neighbour part (-(1/r_i) sum mu_j q_j dW/dz), viscosity, and for comparison the planar
//! (area-weighted) neighbour part -sum mu_j A_j dW/dz. Each part is integrated over the steps
//! (sum dt a) per particle; the particle with the largest -v_z at the end is reported; with a
//! traced ID also the radial split (pair pressure sum, viscosity, hoop term incl. the viscous
//! hoop of sph.rz_viscous_hoop). NSTEPS = 0: the fastest particle along -z over the whole run;
//! NSTEPS < 0: every particle that ever moves along -z faster than RMAX (then a speed, cm/us),
//! with where it started and its fastest -v_z while still compressed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include "args.hpp"
#include "detail/axis_correction.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/sph/kernel.hpp"
#include "hvi/sph/sph.hpp"

using namespace hvi;

struct Acc {
  double self = 0, nb = 0, visc = 0, nbPlanar = 0, selfPlanar = 0, total = 0;
  double rPair = 0, rVisc = 0, hoopSum = 0;  // radial: pair pressure sum, viscosity, H_i
  double hoopPi = 0;                         // sum_j nu_j Pi_ij W_ij (the viscous hoop's sum)
};

int run(int argc, char** argv) {
  using hvi::bench::numberArg;
  const std::string path = argc > 1 ? argv[1] : "cases/scenes/variant1_sph_coarse.toml";
  const auto nsteps = static_cast<long>(numberArg(argc, argv, 2, "NSTEPS", 160, -1, 1e12));
  const double rmax = numberArg(argc, argv, 3, "RMAX", 0.03, 0.0, 1e6);
  const auto trace = static_cast<long>(numberArg(argc, argv, 4, "ID", -1, -1, 1e12));
  const cases::Scene scene = cases::loadScene(path);
  sph::SphSolver solver(scene);
  const double alpha = scene.sph.alpha, beta = scene.sph.beta;
  if (nsteps < 0) {
    // Every particle that ever moves along -z faster than `rmax` (here a speed, cm/us): where
    // it started, its fastest -v_z and when, and its fastest -v_z while still compressed
    // (P > 1 % of its peak): the shocked state before the release adds to it.
    struct Rec {
      double r0 = 0, z0 = 0, best = 0, tBest = 0, rBest = 0, zBest = 0, shocked = 0, pPeak = 0;
      int obj = -1;
    };
    std::map<long, Rec> rec;
    {
      const sph::ParticleSystem p = solver.stepper().particles();
      for (std::size_t i = 0; i < p.size(); ++i) {
        Rec& r = rec[p.id[i]];
        r.r0 = p.x[i], r.z0 = p.z[i], r.obj = p.object[i];
      }
    }
    while (solver.time() < scene.tEnd) {
      solver.advance(scene.tEnd);
      const sph::ParticleSystem p = solver.stepper().particles();
      for (std::size_t i = 0; i < p.size(); ++i) {
        Rec& r = rec[p.id[i]];
        r.pPeak = std::max(r.pPeak, p.p[i]);
        if (p.p[i] > 0.01 * r.pPeak) r.shocked = std::max(r.shocked, -p.vz[i]);
        if (-p.vz[i] > r.best)
          r.best = -p.vz[i], r.tBest = solver.time(), r.rBest = p.x[i], r.zBest = p.z[i];
      }
    }
    int count = 0;
    for (const auto& [id, r] : rec)
      if (r.best > rmax) {
        ++count;
        std::printf(
            "id %6ld body %d from (%.4f, %.4f): -vz max %.4f at t %.3f (%.4f, %.4f), "
            "compressed max %.4f, P peak %.4f\n",
            id, r.obj, r.r0, r.z0, r.best, r.tBest, r.rBest, r.zBest, r.shocked, r.pPeak);
      }
    std::printf("%d particles faster than %.4f cm/us along -z, %ld steps\n", count, rmax,
                solver.step());
    return 0;
  }
  if (nsteps == 0) {
    // The whole run: the fastest particle along the impact (-v_z) after any step.
    double best = 0.0, bt = 0.0, bx = 0.0, bz = 0.0;
    int bo = -1;
    long bid = -1;
    while (solver.time() < scene.tEnd) {
      solver.advance(scene.tEnd);
      const sph::ParticleSystem p = solver.stepper().particles();
      for (std::size_t i = 0; i < p.size(); ++i)
        if (-p.vz[i] > best)
          best = -p.vz[i], bt = solver.time(), bx = p.x[i], bz = p.z[i], bo = p.object[i],
          bid = p.id[i];
    }
    std::printf(
        "%s rz_form %s: fastest along -z %.4f cm/us (id %ld body %d at r = %.4f, z = %.3f, t = "
        "%.3f us), %ld steps\n",
        path.c_str(),
        sph::stepperConfig(scene).rzForm == cases::RzForm::Symmetric ? "symmetric" : "ring", best,
        bid, bo, bx, bz, bt, solver.step());
    return 0;
  }
  std::map<long, Acc> acc;  // by id: integrated dv_z
  using K = sph::GaussianKernel;
  const bool sym = sph::stepperConfig(scene).rzForm == cases::RzForm::Symmetric;
  const auto& ring = sph::detail::ringScale(scene.sph.kernel);
  const sph::detail::AxisCorrection axisC(scene.sph.kernel);
  for (long s = 0; s < nsteps; ++s) {
    const sph::ParticleSystem p = solver.stepper().particles();
    const double t0 = solver.time();
    std::map<long, Acc> now;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (p.x[i] > rmax || (trace >= 0 && p.id[i] != trace)) continue;
      const double ri = sym ? ring.value(p.x[i], p.h[i]) : p.x[i],
                   Ai = p.p[i] / (p.rho[i] * p.rho[i]);
      const double qi = sym ? Ai : ri * Ai;
      Acc a;
      for (std::size_t j = 0; j < n; ++j)
        for (int g = 0; g < 2; ++g) {  // the particle and its mirror ghost across the axis
          const double xj = g ? -p.x[j] : p.x[j], vxj = g ? -p.vx[j] : p.vx[j];
          if (j == i && g == 0) continue;
          const double dx = p.x[i] - xj, dz = p.z[i] - p.z[j];
          const double r2 = dx * dx + dz * dz, h = 0.5 * (p.h[i] + p.h[j]);
          if (r2 >= 9.0 * h * h) continue;
          const double w = K::value(r2, h);
          const double gz = K::gradFactor(w, r2, h) * dz;
          const double gx = K::gradFactor(w, r2, h) * dx;
          const double rj = sym ? ring.value(std::abs(p.x[j]), p.h[j]) : std::abs(p.x[j]);
          const double muj = p.m[j] / (2 * std::numbers::pi * rj);
          const double Aj = p.p[j] / (p.rho[j] * p.rho[j]), qj = sym ? Aj : rj * Aj;
          // planar reference: the weight rho_j dA_j = m_j / (2 pi |r_j|)
          const double dAj = p.m[j] / (2 * std::numbers::pi * std::abs(p.x[j]));
          a.rPair += -muj * (qi + qj) * gx / ri;
          a.hoopSum += muj * qj * w;
          a.self += -muj * qi * gz / ri;
          a.nb += -muj * qj * gz / ri;
          a.selfPlanar += -dAj * Ai * gz;
          a.nbPlanar += -dAj * Aj * gz;
          const double dvx = p.vx[i] - vxj, dvz = p.vz[i] - p.vz[j];
          const double vdx = dvx * dx + dvz * dz;
          if (vdx < 0) {
            const double phi = h * vdx / (r2 + 0.01 * h * h);
            const double pi = (-alpha * 0.5 * (p.c[i] + p.c[j]) * phi + beta * phi * phi) /
                              (0.5 * (p.rho[i] + p.rho[j]));
            a.visc += -muj * (sym ? 1.0 : 0.5 * (ri + rj)) * pi * gz / ri;
            a.rVisc += -muj * (sym ? 1.0 : 0.5 * (ri + rj)) * pi * gx / ri;
            a.hoopPi += muj * pi * w;
          }
        }
      {  // the hoop term as the force passes form it (passes.cpp)
        const double mui = p.m[i] / (2 * std::numbers::pi * ri), wii = K::value(0.0, p.h[i]);
        const double H = a.hoopSum + mui * qi * wii + scene.sph.rzViscousHoop * a.hoopPi;
        a.hoopSum = sym ? ring.slope(p.x[i], p.h[i]) / (ri * ri) * (H + Ai * ri * p.rho[i])
                        : axisC(p.x[i], p.h[i]) * H / (ri * ri);
      }
      now[p.id[i]] = a;
    }
    double vzBefore = 0.0, vxBefore = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (p.id[i] == trace) vzBefore = p.vz[i], vxBefore = p.vx[i];
    const double dt = solver.advance(scene.tEnd);
    (void)t0;
    if (trace >= 0 && now.count(trace)) {
      const sph::ParticleSystem q = solver.stepper().particles();
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q.id[i] == trace) {
          const Acc& a = now[trace];
          std::printf(
              "step %3ld t %.4f r %.4f z %.4f vz %+.4f rho %.3f P %+.4f | dvz/dt %+8.3f  a_n: self "
              "%+8.3f nb %+8.3f visc %+8.3f sum %+8.3f | planar nb %+8.3f\n",
              s, solver.time(), q.x[i], q.z[i], q.vz[i], q.rho[i], q.p[i],
              (q.vz[i] - vzBefore) / dt, a.self, a.nb, a.visc, a.self + a.nb + a.visc, a.nbPlanar);
          std::printf(
              "         vr %+.4f | dvr/dt %+8.3f  a_r: pair %+8.3f visc %+8.3f hoop %+8.3f sum "
              "%+8.3f\n",
              q.vx[i], (q.vx[i] - vxBefore) / dt, a.rPair, a.rVisc, a.hoopSum,
              a.rPair + a.rVisc + a.hoopSum);
        }
    }
    for (auto& [id, a] : now) {
      Acc& s2 = acc[id];
      s2.self += dt * a.self;
      s2.nb += dt * a.nb;
      s2.visc += dt * a.visc;
      s2.nbPlanar += dt * a.nbPlanar;
      s2.selfPlanar += dt * a.selfPlanar;
    }
  }
  const sph::ParticleSystem p = solver.stepper().particles();
  std::printf("t = %.4f us after %ld steps\n", solver.time(), nsteps);
  // The five fastest along -z among the tracked particles, and the fastest overall.
  std::multimap<double, std::size_t> order;
  for (std::size_t i = 0; i < p.size(); ++i) order.insert({p.vz[i], i});
  int shown = 0;
  for (auto& [vz, i] : order) {
    if (shown++ >= 12) break;
    const auto it = acc.find(p.id[i]);
    std::printf("id %6ld obj %d r = %.4f z = %.4f vz = %.4f vr = %.4f rho = %.3f P = %.4f",
                (long)p.id[i], p.object[i], p.x[i], p.z[i], p.vz[i], p.vx[i], p.rho[i], p.p[i]);
    if (it != acc.end()) {
      const Acc& a = it->second;
      std::printf(
          "  int dv_z: self %+.4f nb %+.4f visc %+.4f sum %+.4f | planar self %+.4f nb %+.4f",
          a.self, a.nb, a.visc, a.self + a.nb + a.visc, a.selfPlanar, a.nbPlanar);
    }
    std::printf("\n");
  }
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr,
                 "hvi_probe_axis: %s\n(usage: hvi_probe_axis [SCENE] [NSTEPS] [RMAX] [ID])\n",
                 e.what());
    return 2;
  }
}
