//! @file What the pair loops read: real particles [0, n), then their mirror ghosts.
#pragma once
#include <cstddef>
#include <vector>

namespace hvi::sph::detail {

//! Per-particle values of the pair sums (pair_force.hpp's PairState as arrays). Real particles
//! come first; ghosts follow and hold copies of their parents (mirrored position, velocity).
struct PairArrays {
  std::vector<double> x, z, vx, vz, rho, p, c, h;
  std::vector<double> mu;   //!< kernel weight: m (planar) or m / (2 pi r) (r-z)
  std::vector<double> rw;   //!< radius weight: 1 (planar) or r (r-z)
  std::vector<double> q;    //!< rw P / rho^2
  std::vector<double> lam;  //!< -v_r / r (r-z), 0 planar
  std::vector<int> obj;

  void resize(std::size_t n) {
    for (auto* v : {&x, &z, &vx, &vz, &rho, &p, &c, &h, &mu, &rw, &q, &lam}) v->resize(n);
    obj.resize(n);
  }
  [[nodiscard]] std::size_t size() const { return x.size(); }
};

}  // namespace hvi::sph::detail
