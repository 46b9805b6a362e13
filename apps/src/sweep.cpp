//! @file `hvi sweep` and `hvi ballistic-limit` (docs/shield.md).
#include "hvi/apps/sweep.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <map>

#include <fmt/format.h>

#include "case_runner.hpp"
#include "hvi/apps/driver.hpp"
#include "hvi/cases/names.hpp"
#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/common/stop_flag.hpp"
#include "hvi/shield/bisection.hpp"
#include "hvi/shield/ble.hpp"

namespace hvi::app {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json caseJson(const CaseOutcome& o) {
  json j = {{"id", o.id},
            {"solver", cases::toString(o.c.solver)},
            {"speed_km_s", o.c.speed},
            {"diameter_cm", o.c.diameter},
            {"status", o.status},
            {"perforated", o.perforated ? json(*o.perforated) : json(nullptr)},
            {"mode", o.verdict.is_null() ? json(nullptr) : o.verdict.value("mode", json(nullptr))},
            {"first_failure_time_us",
             o.verdict.is_null() ? json(nullptr) : o.verdict.value("first_time_us", json(nullptr))},
            {"wall_seconds", o.wallSeconds},
            {"reused", o.reused},
            {"run_folder", "runs/" + o.id}};
  if (o.c.standoff) j["standoff_cm"] = *o.c.standoff;
  if (o.c.rearWall) j["rear_wall_cm"] = *o.c.rearWall;
  if (o.c.bumper) j["bumper_cm"] = *o.c.bumper;
  return j;
}

std::string opt(const json& j, const char* key) {
  if (!j.contains(key) || j.at(key).is_null()) return "";
  const auto& v = j.at(key);
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_number()) return fmt::format("{:.6g}", v.get<double>());
  return v.get<std::string>();
}

std::string casesCsv(const json& runs) {
  std::string csv =
      "id,solver,speed_km_s,diameter_cm,standoff_cm,rear_wall_cm,bumper_cm,status,perforated,mode,"
      "first_failure_time_us,wall_seconds\n";
  for (const auto& r : runs)
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", opt(r, "id"), opt(r, "solver"),
                       opt(r, "speed_km_s"), opt(r, "diameter_cm"), opt(r, "standoff_cm"),
                       opt(r, "rear_wall_cm"), opt(r, "bumper_cm"), opt(r, "status"),
                       opt(r, "perforated"), opt(r, "mode"), opt(r, "first_failure_time_us"),
                       opt(r, "wall_seconds"));
  return csv;
}

json shieldJson(const shield::ShieldSpec& s) {
  json walls = json::array();
  for (const auto& w : s.walls)
    walls.push_back({{"name", w.name},
                     {"material", w.material.name},
                     {"thickness_cm", w.thickness},
                     {"gap_cm", w.gap}});
  return {{"file", s.path},           {"title", s.title},
          {"source", s.source},       {"projectile_material", s.projectile.material.name},
          {"walls", walls},           {"standoff_cm", s.standoff()},
          {"spacing_cm", s.spacing()}};
}

// A list of a sweep's values: every one finite and > 0.
void checkPositive(const char* option, const std::vector<double>& v, const char* unit) {
  for (double x : v)
    if (!(x > 0.0) || !std::isfinite(x))
      throw InputError(fmt::format("{} {}: allowed: values > 0 in {}", option, x, unit));
}

// Shared by both commands: parse, stop handlers, and errors to exit codes.
template <class F>
int guarded(const char* label, F&& body) {
  try {
    installStopHandlers();
    return body();
  } catch (const InputError& e) {
    fmt::print(stderr, "hvi {}: {}\n", label, e.what());
    return kBadInput;
  } catch (const OutputError& e) {
    fmt::print(stderr, "hvi {}: output could not be written: {}\n", label, e.what());
    return kOutputFailed;
  }
}

}  // namespace

