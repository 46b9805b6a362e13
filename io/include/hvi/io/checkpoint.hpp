//! @file Checkpoint files: a solver's exact binary state wrapped with a header and a checksum.
//! Bodies are written and read with hvi::BinaryWriter / BinaryReader (hvi/common/binary.hpp).
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <ostream>
#include <string>

namespace hvi::io {

//! Version of the checkpoint container (docs/output.md); the body's own layout is the solver's.
inline constexpr std::uint32_t checkpointFormatVersion = 1;

//! Writes `header` (the resolved scene TOML and solver name, as the driver formats them) and
//! the bytes `body` puts into its stream, followed by the body length and an FNV-1a 64 checksum,
//! atomically: a killed run leaves the previous checkpoint or the complete new one.
//! If `body` throws, the previous file is untouched and the exception propagates.
void writeCheckpointFile(const std::filesystem::path& file, const std::string& header,
                         const std::function<void(std::ostream&)>& body);

//! Verifies magic, version, length and checksum of the whole file, then hands the body to
//! `body` (which may be empty to read only the header) and returns the header. The stream given
//! to `body` ends where the body ends. Throws hvi::InputError naming the file if it is missing,
//! not a checkpoint, truncated or corrupted, or if `body` reads past the end of the body or
//! leaves part of it unread (a reader that does not match the writer).
std::string readCheckpointFile(const std::filesystem::path& file,
                               std::function<void(std::istream&)> body);

//! FNV-1a 64-bit hash, continuing from `hash` (pass the offset basis for a fresh hash).
inline constexpr std::uint64_t fnv1aOffsetBasis = 14695981039346656037ULL;
std::uint64_t fnv1a64(const void* data, std::size_t bytes, std::uint64_t hash = fnv1aOffsetBasis);

}  // namespace hvi::io
