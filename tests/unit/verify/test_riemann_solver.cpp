//! @file The exact Riemann solution behind the Solver interface (verify/src/riemann_solver.cpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "hvi/apps/driver.hpp"
#include "hvi/cases/load.hpp"
#include "hvi/common/stop_flag.hpp"
#include "hvi/verify/riemann_solver.hpp"

namespace hvi::app {
namespace {

// Sod's tube; `order` puts the dense left gas first or second in the file.
std::string sod(bool leftFirst) {
  const std::string left = R"(
[[bodies]]
name = "left"
material = "gas"
shape = "rect"
x = ["0 cm", "0.5 cm"]
z = ["0 cm", "0.02 cm"]
pressure = "1 Mbar"
)";
  const std::string right = R"(
[[bodies]]
name = "right"
material = "gas"
shape = "rect"
x = ["0.5 cm", "1 cm"]
z = ["0 cm", "0.02 cm"]
density = "0.125 g/cm^3"
pressure = "0.1 Mbar"
)";
  return R"(geometry = "planar"
solver = "riemann"
[time]
end = "0.2 us"
[domain]
x = ["0 cm", "1 cm"]
z = ["0 cm", "0.02 cm"]
[materials.gas]
eos = "ideal_gas"
gamma = 1.4
rho0 = "1 g/cm^3"
[riemann]
cells = 100
)" + (leftFirst ? left + right : right + left);
}

// Validation accepts the two bodies in either order; the solver must then still put each state
// where its body is (it used to take bodies[0] as the left state whatever its position).
TEST(RiemannSolver, BodiesInEitherOrderGiveTheSameSolution) {
  for (const double t : {0.0, 0.1}) {
    std::vector<std::vector<double>> rho;
    for (const bool leftFirst : {true, false}) {
      auto solver = verify::createRiemannSolver(cases::parseScene(sod(leftFirst), "sod.toml"));
      if (t > 0.0) (void)solver->advance(t);
      const Snapshot s = solver->snapshot();
      const Field* d = s.find("density");
      ASSERT_NE(d, nullptr);
      EXPECT_DOUBLE_EQ(d->data.front(), 1.0);    // far left: the undisturbed left state
      EXPECT_DOUBLE_EQ(d->data.back(), 0.125);   // far right: the right state
      rho.push_back(d->data);
    }
    EXPECT_EQ(rho[0], rho[1]) << "t = " << t;
  }
}

// A stop request while the solver is built (SPH fill or mass iteration, TVD grid, exact
// solution) ends `hvi run` with exit 130 and no checkpoint: nothing has been computed yet.
TEST(RiemannSolver, StopDuringSetUpExits130WithoutCheckpoint) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("hvi_setup_stop_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RunOptions o;
  o.scene = fs::path(HVI_SOURCE_DIR) / "cases" / "scenes" / "sod_x.toml";
  o.out = dir / "out";
  o.quiet = true;
  const int rc = runScene(o, [](const cases::Scene& scene) -> std::unique_ptr<Solver> {
    auto solver = verify::createRiemannSolver(scene);  // the real set-up, then the signal arrives
    requestStop();
    throwIfStopRequested("the test's set-up");
    return solver;
  });
  clearStop();
  EXPECT_EQ(rc, kInterrupted);
  EXPECT_FALSE(fs::exists(o.out / "checkpoint.bin"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hvi::app
