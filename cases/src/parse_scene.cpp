//! @file Scene files to Scene: the document, its top-level keys, effects, [time] and [domain];
//! loadScene and parseScene.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "detail/keys.hpp"
#include "detail/parse.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/cases/names.hpp"
#include "hvi/common/error.hpp"

namespace hvi::cases {
namespace detail {
namespace {

constexpr std::array<std::string_view, 1> kUnitSystems{"cm-g-us"};

void parseEffects(const TableReader& root, Scene& scene) {
  const toml::node* n = root.find("effects");
  if (n == nullptr) return;
  const auto names = allEffectNames();
  const auto& arr = readArray(root.ctx(), *n, "effects", 0, "[\"tension_cutoff\", ...]");
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string path = "effects[" + std::to_string(i) + "]";
    const std::string name = readString(root.ctx(), *arr.get(i), path);
    const auto e = effectFromString(name);
    if (!e) {
      std::string problem = "unknown effect \"" + name + "\"";
      if (auto near = closestKey(name, names); !near.empty())
        problem += " (did you mean \"" + std::string(near) + "\"?)";
      fail(root.ctx(), arr.get(i), path, problem, join(names));
    }
    if (!supports(scene.solver, *e)) {
      std::vector<std::string_view> ok;
      for (Effect s : supportedEffects(scene.solver)) ok.push_back(toString(s));
      fail(root.ctx(), arr.get(i), path,
           "effect \"" + name + "\" is not supported by solver \"" +
               std::string(toString(scene.solver)) + "\"",
           join(ok));
    }
    if (!scene.effects.insert(*e).second)
      fail(root.ctx(), arr.get(i), path, "effect \"" + name + "\" is listed twice",
           "each effect once");
  }
}

void parseTime(const TableReader& root, Scene& scene) {
  const auto t = root.subTable("time", true);
  t->rejectUnknown(keyNames("time"));
  readKeys(*t, timeKeys(), scene);
  t->check(scene.tEnd > scene.tStart, "end",
           "must be after time.start (" + shortNumber(scene.tStart) + " us)", "end > start");
}

void parseDomain(const TableReader& root, Scene& scene) {
  const auto d = root.subTable("domain", true);
  d->rejectUnknown(keyNames("domain"));
  Domain& dom = scene.domain;
  std::tie(dom.xmin, dom.xmax) =
      readInterval(root.ctx(), d->require("x", "[min, max] such as [\"0 cm\", \"1 cm\"]"),
                   d->keyPath("x"), Dimension::Length);
  std::tie(dom.zmin, dom.zmax) =
      readInterval(root.ctx(), d->require("z", "[min, max] such as [\"0 cm\", \"1 cm\"]"),
                   d->keyPath("z"), Dimension::Length);
  const bool rz = scene.geometry == Geometry::Axisymmetric;
  if (rz)
    d->check(dom.xmin == 0.0, "x",
             "in rz geometry x is the radius and the domain starts on the axis: x[0] must be 0",
             "x = [\"0 cm\", max]");
  dom.boundary = {rz ? Boundary::Axis : Boundary::Outflow, Boundary::Outflow, Boundary::Outflow,
                  Boundary::Outflow};
  const auto b = d->subTable("boundaries", false);
  if (!b) return;
  b->rejectUnknown(keyNames("domain.boundaries"));
  const auto sides = boundaryKeys();
  for (std::size_t side = 0; side < sides.size(); ++side) {
    const std::string_view key = sides[side].key;
    readKeys(*b, sides.subspan(side, 1), dom);  // each side checked before the next is read
    const bool axis = dom.boundary[side] == Boundary::Axis;
    if (rz && side == 0)
      b->check(axis, key, "in rz geometry the xmin boundary is the symmetry axis", "axis");
    else if (rz)
      b->check(!axis, key, "axis is allowed only at xmin in rz geometry", "outflow, wall");
    else
      b->check(!axis, key, "an axis boundary needs geometry = \"rz\"", "outflow, wall");
  }
}

Scene build(const toml::table& doc, const std::string& file) {
  Context ctx{file, false};
  const TableReader root(ctx, doc, "");
  root.rejectUnknown(keyNames("root"));
  if (root.has("units")) {
    (void)root.choice("units", kUnitSystems);
    ctx.bareNumbersAreInternal = true;
  }
  Scene scene;
  scene.path = file;
  scene.title = root.string("title", "");
  readKeys(root, rootKeys(), scene);  // geometry, solver
  parseEffects(root, scene);
  parseTime(root, scene);
  parseDomain(root, scene);
  parseMaterials(root, scene);
  Sources sources;
  parseBodies(root, scene, sources);
  parseSolverParams(root, scene);
  parseOutput(root, scene);
  validateScene(root, scene, sources);
  return scene;
}

}  // namespace
}  // namespace detail

