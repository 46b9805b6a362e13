//! @file Debris-cloud features and rear-wall failure of a snapshot, through the compare and
//! shield libraries.
#include "hvi/apps/features_hook.hpp"

#include "hvi/common/error.hpp"
#include "hvi/compare/features.hpp"
#include "hvi/shield/failure.hpp"

namespace hvi::app {

nlohmann::json measureFeaturesJson(const Snapshot& snap, const cases::Scene& scene) {
  // A scene without a striker and a shield, or a snapshot without an object field, has no
  // debris-cloud features: the entry is null and the run goes on.
  try {
    return compare::toJson(compare::measureFeatures(snap, compare::featureConfigFromScene(scene)));
  } catch (const InputError&) {
    return nullptr;
  }
}

nlohmann::json measureRearWallJson(const Snapshot& snap, const cases::Scene& scene) {
  const auto cfg = shield::rearWallConfigFromScene(scene);
  if (!cfg) return nullptr;
  try {
    return shield::toJson(shield::measureRearWall(snap, *cfg));
  } catch (const InputError&) {
    return nullptr;  // no object or velocity field: nothing to measure, the run goes on
  }
}

nlohmann::json measurePlatesJson(const Snapshot& snap, const cases::Scene& scene) {
  const auto plates = shield::plateConfigsFromScene(scene);
  if (plates.empty()) return nullptr;
  try {
    const auto states = shield::measurePlates(snap, plates);
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < plates.size(); ++i)
      out.push_back(shield::plateJson(plates[i].name, states[i]));
    return out;
  } catch (const InputError&) {
    return nullptr;  // no object or velocity field: nothing to measure, the run goes on
  }
}

nlohmann::json platesSummaryJson(const nlohmann::json& history) {
  nlohmann::json perSnapshot = nlohmann::json::array();
  for (const auto& e : history)
    if (e.contains("plates")) perSnapshot.push_back(e.at("plates"));
  if (perSnapshot.empty()) return nullptr;
  return shield::platesSummary(perSnapshot);
}

nlohmann::json rearWallVerdictJson(const nlohmann::json& history) {
  nlohmann::json states = nlohmann::json::array();
  for (const auto& e : history)
    if (e.contains("rear_wall")) states.push_back(e.at("rear_wall"));
  if (states.empty()) return nullptr;
  return shield::failureVerdict(states);
}

}  // namespace hvi::app
