//! @file Crash safety: a failed or killed write leaves the previous file complete.
#include <fcntl.h>
#include <sys/resource.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hvi/common/atomic_file.hpp"
#include "hvi/common/binary.hpp"
#include "hvi/common/error.hpp"
#include "hvi/io/checkpoint.hpp"
#include "hvi/io/output.hpp"
#include "test_support.hpp"

namespace hvi::io::test {
namespace {
namespace fs = std::filesystem;

TEST(Atomic, ThrowingCheckpointBodyLeavesOldFileAndNoTemporary) {
  ScratchDir dir;
  writeCheckpointFile(dir / "c.ckpt", "old",
                      [](std::ostream& out) { BinaryWriter(out, "test body").value(1.5); });
  const std::vector<double> lots(1 << 18, 2.0);  // past the stream buffers: bytes reach the disk
  EXPECT_THROW(writeCheckpointFile(dir / "c.ckpt", "new",
                                   [&](std::ostream& out) {
                                     BinaryWriter(out, "test body").array(lots);
                                     throw std::runtime_error("solver failed mid-checkpoint");
                                   }),
               std::runtime_error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"c.ckpt"});
  EXPECT_EQ(readCheckpointFile(dir / "c.ckpt",
                               [](std::istream& in) {
                                 EXPECT_EQ(BinaryReader(in, "test body").value<double>(), 1.5);
                               }),
            "old");
}

TEST(Atomic, ThrowAfterAPartialHdf5WriteLeavesOldFileAndNoTemporary) {
  ScratchDir dir;
  const Snapshot old = gridSnapshot(8, 8, 1.0);
  writeHdf5(dir / "s.h5", old, "old");
  // The callback of writeAtomically is where writeHdf5 does its work; a failure after HDF5
  // has put a complete file at the temporary path must still not replace the target.
  EXPECT_THROW(writeAtomically(dir / "s.h5",
                               [&](const fs::path& tmp) {
                                 writeHdf5(tmp, gridSnapshot(50, 50, 2.0), "new");
                                 throw std::runtime_error("disk full");
                               }),
               std::runtime_error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.h5"});
  expectBitEqual(old, readHdf5(dir / "s.h5"));
}

//! Starts `write` over and over in a child process and SIGKILLs it while its temporary file is
//! partly written. Returns the number of writes the child completed before the kill, and the
//! size the temporary file had reached.
std::pair<int, std::uintmax_t> killMidWrite(const fs::path& target, const std::function<void()>& write) {
  int done[2];
  if (::pipe(done) != 0) throw std::runtime_error("pipe");
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(done[0]);
    try {
      for (;;) {
        write();
        (void)!::write(done[1], "x", 1);
      }
    } catch (...) {
      ::_exit(3);
    }
  }
  ::close(done[1]);
  // The temporary name of common/atomic_file.cpp: ".<name>.tmp<pid><extension>".
  const fs::path tmp = target.parent_path() / fmt::format(".{}.tmp{}{}", target.filename().string(),
                                                          child, target.extension().string());
  std::uintmax_t size = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  std::error_code ec;
  // Kill once more than 1 MiB is on disk: well inside a write of tens of MiB.
  while (std::chrono::steady_clock::now() < deadline) {
    size = fs::file_size(tmp, ec);
    if (ec) size = 0;
    else if (size > (1u << 20)) break;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child ended by itself";
  ::fcntl(done[0], F_SETFL, O_NONBLOCK);
  int completed = 0;
  char c;
  while (::read(done[0], &c, 1) == 1) ++completed;
  ::close(done[0]);
  return {completed, size};
}

TEST(Atomic, SnapshotWriteKilledMidwayLeavesACompleteFile) {
  ScratchDir dir;
  const fs::path target = dir / "snap.h5";
  const Snapshot old = particleSnapshot(1000, 1.0, 10);
  writeHdf5(target, old, "old");
  const Snapshot big = particleSnapshot(1'000'000, 2.0, 20);  // about 72 MB of doubles
  const auto [completed, size] = killMidWrite(target, [&] { writeHdf5(target, big, "new"); });
  std::cout << "killed with " << size << " bytes of the temporary written, after " << completed
            << " complete writes\n";
  EXPECT_GT(size, 1u << 20) << "the child never got far into its write";
  std::string scene;
  const Snapshot now = readHdf5(target, &scene);  // complete, whatever the child did
  if (completed == 0) {
    expectBitEqual(old, now);
    EXPECT_EQ(scene, "old");
  } else {
    expectBitEqual(big, now);  // a write finished before the kill: the new file, complete
  }
  // The killed child's temporary is left behind, half written: unreadable, and ignored by
  // anything that looks for "*.h5" without a leading dot.
  for (const auto& name : dir.entries()) {
    if (name == "snap.h5") continue;
    EXPECT_EQ(name.front(), '.') << name;
    EXPECT_THROW(readHdf5(dir / name), InputError);
  }
}

TEST(Atomic, CheckpointWriteKilledMidwayLeavesACompleteFile) {
  ScratchDir dir;
  const fs::path target = dir / "run.ckpt";
  writeCheckpointFile(target, "old",
                      [](std::ostream& out) { BinaryWriter(out, "test body").value(7L); });
  const std::vector<double> state(8'000'000, 3.25);  // 64 MB
  const auto [completed, size] = killMidWrite(target, [&] {
    writeCheckpointFile(target, "new",
                        [&](std::ostream& out) { BinaryWriter(out, "test body").array(state); });
  });
  EXPECT_GT(size, 1u << 20);
  const std::string header = readCheckpointFile(target, [&](std::istream& in) {
    if (completed == 0)
      EXPECT_EQ(BinaryReader(in, "test body").value<long>(), 7L);
    else
      EXPECT_EQ(BinaryReader(in, "test body").array<double>(), state);
  });
  EXPECT_EQ(header, completed == 0 ? "old" : "new");
}

//! A full disk, portably: RLIMIT_FSIZE makes every write past `bytes` fail with EFBIG (SIGXFSZ
//! ignored, as a signal would end the test), which is how ENOSPC reaches a writer too. Restored
//! on destruction; the limit is per file, so the test's other files are not affected.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit l = saved_;
    l.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &l);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, oldHandler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*oldHandler_)(int) = nullptr;
};

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(Atomic, FullDiskTextWriteNamesFileAndCauseAndKeepsOldFile) {
  ScratchDir dir;
  writeTextAtomically(dir / "summary.json", "old");
  const std::string big(1 << 16, 'x');
  try {
    FileSizeLimit full(4096);
    writeTextAtomically(dir / "summary.json", big);
    ADD_FAILURE() << "a write past the file size limit succeeded";
  } catch (const OutputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("summary.json"), std::string::npos) << what;
    EXPECT_NE(what.find(std::strerror(EFBIG)), std::string::npos) << what;
  }
  EXPECT_EQ(readText(dir / "summary.json"), "old");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"summary.json"});
}

