//! @file Consistency check of a Snapshot before it is written.
#include <cmath>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "hvi/io/output.hpp"

namespace hvi::io {

void validateSnapshot(const Snapshot& snap) {
  if (snap.kind == Snapshot::Kind::Grid) {
    const GridSpec& g = snap.grid;
    if (g.nx < 1 || g.nz < 1 || !(g.dx > 0.0) || !(g.dz > 0.0) || !std::isfinite(g.dx) ||
        !std::isfinite(g.dz) || !std::isfinite(g.x0) || !std::isfinite(g.z0))
      throw std::invalid_argument(fmt::format(
          "snapshot grid must have nx, nz >= 1 and finite dx, dz > 0 (got nx={} nz={} dx={} dz={} "
          "x0={} z0={})", g.nx, g.nz, g.dx, g.dz, g.x0, g.z0));
  }
  const long count = snap.count();
  std::set<std::string> seen;
  for (const Field& f : snap.fields) {
    if (f.name.empty() || f.name == "." || f.name.find('/') != std::string::npos)
      throw std::invalid_argument(fmt::format(
          "snapshot field name '{}' is not allowed (must be non-empty, not '.', without '/')",
          f.name));
    if (!seen.insert(f.name).second)
      throw std::invalid_argument(fmt::format("snapshot has two fields named '{}'", f.name));
    if (f.components < 1)
      throw std::invalid_argument(
          fmt::format("snapshot field '{}' has {} components (must be >= 1)", f.name, f.components));
    const auto expected = static_cast<std::size_t>(count) * static_cast<std::size_t>(f.components);
    if (f.data.size() != expected)
      throw std::invalid_argument(fmt::format(
          "snapshot field '{}' holds {} values; {} {} x {} components need {}", f.name,
          f.data.size(), count, snap.kind == Snapshot::Kind::Grid ? "cells" : "particles",
          f.components, expected));
  }
}

}  // namespace hvi::io
