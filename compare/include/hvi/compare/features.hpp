//! @file Debris-cloud features measured on a resampled field (hole, cloud, striker remnant).
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hvi/compare/resample.hpp"

namespace hvi::cases {
struct Scene;
}

namespace hvi::compare {

//! Which parts are the shield and the striker, and where the shield was at t = 0.
//! A part is looked up by name first (in the object names, or the material names when
//! `byMaterial`), then by index when the name is absent. The impact runs along the line
//! x = axisX in the direction `direction` (-1: towards -z, the convention of the cases).
struct FeatureConfig {
  std::string shield = "shield";
  std::string striker = "striker";
  int shieldIndex = 1;
  int strikerIndex = 0;
  bool byMaterial = false;   //!< select by material id (needed when there is no object field)
  double shieldZMin = 0.0;   //!< cm, the shield's initial faces
  double shieldZMax = 0.0;
  double axisX = 0.0;        //!< cm
  int direction = -1;        //!< -1 or +1
};

//! Features of one state, lengths in cm, density in g/cm^3. A feature that does not exist in the
//! state (no shield material in the shield band, no material beyond the shield, no striker
//! material) is empty and written as null.
struct Features {
  double time = 0.0;         //!< us
  double cellSize = 0.0;     //!< cm, the resolution the features were measured at
  //! Smallest |x - axisX| of shield material whose cell centre lies in the initial shield band
  //! [shieldZMin, shieldZMax], measured at the cell's inner face: the aperture radius.
  std::optional<double> holeRadius;
  //! Farthest reach of any material beyond the shield's initial rear face (the cell's outer face
  //! along the impact direction): the leading edge of the debris cloud.
  std::optional<double> cloudLeadingEdgeZ;
  //! Largest |x - axisX| (outer face) of material beyond the rear face: the bubble's radius.
  //! An extreme value: one fragment sets it, so it need not converge with resolution (the
  //! study's feature, kept).
  std::optional<double> bubbleRadius;
  //! The radius |x - axisX| within which 90 % of the mass more than a cell beyond the rear face
  //! lies (each column's mass spread evenly over its width, so the value is continuous): the
  //! cloud's lateral extent by its mass, which a fragment cannot set and the reading's spill of
  //! the plate into the next row does not reach.
  std::optional<double> bubbleRadius90;
  //! Striker remnant: extreme faces along z and its mass-weighted centroid.
  std::optional<double> strikerZMin, strikerZMax, strikerCentroidZ;
  //! Peak density and the centre of the cell where it is reached.
  double peakDensity = 0.0, peakDensityX = 0.0, peakDensityZ = 0.0;
};

//! Measures the features of `r` (docs/compare.md gives the exact definitions). Throws
//! InputError if a part named by `cfg` is in neither the names nor the index range.
Features measureFeatures(const Resampled& r, const FeatureConfig& cfg);
//! Convenience for `hvi run`: resamples `s` first. A grid snapshot is measured on its own grid;
//! particles on a covering grid of spacing `spacing` (0: the native particle spacing), read as
//! `opt` says (by default adaptively to the particle spacing).
Features measureFeatures(const Snapshot& s, const FeatureConfig& cfg, double spacing = 0.0,
                         const ResampleOptions& opt = {});

//! Config from a scene: bodies named "striker" and "shield", else the first and second body;
//! the shield band from the shield's bounding box; the axis through the striker's centre (x = 0
//! in r-z); the direction from the sign of the striker's z velocity. Objects are indexed like
//! the scene's bodies. Throws InputError if the scene has fewer than two bodies.
FeatureConfig featureConfigFromScene(const cases::Scene& scene);

nlohmann::json toJson(const Features& f);
nlohmann::json toJson(const FeatureConfig& c);
//! b - a for each feature present in both (null otherwise), same keys as toJson(Features).
nlohmann::json differenceJson(const Features& a, const Features& b);

}  // namespace hvi::compare