TEST(Atomic, FullDiskCheckpointNamesFileAndCauseAndKeepsOldCheckpoint) {
  ScratchDir dir;
  writeCheckpointFile(dir / "checkpoint.bin", "old",
                      [](std::ostream& out) { BinaryWriter(out, "test body").value(7L); });
  const std::vector<double> state(1 << 16, 1.0);
  try {
    FileSizeLimit full(8192);
    // The body's writer sees its stream fail and throws its own vague error ("...: write
    // failed"); the container must replace it by the file and the system's reason.
    writeCheckpointFile(dir / "checkpoint.bin", "new",
                        [&](std::ostream& out) { BinaryWriter(out, "test body").array(state); });
    ADD_FAILURE() << "a checkpoint past the file size limit was written";
  } catch (const OutputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("checkpoint.bin"), std::string::npos) << what;
    EXPECT_NE(what.find(std::strerror(EFBIG)), std::string::npos) << what;
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"checkpoint.bin"});
  EXPECT_EQ(readCheckpointFile(dir / "checkpoint.bin",
                               [](std::istream& in) {
                                 EXPECT_EQ(BinaryReader(in, "test body").value<long>(), 7L);
                               }),
            "old");
}

TEST(Atomic, UnwritableFolderIsAnOutputErrorNamingTheFolder) {
  // Below a regular file no folder can be made, for root too.
  ScratchDir dir;
  std::ofstream(dir / "plain") << "x";
  try {
    writeTextAtomically(dir.path() / "plain" / "sub" / "a.json", "{}");
    ADD_FAILURE();
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("plain/sub"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(std::strerror(ENOTDIR)), std::string::npos) << e.what();
  }
}

TEST(Atomic, TemporaryNamesCarryTheirOwner) {
  const fs::path t = temporaryPath("out/snap_00000012.h5", 4321);
  EXPECT_EQ(t, fs::path("out/.snap_00000012.h5.tmp4321.h5"));
  EXPECT_EQ(temporaryOwner(t.filename().string()), 4321L);
  EXPECT_EQ(temporaryOwner(".checkpoint.bin.tmp77.bin"), 77L);
  EXPECT_FALSE(temporaryOwner("snap_00000012.h5"));
  EXPECT_FALSE(temporaryOwner(".hvi.lock"));
  EXPECT_FALSE(temporaryOwner(".x.tmp"));
}

}  // namespace
}  // namespace hvi::io::test
