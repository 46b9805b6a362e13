//! @file Crash-safe file replacement: write beside the target, fsync, rename over it.
#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace hvi {

//! Calls `write(tmpPath)` to produce the file under a temporary name in the same folder, syncs
//! it to disk and renames it to `target`. A run killed at any moment leaves either the old file
//! or the complete new one under `target`, never a half-written one. If `write` throws, the
//! temporary file is removed and the exception propagates. Failures of the folder creation,
//! the sync or the rename throw hvi::OutputError naming the file and the system's reason.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& tmp)>& write);

//! Same, for text content. Throws hvi::OutputError naming `target` and the reason (strerror:
//! "No space left on device", "Permission denied", ...).
void writeTextAtomically(const std::filesystem::path& target, const std::string& text);

//! The temporary name writeAtomically uses for `target` in process `pid`:
//! "<folder>/.<name>.tmp<pid><extension>".
std::filesystem::path temporaryPath(const std::filesystem::path& target, long pid);
//! The pid in a file name made by temporaryPath, or nothing if `name` is not one.
std::optional<long> temporaryOwner(const std::string& name);

//! strerror(err) (a function so that callers need not include <cstring>).
std::string errnoText(int err);

}  // namespace hvi
