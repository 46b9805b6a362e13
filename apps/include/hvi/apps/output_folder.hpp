//! @file The output folder of `hvi run`: checks, the run lock, which files a run owns.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace hvi::app {

//! Name of the lock file inside an output folder.
inline constexpr const char* kLockFileName = ".hvi.lock";

//! Checks that `dir` can be an output folder and creates it (with its parents) if `create`.
//! Throws hvi::InputError naming the folder and the cause (empty name, not a folder, cannot be
//! created: the system's reason, e.g. "Not a directory", "Read-only file system").
void prepareOutputFolder(const std::filesystem::path& dir, bool create);

//! An exclusive flock on `<dir>/.hvi.lock`, held while the object lives. The kernel releases it
//! when the process ends in any way (SIGKILL included), so a dead run never leaves a stale lock.
//! The file holds the holder's pid for the message a second run gets.
class FolderLock {
 public:
  //! Throws hvi::InputError naming the folder and the holder's pid if another process holds
  //! the lock, or naming the cause if the lock file cannot be created (folder not writable).
  explicit FolderLock(const std::filesystem::path& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

//! True for the names `hvi run` writes: scene.toml, summary.json, timeseries.json,
//! energy_budget.csv, checkpoint.bin, hvi.pvd and snap_<step> / failed_<step> with .h5, .vtu,
//! .vti or _markers.vtp. Nothing else in a folder is touched by --overwrite.
bool isRunFile(const std::string& name);
//! The run files present in `dir` (regular files only), sorted.
std::vector<std::filesystem::path> runFiles(const std::filesystem::path& dir);
//! Removes them; returns how many. Throws hvi::OutputError naming a file that cannot go.
int removeRunFiles(const std::filesystem::path& dir);

//! Removes temporaries (".<name>.tmp<pid><ext>") whose writing process no longer exists: a run
//! killed while writing leaves one. Call with the folder lock held; files of a live process (an
//! `hvi compare --out` into the folder, say) are left alone.
void removeStaleTemporaries(const std::filesystem::path& dir);

//! `word` quoted for a POSIX shell, unchanged when it needs no quoting.
std::string shellQuote(const std::string& word);

}  // namespace hvi::app
