//! @file Reading scene files (TOML) into a validated Scene, and writing the resolved scene.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "hvi/cases/scene.hpp"

namespace hvi::cases {

//! The whole text of an input file (TOML) of the given kind ("scene", "shield"), refusing
//! directories, FIFOs, devices and files over 8 MiB before they are opened or read to the end:
//! no input file makes hvi block or read without end. Throws hvi::InputError naming the file.
std::string readInputFile(const std::string& name, std::string_view kind);

//! Parses and validates a scene file. `overrides` are "dotted.key=value" strings (as given to
//! `hvi run --set`) applied to the document before validation. Throws hvi::InputError whose
//! message names the file, the line, the key and what is allowed. No partial Scene escapes.
Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
//! Same, from text; `sourceName` stands for the file name in messages.
Scene parseScene(std::string_view text, const std::string& sourceName,
                 const std::vector<std::string>& overrides = {});

//! The resolved scene, every default filled in and every value in internal units, as TOML that
//! parseScene reads back to an equal Scene. Written into every output.
std::string toToml(const Scene& scene);

}  // namespace hvi::cases
