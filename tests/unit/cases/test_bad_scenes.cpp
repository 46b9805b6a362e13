//! @file Every deliberately broken scene in tests/scenes/bad gives an InputError that names the
//! file, the line and the expected problem; nothing else escapes (no crash, no other exception).
#include <gtest/gtest.h>

#include "hvi/cases/load.hpp"
#include "hvi/common/error.hpp"
#include "hvi/test/scene_files.hpp"

namespace hvi::cases {
namespace {

// The header of a bad scene: "# expect: <fragment>", "# set: <override>", "# line: <n>".
struct Expectation {
  std::vector<std::string> fragments, overrides;
  int line = 0;  // 0: the error is in an override
};

Expectation readHeader(const std::string& text) {
  Expectation e;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l) && l.rfind("#", 0) == 0;) {
    if (l.rfind("# expect: ", 0) == 0) e.fragments.push_back(l.substr(10));
    if (l.rfind("# set: ", 0) == 0) e.overrides.push_back(l.substr(7));
    if (l.rfind("# line: ", 0) == 0 && l.find("none") == std::string::npos)
      e.line = std::stoi(l.substr(8));
  }
  return e;
}

TEST(SceneBadFiles, EachGivesALocatedInputError) {
  const auto files = test::tomlFiles(test::badDir());
  ASSERT_GE(files.size(), 20u);
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    const Expectation e = readHeader(test::readText(f));
    ASSERT_FALSE(e.fragments.empty()) << "a bad scene needs # expect: lines";
    ASSERT_TRUE(e.line > 0 || !e.overrides.empty()) << "a bad scene needs # line: or # set:";
    std::string msg;
    try {
      (void)loadScene(f, e.overrides);
      ADD_FAILURE() << "accepted";
      continue;
    } catch (const InputError& err) {
      msg = err.what();
    } catch (const std::exception& err) {
      ADD_FAILURE() << "not an InputError: " << err.what();
      continue;
    }
    if (e.line > 0)
      EXPECT_NE(msg.find(f.string() + ":" + std::to_string(e.line) + ": "), std::string::npos)
          << "expected " << f.filename() << ":" << e.line << " in: " << msg;
    else
      EXPECT_NE(msg.find(f.string() + " (--set "), std::string::npos) << msg;
    for (const auto& frag : e.fragments)
      EXPECT_NE(msg.find(frag), std::string::npos) << "missing \"" << frag << "\" in: " << msg;
  }
}

TEST(SceneBadFiles, MissingFileIsAnInputError) {
  EXPECT_THROW((void)loadScene(test::badDir() / "no_such_scene.toml"), InputError);
}

}  // namespace
}  // namespace hvi::cases
