//! @file Debris-cloud features of a snapshot for the run's time series.
#pragma once
#include <nlohmann/json.hpp>

#include "hvi/cases/scene.hpp"
#include "hvi/common/snapshot.hpp"

namespace hvi::app {

//! Aperture radius, cloud leading edge, striker remnant, bubble extent, peak density.
nlohmann::json measureFeaturesJson(const Snapshot& snap, const cases::Scene& scene);

}  // namespace hvi::app
