#!/usr/bin/env bash
# The main job: install what is missing, build, run the default scene, draw its density.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
# Only the program: the test suite (tools/test.sh builds it) took most of a fresh build's 6 min.
cmake --build build -j"$(nproc)" --target hvi
# --overwrite: a second demo replaces the first one's results instead of being refused.
./build/bin/hvi run cases/scenes/default.toml --out out/default --overwrite
/usr/bin/python3 tools/plot_snapshot.py out/default --png out/default/density.png
echo "ParaView: open out/default/hvi.pvd; picture: out/default/density.png"
