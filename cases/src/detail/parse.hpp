//! @file The parser's sections, each filling its part of a Scene from the TOML document.
#pragma once
#include <string>
#include <vector>

#include "detail/reader.hpp"
#include "hvi/cases/scene.hpp"

namespace hvi::cases::detail {

//! Where the parts of a scene came from, for checks that span several sections.
struct Sources {
  std::vector<const toml::table*> bodies;  //!< one per Scene::bodies
};

void parseMaterials(const TableReader& root, Scene& scene);
//! [materials.<name>.strength] (parse_strength.cpp).
strength::Material parseStrength(const TableReader& t);
void parseBodies(const TableReader& root, Scene& scene, Sources& sources);
void parseSolverParams(const TableReader& root, Scene& scene);
void parseOutput(const TableReader& root, Scene& scene);
//! Checks across sections: bodies inside the domain, r-z rules, overlaps, resolution, the
//! Riemann layout.
void validateScene(const TableReader& root, const Scene& scene, const Sources& sources);

//! Applies "dotted.key=value" overrides to the document; an unknown path is an InputError.
void applyOverrides(toml::table& doc, const std::vector<std::string>& overrides,
                    const std::string& file);

}  // namespace hvi::cases::detail
