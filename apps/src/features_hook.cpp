//! @file Debris-cloud features of a snapshot, through the compare library.
#include "hvi/apps/features_hook.hpp"

#include "hvi/compare/features.hpp"

namespace hvi::app {

nlohmann::json measureFeaturesJson(const Snapshot& snap, const cases::Scene& scene) {
  return compare::toJson(compare::measureFeatures(snap, compare::featureConfigFromScene(scene)));
}

}  // namespace hvi::app
