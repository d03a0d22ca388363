#!/usr/bin/env bash
# The first command of README.md: install what is missing, build (Release), run the
# bundled default scene and draw its plots.
#   results/default.h5, results/default_*.dat, results/default_*.png
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
./build/vibrobeam inputs/default.nml
bash scripts/plot_results.sh results/default.h5
