//! @file The effect phase_bookkeeping adds the Tillotson phase fields to TVD snapshots.
#include <gtest/gtest.h>

#include <algorithm>

#include "hvi/test/tvd_scenes.hpp"

namespace hvi::tvd {
namespace {
using namespace hvi::tvd::testing;

const Field* find(const Snapshot& s, const std::string& name) {
  for (const Field& f : s.fields)
    if (f.name == name) return &f;
  return nullptr;
}

// Three aluminium blocks at rest at rho0, with e below e1 (solid), halfway between e1 and e2
// and above e2 (vapour): fraction (e - e1) / (e2 - e1) = 0, 0.5, 1 and phases 0, 1, 2.
TEST(TvdSnapshot, PhaseFieldsOnlyWithTheEffect) {
  const eos::Tillotson al = eos::aluminiumStudy();
  const double es[3] = {0.5 * al.e1, 0.5 * (al.e1 + al.e2), 2.0 * al.e2};
  for (bool phase : {false, true}) {
    cases::Scene s = baseScene(0.0, 3.0, 0.0, 1.0, 0.1);
    s.materials.push_back(material("aluminium", al));
    for (int b = 0; b < 3; ++b)
      s.bodies.push_back(body("block" + std::to_string(b), 0, cases::Rect{1.0 * b, b + 1.0, 0, 1},
                              {al.rho0, {}, es[b]}));
    if (phase) s.effects.insert(cases::Effect::PhaseBookkeeping);
    const TvdSolver solver(s);
    const Snapshot snap = solver.snapshot();
    const Field* frac = find(snap, "vapour_fraction");
    const Field* ph = find(snap, "phase");
    if (!phase) {  // a solver pays only for the effects the scene names
      EXPECT_EQ(frac, nullptr);
      EXPECT_EQ(ph, nullptr);
      continue;
    }
    ASSERT_NE(frac, nullptr);
    ASSERT_NE(ph, nullptr);
    const int nx = solver.grid().nx;
    for (int b = 0; b < 3; ++b) {
      const auto c = static_cast<std::size_t>(5 * nx + 10 * b + 5);  // the middle of block b
      EXPECT_NEAR(frac->data[c], 0.5 * b, 1e-12) << "block " << b;
      EXPECT_EQ(ph->data[c], b) << "block " << b;
    }
  }
}

}  // namespace
}  // namespace hvi::tvd