int runSweep(const SweepOptions& o, const SweepGrid& g) {
  return guarded("sweep", [&] {
    checkPositive("--speed", g.speeds, "km/s");
    checkPositive("--diameter", g.diameters, "cm");
    checkPositive("--standoff", g.standoffs, "cm");
    checkPositive("--rear-wall", g.rearWalls, "cm");
    checkPositive("--bumper", g.bumpers, "cm");
    const shield::ShieldSpec base = shield::loadShield(o.shield);
    // The declared value where a list is empty.
    const auto orDeclared = [](const std::vector<double>& v) {
      return v.empty() ? std::vector<std::optional<double>>{std::nullopt}
                       : std::vector<std::optional<double>>(v.begin(), v.end());
    };
    std::vector<ShieldCase> all;
    const auto solvers = g.solvers.empty() ? std::vector{base.solver} : g.solvers;
    const auto speeds = g.speeds.empty() ? std::vector{base.projectile.speed} : g.speeds;
    const auto diameters =
        g.diameters.empty() ? std::vector{base.projectile.diameter} : g.diameters;
    for (auto s : solvers)
      for (double v : speeds)
        for (double d : diameters)
          for (auto S : orDeclared(g.standoffs))
            for (auto tw : orDeclared(g.rearWalls))
              for (auto tb : orDeclared(g.bumpers)) {
                ShieldCase c{s, v, d, S, tw, tb};
                (void)shield::buildScene(detail::applyCase(base, c));  // bad values stop here
                all.push_back(c);
              }
    detail::CaseRunner runner(base, o);
    std::map<std::string, CaseOutcome> done;
    const auto write = [&] {
      json runs = json::array();
      for (const auto& c : all)
        if (auto it = done.find(caseId(c)); it != done.end()) runs.push_back(caseJson(it->second));
      writeTextAtomically(
          o.out / "sweep.json",
          json{{"shield", shieldJson(base)}, {"cases", all.size()}, {"runs", runs}}.dump(1));
      writeTextAtomically(o.out / "sweep.csv", casesCsv(runs));
    };
    const int rc = detail::driveCases(
        runner,
        [&] {
          std::vector<ShieldCase> want;
          for (const auto& c : all)
            if (!done.count(caseId(c))) want.push_back(c);
          return want;
        },
        [&](const CaseOutcome& out) {
          done[out.id] = out;
          write();
        },
        [&] { return static_cast<int>(all.size() - done.size()); }, "sweep");
    write();
    if (!o.quiet)
      fmt::print(stderr, "hvi sweep: {} of {} cases in {}\n", done.size(), all.size(),
                 (o.out / "sweep.json").string());
    return rc;
  });
}

