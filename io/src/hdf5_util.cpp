//! @file Checked HDF5 helpers: every call's status is tested and turned into an exception.
#include "hdf5_util.hpp"

#include <fmt/format.h>

namespace hvi::io::h5 {

void Id::close(const char* what) {
  if (id_ < 0) return;
  const herr_t status = close_ ? close_(id_) : 0;
  id_ = H5I_INVALID_HID;
  checkStatus(status, what);
}

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}
QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

namespace {
herr_t innermost(unsigned /*n*/, const H5E_error2_t* err, void* out) {
  // Walking downward visits the API call first and the lowest-level cause last; keep the last
  // description, which is the one that says why (e.g. "unable to open file ... errno = 2").
  if (err->desc && *err->desc) *static_cast<std::string*>(out) = err->desc;
  return 0;
}
}  // namespace

void fail(const std::string& what) {
  std::string reason;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, innermost, &reason);
  H5Eclear2(H5E_DEFAULT);
  throw Failure(reason.empty() ? what : fmt::format("{} ({})", what, reason));
}

Id utf8StringType() {
  Id t(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
  checkStatus(H5Tset_size(t, H5T_VARIABLE), "H5Tset_size");
  checkStatus(H5Tset_cset(t, H5T_CSET_UTF8), "H5Tset_cset");
  return t;
}

Id scalarSpace() { return {check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose}; }

Id simpleSpace(const std::vector<hsize_t>& dims) {
  return {check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                "H5Screate_simple"),
          H5Sclose};
}

namespace {
Id createAttribute(hid_t obj, const char* name, hid_t type) {
  Id space = scalarSpace();
  return {check(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT),
                fmt::format("creating attribute '{}'", name)),
          H5Aclose};
}

Id openAttribute(hid_t obj, const char* name) {
  return {check(H5Aopen(obj, name, H5P_DEFAULT), fmt::format("opening attribute '{}'", name)),
          H5Aclose};
}

H5T_class_t typeClass(hid_t type, const std::string& what) {
  const H5T_class_t c = H5Tget_class(type);
  if (c == H5T_NO_CLASS) fail(what);
  return c;
}

//! Reads `n` strings (variable or fixed length) through `read(memType, buffer)`.
template <class Read>
std::vector<std::string> readStringData(hid_t fileType, std::size_t n, const std::string& what,
                                        Read read) {
  if (typeClass(fileType, what) != H5T_STRING) throw Failure(fmt::format("{} is not text", what));
  // The file's own string type serves as memory type: HDF5 does not convert between character
  // sets, and a string type has no byte order to convert.
  Id memType(check(H5Tcopy(fileType), "H5Tcopy"), H5Tclose);
  std::vector<std::string> out;
  out.reserve(n);
  const htri_t variable = H5Tis_variable_str(fileType);
  if (variable < 0) fail(what);
  if (variable) {
    std::vector<char*> buf(n, nullptr);
    if (n > 0) checkStatus(read(memType.get(), buf.data()), fmt::format("reading {}", what));
    for (char* s : buf) {
      out.emplace_back(s ? s : "");
      H5free_memory(s);
    }
  } else {
    const std::size_t size = H5Tget_size(fileType);
    if (size == 0) fail(what);
    std::vector<char> buf(n * size);
    if (n > 0) checkStatus(read(memType.get(), buf.data()), fmt::format("reading {}", what));
    for (std::size_t i = 0; i < n; ++i) {
      const char* s = buf.data() + i * size;
      std::size_t len = 0;
      while (len < size && s[len] != '\0') ++len;
      out.emplace_back(s, len);
    }
  }
  return out;
}

std::size_t pointCount(hid_t space, const std::string& what) {
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (n < 0) fail(what);
  return static_cast<std::size_t>(n);
}
}  // namespace

void writeAttribute(hid_t obj, const char* name, const std::string& value) {
  Id type = utf8StringType();
  Id attr = createAttribute(obj, name, type);
  const char* p = value.c_str();
  checkStatus(H5Awrite(attr, type, &p), fmt::format("writing attribute '{}'", name));
}

