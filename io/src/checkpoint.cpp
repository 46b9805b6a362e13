//! @file Checkpoint container: magic, version, header, body, body length, FNV-1a 64 checksum.
#include "hvi/io/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <streambuf>
#include <vector>

#include <fmt/format.h>

#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"

namespace hvi::io {
namespace fs = std::filesystem;

namespace {

// High bit in the first byte (as in PNG) so that a text-mode transfer is caught as bad magic.
constexpr std::array<char, 8> magic = {'\x89', 'H', 'V', 'I', 'C', 'K', 'P', 'T'};
constexpr std::size_t prefixBytes = 8 + 4 + 8;  // magic, version, header length
constexpr std::size_t trailerBytes = 8 + 8;     // body length, checksum
constexpr std::size_t bufferBytes = 1 << 16;

void putLe(char* out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out[i] = static_cast<char>((v >> (8 * i)) & 0xffu);
}
std::uint64_t getLe(const char* in, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= std::uint64_t(static_cast<unsigned char>(in[i])) << (8 * i);
  return v;
}

//! An output buffer of bufferBytes whose derived class says where a full buffer goes
//! (flushBuffer, which also resets the put area); a failed flush is a failed write.
class BufferedOutBuf : public std::streambuf {
 protected:
  BufferedOutBuf() { resetPutArea(); }
  virtual bool flushBuffer() = 0;
  void resetPutArea() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  [[nodiscard]] std::size_t buffered() const { return static_cast<std::size_t>(pptr() - pbase()); }

  int_type overflow(int_type ch) override {
    if (!flushBuffer()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return flushBuffer() ? 0 : -1; }

  std::array<char, bufferBytes> buffer_{};
};

//! Forwards to a file's buffer while hashing and counting every byte, so the body streams to
//! disk without being held in memory.
class HashingOutBuf : public BufferedOutBuf {
 public:
  HashingOutBuf(std::streambuf* sink, std::uint64_t hash) : sink_(sink), hash_(hash) {}
  std::uint64_t hash() const { return hash_; }
  std::uint64_t count() const { return count_; }

 private:
  bool flushBuffer() override {
    const std::size_t n = buffered();
    hash_ = fnv1a64(pbase(), n, hash_);
    count_ += n;
    const bool ok = sink_->sputn(pbase(), static_cast<std::streamsize>(n)) ==
                    static_cast<std::streamsize>(n);
    resetPutArea();
    return ok;
  }
  std::streambuf* sink_;
  std::uint64_t hash_;
  std::uint64_t count_ = 0;
};

//! Writes to a file descriptor and keeps the errno of the first failed write, so that a failed
//! checkpoint can say why (disk full, quota, I/O error): a std::ofstream only says "failed".
class FdOutBuf : public BufferedOutBuf {
 public:
  explicit FdOutBuf(const fs::path& file)
      : fd_(::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)) {
    if (fd_ < 0) error_ = errno;
  }
  ~FdOutBuf() override {
    if (fd_ >= 0) ::close(fd_);
  }
  FdOutBuf(const FdOutBuf&) = delete;
  FdOutBuf& operator=(const FdOutBuf&) = delete;
  //! 0 while every write succeeded, else the errno of the first failure.
  int error() const { return error_; }
  //! Flushes and closes; false (with error() set) if anything failed.
  bool close() {
    const bool flushed = flushBuffer();
    if (fd_ >= 0 && ::close(fd_) != 0 && error_ == 0) error_ = errno;
    fd_ = -1;
    return flushed && error_ == 0;
  }

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n >= static_cast<std::streamsize>(buffer_.size())) {
      if (!flushBuffer() || !writeAll(s, static_cast<std::size_t>(n))) return 0;
      return n;
    }
    return std::streambuf::xsputn(s, n);
  }

 private:
  bool flushBuffer() override {
    const std::size_t n = buffered();
    resetPutArea();
    return writeAll(buffer_.data(), n);
  }
  bool writeAll(const char* p, std::size_t n) {
    if (error_ != 0) return false;
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        error_ = w < 0 ? errno : ENOSPC;
        return false;
      }
      p += w;
      n -= static_cast<std::size_t>(w);
    }
    return true;
  }
  int fd_;
  int error_ = 0;
};

//! Reads at most `limit` bytes from a file's buffer, so a body reader sees end-of-file where the
//! body ends instead of reading the trailer as data.
class BoundedInBuf : public std::streambuf {
 public:
  BoundedInBuf(std::streambuf* source, std::uint64_t limit) : source_(source), left_(limit) {
    setg(buffer_.data(), buffer_.data(), buffer_.data());
  }
  //! Body bytes the reader has not consumed.
  std::uint64_t unread() const { return left_ + static_cast<std::uint64_t>(egptr() - gptr()); }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    const auto want = static_cast<std::streamsize>(std::min<std::uint64_t>(left_, buffer_.size()));
    if (want == 0) return traits_type::eof();
    const std::streamsize got = source_->sgetn(buffer_.data(), want);
    if (got <= 0) return traits_type::eof();
    left_ -= static_cast<std::uint64_t>(got);
    setg(buffer_.data(), buffer_.data(), buffer_.data() + got);
    return traits_type::to_int_type(*gptr());
  }

 private:
  std::streambuf* source_;
  std::uint64_t left_;
  std::array<char, bufferBytes> buffer_{};
};

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ULL;
  }
  return hash;
}

