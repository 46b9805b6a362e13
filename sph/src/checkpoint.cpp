//! @file Exact binary state of the stepper: what the next step depends on, nothing derived.
#include <cstring>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "detail/stepper_impl.hpp"
#include "hvi/common/error.hpp"

namespace hvi::sph {
namespace {

constexpr char kMagic[8] = {'H', 'V', 'I', 'S', 'P', 'H', '0', '2'};
// Version 1 had no dt0 (the collapse check's reference); it is read with dt0 = 0, which the next
// step sets again.
constexpr char kMagicV1[8] = {'H', 'V', 'I', 'S', 'P', 'H', '0', '1'};

template <class T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void putArray(std::ostream& out, const std::vector<T>& v, std::size_t n) {
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
}
template <class T>
T get(std::istream& in) {
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
  return v;
}
template <class T>
void getArray(std::istream& in, std::vector<T>& v, std::size_t n) {
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
}

}  // namespace

// Density, pressure, sound speed, ghosts and the neighbour list are functions of the stored
// positions, masses and energies, recomputed by the same corrector code: a restart reproduces
// them, and hence every later step, bit for bit.
void Stepper::writeState(std::ostream& out) const {
  const Impl& s = *impl_;
  out.write(kMagic, sizeof kMagic);
  put<std::uint64_t>(out, s.n);
  put<std::int32_t>(out, static_cast<std::int32_t>(s.cfg.geometry));
  put<std::int32_t>(out, static_cast<std::int32_t>(s.materials.size()));
  put(out, s.t);
  put<std::int64_t>(out, s.steps);
  put(out, s.dt0);
  put(out, s.out.mass);
  put(out, s.out.momentumX);
  put(out, s.out.momentumZ);
  put(out, s.out.kinetic);
  put(out, s.out.internal);
  putArray(out, s.a.x, s.n);
  putArray(out, s.a.z, s.n);
  putArray(out, s.a.vx, s.n);
  putArray(out, s.a.vz, s.n);
  putArray(out, s.a.h, s.n);
  putArray(out, s.a.obj, s.n);
  putArray(out, s.e, s.n);
  putArray(out, s.m, s.n);
  putArray(out, s.rhoRef, s.n);
  putArray(out, s.mat, s.n);
  putArray(out, s.id, s.n);
  if (!out) throw SimulationError("SPH checkpoint: write failed");
}

void Stepper::readState(std::istream& in) {
  Impl& s = *impl_;
  char magic[sizeof kMagic];
  in.read(magic, sizeof magic);
  const bool v1 = in && std::memcmp(magic, kMagicV1, sizeof kMagicV1) == 0;
  if (!in || (!v1 && std::memcmp(magic, kMagic, sizeof kMagic) != 0))
    throw InputError("SPH checkpoint: not an hvi SPH state (bad magic)");
  const auto n = get<std::uint64_t>(in);
  const auto geom = get<std::int32_t>(in);
  const auto nmat = get<std::int32_t>(in);
  if (geom != static_cast<std::int32_t>(s.cfg.geometry) ||
      nmat != static_cast<std::int32_t>(s.materials.size()))
    throw InputError(fmt::format(
        "SPH checkpoint: written for geometry {} with {} materials, but the scene has "
        "geometry {} with {} materials; restart with the scene that wrote it",
        geom, nmat, static_cast<int>(s.cfg.geometry), s.materials.size()));
  s.t = get<double>(in);
  s.steps = get<std::int64_t>(in);
  s.dt0 = v1 ? 0.0 : get<double>(in);
  s.out.mass = get<double>(in);
  s.out.momentumX = get<double>(in);
  s.out.momentumZ = get<double>(in);
  s.out.kinetic = get<double>(in);
  s.out.internal = get<double>(in);
  s.n = n;
  s.a.resize(n);
  getArray(in, s.a.x, n);
  getArray(in, s.a.z, n);
  getArray(in, s.a.vx, n);
  getArray(in, s.a.vz, n);
  getArray(in, s.a.h, n);
  getArray(in, s.a.obj, n);
  getArray(in, s.e, n);
  getArray(in, s.m, n);
  getArray(in, s.rhoRef, n);
  getArray(in, s.mat, n);
  getArray(in, s.id, n);
  if (!in) throw InputError("SPH checkpoint: truncated");
  for (int k : s.mat)
    if (k < 0 || k >= nmat) throw InputError("SPH checkpoint: material index out of range");
  for (auto* v : {&s.x0, &s.z0, &s.vx0, &s.vz0, &s.e0, &s.rho0, &s.ax0, &s.az0, &s.de0,
                  &s.drho0, &s.phi0, &s.ax1, &s.az1, &s.de1})
    v->resize(n);
  s.keep.resize(n);
  s.corrector();
}

}  // namespace hvi::sph
