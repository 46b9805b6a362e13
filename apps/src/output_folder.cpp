//! @file Output folder checks, the run lock and the files a run owns.
#include "hvi/apps/output_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <regex>

#include <fmt/format.h>

#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"

namespace hvi::app {
namespace fs = std::filesystem;

namespace {
std::string kindOf(fs::file_type t) {
  switch (t) {
    case fs::file_type::regular: return "a file";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::socket: return "a socket";
    default: return "not a folder";
  }
}
}  // namespace

void prepareOutputFolder(const fs::path& dir, bool create) {
  if (dir.empty()) throw InputError("--out is empty: name an output folder");
  std::error_code ec;
  const auto st = fs::status(dir, ec);
  if (fs::is_directory(st)) return;
  if (fs::exists(st))
    throw InputError(fmt::format("output folder {} is {}, not a folder; choose another --out",
                                 dir.string(), kindOf(st.type())));
  if (!create)
    throw InputError(fmt::format("output folder {} does not exist", dir.string()));
  fs::create_directories(dir, ec);
  if (ec)
    throw InputError(fmt::format("cannot create output folder {}: {}", dir.string(), ec.message()));
  // create_directories reports success for some paths it could not make usable (a symlink to
  // nowhere, say); check again.
  if (!fs::is_directory(dir, ec))
    throw InputError(fmt::format("cannot create output folder {}", dir.string()));
}

FolderLock::FolderLock(const fs::path& dir) {
  const fs::path file = dir / kLockFileName;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(fmt::format("output folder {} is not writable: cannot create {}: {}",
                                 dir.string(), file.filename().string(), errnoText(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    std::string holder;
    if (err == EWOULDBLOCK) {
      char buf[32] = {};
      const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
      holder = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
      holder.erase(std::remove_if(holder.begin(), holder.end(),
                                  [](char c) { return c < '0' || c > '9'; }),
                   holder.end());
    }
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(fmt::format(
          "output folder {} is in use by another hvi run (pid {}); wait for it to end or choose "
          "another --out", dir.string(), holder.empty() ? std::string("unknown") : holder));
    throw InputError(fmt::format("cannot lock output folder {}: {}", dir.string(), errnoText(err)));
  }
  // The pid is for the message a second run prints; the lock itself is the flock.
  const std::string pid = fmt::format("{}\n", ::getpid());
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // A full disk may refuse even these bytes; the lock holds without them.
  }
}

FolderLock::~FolderLock() {
  // The file stays: unlinking it would let a third process lock a new file while a second
  // still waits on the old one. Closing releases the flock.
  if (fd_ >= 0) ::close(fd_);
}

bool isRunFile(const std::string& name) {
  static const std::regex pattern(
      R"((scene\.toml|summary\.json|timeseries\.json|energy_budget\.csv|checkpoint\.bin|hvi\.pvd|(snap|failed)_\d+(\.h5|\.vtu|\.vti|_markers\.vtp)))");
  return std::regex_match(name, pattern);
}

std::vector<fs::path> runFiles(const fs::path& dir) {
  std::vector<fs::path> v;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file(ec) && isRunFile(e.path().filename().string())) v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

int removeRunFiles(const fs::path& dir) {
  int n = 0;
  for (const auto& f : runFiles(dir)) {
    std::error_code ec;
    if (!fs::remove(f, ec) && ec)
      throw OutputError(fmt::format("--overwrite: cannot remove {}: {}", f.string(), ec.message()));
    ++n;
  }
  return n;
}

void removeStaleTemporaries(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const auto owner = temporaryOwner(e.path().filename().string());
    if (!owner || !e.is_regular_file(ec)) continue;
    // kill(pid, 0) fails with ESRCH only when no such process exists.
    if (*owner != ::getpid() && ::kill(static_cast<pid_t>(*owner), 0) != 0 && errno == ESRCH)
      fs::remove(e.path(), ec);
  }
}

std::string shellQuote(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_-./=:,+@%") == std::string::npos)
    return word;
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace hvi::app
