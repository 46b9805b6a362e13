//! @file Particle state as a structure of arrays.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hvi::sph {

//! The state of the real particles, one entry per particle in every array. Units cm-g-us.
//! In r-z geometry x is the radius, vx the radial velocity and m the mass of the whole ring
//! (2 pi r rho dA); in planar geometry m is the mass per cm of depth.
struct ParticleSystem {
  std::vector<double> x, z;       //!< position, cm
  std::vector<double> vx, vz;     //!< velocity, cm/us
  std::vector<double> rho;        //!< density, g/cm^3 (summation density after each step)
  std::vector<double> e;          //!< specific internal energy, cm^2/us^2
  std::vector<double> p, c;       //!< pressure (Mbar) and sound speed (cm/us), from the EOS
  std::vector<double> m;          //!< mass, g (planar: g/cm)
  std::vector<double> h;          //!< smoothing length, cm (constant within an object)
  std::vector<double> rhoRef;     //!< initial body density: target of the mass iteration
  std::vector<int> material;      //!< index into Scene::materials
  std::vector<int> object;        //!< index into Scene::bodies
  std::vector<std::int64_t> id;   //!< index at creation, kept through deletions and reordering

  [[nodiscard]] std::size_t size() const { return x.size(); }
  void resize(std::size_t n);
  //! Appends one particle with every field given explicitly.
  void push(double px, double pz, double pvx, double pvz, double prho, double pe, double pm,
            double ph, double prhoRef, int pmaterial, int pobject, std::int64_t pid);
  //! Removes the particles whose `keep` flag is 0, preserving the order of the rest.
  void compact(const std::vector<unsigned char>& keep);
};

}  // namespace hvi::sph
