//! @file Checkpoint files: a solver's exact binary state wrapped with a header and a checksum.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

#include "hvi/common/error.hpp"

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

// Helpers for checkpoint bodies. They write the machine's native representation: a checkpoint
// restarts a run bit for bit on the same kind of machine, it is not an exchange format.

template <class T>
void writeValue(std::ostream& out, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
T readValue(std::istream& in) {
  static_assert(std::is_trivially_copyable_v<T>);
  T value{};
  in.read(reinterpret_cast<char*>(&value), sizeof(T));
  if (!in) throw InputError("checkpoint body ends inside a value");
  return value;
}

//! Writes the element count (uint64) then the elements.
template <class T>
void writeArray(std::ostream& out, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  writeValue<std::uint64_t>(out, values.size());
  out.write(reinterpret_cast<const char*>(values.data()),
            static_cast<std::streamsize>(values.size() * sizeof(T)));
}

template <class T>
std::vector<T> readArray(std::istream& in) {
  static_assert(std::is_trivially_copyable_v<T>);
  const auto n = readValue<std::uint64_t>(in);
  // The file's checksum has been verified, so a count this large means the reader is out of
  // step with the writer; refuse it rather than attempt the allocation.
  if (n > (std::uint64_t(1) << 40) / sizeof(T))
    throw InputError("checkpoint array count " + std::to_string(n) +
                     " is implausible; checkpoint and solver versions differ");
  // One allocation: growing in blocks costs a page fault storm on large states.
  std::vector<T> values(static_cast<std::size_t>(n));
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(n * sizeof(T)));
  if (!in) throw InputError("checkpoint body ends inside an array");
  return values;
}

//! Strings as length (uint64) + bytes.
void writeString(std::ostream& out, const std::string& s);
std::string readString(std::istream& in);

}  // namespace hvi::io
