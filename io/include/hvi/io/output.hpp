//! @file Snapshot files: HDF5 (exact, documented layout) and VTK XML (for ParaView).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "hvi/common/snapshot.hpp"

namespace hvi::io {

//! Value of the root attribute `format` of an hvi HDF5 snapshot, and the layout version this
//! build writes and reads (docs/output.md).
inline constexpr const char* hdf5Format = "hvi-snapshot";
inline constexpr int hdf5FormatVersion = 1;

//! Checks that a snapshot can be written: field names non-empty, unique, without '/', each
//! field's data holding count() * components values, a grid with positive size and spacing.
//! Throws std::invalid_argument naming the offending field (a solver bug, not bad input).
//! writeHdf5 and writeVtk call it before touching any file.
void validateSnapshot(const Snapshot& snap);

//! Writes one snapshot as HDF5 (layout in docs/output.md), atomically: a killed run leaves
//! the previous file or the complete new one. `sceneToml` is the resolved scene.
//! Throws std::invalid_argument (see validateSnapshot) or std::runtime_error naming the file
//! and the failed HDF5 operation; the previous file is then untouched.
void writeHdf5(const std::filesystem::path& file, const Snapshot& snap, const std::string& sceneToml);

//! Reads a snapshot written by writeHdf5 (for compare and tests). Throws hvi::InputError
//! naming the file and the missing dataset if the layout is not hvi's.
Snapshot readHdf5(const std::filesystem::path& file, std::string* sceneToml = nullptr);

//! Writes VTK XML with the VTK library: `<stem>.vtu` (particles as vertices) or `<stem>.vti`
//! (grid, cell data), and `<stem>_markers.vtp` when the snapshot has marker lines. Atomic.
//! Returns the files written. Throws like writeHdf5.
std::vector<std::filesystem::path> writeVtk(const std::filesystem::path& stem, const Snapshot& snap);

//! A ParaView time series (.pvd), rewritten atomically after each added snapshot so that it is
//! valid at every moment of the run.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path file);
  //! Adds entries for `files` (paths relative to the .pvd's folder or absolute) at `time`;
  //! several files at one time become parts 0, 1, ...
  void add(double time, const std::vector<std::filesystem::path>& files);
  //! Reloads entries already listed in an existing .pvd with time <= `upTo` (for restarts).
  void resumeFrom(double upTo);

 private:
  void write() const;
  std::filesystem::path file_;
  struct Entry { double time; int part; std::string file; };
  std::vector<Entry> entries_;
};

}  // namespace hvi::io
