//! @file docs/scenes.md's tables of effects and keys, rendered from the tables the parser runs
//! on (tests/unit/cases checks that the document holds them verbatim; paste the output of a
//! failing check to update it).
#pragma once
#include <initializer_list>
#include <string>
#include <string_view>

namespace hvi::cases {

//! | effect | meaning | sph | tvd | riemann |: effectTable() and supportedEffects().
std::string effectTableMarkdown();
//! | key | value | default |: the key tables of `sections` ("root", "time", "domain",
//! "materials" (preset, eos), "materials.<eos>" (one EOS's parameters), "bodies", "sph", "tvd",
//! "riemann", "output"), keys written section.key when there are several.
std::string keyTableMarkdown(std::initializer_list<std::string_view> sections);

}  // namespace hvi::cases
