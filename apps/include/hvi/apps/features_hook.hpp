//! @file Debris-cloud features and rear-wall failure of a snapshot for the run's time series.
#pragma once
#include <nlohmann/json.hpp>

#include "hvi/cases/scene.hpp"
#include "hvi/common/snapshot.hpp"

namespace hvi::app {

//! Aperture radius, cloud leading edge, striker remnant, bubble extent, peak density.
nlohmann::json measureFeaturesJson(const Snapshot& snap, const cases::Scene& scene);

//! Holes and detached spall of the body named "rear_wall" (a shield scene, docs/shield.md);
//! null for a scene without one.
nlohmann::json measureRearWallJson(const Snapshot& snap, const cases::Scene& scene);

//! Every plate of an r-z scene (each rect body at rest from the axis: a shield's bumper,
//! intermediate walls and rear wall, the study's plate), each with its hole radius and spall
//! flag and their evidence (docs/output.md); null for a scene without plates.
nlohmann::json measurePlatesJson(const Snapshot& snap, const cases::Scene& scene);

//! Per plate over the run, from the timeseries entries' `plates`; null when none has them.
nlohmann::json platesSummaryJson(const nlohmann::json& history);

//! The run's rear-wall verdict from its timeseries entries (the first snapshot showing
//! perforation, with its evidence); null when no entry measured a rear wall.
nlohmann::json rearWallVerdictJson(const nlohmann::json& history);

}  // namespace hvi::app