int runBallisticLimit(const SweepOptions& o, const BallisticLimitOptions& bl) {
  return guarded("ballistic-limit", [&] {
    shield::ShieldSpec base = shield::loadShield(o.shield);
    if (bl.solver) base.solver = *bl.solver;
    if (bl.speeds.empty()) throw InputError("--speed: give one or more speeds (km/s)");
    checkPositive("--speed", bl.speeds, "km/s");
    if (!(bl.tolerance > 0 && bl.tolerance < 1))
      throw InputError(fmt::format("--tolerance {}: allowed: 0 < tolerance < 1", bl.tolerance));
    std::optional<shield::WhippleBle> ble;
    if (base.walls.size() == 2) ble = shield::whippleBle(base);
    if (!ble && !(bl.dMin && bl.dMax))
      throw InputError(o.shield.string() +
                       ": not a two-wall shield, so no BLE to start from; "
                       "allowed: give --d-min and --d-max");
    struct Speed {
      double v;
      shield::CriticalDiameterSearch search;
      std::map<double, CaseOutcome> outcomes;
      std::string error;
    };
    std::vector<Speed> speeds;
    for (double v : bl.speeds) {
      const double dc = ble ? shield::criticalDiameter(*ble, v) : 0.0;
      const double lo = bl.dMin.value_or(0.5 * dc), hi = bl.dMax.value_or(2.0 * dc);
      if (!(hi > lo && lo > 0))
        throw InputError(
            fmt::format("--d-min {} / --d-max {}: allowed: 0 < d-min < d-max", lo, hi));
      speeds.push_back({v, shield::CriticalDiameterSearch(lo, hi, bl.tolerance), {}, {}});
    }
    const auto caseOf = [&](double v, double d) { return ShieldCase{base.solver, v, d, {}, {}, {}}; };
    detail::CaseRunner runner(base, o);

    const auto write = [&] {
      json points = json::array(), runs = json::array();
      std::string csv =
          "speed_km_s,critical_diameter_cm,survived_cm,failed_cm,bracketed,runs,ble_cm,ble_regime,"
          "note\n";
      for (const auto& s : speeds) {
        const auto est = s.search.estimate();
        const auto sv = s.search.survived(), fd = s.search.failed();
        const double bleDc = ble ? shield::criticalDiameter(*ble, s.v) : 0.0;
        const std::string note = s.error.empty() ? s.search.note() : s.error;
        points.push_back({{"speed_km_s", s.v},
                          {"critical_diameter_cm", est ? json(*est) : json(nullptr)},
                          {"survived_cm", sv ? json(*sv) : json(nullptr)},
                          {"failed_cm", fd ? json(*fd) : json(nullptr)},
                          {"bracketed", s.search.bracketed()},
                          {"done", s.search.done() || !s.error.empty()},
                          {"runs", s.outcomes.size()},
                          {"ble_cm", ble ? json(bleDc) : json(nullptr)},
                          {"note", note}});
        csv += fmt::format("{:.6g},{},{},{},{},{},{},{},\"{}\"\n", s.v,
                           est ? fmt::format("{:.6g}", *est) : "",
                           sv ? fmt::format("{:.6g}", *sv) : "",
                           fd ? fmt::format("{:.6g}", *fd) : "", s.search.bracketed() ? 1 : 0,
                           s.outcomes.size(), ble ? fmt::format("{:.6g}", bleDc) : "",
                           ble ? shield::toString(shield::bleRegime(*ble, s.v)) : "", note);
        for (const auto& [d, out] : s.outcomes) runs.push_back(caseJson(out));
      }
      json curve = json::array();
      if (ble)
        for (double v = 1.0; v <= 15.0 + 1e-9; v += 0.1)
          curve.push_back({v, shield::criticalDiameter(*ble, v)});
      json bleJson = nullptr;
      if (ble)
        bleJson = {{"name", "Whipple shield BLE (Christiansen 1993; NASA/TM-2009-214785)"},
                   {"units", "d_c cm, t cm, S cm, rho g/cm^3, V km/s, sigma ksi"},
                   {"projectile_density", ble->projectileDensity},
                   {"bumper_density", ble->bumperDensity},
                   {"bumper_thickness", ble->bumperThickness},
                   {"rear_wall_thickness", ble->rearWallThickness},
                   {"rear_wall_yield_ksi", ble->rearWallYieldKsi},
                   {"standoff", ble->standoff},
                   {"regimes_km_s", {shield::kBallisticLimitSpeed, shield::kHypervelocitySpeed}},
                   {"curve", curve}};
      writeTextAtomically(
          o.out / "ballistic_limit.json",
          json{{"shield", shieldJson(base)},
               {"solver", cases::toString(base.solver)},
               {"tolerance", bl.tolerance},
               {"tolerance_definition", "(failed - survived) <= tolerance * midpoint"},
               {"points", points},
               {"runs", runs},
               {"ble", bleJson}}
              .dump(1));
      writeTextAtomically(o.out / "ballistic_limit.csv", csv);
    };

    const int rc = detail::driveCases(
        runner,
        [&] {
          std::vector<ShieldCase> want;
          for (const auto& s : speeds)
            if (s.error.empty())
              for (double d : s.search.pending()) want.push_back(caseOf(s.v, d));
          return want;
        },
        [&](const CaseOutcome& out) {
          for (auto& s : speeds) {
            if (s.v != out.c.speed) continue;
            s.outcomes[out.c.diameter] = out;
            if (out.perforated)
              s.search.record(out.c.diameter, *out.perforated);
            else if (out.status != "interrupted")
              s.error = fmt::format(
                  "run {} ended '{}' without a rear-wall verdict (see runs/{}/hvi_run.log)", out.id,
                  out.status, out.id);
          }
          write();
        },
        [&] {
          int n = 0;
          for (const auto& s : speeds)
            if (s.error.empty()) n += s.search.remainingEstimate();
          return n;
        },
        "ballistic-limit");
    write();
    if (!o.quiet) {
      fmt::print(stderr,
                 "hvi ballistic-limit: {}\n  speed km/s   d_c cm (bracket)          BLE cm\n",
                 (o.out / "ballistic_limit.json").string());
      for (const auto& s : speeds) {
        const auto e = s.search.estimate();
        fmt::print(
            stderr, "  {:9.3g}   {:<26} {}\n", s.v,
            e ? fmt::format("{:.4g} [{:.4g}, {:.4g}]", *e, *s.search.survived(), *s.search.failed())
              : (s.error.empty() ? s.search.note() : s.error),
            ble ? fmt::format("{:.4g}", shield::criticalDiameter(*ble, s.v)) : "-");
      }
    }
    if (rc == kOk && !bl.plotScript.empty() && fs::exists(bl.plotScript) &&
        fs::exists("/usr/bin/python3")) {
      const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}'", bl.plotScript,
                                          (o.out / "ballistic_limit.json").string(),
                                          (o.out / "ballistic_limit.png").string());
      if (std::system(cmd.c_str()) != 0)
        fmt::print(stderr,
                   "hvi ballistic-limit: the plot failed (the JSON and CSV are written): {}\n",
                   cmd);
    }
    return rc;
  });
}

}  // namespace hvi::app
