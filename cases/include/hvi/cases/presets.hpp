//! @file Named materials a scene can use with `preset = "..."`.
#pragma once
#include <optional>
#include <span>
#include <string_view>

#include "hvi/eos/eos.hpp"

namespace hvi::cases {

//! aluminium_tillotson (the study's aluminium, spec section 2, docs/method.md),
//! aluminium_mie_gruneisen, copper_mie_gruneisen, air_ideal_gas. Values in cm-g-us.
std::span<const std::string_view> presetNames();
std::optional<eos::Eos> materialPreset(std::string_view name);

}  // namespace hvi::cases
