//! @file Marker-set measures (area, volume, counts), output polylines and checkpoint I/O.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <numbers>
#include <ostream>

#include "hvi/common/error.hpp"
#include "hvi/tvd/markers.hpp"
#include "markers_internal.hpp"

namespace hvi::tvd {
namespace {

constexpr std::array<char, 8> kMagic{'H', 'V', 'I', 'M', 'R', 'K', '0', '1'};
constexpr std::uint32_t kVersion = 1;

template <class T>
void put(std::ostream& os, const T& v) {
  os.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
T get(std::istream& is) {
  T v{};
  is.read(reinterpret_cast<char*>(&v), sizeof(T));
  if (!is) throw InputError("marker checkpoint: stream ended early");
  return v;
}

}  // namespace

double MarkerSet::area(int object) const {
  double a = 0.0;
  for (const auto& l : lines_)
    if (l.object == object) a += detail::twiceSignedArea(l.points);
  return 0.5 * a;
}

double MarkerSet::volume(int object) const {
  if (geometry_ == Geometry::Planar) return area(object);
  double m = 0.0;
  for (const auto& l : lines_)
    if (l.object == object) m += detail::sixTimesMomentX(l.points);
  return 2.0 * std::numbers::pi * m / 6.0;
}

std::vector<Polyline> MarkerSet::polylines() const {
  std::vector<Polyline> out;
  out.reserve(lines_.size());
  for (const auto& l : lines_) out.push_back({l.object, l.closed, l.points});
  return out;
}

std::size_t MarkerSet::size() const {
  std::size_t n = 0;
  for (const auto& l : lines_) n += l.points.size();
  return n;
}

// Native byte order: a checkpoint is read back by the same build on the same machine.
void MarkerSet::write(std::ostream& os) const {
  os.write(kMagic.data(), kMagic.size());
  put(os, kVersion);
  put(os, static_cast<std::int32_t>(geometry_ == Geometry::Axisymmetric ? 1 : 0));
  put(os, static_cast<std::int32_t>(objects_));
  put(os, spacingCells_);
  put(os, minCells_);
  put(os, maxCells_);
  put(os, tinyLoopCells_);
  put(os, static_cast<std::uint64_t>(lines_.size()));
  for (const auto& l : lines_) {
    put(os, static_cast<std::int32_t>(l.object));
    put(os, static_cast<std::uint8_t>(l.closed ? 1 : 0));
    put(os, static_cast<std::uint64_t>(l.points.size()));
    os.write(reinterpret_cast<const char*>(l.points.data()),
             static_cast<std::streamsize>(l.points.size() * sizeof(Vec2)));
  }
  if (!os) throw SimulationError("marker checkpoint: write failed");
}

void MarkerSet::read(std::istream& is) {
  std::array<char, 8> magic{};
  is.read(magic.data(), magic.size());
  if (!is || magic != kMagic) throw InputError("marker checkpoint: not a marker-set record");
  if (const auto v = get<std::uint32_t>(is); v != kVersion)
    throw InputError(
        fmt::format("marker checkpoint: version {} (this build reads {})", v, kVersion));
  MarkerSet s;
  const auto geom = get<std::int32_t>(is);
  s.objects_ = get<std::int32_t>(is);
  s.spacingCells_ = get<double>(is);
  s.minCells_ = get<double>(is);
  s.maxCells_ = get<double>(is);
  s.tinyLoopCells_ = get<double>(is);
  if ((geom != 0 && geom != 1) || s.objects_ < 0 || !(s.spacingCells_ > 0.0) ||
      !(s.minCells_ > 0.0) || !(s.maxCells_ >= 2.0 * s.minCells_))
    throw InputError("marker checkpoint: corrupt header");
  s.geometry_ = geom == 1 ? Geometry::Axisymmetric : Geometry::Planar;
  const auto nlines = get<std::uint64_t>(is);
  constexpr std::uint64_t kLimit = std::uint64_t{1} << 32;  // guards against corrupt counts
  if (nlines > kLimit) throw InputError("marker checkpoint: corrupt line count");
  s.lines_.resize(nlines);
  for (auto& l : s.lines_) {
    l.object = get<std::int32_t>(is);
    l.closed = get<std::uint8_t>(is) != 0;
    const auto n = get<std::uint64_t>(is);
    if (n > kLimit || l.object < 0 || l.object >= s.objects_)
      throw InputError("marker checkpoint: corrupt line record");
    l.points.resize(n);
    is.read(reinterpret_cast<char*>(l.points.data()),
            static_cast<std::streamsize>(n * sizeof(Vec2)));
    if (!is) throw InputError("marker checkpoint: stream ended inside a line");
  }
  lines_ = std::move(s.lines_);
  objects_ = s.objects_;
  geometry_ = s.geometry_;
  spacingCells_ = s.spacingCells_;
  minCells_ = s.minCells_;
  maxCells_ = s.maxCells_;
  tinyLoopCells_ = s.tinyLoopCells_;
}

}  // namespace hvi::tvd
