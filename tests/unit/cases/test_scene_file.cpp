//! @file The scene loader refuses what is not a regular file of sane size (issue 11, item 5):
//! a FIFO must not block, /dev/zero must not be read until memory runs out.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>

#include "hvi/cases/doc_tables.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"

namespace hvi::cases {
namespace {
namespace fs = std::filesystem;

//! The InputError message of loadScene(path), or "" (with a test failure) if it accepted the file
//! or threw something else.
std::string refusal(const fs::path& path) {
  try {
    (void)loadScene(path);
    ADD_FAILURE() << path << " accepted";
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << ": not an InputError: " << e.what();
  }
  return "";
}

fs::path tempDir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("hvi_scene_file_" + tag + "_" +
                                                  std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(SceneFile, FifoIsRefusedWithoutBlocking) {
  const fs::path dir = tempDir("fifo");
  const fs::path fifo = dir / "scene.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto job = std::async(std::launch::async, [&] { return refusal(fifo); });
  // A guard against a hang, not a timing assertion: if the loader blocks on the FIFO, a writer
  // that opens and closes it releases the reader so the test fails instead of hanging.
  if (job.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    ADD_FAILURE() << "loadScene blocked on a FIFO";
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  }
  const std::string msg = job.get();
  EXPECT_NE(msg.find(fifo.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("FIFO"), std::string::npos) << msg;
  EXPECT_NE(msg.find("regular scene file"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(SceneFile, DevZeroAndDevUrandomAreRefused) {
  for (const char* dev : {"/dev/zero", "/dev/urandom", "/dev/null"}) {
    if (!fs::exists(dev)) continue;
    const std::string msg = refusal(dev);
    EXPECT_NE(msg.find(dev), std::string::npos) << msg;
    EXPECT_NE(msg.find("character device"), std::string::npos) << msg;
  }
}

TEST(SceneFile, DirectoryIsRefused) {
  const fs::path dir = tempDir("dir");
  const std::string msg = refusal(dir);
  EXPECT_NE(msg.find("directory"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(SceneFile, OversizedFileIsRefusedBeforeParsing) {
  const fs::path dir = tempDir("big");
  const fs::path big = dir / "big.toml";
  {
    std::ofstream out(big, std::ios::binary);
    out << "# a comment line\n";
  }
  // A sparse file: 9 MiB long without writing 9 MiB.
  fs::resize_file(big, 9u * 1024 * 1024);
  const std::string msg = refusal(big);
  EXPECT_NE(msg.find("too large"), std::string::npos) << msg;
  EXPECT_NE(msg.find("8 MiB"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(SceneFile, MissingFileNamesTheFileAndTheCause) {
  const std::string msg = refusal(test::badDir() / "no_such_scene.toml");
  EXPECT_NE(msg.find("no_such_scene.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("No such file"), std::string::npos) << msg;
}

TEST(SceneFile, SymlinkToARegularSceneIsRead) {
  const fs::path dir = tempDir("link");
  const fs::path link = dir / "link.toml";
  fs::create_symlink(test::shippedDir() / "sod_x.toml", link);
  EXPECT_NO_THROW((void)loadScene(link));
  fs::remove_all(dir);
}

// docs/scenes.md shows the tables the parser runs on, verbatim: a key or effect added to a
// table fails here until the document shows it (the message is the table to paste).
TEST(SceneDocs, TablesMatchTheParser) {
  const std::string doc = test::readText(fs::path(HVI_SOURCE_DIR) / "docs" / "scenes.md");
  const std::string effects = effectTableMarkdown();
  EXPECT_NE(doc.find(effects), std::string::npos) << "docs/scenes.md lacks:\n" << effects;
  for (const std::string& keys :
       {keyTableMarkdown({"root"}), keyTableMarkdown({"time"}), keyTableMarkdown({"domain"}),
        keyTableMarkdown({"materials"}), keyTableMarkdown({"materials.tillotson"}),
        keyTableMarkdown({"materials.ideal_gas"}), keyTableMarkdown({"materials.mie_gruneisen"}),
        keyTableMarkdown({"materials.strength"}), keyTableMarkdown({"bodies"}), keyTableMarkdown({"sph", "tvd", "riemann"}),
        keyTableMarkdown({"output"})})
    EXPECT_NE(doc.find(keys), std::string::npos) << "docs/scenes.md lacks:\n" << keys;
}

}  // namespace
}  // namespace hvi::cases
