//! @file The shield materials a declaration may name.
#include <array>

#include "hvi/shield/shield.hpp"

namespace hvi::shield {
namespace {
// Densities and yield stresses as NASA's Whipple test records list them (the rear wall's sigma
// in ksi in Christiansen's BLE; pyBLOSSUM's data/database_whipple_pyBLOSSUM.csv reproduces
// them): 6061-T6 40 ksi, 2024-T3 50 ksi, 2017-T4 40 ksi, 7075-T6 73 ksi, 1100-O 5 ksi.
// Hydrodynamically every aluminium alloy runs with the study's Tillotson aluminium, its rho0 set
// to the alloy's density.
constexpr const char* kNasa = "NASA/TP-2003-210788 test records; yield 0.2 % offset";
const std::array<ShieldMaterial, 6> kMaterials{{
    {"al6061_t6", "aluminium_tillotson", 2.70, 40.0 * kMpaPerKsi, kNasa},
    {"al2024_t3", "aluminium_tillotson", 2.77, 50.0 * kMpaPerKsi, kNasa},
    {"al2017_t4", "aluminium_tillotson", 2.80, 40.0 * kMpaPerKsi, kNasa},
    {"al7075_t6", "aluminium_tillotson", 2.80, 73.0 * kMpaPerKsi, kNasa},
    {"al1100_o", "aluminium_tillotson", 2.71, 5.0 * kMpaPerKsi, kNasa},
    {"aluminium", "aluminium_tillotson", 2.70, 0.0, "the study's Tillotson aluminium (no yield)"},
}};
}  // namespace

std::span<const ShieldMaterial> shieldMaterials() { return kMaterials; }

const ShieldMaterial* findShieldMaterial(std::string_view name) {
  for (const auto& m : kMaterials)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace hvi::shield
