//! @file HDF5 snapshot reader: checks every part of the layout and names what is missing.
#include <algorithm>
#include <charconv>
#include <limits>

#include <fmt/format.h>

#include "hdf5_util.hpp"
#include "hvi/common/error.hpp"
#include "hvi/io/output.hpp"

namespace hvi::io {
namespace fs = std::filesystem;

namespace {

class Reader {
 public:
  explicit Reader(const fs::path& path) : name_(path.string()) {}

  Snapshot read(const fs::path& path, std::string* sceneToml) {
    h5::Id file(h5::check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "opening the file"),
                H5Fclose);
    if (!h5::hasAttribute(file, "format"))
      bad(fmt::format("root attribute 'format' is missing (an hvi snapshot has format = \"{}\")",
                      hdf5Format));
    const std::string format = h5::readStringAttribute(file, "format");
    if (format != hdf5Format)
      bad(fmt::format("root attribute format = \"{}\", expected \"{}\"", format, hdf5Format));
    const long long version = intAttr(file, "format_version", "root");
    if (version != hdf5FormatVersion)
      bad(fmt::format("layout format_version {}; this build reads version {}", version,
                      hdf5FormatVersion));

    Snapshot snap;
    snap.time = doubleAttr(file, "time", "root");
    snap.step = static_cast<long>(intAttr(file, "step", "root"));
    snap.solver = stringAttr(file, "solver", "root");
    const std::string geometry = stringAttr(file, "geometry", "root");
    if (geometry == "planar") snap.geometry = Geometry::Planar;
    else if (geometry == "rz") snap.geometry = Geometry::Axisymmetric;
    else bad(fmt::format("geometry = \"{}\" (allowed: planar, rz)", geometry));
    const std::string kind = stringAttr(file, "kind", "root");
    if (kind == "particles") snap.kind = Snapshot::Kind::Particles;
    else if (kind == "grid") snap.kind = Snapshot::Kind::Grid;
    else bad(fmt::format("kind = \"{}\" (allowed: particles, grid)", kind));
    stringAttr(file, "units", "root");  // informative, but part of the layout
    require(file, "scene");
    if (sceneToml) *sceneToml = h5::readString(file, "scene");

    if (snap.kind == Snapshot::Kind::Particles) readParticles(file, snap);
    else readGrid(file, snap);
    readFields(file, snap);
    if (h5::hasLink(file, "markers")) readMarkers(file, snap);
    require(file, "materials");
    snap.materialNames = h5::readStrings(file, "materials");
    require(file, "objects");
    snap.objectNames = h5::readStrings(file, "objects");
    return snap;
  }

 private:
  [[noreturn]] void bad(const std::string& what) const {
    throw InputError(fmt::format("{}: not a valid hvi snapshot: {}", name_, what));
  }
  void require(hid_t loc, const char* path) const {
    if (!h5::hasLink(loc, path)) bad(fmt::format("'{}' is missing", path));
  }
  void requireAttr(hid_t obj, const char* attr, const char* where) const {
    if (!h5::hasAttribute(obj, attr))
      bad(fmt::format("attribute '{}' of {} is missing", attr, where));
  }
  std::string stringAttr(hid_t obj, const char* attr, const char* where) const {
    requireAttr(obj, attr, where);
    return h5::readStringAttribute(obj, attr);
  }
  double doubleAttr(hid_t obj, const char* attr, const char* where) const {
    requireAttr(obj, attr, where);
    return h5::readDoubleAttribute(obj, attr);
  }
  long long intAttr(hid_t obj, const char* attr, const char* where) const {
    requireAttr(obj, attr, where);
    return h5::readIntAttribute(obj, attr);
  }
  int intAttr32(hid_t obj, const char* attr, const char* where) const {
    const long long v = intAttr(obj, attr, where);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      bad(fmt::format("attribute '{}' of {} = {} is out of range", attr, where, v));
    return static_cast<int>(v);
  }

  //! Opens a dataset and checks its shape is [rows] (columns == 0) or [rows, columns].
  std::vector<double> readArray(hid_t loc, const std::string& path, hsize_t rows, hsize_t columns) {
    require(loc, path.c_str());
    h5::Id ds(h5::check(H5Dopen2(loc, path.c_str(), H5P_DEFAULT), "opening " + path), H5Dclose);
    const auto shape = h5::datasetShape(ds);
    const std::vector<hsize_t> want =
        columns == 0 ? std::vector<hsize_t>{rows} : std::vector<hsize_t>{rows, columns};
    if (shape != want)
      bad(fmt::format("dataset '{}' has shape [{}], expected [{}]", path, fmt::join(shape, ", "),
                      fmt::join(want, ", ")));
    return h5::readDoubles(ds);
  }

