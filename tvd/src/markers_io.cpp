//! @file Marker-set measures (area, volume, counts), output polylines and checkpoint I/O.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <numbers>
#include <ostream>

#include "hvi/common/binary.hpp"
#include "hvi/common/error.hpp"
#include "hvi/tvd/markers.hpp"
#include "hvi/tvd/marker_geometry.hpp"

namespace hvi::tvd {
namespace {

constexpr std::array<char, 8> kMagic{'H', 'V', 'I', 'M', 'R', 'K', '0', '1'};
// Version 2: each line's spacing scale (MarkerLine::scale); version 1 (none) is read as 1.
constexpr std::uint32_t kVersion = 2;

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
  BinaryWriter w(os, "marker checkpoint");
  w.bytes(kMagic.data(), kMagic.size());
  w.value(kVersion);
  w.value(static_cast<std::int32_t>(geometry_ == Geometry::Axisymmetric ? 1 : 0));
  w.value(static_cast<std::int32_t>(objects_));
  for (double v : {spacingCells_, minCells_, maxCells_, tinyLoopCells_}) w.value(v);
  w.value(static_cast<std::uint64_t>(lines_.size()));
  for (const auto& l : lines_) {
    w.value(static_cast<std::int32_t>(l.object));
    w.value(static_cast<std::uint8_t>(l.closed ? 1 : 0));
    w.value(l.scale);
    w.array(l.points);
  }
}

void MarkerSet::read(std::istream& is) {
  BinaryReader r(is, "marker checkpoint");
  std::array<char, 8> magic{};
  r.bytes(magic.data(), magic.size(), "the magic");
  if (magic != kMagic) throw InputError("marker checkpoint: not a marker-set record");
  const auto version = r.value<std::uint32_t>();
  if (version != kVersion && version != 1)
    throw InputError(fmt::format("marker checkpoint: version {} (this build reads 1 and {})",
                                 version, kVersion));
  MarkerSet s;
  const auto geom = r.value<std::int32_t>();
  s.objects_ = r.value<std::int32_t>();
  for (double* v : {&s.spacingCells_, &s.minCells_, &s.maxCells_, &s.tinyLoopCells_})
    *v = r.value<double>();
  if ((geom != 0 && geom != 1) || s.objects_ < 0 || !(s.spacingCells_ > 0.0) ||
      !(s.minCells_ > 0.0) || !(s.maxCells_ >= 2.0 * s.minCells_))
    throw InputError("marker checkpoint: corrupt header");
  s.geometry_ = geom == 1 ? Geometry::Axisymmetric : Geometry::Planar;
  const auto nlines = r.count();
  constexpr std::uint64_t kLimit = std::uint64_t{1} << 32;  // guards against corrupt counts
  if (nlines > kLimit) throw InputError("marker checkpoint: corrupt line count");
  s.lines_.resize(nlines);
  for (auto& l : s.lines_) {
    l.object = r.value<std::int32_t>();
    l.closed = r.value<std::uint8_t>() != 0;
    l.scale = version >= 2 ? r.value<double>() : 1.0;
    if (!(l.scale >= 1.0) || !(l.scale <= kMaxLineScale))
      throw InputError("marker checkpoint: corrupt line scale");
    const auto n = r.count();
    if (n > kLimit || l.object < 0 || l.object >= s.objects_)
      throw InputError("marker checkpoint: corrupt line record");
    r.elements(l.points, n, "a line");
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
