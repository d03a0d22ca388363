#!/usr/bin/env bash
# The cost of the loads of &forces against what they replace (studies/forces_cost/REPORT.md):
# the vibrobeam executable on pairs of generated scenes that differ only in how the load is
# given, run in turn (A B A B ...) so that a drift of the machine's speed hits both, each
# pair RUNS times; the medians of the processor times (user + system: on a shared machine
# they move less than the wall-clock times, which are printed too) and of the ratios A/B,
# per step, set-up and writing included.
#   (1) a point force at the tip, N = 1024, 20000 steps: &forces against &load;
#   (2) a uniform load over the whole beam, N = 1024: &forces against &load;
#   (3) the hard case of many loads: 64 harmonic point forces of &forces against one
#       point force of &load, N = 1024;
#   (4) the same scenes at N = 16 (the loads a larger share of a cheap step);
#   (5) a table signal read from a record of 10^6 lines against the harmonic it samples
#       (the reading, then an O(1) search per step), N = 16, 200000 steps;
#   (6) a random point force (one-sided density over 5..300 Hz: 2^15 filter taps at
#       dt = 1e-5 s) against a harmonic one, N = 16 and 1024;
#   (7) a random distributed load with spatial coherence over the whole beam (N + 1 field
#       points) against a harmonic uniform load, N = 64;
#   (8) memory: the peak resident size of the random scenes of (6) and (7) run 10 times
#       longer (it must not grow with the run's length).
# Writes studies/forces_cost/forces_cost.txt. Builds Release in BUILD_DIR (default build).
#   usage: studies/forces_cost/forces_cost.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
runs=${2:-7}
table=studies/forces_cost/forces_cost.txt
source scripts/build_release.sh
build_release "$build" vibrobeam
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# scene NAME ELEMENTS STEPS LOAD_GROUPS: a steel cantilever without obstacles, dt = 1e-5 s
scene() {
  cat > "$work/$1.nml" <<NML
&beam   length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
        inertia = 1.6666666666666667e-9, rayleigh_mass = 2.0 /
&mesh   elements = $2 /
&time   t_end = $(awk -v n="$3" 'BEGIN { printf "%.6f", n * 1e-5 }'), dt = 1e-5 /
$4
&output file = '$work/$1.h5', every = 1000000, text = .false. /
NML
}
many_forces() {
  local i text="&forces count = 64"
  for i in $(seq 1 64); do
    text="$text, position($i) = $(awk -v i="$i" 'BEGIN { printf "%.6f", 0.5 * i / 64 }'), amplitude($i) = 0.3, frequency($i) = $((100 + i))"
  done
  echo "$text /"
}
# time_pair LABEL A B STEPS: RUNS alternating runs of scenes A and B
time_pair() {
  local label=$1 a=$2 b=$3 steps=$4 k ta tb
  : > "$work/a.txt"; : > "$work/b.txt"; : > "$work/r.txt"
  for k in $(seq 1 "$runs"); do
    for side in a b; do
      local name=$a; [ $side = b ] && name=$b
      /usr/bin/time -f "%U %S %e" -o "$work/t.txt" "$build/vibrobeam" "$work/$name.nml" > /dev/null 2>&1 ||
        { echo "forces_cost: $name failed" >&2; exit 1; }
      awk '{ print $1 + $2 }' "$work/t.txt" >> "$work/$side.txt"
      awk '{ print $3 }' "$work/t.txt" >> "$work/${side}_wall.txt"
    done
    ta=$(tail -1 "$work/a.txt"); tb=$(tail -1 "$work/b.txt")
    awk -v a="$ta" -v b="$tb" 'BEGIN { printf "%.4f\n", a / b }' >> "$work/r.txt"
  done
  median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
  per_step() { awk -v t="$(median "$1")" -v n="$steps" 'BEGIN { printf "%.2f", 1e6 * t / n }'; }
  printf '%-54s %9s %9s %7.3f  (A/B %s-%s; wall A %s, B %s)\n' "$label" "$(per_step "$work/a.txt")" \
    "$(per_step "$work/b.txt")" "$(median "$work/r.txt")" "$(sort -g "$work/r.txt" | head -1)" \
    "$(sort -g "$work/r.txt" | tail -1)" "$(per_step "$work/a_wall.txt")" "$(per_step "$work/b_wall.txt")"
  rm -f "$work/a_wall.txt" "$work/b_wall.txt"
}

