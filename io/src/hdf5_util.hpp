//! @file Thin checked RAII layer over the HDF5 C API used by the snapshot reader and writer.
#pragma once
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hvi::io::h5 {

//! A failed HDF5 call; the message names the operation and HDF5's innermost reason.
class Failure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Owns an HDF5 identifier and closes it with the matching H5*close.
class Id {
 public:
  using Closer = herr_t (*)(hid_t);
  Id() = default;
  Id(hid_t id, Closer close) : id_(id), close_(close) {}
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  Id(Id&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), close_(o.close_) {}
  Id& operator=(Id&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      close_ = o.close_;
    }
    return *this;
  }
  ~Id() { reset(); }
  [[nodiscard]] hid_t get() const { return id_; }
  operator hid_t() const { return id_; }  // NOLINT: reads like the C API it wraps
  //! Closes now and reports a failure (H5Fclose flushes, so its result matters).
  void close(const char* what);

 private:
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

//! Switches HDF5's automatic error printing off for its lifetime and restores it afterwards;
//! errors are reported through exceptions instead.
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

[[noreturn]] void fail(const std::string& what);
inline hid_t check(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}
inline void checkStatus(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

Id utf8StringType();
Id scalarSpace();
Id simpleSpace(const std::vector<hsize_t>& dims);

// Attributes on a file, group or dataset.
void writeAttribute(hid_t obj, const char* name, const std::string& value);
void writeAttribute(hid_t obj, const char* name, double value);
void writeAttribute(hid_t obj, const char* name, long long value);
bool hasAttribute(hid_t obj, const char* name);
std::string readStringAttribute(hid_t obj, const char* name);
double readDoubleAttribute(hid_t obj, const char* name);
long long readIntAttribute(hid_t obj, const char* name);

// Links and datasets.
bool hasLink(hid_t loc, const char* path);
//! A group whose members are listed in creation order (so fields keep their order).
//! A file creation property list without object time stamps (for the root group): identical
//! snapshots must be identical files (issue 11), and HDF5 by default stamps every object.
Id fileCreationWithoutTimes();
Id createGroup(hid_t loc, const char* name);
Id openGroup(hid_t loc, const char* name);
//! Member names in creation order when the group tracks it, else in name order.
std::vector<std::string> memberNames(hid_t group);

//! Creates and fills a float64 dataset; returns it so that attributes can be attached.
Id writeDoubles(hid_t loc, const char* name, const std::vector<hsize_t>& dims, const double* data);
//! Dataset shape; throws if it is not a numeric dataset.
std::vector<hsize_t> datasetShape(hid_t dataset);
std::vector<double> readDoubles(hid_t dataset);

void writeStrings(hid_t loc, const char* name, const std::vector<std::string>& values);
std::vector<std::string> readStrings(hid_t loc, const char* name);
void writeString(hid_t loc, const char* name, const std::string& value);
std::string readString(hid_t loc, const char* name);

}  // namespace hvi::io::h5