Scene parseScene(std::string_view text, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  toml::table doc;
  try {
    doc = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    const auto& pos = e.source().begin;
    throw InputError(sourceName + ":" + std::to_string(pos.line) + ": syntax error: " +
                     std::string(e.description()) + " (column " + std::to_string(pos.column) + ")");
  }
  detail::applyOverrides(doc, overrides, sourceName);
  return detail::build(doc, sourceName);
}

namespace {

// Scene files are a few KiB (the largest shipped one is under 2 KiB); a polygon of 100 000
// vertices still fits in ~5 MiB. toml++ builds a node tree of several times the text, so 8 MiB
// keeps `hvi check` far below 1 GiB whatever it is given, instead of reading /dev/zero until the
// allocation fails.
constexpr off_t kMaxSceneBytes = 8 * 1024 * 1024;

std::string fileTypeName(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void refuseFile(const std::string& name, std::string_view kind,
                             const std::string& why) {
  throw InputError(name + ": " + why + "; allowed: a regular " + std::string(kind) +
                   " file (TOML) of at most " + std::to_string(kMaxSceneBytes / (1024 * 1024)) +
                   " MiB");
}

void checkFileStatus(const std::string& name, std::string_view kind, const struct stat& st) {
  if (!S_ISREG(st.st_mode)) refuseFile(name, kind, "is " + fileTypeName(st.st_mode));
  if (st.st_size > kMaxSceneBytes)
    refuseFile(name, kind,
               "is " + std::to_string(st.st_size) + " bytes, too large for a " + std::string(kind) +
                   " file");
}

}  // namespace

std::string readInputFile(const std::string& name, std::string_view kind) {
  const std::string what = std::string(kind) + " file";
  struct stat st {};
  if (::stat(name.c_str(), &st) != 0)
    throw InputError(name + ": cannot read the " + what + ": " + std::strerror(errno));
  checkFileStatus(name, kind, st);
  // O_NONBLOCK: should the path be swapped for a FIFO after the stat, the open still returns at
  // once and the fstat below refuses it.
  const int fd = ::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(name + ": cannot open the " + what + ": " + std::strerror(errno));
  std::string text;
  try {
    if (::fstat(fd, &st) != 0)
      throw InputError(name + ": cannot read the " + what + ": " + std::strerror(errno));
    checkFileStatus(name, kind, st);
    // Read at most one byte past the limit, so a file growing while it is read is refused too.
    char buf[65536];
    for (;;) {
      const ssize_t got = ::read(fd, buf, sizeof buf);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0)
        throw InputError(name + ": cannot read the " + what + ": " + std::strerror(errno));
      if (got == 0) break;
      text.append(buf, static_cast<std::size_t>(got));
      if (text.size() > static_cast<std::size_t>(kMaxSceneBytes))
        refuseFile(name, kind, "grew beyond the size limit while it was read");
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return text;
}

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return parseScene(readInputFile(file.string(), "scene"), file.string(), overrides);
}

}  // namespace hvi::cases
