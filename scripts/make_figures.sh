#!/usr/bin/env bash
# The figures of README.md and docs/sweeps.md (docs/figures/*.png), made again from the
# bundled inputs they show: runs each input into results/, draws its plots with
# scripts/plot_sweep.sh or scripts/plot_results.sh, and copies the figures shown:
#   tube_frequency_sweep_response.png   frequency response of the tube, up and down
#   rattling_bifurcation_bifurcation.png  bifurcation diagram of the forced rattling beam
#   frequency_gap_map_response.png      the 2-D map's lines, one colour and key entry per gap,
#                                       on the normalised axis Omega/omega_1 (--normalise)
#   frequency_gap_map_map.png           the 2-D map as colour, on the same axis
#   rattling_poincare_poincare.png      Poincare section of one run (rattling_poincare.nml)
#   random_rattling_forces_psd.png      target and measured density of random_rattling.nml's load
#   compliant_stop_branches_branches.png  three response curves continued through their folds,
#                                       the branches of a sweep of periodic analyses
# usage: bash scripts/make_figures.sh [BUILD_DIR]
#   BUILD_DIR: where vibrobeam is built (Release, default build/ of this repository);
#   about 2 minutes of two cores, most of it the four sweeps.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tree=${1:-$root/build}
# shellcheck source=build_release.sh
source "$root/scripts/build_release.sh"
build_release "$tree" vibrobeam
tree=$(cd "$tree" && pwd)
export VIBROBEAM=$tree/vibrobeam
cd "$root"

run() {  # run NAME: inputs/NAME.nml into results/NAME.h5
  echo "make_figures: running inputs/$1.nml"
  "$VIBROBEAM" "inputs/$1.nml" > /dev/null
}
run tube_frequency_sweep
bash scripts/plot_sweep.sh results/tube_frequency_sweep.h5
run rattling_bifurcation
bash scripts/plot_sweep.sh results/rattling_bifurcation.h5
run frequency_gap_map
bash scripts/plot_sweep.sh results/frequency_gap_map.h5 --normalise
run rattling_poincare
bash scripts/plot_results.sh results/rattling_poincare.h5
run random_rattling
bash scripts/plot_results.sh results/random_rattling.h5
run compliant_stop_branches
bash scripts/plot_sweep.sh results/compliant_stop_branches.h5

figures="tube_frequency_sweep_response rattling_bifurcation_bifurcation frequency_gap_map_response
         frequency_gap_map_map rattling_poincare_poincare random_rattling_forces_psd
         compliant_stop_branches_branches"
for figure in $figures; do
  cp "results/$figure.png" "docs/figures/$figure.png"
done
echo "make_figures: docs/figures/ holds the figures of these runs:" $figures
