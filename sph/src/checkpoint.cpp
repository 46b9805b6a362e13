//! @file Exact binary state of the stepper: what the next step depends on, nothing derived.
#include <cstring>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "detail/stepper_impl.hpp"
#include "hvi/common/binary.hpp"
#include "hvi/common/error.hpp"

namespace hvi::sph {
namespace {

constexpr char kMagic[8] = {'H', 'V', 'I', 'S', 'P', 'H', '0', '2'};
// Version 1 had no dt0 (the collapse check's reference); it is read with dt0 = 0, which the next
// step sets again.
constexpr char kMagicV1[8] = {'H', 'V', 'I', 'S', 'P', 'H', '0', '1'};

}  // namespace

// Density, pressure, sound speed, ghosts and the neighbour list are functions of the stored
// positions, masses and energies, recomputed by the same corrector code: a restart reproduces
// them, and hence every later step, bit for bit.
void Stepper::writeState(std::ostream& out) const {
  const Impl& s = *impl_;
  BinaryWriter w(out, "SPH checkpoint");
  w.bytes(kMagic, sizeof kMagic);
  w.value<std::uint64_t>(s.n);
  w.value<std::int32_t>(static_cast<std::int32_t>(s.cfg.geometry));
  w.value<std::int32_t>(static_cast<std::int32_t>(s.materials.size()));
  w.value(s.t);
  w.value<std::int64_t>(s.steps);
  w.value(s.dt0);
  for (double v : {s.out.mass, s.out.momentumX, s.out.momentumZ, s.out.kinetic, s.out.internal})
    w.value(v);
  // The per-particle state (Impl::forEachState, in its order); the particle count is stored
  // once before it, so the arrays go without counts.
  Impl::forEachState(s, [&](auto, const auto& v) { w.elements(v.data(), s.n); });
  // With strength the deviator and plastic strain follow (a scene without it: the format above).
  if (s.strength)
    detail::StrengthModel::forEachState(*s.strength,
                                        [&](const auto& v) { w.elements(v.data(), s.n); });
  // With the viscosity switch its alpha_i follow (the scene says whether they are there).
  if (s.strength && s.strength->viscositySwitch()) w.elements(s.strength->alpha.data(), s.n);
  if (s.strength && s.strength->plasticStrainRate())
    w.elements(s.strength->plasticRate.data(), s.n);
}

void Stepper::readState(std::istream& in) {
  Impl& s = *impl_;
  BinaryReader r(in, "SPH checkpoint");
  char magic[sizeof kMagic];
  r.bytes(magic, sizeof magic, "the magic");
  const bool v1 = std::memcmp(magic, kMagicV1, sizeof kMagicV1) == 0;
  if (!v1 && std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    throw InputError("SPH checkpoint: not an hvi SPH state (bad magic)");
  const auto n = r.value<std::uint64_t>();
  const auto geom = r.value<std::int32_t>();
  const auto nmat = r.value<std::int32_t>();
  if (geom != static_cast<std::int32_t>(s.cfg.geometry) ||
      nmat != static_cast<std::int32_t>(s.materials.size()))
    throw InputError(fmt::format(
        "SPH checkpoint: written for geometry {} with {} materials, but the scene has "
        "geometry {} with {} materials; restart with the scene that wrote it",
        geom, nmat, static_cast<int>(s.cfg.geometry), s.materials.size()));
  s.t = r.value<double>();
  s.steps = r.value<std::int64_t>();
  s.dt0 = v1 ? 0.0 : r.value<double>();
  for (double* v : {&s.out.mass, &s.out.momentumX, &s.out.momentumZ, &s.out.kinetic,
                    &s.out.internal})
    *v = r.value<double>();
  s.n = n;
  s.a.resize(n);
  Impl::forEachState(s, [&](auto, auto& v) { r.elements(v, n); });
  if (s.strength) {
    s.strength->resize(n);
    detail::StrengthModel::forEachState(*s.strength, [&](auto& v) { r.elements(v, n); });
    if (s.strength->viscositySwitch()) r.elements(s.strength->alpha, n);
    if (s.strength->plasticStrainRate()) r.elements(s.strength->plasticRate, n);
  }
  for (int k : s.mat)
    if (k < 0 || k >= nmat) throw InputError("SPH checkpoint: material index out of range");
  s.resizeWork();
  s.corrector();
}

}  // namespace hvi::sph