void writeAttribute(hid_t obj, const char* name, double value) {
  Id attr = createAttribute(obj, name, H5T_IEEE_F64LE);
  checkStatus(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), fmt::format("writing attribute '{}'", name));
}

void writeAttribute(hid_t obj, const char* name, long long value) {
  Id attr = createAttribute(obj, name, H5T_STD_I64LE);
  checkStatus(H5Awrite(attr, H5T_NATIVE_LLONG, &value), fmt::format("writing attribute '{}'", name));
}

bool hasAttribute(hid_t obj, const char* name) {
  const htri_t r = H5Aexists(obj, name);
  if (r < 0) fail(fmt::format("looking for attribute '{}'", name));
  return r > 0;
}

std::string readStringAttribute(hid_t obj, const char* name) {
  const std::string what = fmt::format("attribute '{}'", name);
  Id attr = openAttribute(obj, name);
  Id type(check(H5Aget_type(attr), what), H5Tclose);
  Id space(check(H5Aget_space(attr), what), H5Sclose);
  if (pointCount(space, what) != 1) throw Failure(fmt::format("{} is not a single string", what));
  return readStringData(type, 1, what, [&](hid_t mem, void* buf) { return H5Aread(attr, mem, buf); })
      .front();
}

namespace {
template <class T>
T readNumberAttribute(hid_t obj, const char* name, hid_t memType, bool integerOnly) {
  const std::string what = fmt::format("attribute '{}'", name);
  Id attr = openAttribute(obj, name);
  Id type(check(H5Aget_type(attr), what), H5Tclose);
  Id space(check(H5Aget_space(attr), what), H5Sclose);
  const H5T_class_t c = typeClass(type, what);
  if (!(c == H5T_INTEGER || (!integerOnly && c == H5T_FLOAT)) || pointCount(space, what) != 1)
    throw Failure(fmt::format("{} is not a single {}", what, integerOnly ? "integer" : "number"));
  T value{};
  checkStatus(H5Aread(attr, memType, &value), fmt::format("reading {}", what));
  return value;
}
}  // namespace

double readDoubleAttribute(hid_t obj, const char* name) {
  return readNumberAttribute<double>(obj, name, H5T_NATIVE_DOUBLE, false);
}

long long readIntAttribute(hid_t obj, const char* name) {
  return readNumberAttribute<long long>(obj, name, H5T_NATIVE_LLONG, true);
}

bool hasLink(hid_t loc, const char* path) {
  const htri_t r = H5Lexists(loc, path, H5P_DEFAULT);
  if (r < 0) fail(fmt::format("looking for '{}'", path));
  return r > 0;
}

// Object headers carry access/modification/change/birth times by default: two runs that write
// the same numbers would give files differing in those bytes. Nothing reads them.
namespace {
Id datasetCreation() {
  Id dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate"), H5Pclose);
  checkStatus(H5Pset_obj_track_times(dcpl, false), "H5Pset_obj_track_times");
  return dcpl;
}
}  // namespace

Id fileCreationWithoutTimes() {
  Id fcpl(check(H5Pcreate(H5P_FILE_CREATE), "H5Pcreate"), H5Pclose);
  checkStatus(H5Pset_obj_track_times(fcpl, false), "H5Pset_obj_track_times");
  return fcpl;
}

Id createGroup(hid_t loc, const char* name) {
  Id gcpl(check(H5Pcreate(H5P_GROUP_CREATE), "H5Pcreate"), H5Pclose);
  checkStatus(H5Pset_obj_track_times(gcpl, false), "H5Pset_obj_track_times");
  checkStatus(H5Pset_link_creation_order(gcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
              "H5Pset_link_creation_order");
  return {check(H5Gcreate2(loc, name, H5P_DEFAULT, gcpl, H5P_DEFAULT),
                fmt::format("creating group '{}'", name)),
          H5Gclose};
}

Id openGroup(hid_t loc, const char* name) {
  return {check(H5Gopen2(loc, name, H5P_DEFAULT), fmt::format("opening group '{}'", name)),
          H5Gclose};
}

std::vector<std::string> memberNames(hid_t group) {
  Id gcpl(check(H5Gget_create_plist(group), "H5Gget_create_plist"), H5Pclose);
  unsigned flags = 0;
  checkStatus(H5Pget_link_creation_order(gcpl, &flags), "H5Pget_link_creation_order");
  const H5_index_t index = (flags & H5P_CRT_ORDER_INDEXED) ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
  H5G_info_t info;
  checkStatus(H5Gget_info(group, &info), "H5Gget_info");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) fail("listing group members");
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    if (H5Lget_name_by_idx(group, ".", index, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT) < 0)
      fail("listing group members");
    name.resize(static_cast<std::size_t>(len));
    names.push_back(std::move(name));
  }
  return names;
}