for n in 1024 16; do
  steps=20000; [ $n = 16 ] && steps=200000
  scene "load_point_$n" $n $steps "&load point_force = 0.3, point_frequency = 100.0 /"
  scene "forces_point_$n" $n $steps "&forces count = 1, amplitude(1) = 0.3, frequency(1) = 100.0 /"
  scene "load_uniform_$n" $n $steps "&load distributed = 0.3, distributed_frequency = 100.0 /"
  scene "forces_uniform_$n" $n $steps "&forces count = 1, kind(1) = 'distributed', amplitude(1) = 0.3, frequency(1) = 100.0 /"
  scene "forces_many_$n" $n $steps "$(many_forces)"
done
# a record of 10^6 samples every 2e-6 s (2 s) of 0.3 cos(100 t), and the harmonic itself
awk 'BEGIN { for (k = 0; k < 1000000; k++) printf "%.7e %.16e\n", k * 2e-6, 0.3 * cos(100 * k * 2e-6) }' > "$work/record.dat"
scene "forces_table_16" 16 200000 "&forces count = 1, signal(1) = 'table', table(1) = 'record.dat' /"
random_point="&forces count = 1, signal(1) = 'random', psd_level(1) = 0.01, band_from(1) = 5.0, band_to(1) = 300.0 /"
random_field="&forces count = 1, kind(1) = 'distributed', signal(1) = 'random', psd_level(1) = 0.01, band_from(1) = 5.0,
        band_to(1) = 300.0, correlation_length(1) = 0.05 /"
scene "random_point_16" 16 200000 "$random_point"
scene "random_point_1024" 1024 20000 "$random_point"
scene "random_field_64" 64 100000 "$random_field"
scene "forces_uniform_64" 64 100000 "&forces count = 1, kind(1) = 'distributed', amplitude(1) = 0.1, frequency(1) = 100.0 /"
scene "random_point_16_long" 16 2000000 "$random_point"
scene "random_field_64_long" 64 1000000 "$random_field"
# peak NAME: the peak resident size (kB) of one run
peak() {
  /usr/bin/time -f "%M" -o "$work/m.txt" "$build/vibrobeam" "$work/$1.nml" > /dev/null 2>&1 ||
    { echo "forces_cost: $1 failed" >&2; exit 1; }
  cat "$work/m.txt"
}

{
  echo "# forces_cost.sh: processor microseconds per step (user + system, whole executable, set-up and writing"
  echo "# included), medians of $runs runs of each scene run in turn, the median of the $runs ratios A/B (their"
  echo "# range) and the median wall-clock microseconds per step"
  echo "# $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load average before $(cut -d' ' -f1-3 /proc/loadavg)"
  printf '%-54s %9s %9s %7s\n' "# case (A against B)" "A us/step" "B us/step" "A/B"
  for n in 1024 16; do
    steps=20000; [ $n = 16 ] && steps=200000
    time_pair "point force, N = $n: &forces / &load" "forces_point_$n" "load_point_$n" $steps
    time_pair "uniform load, N = $n: &forces / &load" "forces_uniform_$n" "load_uniform_$n" $steps
    time_pair "64 point forces of &forces / 1 of &load, N = $n" "forces_many_$n" "load_point_$n" $steps
  done
  time_pair "table of 1e6 lines / harmonic, N = 16" "forces_table_16" "forces_point_16" 200000
  time_pair "random point force / harmonic, N = 16" "random_point_16" "forces_point_16" 200000
  time_pair "random point force / harmonic, N = 1024" "random_point_1024" "forces_point_1024" 20000
  time_pair "random coherent field (65 points) / uniform, N = 64" "random_field_64" "forces_uniform_64" 100000
  echo "# peak resident size (kB): random point force, N = 16, 2e5 and 2e6 steps:" \
    "$(peak random_point_16) $(peak random_point_16_long);" \
    "random field, N = 64, 1e5 and 1e6 steps: $(peak random_field_64) $(peak random_field_64_long)"
} | tee "$table"