  void readParticles(hid_t file, Snapshot& snap) {
    require(file, "particles");
    require(file, "particles/x");
    h5::Id xs(h5::check(H5Dopen2(file, "particles/x", H5P_DEFAULT), "opening particles/x"),
              H5Dclose);
    const auto shape = h5::datasetShape(xs);
    if (shape.size() != 1) bad("dataset 'particles/x' is not one-dimensional");
    const auto x = h5::readDoubles(xs);
    const auto z = readArray(file, "particles/z", shape[0], 0);
    snap.positions.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) snap.positions[i] = {x[i], z[i]};
  }

  void readGrid(hid_t file, Snapshot& snap) {
    require(file, "grid");
    h5::Id g = h5::openGroup(file, "grid");
    snap.grid.nx = intAttr32(g, "nx", "/grid");
    snap.grid.nz = intAttr32(g, "nz", "/grid");
    snap.grid.x0 = doubleAttr(g, "x0", "/grid");
    snap.grid.z0 = doubleAttr(g, "z0", "/grid");
    snap.grid.dx = doubleAttr(g, "dx", "/grid");
    snap.grid.dz = doubleAttr(g, "dz", "/grid");
    if (snap.grid.nx < 0 || snap.grid.nz < 0)
      bad(fmt::format("grid size {} x {} is negative", snap.grid.nx, snap.grid.nz));
  }

  void readFields(hid_t file, Snapshot& snap) {
    require(file, "fields");
    h5::Id group = h5::openGroup(file, "fields");
    const auto count = static_cast<hsize_t>(snap.count());
    for (const std::string& name : h5::memberNames(group)) {
      const std::string path = "fields/" + name;
      h5::Id ds(h5::check(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "opening " + path),
                H5Dclose);
      const auto shape = h5::datasetShape(ds);
      Field f;
      f.name = name;
      if (shape.size() == 2 && shape[0] == count && shape[1] >= 1)
        f.components = static_cast<int>(shape[1]);
      else if (!(shape.size() == 1 && shape[0] == count))
        bad(fmt::format("dataset '{}' has shape [{}], expected [{}] or [{}, components]", path,
                        fmt::join(shape, ", "), count, count));
      f.unit = stringAttr(ds, "unit", path.c_str());
      f.data = h5::readDoubles(ds);
      snap.fields.push_back(std::move(f));
    }
  }

  void readMarkers(hid_t file, Snapshot& snap) {
    h5::Id group = h5::openGroup(file, "markers");
    const auto names = h5::memberNames(group);
    snap.markers.resize(names.size());
    std::vector<bool> filled(names.size(), false);
    for (const std::string& name : names) {
      std::size_t index = 0;
      const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), index);
      if (ec != std::errc() || end != name.data() + name.size() || index >= names.size() ||
          filled[index])
        bad(fmt::format("marker dataset 'markers/{}' is not named 0..{}", name, names.size() - 1));
      filled[index] = true;
      const std::string path = "markers/" + name;
      h5::Id ds(h5::check(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "opening " + path),
                H5Dclose);
      const auto shape = h5::datasetShape(ds);
      if (shape.size() != 2 || shape[1] != 2)
        bad(fmt::format("dataset '{}' has shape [{}], expected [points, 2]", path,
                        fmt::join(shape, ", ")));
      const auto xz = h5::readDoubles(ds);
      Polyline& line = snap.markers[index];
      line.object = intAttr32(ds, "object", path.c_str());
      line.closed = intAttr(ds, "closed", path.c_str()) != 0;
      line.points.resize(static_cast<std::size_t>(shape[0]));
      for (std::size_t i = 0; i < line.points.size(); ++i) line.points[i] = {xz[2 * i], xz[2 * i + 1]};
    }
  }

  std::string name_;
};

}  // namespace

Snapshot readHdf5(const fs::path& file, std::string* sceneToml) {
  const std::string name = file.string();
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw InputError(fmt::format("{}: no such snapshot file", name));
  h5::QuietErrors quiet;
  const htri_t isHdf5 = H5Fis_hdf5(file.c_str());
  if (isHdf5 <= 0)
    throw InputError(fmt::format("{} is not an HDF5 file (hvi snapshots are HDF5, see "
                                 "docs/output.md)", name));
  try {
    return Reader(file).read(file, sceneToml);
  } catch (const h5::Failure& e) {
    throw InputError(fmt::format("{}: not a readable hvi snapshot: {}", name, e.what()));
  }
}

}  // namespace hvi::io
