#!/usr/bin/env bash
# The main job: install what is missing, build, run the default scene, draw its density.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
./build/bin/hvi run cases/scenes/default.toml --out out/default
/usr/bin/python3 tools/plot_snapshot.py out/default --png out/default/density.png
echo "ParaView: open out/default/hvi.pvd; picture: out/default/density.png"
