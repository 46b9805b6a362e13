// Steps a small Sod tube with the installed TVD and SPH solvers and the exact solution, and
// writes a checkpoint: every solver library and io link from outside the build tree.
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "hvi/cases/load.hpp"
#include "hvi/common/binary.hpp"
#include "hvi/io/checkpoint.hpp"
#include "hvi/sph/sph.hpp"
#include "hvi/tvd/tvd.hpp"
#include "hvi/verify/riemann_solver.hpp"

int main(int argc, char** argv) {
  const char* text = R"(geometry = "planar"
solver = "tvd"
[time]
end = "0.01 us"
[domain]
x = ["0 cm", "1 cm"]
z = ["0 cm", "0.04 cm"]
boundaries = { xmin = "wall", xmax = "wall", zmin = "wall", zmax = "wall" }
[materials.gas]
eos = "ideal_gas"
gamma = 1.4
rho0 = "1 g/cm^3"
[[bodies]]
name = "left"
material = "gas"
shape = "rect"
x = ["0 cm", "0.5 cm"]
z = ["0 cm", "0.04 cm"]
pressure = "1 Mbar"
[[bodies]]
name = "right"
material = "gas"
shape = "rect"
x = ["0.5 cm", "1 cm"]
z = ["0 cm", "0.04 cm"]
density = "0.125 g/cm^3"
pressure = "0.1 Mbar"
[riemann]
cells = 50
interface = "0.5 cm"
[sph]
spacing = "0.02 cm"
[tvd]
cell_size = "0.02 cm"
)";
  hvi::cases::Scene scene = hvi::cases::parseScene(text, "consumer.toml");
  auto tvd = hvi::tvd::createSolver(scene);
  tvd->advance(scene.tEnd);
  scene.solver = hvi::cases::SolverKind::Sph;
  auto sph = hvi::sph::createSolver(scene);
  sph->advance(scene.tEnd);
  scene.solver = hvi::cases::SolverKind::Riemann;
  auto exact = hvi::verify::createRiemannSolver(scene);
  exact->advance(scene.tEnd);

  const auto file = std::filesystem::path(argc > 1 ? argv[1] : ".") / "consumer.ckpt";
  hvi::io::writeCheckpointFile(file, "consumer", [&](std::ostream& out) {
    hvi::BinaryWriter(out, "consumer").value(tvd->time());
  });
  double t = 0.0;
  hvi::io::readCheckpointFile(file, [&](std::istream& in) {
    t = hvi::BinaryReader(in, "consumer").value<double>();
  });
  std::printf("mass: tvd %.6g, sph %.6g, exact %.6g; checkpoint time %g us\n",
              tvd->totals().mass, sph->totals().mass, exact->totals().mass, t);
  return t == tvd->time() && tvd->totals().mass > 0.0 && sph->totals().mass > 0.0 ? 0 : 1;
}
