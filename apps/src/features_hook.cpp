//! @file Debris-cloud features of a snapshot, through the compare library.
#include "hvi/apps/features_hook.hpp"

#include "hvi/common/error.hpp"
#include "hvi/compare/features.hpp"

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

}  // namespace hvi::app
