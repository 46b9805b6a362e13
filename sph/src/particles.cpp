//! @file Bulk operations on the particle arrays.
#include "hvi/sph/particles.hpp"

namespace hvi::sph {
namespace {

// Applies `f` to every array of the system, so that no operation forgets one.
template <class F>
void forEachArray(ParticleSystem& ps, F&& f) {
  f(ps.x); f(ps.z); f(ps.vx); f(ps.vz); f(ps.rho); f(ps.e); f(ps.p); f(ps.c); f(ps.m); f(ps.h);
  f(ps.rhoRef); f(ps.material); f(ps.object); f(ps.id);
}

}  // namespace

void ParticleSystem::resize(std::size_t n) {
  forEachArray(*this, [n](auto& v) { v.resize(n); });
}

void ParticleSystem::push(double px, double pz, double pvx, double pvz, double prho, double pe,
                          double pm, double ph, double prhoRef, int pmaterial, int pobject,
                          std::int64_t pid) {
  x.push_back(px); z.push_back(pz); vx.push_back(pvx); vz.push_back(pvz);
  rho.push_back(prho); e.push_back(pe); p.push_back(0.0); c.push_back(0.0);
  m.push_back(pm); h.push_back(ph); rhoRef.push_back(prhoRef);
  material.push_back(pmaterial); object.push_back(pobject); id.push_back(pid);
}

void ParticleSystem::compact(const std::vector<unsigned char>& keep) {
  forEachArray(*this, [&keep](auto& v) {
    if (v.empty()) return;  // an array not held (SphSolver's set-up drops rho, p, c)
    std::size_t k = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (keep[i]) v[k++] = v[i];
    v.resize(k);
  });
}

}  // namespace hvi::sph