void writeCheckpointFile(const fs::path& file, const std::string& header,
                         const std::function<void(std::ostream&)>& body) {
  writeAtomically(file, [&](const fs::path& tmp) {
    FdOutBuf sink(tmp);
    // A failed write names the checkpoint and the system's reason; the body's own exception
    // (a solver that sees its stream fail says only "write failed") is replaced by it.
    const auto writeFailed = [&] {
      return OutputError(fmt::format("cannot write checkpoint {}: {} (the previous checkpoint "
                                     "is unchanged)", file.string(), errnoText(sink.error())));
    };
    if (sink.error() != 0) throw writeFailed();
    std::ostream out(&sink);
    std::array<char, prefixBytes> prefix{};
    std::memcpy(prefix.data(), magic.data(), magic.size());
    putLe(prefix.data() + 8, checkpointFormatVersion, 4);
    putLe(prefix.data() + 12, header.size(), 8);
    out.write(prefix.data(), prefix.size());
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    std::uint64_t hash = fnv1a64(prefix.data(), prefix.size());
    hash = fnv1a64(header.data(), header.size(), hash);

    HashingOutBuf hashing(&sink, hash);
    std::ostream bodyStream(&hashing);
    try {
      if (body) body(bodyStream);
    } catch (...) {
      if (sink.error() != 0) throw writeFailed();
      throw;
    }
    bodyStream.flush();
    if (sink.error() != 0) throw writeFailed();
    if (!bodyStream)
      throw std::runtime_error(fmt::format("writing checkpoint body to {} failed", tmp.string()));

    std::array<char, trailerBytes> trailer{};
    putLe(trailer.data(), hashing.count(), 8);
    putLe(trailer.data() + 8, fnv1a64(trailer.data(), 8, hashing.hash()), 8);
    out.write(trailer.data(), trailer.size());
    if (!sink.close()) throw writeFailed();
  });
}

std::string readCheckpointFile(const fs::path& file, std::function<void(std::istream&)> body) {
  const std::string name = file.string();
  std::error_code ec;
  const std::uint64_t size = fs::file_size(file, ec);
  if (ec) throw InputError(fmt::format("cannot read checkpoint {}: {}", name, ec.message()));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot open checkpoint {}", name));

  std::array<char, prefixBytes> prefix{};
  in.read(prefix.data(), prefix.size());
  if (!in || std::memcmp(prefix.data(), magic.data(), magic.size()) != 0)
    throw InputError(fmt::format("{} is not an hvi checkpoint (its first bytes are not the "
                                 "checkpoint magic)", name));
  const auto version = static_cast<std::uint32_t>(getLe(prefix.data() + 8, 4));
  if (version != checkpointFormatVersion)
    throw InputError(fmt::format("{}: checkpoint format version {}; this build reads version {}",
                                 name, version, checkpointFormatVersion));
  const std::uint64_t headerBytes = getLe(prefix.data() + 12, 8);
  if (size < prefixBytes + trailerBytes || headerBytes > size - prefixBytes - trailerBytes)
    throw InputError(fmt::format("{}: checkpoint truncated ({} bytes, header alone needs {})",
                                 name, size, headerBytes));
  const std::uint64_t bodyBytes = size - prefixBytes - headerBytes - trailerBytes;

  // Whole-file checksum before anything is handed to the solver: a restart from a damaged file
  // must fail here, not halfway through rebuilding the state.
  std::uint64_t hash = fnv1a64(prefix.data(), prefix.size());
  std::string header(static_cast<std::size_t>(headerBytes), '\0');
  in.read(header.data(), static_cast<std::streamsize>(headerBytes));
  hash = fnv1a64(header.data(), header.size(), hash);
  std::vector<char> chunk(bufferBytes);
  for (std::uint64_t left = bodyBytes; left > 0;) {
    const auto m = static_cast<std::streamsize>(std::min<std::uint64_t>(left, chunk.size()));
    in.read(chunk.data(), m);
    hash = fnv1a64(chunk.data(), static_cast<std::size_t>(m), hash);
    left -= static_cast<std::uint64_t>(m);
  }
  std::array<char, trailerBytes> trailer{};
  in.read(trailer.data(), trailer.size());
  if (!in) throw InputError(fmt::format("{}: checkpoint could not be read to its end", name));
  const std::uint64_t storedBodyBytes = getLe(trailer.data(), 8);
  if (storedBodyBytes != bodyBytes)
    throw InputError(fmt::format("{}: checkpoint truncated or extended: body should be {} bytes, "
                                 "file holds {}", name, storedBodyBytes, bodyBytes));
  hash = fnv1a64(trailer.data(), 8, hash);
  if (hash != getLe(trailer.data() + 8, 8))
    throw InputError(fmt::format("{}: checkpoint corrupted (checksum mismatch)", name));

  if (body) {
    in.clear();
    in.seekg(static_cast<std::streamoff>(prefixBytes + headerBytes));
    BoundedInBuf bounded(in.rdbuf(), bodyBytes);
    std::istream bodyStream(&bounded);
    try {
      body(bodyStream);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", name, e.what()));
    }
    if (bodyStream.fail())
      throw InputError(fmt::format("{}: the solver read past the end of the checkpoint body "
                                   "({} bytes); checkpoint and solver versions differ",
                                   name, bodyBytes));
    if (bounded.unread() != 0)
      throw InputError(fmt::format("{}: {} of {} checkpoint body bytes left unread; checkpoint "
                                   "and solver versions differ", name, bounded.unread(),
                                   bodyBytes));
  }
  return header;
}

}  // namespace hvi::io
