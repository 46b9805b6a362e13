//! @file What the pair loops read: real particles [0, n), then their mirror ghosts.
#pragma once
#include <cstddef>
#include <vector>

namespace hvi::sph::detail {

//! Resizes v to n, growing its capacity to n plus 1/16 (room for a varying ghost count)
//! instead of std::vector's doubling, which would hold up to twice the particles' memory.
template <class V>
void growExactly(V& v, std::size_t n) {
  if (v.capacity() < n) v.reserve(v.empty() ? n : n + n / 16);
  v.resize(n);
}

//! Per-particle values of the pair sums (pair_force.hpp's PairState as arrays). Real particles
//! come first; ghosts follow and hold copies of their parents (mirrored position, velocity).
struct PairArrays {
  // Mirrored by a ghost: its parent's, reflected in the wall or the axis.
  std::vector<double> x, z, vx, vz;
  // Copied by a ghost at every refresh.
  std::vector<double> rho, p, c;
  std::vector<double> mu;   //!< kernel weight: m (planar) or m / (2 pi r) (r-z)
  std::vector<double> rw;   //!< radius weight: 1 (planar), r (r-z ring form), 1 (r-z symmetric)
  //! Divisor of the pair sums: 1 (planar), r (ring form) or s(r) (symmetric form, RingScale)
  std::vector<double> rs;
  std::vector<double> q;    //!< rw P / rho^2
  std::vector<double> lam;  //!< -v_r / r (r-z), 0 planar
  // Fixed per particle: copied when the ghosts are made.
  std::vector<double> h;
  std::vector<int> obj;
  //! r-z axis correction only (else empty; sized and mirrored by the stepper): the z row of
  //! each point's corrected-gradient matrix, and a scratch column for the mirror.
  std::vector<double> lzx, lzz, lxx;
  //! Only x, z, h, obj, mu and rw are sized and kept (the mass iteration, which reads nothing
  //! else: 56 B per point less at the peak of a run's set-up).
  bool lean = false;

  // The lists of the groups above (boundary.cpp's ghosts and resize go through them).
  template <class F>
  void forEachCopied(F&& f) {
    if (!lean) { f(rho); f(p); f(c); }
    f(mu); f(rw);
    if (!lean) { f(rs); f(q); f(lam); }
  }
  template <class F>
  void forEachFixed(F&& f) {
    f(h); f(obj);
  }
  void resize(std::size_t n) {
    const auto sized = [n](auto& v) { growExactly(v, n); };
    for (auto* v : {&x, &z}) sized(*v);
    if (!lean) for (auto* v : {&vx, &vz}) sized(*v);
    forEachCopied(sized);
    forEachFixed(sized);
  }
  [[nodiscard]] std::size_t size() const { return x.size(); }
};

}  // namespace hvi::sph::detail