Id writeDoubles(hid_t loc, const char* name, const std::vector<hsize_t>& dims, const double* data) {
  Id space = simpleSpace(dims);
  Id dcpl = datasetCreation();
  Id ds(check(H5Dcreate2(loc, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
              fmt::format("creating dataset '{}'", name)),
        H5Dclose);
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  if (total > 0)
    checkStatus(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                fmt::format("writing dataset '{}'", name));
  return ds;
}

std::vector<hsize_t> datasetShape(hid_t dataset) {
  Id space(check(H5Dget_space(dataset), "H5Dget_space"), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail("H5Sget_simple_extent_ndims");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space, dims.data(), nullptr) < 0)
    fail("H5Sget_simple_extent_dims");
  return dims;
}

std::vector<double> readDoubles(hid_t dataset) {
  Id type(check(H5Dget_type(dataset), "H5Dget_type"), H5Tclose);
  const H5T_class_t c = typeClass(type, "dataset type");
  if (c != H5T_FLOAT && c != H5T_INTEGER) throw Failure("dataset is not numeric");
  hsize_t total = 1;
  for (hsize_t d : datasetShape(dataset)) total *= d;
  std::vector<double> out(static_cast<std::size_t>(total));
  if (total > 0)
    checkStatus(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()),
                "H5Dread");
  return out;
}

void writeStrings(hid_t loc, const char* name, const std::vector<std::string>& values) {
  Id type = utf8StringType();
  Id space = simpleSpace({values.size()});
  Id dcpl = datasetCreation();
  Id ds(check(H5Dcreate2(loc, name, type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
              fmt::format("creating dataset '{}'", name)),
        H5Dclose);
  std::vector<const char*> ptrs;
  ptrs.reserve(values.size());
  for (const auto& v : values) ptrs.push_back(v.c_str());
  if (!ptrs.empty())
    checkStatus(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()),
                fmt::format("writing dataset '{}'", name));
}

namespace {
std::vector<std::string> readStringDataset(hid_t loc, const char* name, bool scalar) {
  const std::string what = fmt::format("dataset '{}'", name);
  Id ds(check(H5Dopen2(loc, name, H5P_DEFAULT), fmt::format("opening {}", what)), H5Dclose);
  Id type(check(H5Dget_type(ds), what), H5Tclose);
  Id space(check(H5Dget_space(ds), what), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank != (scalar ? 0 : 1))
    throw Failure(fmt::format("{} should be {}", what, scalar ? "a single string" : "a list"));
  return readStringData(type, pointCount(space, what), what, [&](hid_t mem, void* buf) {
    return H5Dread(ds, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  });
}
}  // namespace

std::vector<std::string> readStrings(hid_t loc, const char* name) {
  return readStringDataset(loc, name, false);
}

void writeString(hid_t loc, const char* name, const std::string& value) {
  Id type = utf8StringType();
  Id space = scalarSpace();
  Id dcpl = datasetCreation();
  Id ds(check(H5Dcreate2(loc, name, type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
              fmt::format("creating dataset '{}'", name)),
        H5Dclose);
  const char* p = value.c_str();
  checkStatus(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &p),
              fmt::format("writing dataset '{}'", name));
}

std::string readString(hid_t loc, const char* name) {
  return readStringDataset(loc, name, true).front();
}

}  // namespace hvi::io::h5
