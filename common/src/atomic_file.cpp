//! @file Crash-safe file replacement.
#include "hvi/common/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include <fmt/format.h>

#include "hvi/common/error.hpp"

namespace hvi {
namespace fs = std::filesystem;

namespace {
//! Syncs a written file (its data must be on disk before the rename makes it visible) or a
//! folder (the rename itself). A failing fsync of the file is a write failure: on NFS and some
//! quota setups ENOSPC or EIO surfaces only here. A folder that cannot be synced is tolerated:
//! the rename is still atomic, only its durability across a power cut is weaker.
void fsyncPath(const fs::path& p, bool directory) {
  const int fd = ::open(p.c_str(), directory ? O_RDONLY | O_DIRECTORY | O_CLOEXEC
                                             : O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (directory) return;
    throw OutputError(fmt::format("cannot write {}: {}", p.string(), errnoText(errno)));
  }
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  // EINVAL / ENOTSUP: a special file or a file system without fsync; nothing was lost.
  if (rc != 0 && !directory && err != EINVAL && err != ENOTSUP)
    throw OutputError(fmt::format("cannot write {}: {}", p.string(), errnoText(err)));
}
}  // namespace

std::string errnoText(int err) { return std::strerror(err); }

fs::path temporaryPath(const fs::path& target, long pid) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // The temporary name keeps the extension last but starts with a dot so that readers that
  // glob for snapshots ignore it; the pid tells whose it is (see isTemporaryOfDeadProcess).
  return dir / fmt::format(".{}.tmp{}{}", target.filename().string(), pid,
                           target.extension().string());
}

std::optional<long> temporaryOwner(const std::string& name) {
  if (name.size() < 2 || name[0] != '.') return std::nullopt;
  const auto at = name.rfind(".tmp");
  if (at == std::string::npos || at == 0) return std::nullopt;
  std::size_t i = at + 4, j = i;
  while (j < name.size() && name[j] >= '0' && name[j] <= '9') ++j;
  if (j == i || j - i > 9) return std::nullopt;
  return std::stol(name.substr(i, j - i));
}

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw OutputError(fmt::format("cannot create folder {} for {}: {}", dir.string(),
                                  target.filename().string(), ec.message()));
  const fs::path tmp = temporaryPath(target, ::getpid());
  try {
    write(tmp);
    fsyncPath(tmp, false);
    fs::rename(tmp, target, ec);
    if (ec)
      throw OutputError(fmt::format("cannot rename {} to {}: {}", tmp.string(), target.string(),
                                    ec.message()));
    fsyncPath(dir, true);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

void writeTextAtomically(const fs::path& target, const std::string& text) {
  writeAtomically(target, [&](const fs::path& tmp) {
    // POSIX calls rather than a stream: a stream's failure says nothing about why, and the
    // user needs to know it was ENOSPC (free space) rather than EACCES (permissions).
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
      throw OutputError(fmt::format("cannot write {}: {}", target.string(), errnoText(errno)));
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
      const ssize_t n = ::write(fd, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const int err = n < 0 ? errno : ENOSPC;
        ::close(fd);
        throw OutputError(fmt::format("cannot write {}: {}", target.string(), errnoText(err)));
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0)
      throw OutputError(fmt::format("cannot write {}: {}", target.string(), errnoText(errno)));
  });
}

}  // namespace hvi
