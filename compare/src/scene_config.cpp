//! @file Feature configuration from a scene: which bodies are striker and shield, and where.
#include <algorithm>

#include <fmt/format.h>

#include "hvi/cases/scene.hpp"
#include "hvi/common/error.hpp"
#include "hvi/compare/features.hpp"

namespace hvi::compare {

FeatureConfig featureConfigFromScene(const cases::Scene& scene) {
  const auto& bodies = scene.bodies;
  if (bodies.size() < 2)
    throw InputError(fmt::format("compare: scene '{}' has {} bod{}; debris features need a striker "
                                 "and a shield",
                                 scene.path, bodies.size(), bodies.size() == 1 ? "y" : "ies"));
  auto byName = [&](const char* name, int fallback) {
    const auto it = std::find_if(bodies.begin(), bodies.end(),
                                 [&](const cases::Body& b) { return b.name == name; });
    return it != bodies.end() ? static_cast<int>(it - bodies.begin()) : fallback;
  };
  // By convention the bodies are named; otherwise the first body strikes the second.
  const int striker = byName("striker", 0);
  int shield = byName("shield", 1);
  if (shield == striker) shield = striker == 0 ? 1 : 0;

  FeatureConfig cfg;
  cfg.striker = bodies[striker].name;
  cfg.shield = bodies[shield].name;
  cfg.strikerIndex = striker;
  cfg.shieldIndex = shield;
  const cases::Box sb = cases::boundingBox(bodies[shield].shape);
  cfg.shieldZMin = sb.zmin;
  cfg.shieldZMax = sb.zmax;
  const cases::Box kb = cases::boundingBox(bodies[striker].shape);
  cfg.axisX = scene.geometry == Geometry::Axisymmetric ? 0.0 : 0.5 * (kb.xmin + kb.xmax);
  cfg.direction = bodies[striker].velocity.z > 0.0 ? 1 : -1;
  return cfg;
}

}  // namespace hvi::compare
