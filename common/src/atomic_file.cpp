//! @file Crash-safe file replacement.
#include "hvi/common/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

namespace hvi {
namespace fs = std::filesystem;

namespace {
void fsyncPath(const fs::path& p, bool directory) {
  int fd = ::open(p.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
  if (fd < 0) return;  // best effort: a filesystem without fsync on directories is still atomic
  ::fsync(fd);
  ::close(fd);
}
}  // namespace

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  fs::create_directories(dir);
  // The temporary name keeps the extension last but starts with a dot so that readers that
  // glob for snapshots ignore it.
  fs::path tmp = dir / fmt::format(".{}.tmp{}{}", target.filename().string(), ::getpid(),
                                   target.extension().string());
  try {
    write(tmp);
    fsyncPath(tmp, false);
    fs::rename(tmp, target);
    fsyncPath(dir, true);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
}

void writeTextAtomically(const fs::path& target, const std::string& text) {
  writeAtomically(target, [&](const fs::path& tmp) {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
  });
}

}  // namespace hvi
