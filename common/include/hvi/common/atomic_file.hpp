//! @file Crash-safe file replacement: write beside the target, fsync, rename over it.
#pragma once
#include <filesystem>
#include <functional>

namespace hvi {

//! Calls `write(tmpPath)` to produce the file under a temporary name in the same folder, syncs
//! it to disk and renames it to `target`. A run killed at any moment leaves either the old file
//! or the complete new one under `target`, never a half-written one. If `write` throws, the
//! temporary file is removed and the exception propagates.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

//! Same, for text content.
void writeTextAtomically(const std::filesystem::path& target, const std::string& text);

}  // namespace hvi
