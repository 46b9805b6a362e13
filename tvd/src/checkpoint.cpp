//! @file Exact binary checkpoint of the TVD state (restart continues bit for bit).
#include <fmt/format.h>

#include <cstdint>
#include <istream>
#include <ostream>
#include <type_traits>

#include "hvi/common/error.hpp"
#include "hvi/tvd/tvd.hpp"

namespace hvi::tvd {
namespace {

constexpr std::uint64_t kMagic = 0x31304456544956ULL;  // "VITVD01" little-endian tag
constexpr std::uint32_t kVersion = 2;

template <class T>
void put(std::ostream& out, const T& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
T get(std::istream& in) {
  static_assert(std::is_trivially_copyable_v<T>);
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
  if (!in) throw InputError("tvd checkpoint: the stream ends inside a value");
  return v;
}
template <class T>
void putArray(std::ostream& out, const std::vector<T>& v) {
  put<std::uint64_t>(out, v.size());
  out.write(reinterpret_cast<const char*>(v.data()),
            static_cast<std::streamsize>(v.size() * sizeof(T)));
}
template <class T>
void getArray(std::istream& in, std::vector<T>& v, std::size_t expected, const char* what) {
  const auto n = get<std::uint64_t>(in);
  if (n != expected)
    throw InputError(fmt::format("tvd checkpoint: array '{}' has {} values, this run has {}", what,
                                 n, expected));
  v.resize(expected);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
  if (!in) throw InputError(fmt::format("tvd checkpoint: the stream ends inside '{}'", what));
}
void putBudget(std::ostream& out, const Budget& b) {
  put(out, b.mass);
  put(out, b.momentumX);
  put(out, b.momentumZ);
  put(out, b.energy);
}
Budget getBudget(std::istream& in) {
  Budget b;
  b.mass = get<double>(in);
  b.momentumX = get<double>(in);
  b.momentumZ = get<double>(in);
  b.energy = get<double>(in);
  return b;
}

}  // namespace

void TvdSolver::writeCheckpoint(std::ostream& out) const {
  put(out, kMagic);
  put(out, kVersion);
  put<std::int32_t>(out, grid_.nx);
  put<std::int32_t>(out, grid_.nz);
  put<std::int32_t>(out, geometry_ == Geometry::Axisymmetric ? 1 : 0);
  put<std::int32_t>(out, markersOn_ ? 1 : 0);
  put(out, time_);
  put(out, dt0_);
  put<std::int64_t>(out, step_);
  put<std::int64_t>(out, ownerChangeCount_);
  for (const Budget* b :
       {&ledger_.boundary, &ledger_.interfaces, &ledger_.ownerChanges, &ledger_.floors})
    putBudget(out, *b);
  putArray(out, U_.rho);
  putArray(out, U_.mx);
  putArray(out, U_.mz);
  putArray(out, U_.E);
  if (markersOn_) {
    putArray(out, owner_);
    putArray(out, normal_);
    putArray(out, materialTarget_);
    markerSet_.write(out);
  }
  if (!out) throw SimulationError("tvd checkpoint: writing the state failed");
}

void TvdSolver::readCheckpoint(std::istream& in) {
  if (get<std::uint64_t>(in) != kMagic)
    throw InputError("tvd checkpoint: not a TVD solver state (wrong magic number)");
  const auto version = get<std::uint32_t>(in);
  if (version != kVersion)
    throw InputError(
        fmt::format("tvd checkpoint: format version {}, this build reads {}", version, kVersion));
  const auto nx = get<std::int32_t>(in), nz = get<std::int32_t>(in);
  const auto rz = get<std::int32_t>(in), markers = get<std::int32_t>(in);
  if (nx != grid_.nx || nz != grid_.nz || (rz == 1) != (geometry_ == Geometry::Axisymmetric) ||
      (markers == 1) != markersOn_)
    throw InputError(fmt::format(
        "tvd checkpoint: written for a {} x {} {} grid {} markers; this scene gives {} x {} {} "
        "{} markers",
        nx, nz, rz == 1 ? "r-z" : "planar", markers == 1 ? "with" : "without", grid_.nx, grid_.nz,
        toString(geometry_), markersOn_ ? "with" : "without"));
  const double t = get<double>(in), dt0 = get<double>(in);
  const auto step = get<std::int64_t>(in), changes = get<std::int64_t>(in);
  Ledger ledger;
  for (Budget* b : {&ledger.boundary, &ledger.interfaces, &ledger.ownerChanges, &ledger.floors})
    *b = getBudget(in);
  const auto n = static_cast<std::size_t>(grid_.cells());
  Conserved U;
  getArray(in, U.rho, n, "density");
  getArray(in, U.mx, n, "momentum x");
  getArray(in, U.mz, n, "momentum z");
  getArray(in, U.E, n, "energy");
  if (markersOn_) {
    std::vector<int> owner;
    std::vector<Vec2> normal;
    getArray(in, owner, n, "owner");
    getArray(in, normal, n, "normal");
    std::vector<double> target;
    getArray(in, target, materials_.size(), "material target mass");
    MarkerSet ms;
    ms.read(in);
    owner_.swap(owner);
    normal_.swap(normal);
    materialTarget_.swap(target);
    markerSet_ = std::move(ms);
  }
  U_ = std::move(U);
  time_ = t;
  dt0_ = dt0;
  step_ = static_cast<long>(step);
  ownerChangeCount_ = static_cast<long>(changes);
  ledger_ = ledger;
}

}  // namespace hvi::tvd
