//! @file Comparing two snapshots (SPH or TVD) on a common grid: density, material, features.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hvi/compare/features.hpp"
#include "hvi/compare/resample.hpp"

namespace hvi::compare {

struct CompareOptions {
  double spacing = 0.0;  //!< cm; 0: the coarser of the two native spacings
  ResampleOptions resample;
  //! Features of both states and their differences; measured only when set.
  std::optional<FeatureConfig> features;
  //! Features of B when its parts are named or indexed differently from A's (else `features`).
  std::optional<FeatureConfig> featuresB;
};

//! Density differences d = rho_b - rho_a over a set of cells, each weighted by its volume w
//! (planar: area; r-z: volume per radian, so that L1 * volume is the misplaced mass).
struct DensityStats {
  long cells = 0;
  double l1 = 0.0;     //!< sum |d| w / sum w, g/cm^3
  double l2 = 0.0;     //!< sqrt(sum d^2 w / sum w), g/cm^3
  double max = 0.0;    //!< max |d|, g/cm^3
  double relL1 = 0.0;  //!< sum |d| w / sum (rho_a + rho_b) / 2 w (0 when both are empty)
};

//! Per-class agreement of a classification (vacuum, then each material or object).
struct ClassStats {
  std::string name;
  long cellsA = 0, cellsB = 0, intersection = 0;
  std::optional<double> iou;  //!< |A and B| / |A or B|; empty when the class is in neither
};

struct ConfusionTable {
  std::vector<std::string> classes;      //!< "vacuum" first, then matched by name
  std::vector<std::vector<long>> counts; //!< counts[a][b]: cells of class a in A and b in B
  std::vector<ClassStats> stats;
  double mismatchFraction = 0.0;          //!< cells classed differently / all cells
  double mismatchFractionMaterial = 0.0;  //!< same, over cells that are material in A or B
  //! Smallest IoU over the non-vacuum classes present in A or B (empty when there are none).
  std::optional<double> minIou;
};

struct Report {
  GridSpec grid;
  Geometry geometry = Geometry::Planar;
  double timeA = 0.0, timeB = 0.0;
  std::string solverA, solverB;
  double massA = 0.0, massB = 0.0;  //!< sum rho w on the grid (g per cm depth, or g per radian)
  DensityStats whole;     //!< every cell
  DensityStats material;  //!< cells that are material in A or in B
  ConfusionTable materials;
  std::optional<ConfusionTable> objects;  //!< when both snapshots carry an object field
  std::optional<Features> featuresA, featuresB;
  //! Kind::Grid snapshot with density_a, density_b, density_diff (= b - a), material_a,
  //! material_b, material_mismatch (1 where the classes differ, by object if known), object_a,
  //! object_b; write it with io::writeVtk.
  Snapshot difference;
};

//! Resamples `a` and `b` onto the smallest grid of spacing opt.spacing covering both and compares
//! them. Throws InputError for incompatible inputs (different geometry, missing fields).
Report compareSnapshots(const Snapshot& a, const Snapshot& b, const CompareOptions& opt = {});
//! Same, on already resampled fields (they must share the grid).
Report compareResampled(const Resampled& a, const Resampled& b, const CompareOptions& opt = {});

nlohmann::json toJson(const Report& r);
//! A human-readable summary (the table `hvi compare` prints).
std::string formatTable(const Report& r);

//! Pass/fail limits: `maxDensityL1` bounds the relative L1 density difference over the material
//! region (material.relL1); `minIou` bounds the smallest IoU of the object classes (material
//! classes when there are no objects).
struct Thresholds {
  std::optional<double> maxDensityL1;
  std::optional<double> minIou;
};

//! True when every given threshold holds; otherwise false and, if `why`, the reasons.
bool passes(const Report& r, const Thresholds& t, std::string* why = nullptr);

}  // namespace hvi::compare
