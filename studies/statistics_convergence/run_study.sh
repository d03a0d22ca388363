#!/usr/bin/env bash
# Convergence of the steady-state statistics (docs/statistics.md) under refinement of dt
# and N, on two forced scenes (REPORT.md in this folder says what it shows).
#
#   studies/statistics_convergence/run_study.sh [BUILD_DIR] [JOBS]
#
# BUILD_DIR (default: build at the repository root) must hold a built `vibrobeam`;
# JOBS (default 2) single runs go at a time. The runs' result files go to runs/ here
# (not committed); runs.dat (one row per run), the tables convergence_*.txt and the
# plots convergence_*.png are rewritten. Run time: about 15 min of wall time with 2 jobs
# on 2 shared cores (34 runs, 1590 s of run wall time in all, measured under a load
# average of about 9); a run whose result file exists is not redone (delete runs/ to
# start over).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)   # absolute: the script works in its own folder
jobs=${2:-2}
exe=$build/vibrobeam
[[ -x $exe ]] || { echo "run_study.sh: no executable $exe (build first)" >&2; exit 1; }
cd "$here"
mkdir -p runs

# Every run: scene, path, N, dt, replicate (0: as given; 1: forcing amplitude x (1 + 1e-6)).
# Paths: joint (N doubles as dt halves), dt (dt alone at N = 16), N (N alone at
# dt = 5e-6 s), rep (a replicate at the same resolution: how far two runs differ that
# differ only by 1e-6 in the data). A run on two paths is run once.
runs_list() {
   local scene
   for scene in tube_1g forced_rattling; do
      echo "$scene joint 8 4e-5 0"
      echo "$scene joint 16 2e-5 0"
      echo "$scene joint 32 1e-5 0"
      echo "$scene joint 64 5e-6 0"
      echo "$scene joint 128 2.5e-6 0"
      echo "$scene dt 16 1.6e-4 0"
      echo "$scene dt 16 8e-5 0"
      echo "$scene dt 16 4e-5 0"
      echo "$scene dt 16 2e-5 0"
      echo "$scene dt 16 1e-5 0"
      echo "$scene dt 16 5e-6 0"
      echo "$scene dt 16 2.5e-6 0"
      echo "$scene N 4 5e-6 0"
      echo "$scene N 8 5e-6 0"
      echo "$scene N 16 5e-6 0"
      echo "$scene N 32 5e-6 0"
      echo "$scene N 64 5e-6 0"
      echo "$scene N 128 5e-6 0"
      echo "$scene rep 16 2e-5 1"
      echo "$scene rep 64 5e-6 1"
   done
}

# Forcing frequency (rad/s) and the perturbed amplitude line of each scene.
omega_of() { case $1 in tube_1g) echo 208.06 ;; forced_rattling) echo 200.0 ;; esac; }
perturb_of() {
   case $1 in
   tube_1g) echo 's/base_acceleration = 9.81,/base_acceleration = 9.81000981,/' ;;
   forced_rattling) echo 's/point_force = 20.0,/point_force = 20.00002,/' ;;
   esac
}
settle_periods=40
measure_periods=160

run_one() {   # scene N dt replicate
   local scene=$1 n=$2 dt=$3 rep=$4 name omega t_end from
   name=${scene}_N${n}_dt${dt}_r${rep}
   [[ -s runs/$name.h5 ]] && return 0
   omega=$(omega_of "$scene")
   t_end=$(awk -v w="$omega" -v p=$((settle_periods + measure_periods)) 'BEGIN{printf "%.9g", p*2*atan2(0,-1)/w}')
   from=$(awk -v w="$omega" -v p=$settle_periods 'BEGIN{printf "%.9g", p*2*atan2(0,-1)/w}')
   sed -E -e "s/elements = [0-9]+/elements = $n/" -e "s/dt = [0-9.e-]+,/dt = $dt,/" \
       -e "s/t_end = [0-9.e-]+/t_end = $t_end/" -e "s/measure_from = [0-9.e-]+/measure_from = $from/" \
       -e "s|file = '[^']*'|file = 'runs/$name.h5'|" "$scene.nml" > "runs/$name.nml"
   [[ $rep == 1 ]] && sed -i -e "$(perturb_of "$scene")" "runs/$name.nml"
   "$exe" --check "runs/$name.nml" > "runs/$name.check"
   "$exe" "runs/$name.nml" > "runs/$name.log" 2>&1
}
export -f run_one omega_of perturb_of
export exe settle_periods measure_periods

start=$(date +%s)
# The longest runs first (cost ~ steps x (20 + N)), so that the workers finish together.
runs_list | awk '{print $1, $3, $4, $5}' | sort -u | awk '{printf "%.6g %s\n", (20 + $2)/$3, $0}' |
   sort -g -r | cut -d' ' -f2- |
   xargs -P "$jobs" -L 1 bash -c 'run_one "$@"' _
echo "runs: $(( $(date +%s) - start )) s wall"

# One row per (scene, path, N, dt, replicate): the statistics of the tip, the beam and the
# energy, each with its batch-means standard error, read with h5dump (17 significant digits).
stats="points/displacement_rms points/velocity_rms beam/impact_rate beam/episode_rate
beam/episode_impulse_mean beam/episode_impulse_max beam/contact_fraction beam/contact_force
energy/power_input energy/power_impacts energy/power_damping energy/power_dissipated"
read_value() {   # file dataset -> first element
   h5dump -m %.17g -A 0 -d "$2" "$1" | awk '/DATA \{/{getline; sub(/^[^:]*: */, ""); sub(/,.*/, ""); print; exit}'
}
{
   printf '# scene path N dt rep omega_max omega_max_dt steps_per_forcing_period impacts'
   for s in $stats; do printf ' %s %s_error' "${s#*/}" "${s#*/}"; done
   printf ' peak_frequency bin_width\n'
   runs_list | while read -r scene path n dt rep; do
      f=runs/${scene}_N${n}_dt${dt}_r${rep}
      omega_max=$(sed -nE 's/.*omega_max = ([0-9.e+-]+) rad\/s.*/\1/p' "$f.check" | head -1)
      impacts=$(sed -nE 's/.*steps, ([0-9]+) impacts.*/\1/p' "$f.log")
      awk -v s="$scene" -v p="$path" -v n="$n" -v dt="$dt" -v r="$rep" -v om="$omega_max" \
          -v w="$(omega_of "$scene")" -v i="$impacts" \
          'BEGIN{printf "%s %s %d %s %d %s %.4g %.1f %s", s, p, n, dt, r, om, om*dt, 2*atan2(0,-1)/(w*dt), i}'
      for s in $stats; do
         printf ' %s %s' "$(read_value "$f.h5" "/statistics/$s")" "$(read_value "$f.h5" "/statistics/${s}_error")"
      done
      printf ' %s %s\n' "$(read_value "$f.h5" /statistics/spectrum/peak_frequency)" \
         "$(h5dump -m %.17g -a /statistics/spectrum/bin_width "$f.h5" | awk '/\(0\)/{sub(/^[^:]*: */, ""); print; exit}')"
   done
} > runs.dat

bash "$here/tables.sh" runs.dat
gnuplot "$here/plots.gp"
echo "total: $(( $(date +%s) - start )) s wall"
