//! @file HDF5 snapshot writer (layout in docs/output.md).
#include <stdexcept>

#include <fmt/format.h>

#include "hdf5_util.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/units.hpp"
#include "hvi/io/output.hpp"

namespace hvi::io {
namespace fs = std::filesystem;

namespace {

std::string unitsDescription() {
  return fmt::format("cm-g-us: length {}, mass {}, time {}, velocity {}, density {}, pressure {}, "
                     "specific energy {}",
                     units::lengthName, units::massName, units::timeName, units::velocityName,
                     units::densityName, units::pressureName, units::energyName);
}

void writeFields(hid_t file, const Snapshot& snap) {
  h5::Id group = h5::createGroup(file, "fields");
  const auto count = static_cast<hsize_t>(snap.count());
  for (const Field& f : snap.fields) {
    std::vector<hsize_t> dims{count};
    if (f.components > 1) dims.push_back(static_cast<hsize_t>(f.components));
    h5::Id ds = h5::writeDoubles(group, f.name.c_str(), dims, f.data.data());
    h5::writeAttribute(ds, "unit", f.unit);
  }
}

void writeMarkers(hid_t file, const Snapshot& snap) {
  h5::Id group = h5::createGroup(file, "markers");
  std::vector<double> xz;
  for (std::size_t i = 0; i < snap.markers.size(); ++i) {
    const Polyline& line = snap.markers[i];
    xz.clear();
    for (Vec2 p : line.points) {
      xz.push_back(p.x);
      xz.push_back(p.z);
    }
    const std::string name = std::to_string(i);
    h5::Id ds = h5::writeDoubles(group, name.c_str(), {line.points.size(), 2}, xz.data());
    h5::writeAttribute(ds, "object", static_cast<long long>(line.object));
    h5::writeAttribute(ds, "closed", static_cast<long long>(line.closed ? 1 : 0));
  }
}

void writeFile(const fs::path& path, const Snapshot& snap, const std::string& sceneToml) {
  h5::Id fcpl = h5::fileCreationWithoutTimes();
  h5::Id file(h5::check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT),
                        "creating the file"),
              H5Fclose);
  h5::writeAttribute(file, "format", std::string(hdf5Format));
  h5::writeAttribute(file, "format_version", static_cast<long long>(hdf5FormatVersion));
  h5::writeAttribute(file, "time", snap.time);
  h5::writeAttribute(file, "step", static_cast<long long>(snap.step));
  h5::writeAttribute(file, "solver", snap.solver);
  h5::writeAttribute(file, "geometry", std::string(toString(snap.geometry)));
  h5::writeAttribute(file, "kind",
                     std::string(snap.kind == Snapshot::Kind::Particles ? "particles" : "grid"));
  h5::writeAttribute(file, "units", unitsDescription());
  h5::writeString(file, "scene", sceneToml);

  if (snap.kind == Snapshot::Kind::Particles) {
    h5::Id group = h5::createGroup(file, "particles");
    std::vector<double> coord(snap.positions.size());
    const hsize_t n = coord.size();
    for (std::size_t i = 0; i < coord.size(); ++i) coord[i] = snap.positions[i].x;
    h5::writeDoubles(group, "x", {n}, coord.data());
    for (std::size_t i = 0; i < coord.size(); ++i) coord[i] = snap.positions[i].z;
    h5::writeDoubles(group, "z", {n}, coord.data());
  } else {
    h5::Id group = h5::createGroup(file, "grid");
    h5::writeAttribute(group, "nx", static_cast<long long>(snap.grid.nx));
    h5::writeAttribute(group, "nz", static_cast<long long>(snap.grid.nz));
    h5::writeAttribute(group, "x0", snap.grid.x0);
    h5::writeAttribute(group, "z0", snap.grid.z0);
    h5::writeAttribute(group, "dx", snap.grid.dx);
    h5::writeAttribute(group, "dz", snap.grid.dz);
  }
  writeFields(file, snap);
  if (!snap.markers.empty()) writeMarkers(file, snap);
  h5::writeStrings(file, "materials", snap.materialNames);
  h5::writeStrings(file, "objects", snap.objectNames);
  // Closing flushes the metadata; a failure here means the file is incomplete.
  file.close("closing (flushing) the file");
}

}  // namespace

void writeHdf5(const fs::path& file, const Snapshot& snap, const std::string& sceneToml) {
  validateSnapshot(snap);
  writeAtomically(file, [&](const fs::path& tmp) {
    h5::QuietErrors quiet;
    try {
      writeFile(tmp, snap, sceneToml);
    } catch (const h5::Failure& e) {
      throw std::runtime_error(
          fmt::format("cannot write HDF5 snapshot {}: {}", file.string(), e.what()));
    }
  });
}

}  // namespace hvi::io
