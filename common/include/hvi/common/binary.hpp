//! @file The one binary writer and reader of the project's checkpoint bodies (SPH, TVD, marker
//! lines, the exact Riemann solver; io's container around them). Values go out in the machine's
//! native representation: a checkpoint restarts a run bit for bit on the same kind of machine,
//! it is not an exchange format. Every read is checked, so a short or mismatched body is an
//! InputError naming the record, never garbage.
#pragma once
#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "hvi/common/error.hpp"

namespace hvi {

//! Writes values to a stream. `what` names the record in error messages ("tvd checkpoint").
class BinaryWriter {
 public:
  BinaryWriter(std::ostream& out, std::string what) : out_(out), what_(std::move(what)) {}

  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof(T));
  }
  //! `n` elements without a count (the reader knows n from an earlier value).
  template <class T>
  void elements(const T* data, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(data, n * sizeof(T));
  }
  //! The element count (uint64), then the elements.
  template <class T>
  void array(const std::vector<T>& v) {
    value<std::uint64_t>(v.size());
    elements(v.data(), v.size());
  }
  //! Length (uint64), then the characters.
  void string(std::string_view s) {
    value<std::uint64_t>(s.size());
    bytes(s.data(), s.size());
  }
  void bytes(const void* data, std::size_t n) {
    out_.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
    if (!out_) throw OutputError(what_ + ": write failed");
  }

 private:
  std::ostream& out_;
  std::string what_;
};

//! Reads what BinaryWriter wrote. Throws InputError "<what>: ..." when the stream ends early or
//! a count does not fit.
class BinaryReader {
 public:
  BinaryReader(std::istream& in, std::string what) : in_(in), what_(std::move(what)) {}

  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v{};
    bytes(&v, sizeof(T), "a value");
    return v;
  }
  //! `n` elements without a count into `v` (resized to n).
  template <class T>
  void elements(std::vector<T>& v, std::size_t n, std::string_view name = "an array") {
    static_assert(std::is_trivially_copyable_v<T>);
    checkCount(n, sizeof(T), name);
    v.resize(n);
    bytes(v.data(), n * sizeof(T), name);
  }
  //! A count (uint64) and its elements.
  template <class T>
  std::vector<T> array(std::string_view name = "an array") {
    std::vector<T> v;
    elements(v, count(), name);
    return v;
  }
  //! As array(), but the count must be `expected` (the size this run has).
  template <class T>
  void array(std::vector<T>& v, std::size_t expected, std::string_view name) {
    const std::uint64_t n = count();
    if (n != expected)
      throw InputError(what_ + ": array '" + std::string(name) + "' has " + std::to_string(n) +
                       " values, this run has " + std::to_string(expected));
    elements(v, expected, name);
  }
  std::string string() {
    std::string s(checkCount(count(), 1, "a string"), '\0');
    bytes(s.data(), s.size(), "a string");
    return s;
  }
  //! A count (uint64), as written by array() and string().
  std::uint64_t count() { return value<std::uint64_t>(); }
  void bytes(void* data, std::size_t n, std::string_view name = "a value") {
    in_.read(static_cast<char*>(data), static_cast<std::streamsize>(n));
    if (!in_) throw InputError(what_ + ": the stream ends inside " + std::string(name));
  }

 private:
  //! The bodies are checksummed, so a count this large means reader and writer are out of
  //! step; refuse it rather than attempt the allocation.
  std::size_t checkCount(std::uint64_t n, std::size_t elementBytes, std::string_view name) const {
    if (n > (std::uint64_t(1) << 40) / elementBytes)
      throw InputError(what_ + ": count " + std::to_string(n) + " of " + std::string(name) +
                       " is implausible; checkpoint and solver versions differ");
    return static_cast<std::size_t>(n);
  }

  std::istream& in_;
  std::string what_;
};

}  // namespace hvi
