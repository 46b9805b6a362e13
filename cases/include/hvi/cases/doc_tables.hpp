//! @file docs/scenes.md's tables of effects and keys, rendered from the tables the parser runs
//! on (tests/unit/cases checks that the document holds them verbatim; paste the output of a
//! failing check to update it).
#pragma once
#include <string>

namespace hvi::cases {

//! | effect | meaning | sph | tvd | riemann |: effectTable() and supportedEffects().
std::string effectTableMarkdown();

}  // namespace hvi::cases
