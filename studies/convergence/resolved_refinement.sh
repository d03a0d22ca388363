#!/usr/bin/env bash
# Refinement of the two-stop looseness scene with time steps that resolve the mesh: the
# follow-up of studies/convergence/convergence_study.sh (studies/convergence/REPORT.md, section
# "Resolved time steps"). Every run is the bundled scene inputs/looseness_tip_stops.nml
# with only `elements`, `dt`, `t_end`, `restitution`, `scheme`, `velocity_amplitude` and
# the output file and interval changed, run by the vibrobeam executable itself; the
# comparisons use its _tip.dat, _energy.dat and _impacts.dat files.
#
# Studies (window [0, 25 ms], tip history sampled every 1e-5 s, or every step when dt is
# larger):
#   A. N = 8 fixed, dt = 2e-6 ... 6.25e-8 s against dt = 3.125e-8 s (omega_max dt from
#      0.46 down to 0.007), for e = 0.8 (the scene), e = 1 and e = 0;
#   B. joint path dt = dt0/2^k, N = nint(16 2^(k/2)), dt0 = 5e-7 s (omega_max dt = 0.46
#      at every level), against the reference (dt0/16, 4 N0) = (3.125e-8 s, 64), e = 0.8
#      and e = 1;
#   C. the energy lost by T = 25 ms for N = 8 ... 128 with omega_max dt = 0.06, e = 0.8, 0
#      and 1: how much the impacts dissipate as the mesh is refined (e = 0.8: the mean of
#      five runs with the initial velocity changed by up to 1e-3, as the loss jumps);
#   D. the position scheme (SPEC §4) on four joint paths (dt0, N0), reference (dt0/16, 4 N0);
#   E. the sensitivity to the data: the initial velocity perturbed by a relative 1e-10 ... 1e-5.
# (D and E are printed before C, which holds the longest runs.)
#
# usage: studies/convergence/resolved_refinement.sh [BUILD_DIR]   (default: build, relative to the repository
#        root like the other scripts; about 10 min on 2 cores,
#        of which 6 min for the two runs at N = 128)
#        studies/convergence/resolved_refinement.sh --plot-only     (redraws the figure from the table)
# writes studies/convergence/resolved_refinement.txt and resolved_refinement_dissipation.png
# needs: cmake, a Fortran compiler, the project's libraries, awk, gnuplot (pngcairo terminal)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
scene=inputs/looseness_tip_stops.nml
table=studies/convergence/resolved_refinement.txt
figure=studies/convergence/resolved_refinement_dissipation.png
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# plot_dissipation: the figure of study C, drawn from the table
plot_dissipation() {
  awk '/^## C\./ { inside = 1; next } /^##/ { inside = 0 } inside && $1 ~ /^[0-9]+$/' "$table" > "$work/c.dat"
  gnuplot <<EOF
set terminal pngcairo size 900,600 font ',10' noenhanced
set output '$figure'
set title "Energy lost at the stops by t = 25 ms, inputs/looseness_tip_stops.nml, omega_max dt = 0.057\n(e = 0.8: mean of 5 runs with v0 changed by up to 1e-3, bars: smallest and largest; N = 128: one run)"
set logscale x 2
set xrange [6:170]
set yrange [-0.01:0.35]
set xlabel 'N (elements)'
set ylabel '1 - E(T)/E(0)'
set grid
set key top right box opaque
plot '$work/c.dat' using (\$3 == 0.8 ? \$1 : 1/0):5:6:7 with yerrorlines pt 7 title 'e = 0.8', \
     ''            using (\$3 == 0 ? \$1*1.04 : 1/0):5 with linespoints pt 5 title 'e = 0 (one run each)', \
     ''            using (\$3 == 1 ? \$1 : 1/0):5 with linespoints pt 6 title 'e = 1 (conserves energy)'
EOF
}

if [ "$build" = --plot-only ]; then
  plot_dissipation
  echo "resolved_refinement: wrote $figure from $table"
  exit 0
fi

source scripts/build_release.sh
build_release "$build" vibrobeam
program=$build/vibrobeam
window=0.025

# run NAME N DT E [SCHEME [V0]]: the scene with N elements, time step DT, restitution E,
# the time scheme SCHEME (default: the scene's, 'velocity') and the initial tip velocity
# V0 (default: the scene's, 0.5 m/s), over [0, window]
run() {
  local name=$1 elements=$2 dt=$3 restitution=$4 scheme=${5:-velocity} amplitude=${6:-0.5}
  local every
  every=$(awk -v dt="$dt" 'BEGIN { k = int(1e-5/dt + 0.5); print (k < 1 ? 1 : k) }')
  sed -e "s/elements = [0-9]*/elements = $elements/" \
      -e "s/restitution = [0-9.]*/restitution = $restitution/" \
      -e "s/t_end = [0-9.eE+-]*, dt = [0-9.eE+-]*/t_end = $window, dt = $dt, scheme = '$scheme'/" \
      -e "s|file = '[^']*', every = [0-9]*|file = '$work/$name.h5', every = $every|" \
      -e "s/velocity_amplitude = 0.5 /velocity_amplitude = $amplitude /" \
      "$scene" > "$work/$name.nml"
  # every value must appear exactly as set (followed by a delimiter), or the run would
  # silently use the scene's own value
  for value in "elements = $elements /" "restitution = $restitution /" \
               "t_end = $window, dt = $dt, scheme = '$scheme' /" "file = '$work/$name.h5'" \
               "velocity_amplitude = $amplitude /"; do
    grep -qF -- "$value" "$work/$name.nml" || { echo "resolved_refinement: could not set '$value'" >&2; exit 1; }
  done
  "$program" "$work/$name.nml" > "$work/$name.log" 2>&1 || { cat "$work/$name.log" >&2; exit 1; }
}

# tip_errors RUN REFERENCE: max |u_tip - u_tip,ref| over [0, T] for T = 2.5, 5, 12, 25 ms,
# at the output times of RUN (each of them must be an output time of REFERENCE)
tip_errors() {
  awk '
    /^#/ || NF < 4 { next }
    FNR == NR { ref[sprintf("%.9f", $1)] = $2; next }
    {
      key = sprintf("%.9f", $1)
      if (!(key in ref)) { print "tip_errors: no reference value at t = " $1 > "/dev/stderr"; failed = 1; exit 1 }
      d = $2 - ref[key]; if (d < 0) d = -d
      if ($1 <= 0.0025 + 1e-12 && d > a) a = d
      if ($1 <= 0.005 + 1e-12 && d > b) b = d
      if ($1 <= 0.012 + 1e-12 && d > c) c = d
      if (d > e) e = d
    }
    END { if (!failed) printf "%10.2e %10.2e %10.2e %10.2e", a, b, c, e }' "$work/$2_tip.dat" "$work/$1_tip.dat"
}

# summarize RUN: sets run_events (impact events: impulses on one side less than 0.5 ms apart
# count once), run_impulses (impulses), run_energy (kinetic + elastic energy at the last
# output time, J) and run_loss (1 - run_energy/E(0)); stops the script if the run left no
# results
summarize() {
  local impacts=$work/$1_impacts.dat energies=$work/$1_energy.dat
  if [ ! -f "$impacts" ] || [ ! -f "$energies" ]; then
    echo "resolved_refinement: run $1 left no results" >&2
    exit 1
  fi
  run_events=$(awk '
    !/^#/ && NF >= 5 { side = ($3 > 0) ? 1 : -1
                       if (n == 0 || $1 - last > 5e-4 || side != lastside) n++
                       last = $1; lastside = side }
    END { print n + 0 }' "$impacts")
  run_impulses=$(awk '!/^#/ && NF >= 5 { n++ } END { print n + 0 }' "$impacts")
  run_energy=$(awk '!/^#/ && NF > 2 { e = $2 + $3 } END { printf "%.6e", e }' "$energies")
  run_loss=$(awk '!/^#/ && NF > 2 { e = $2 + $3; if (!started) { e0 = e; started = 1 } }
                  END { printf "%.4f", 1 - e/e0 }' "$energies")
}

start=$(date +%s)
{
echo "# Resolved refinement of $scene over [0, $window s] (studies/convergence/resolved_refinement.sh)"
echo "# tip errors: max over the output times (every 1e-5 s) in [0, T] of |u_tip - u_tip,ref| (m)"
echo "# omega_max = 2.2886e5 (N/8)^2 rad/s (the largest eigenvalue of the Hermite pencil, N = 8)"
echo
echo "## A. N = 8, dt alone, against dt = 3.125e-8 s"
for e in 0.8 1 0; do
  run a_ref_$e 8 3.125e-8 $e
  summarize a_ref_$e
  echo "# e = $e; reference: $run_events events, $run_impulses impulses, E(T) = $run_energy J"
  printf "%10s %10s %10s %10s %10s %10s %7s %13s\n" dt omega_dt "T=2.5ms" "T=5ms" "T=12ms" "T=25ms" events "E(T) (J)"
  for dt in 2e-6 1e-6 5e-7 2.5e-7 1.25e-7 6.25e-8; do
    run a_$e 8 $dt $e
    errors=$(tip_errors a_$e a_ref_$e)
    summarize a_$e
    printf "%10s %10.3f %s %7s %13s\n" $dt "$(awk -v dt=$dt 'BEGIN { print 2.2886e5*dt }')" \
      "$errors" "$run_events" "$run_energy"
  done
  echo
done

echo "## B. joint path dt = 5e-7/2^k, N = nint(16 2^(k/2)) (omega_max dt = 0.46), reference (3.125e-8 s, 64)"
for e in 0.8 1; do
  run b_ref_$e 64 3.125e-8 $e
  summarize b_ref_$e
  echo "# e = $e; reference: $run_events events, $run_impulses impulses, E(T) = $run_energy J"
  printf "%3s %10s %4s %10s %10s %10s %10s %7s %9s %13s\n" k dt N "T=2.5ms" "T=5ms" "T=12ms" "T=25ms" events impulses "E(T) (J)"
  for k in 0 1 2 3; do
    elements=$(awk -v k=$k 'BEGIN { printf "%d", 16*2^(k/2) + 0.5 }')
    dt=$(awk -v k=$k 'BEGIN { printf "%.10g", 5e-7/2^k }')
    run b_$e $elements $dt $e
    errors=$(tip_errors b_$e b_ref_$e)
    summarize b_$e
    printf "%3d %10s %4d %s %7s %9s %13s\n" $k $dt $elements "$errors" \
      "$run_events" "$run_impulses" "$run_energy"
  done
  echo
done

echo "## D. the position scheme (SPEC §4) on joint paths dt = dt0/2^k, N = nint(N0 2^(k/2)), reference (dt0/16, 4 N0), e = 0.8"
for path in "2e-5 16" "4e-5 16" "1e-5 16" "1e-5 32"; do
  set -- $path
  dt0=$1; n0=$2
  run d_ref $((4*n0)) "$(awk -v d=$dt0 'BEGIN { printf "%.10g", d/16 }')" 0.8 position
  summarize d_ref
  echo "# dt0 = $dt0 s, N0 = $n0; reference: $run_events events, $run_impulses impulses"
  printf "%3s %10s %4s %10s %10s %10s %10s %7s\n" k dt N "T=2.5ms" "T=5ms" "T=12ms" "T=25ms" events
  for k in 0 1 2 3; do
    elements=$(awk -v k=$k -v n=$n0 'BEGIN { printf "%d", n*2^(k/2) + 0.5 }')
    dt=$(awk -v k=$k -v d=$dt0 'BEGIN { printf "%.10g", d/2^k }')
    run d $elements $dt 0.8 position
    errors=$(tip_errors d d_ref)
    summarize d
    printf "%3d %10s %4d %s %7s\n" $k $dt $elements "$errors" "$run_events"
  done
  echo
done

echo "## E. sensitivity to the data: v0 = 0.5 (1 + delta) m/s against v0 = 0.5 m/s, same dt and N, e = 0.8"
for case in "1e-5 32 the_scene's_mesh_and_step" "2.5e-6 64 the_reference_of_study_2_of_REPORT.md"; do
  set -- $case
  run e_ref $2 $1 0.8
  summarize e_ref
  echo "# dt = $1 s, N = $2 (${3//_/ }); E(T) = $run_energy J"
  printf "%8s %10s %10s %10s %10s %13s\n" delta "T=2.5ms" "T=5ms" "T=12ms" "T=25ms" "E(T) (J)"
  for delta in 1e-10 1e-8 1e-7 3e-7 1e-6 3e-6 1e-5; do
    run e $2 $1 0.8 velocity "$(awk -v d=$delta 'BEGIN { printf "%.12f", 0.5*(1 + d) }')"
    errors=$(tip_errors e e_ref)
    summarize e
    printf "%8s %s %13s\n" $delta "$errors" "$run_energy"
  done
  echo
done

echo "## C. energy lost by T = 25 ms, dt = 2.5e-7 (8/N)^2 s (omega_max dt = 0.057)"
echo "# loss = 1 - E(T)/E(0), each run against its own E(0); with e = 0.8 up to N = 64, five runs"
echo "# with v0 = 0.5 (1 + delta), delta = 0, 1e-6, 1e-5, 1e-4, 1e-3 (study E: the loss jumps"
echo "# under such changes), and their mean, smallest and largest loss; otherwise delta = 0 only"
printf "%4s %11s %5s %5s %9s %9s %9s %16s\n" N dt e runs "loss" smallest largest "impulses (d=0)"
for e in 0.8 0 1; do
  sizes="8 16 32 64"
  [ "$e" != 1 ] && sizes="$sizes 128"
  for elements in $sizes; do
    dt=$(awk -v n=$elements 'BEGIN { printf "%.10g", 2.5e-7*(8/n)^2 }')
    deltas=0
    [ "$e" = 0.8 ] && [ "$elements" -le 64 ] && deltas="0 1e-6 1e-5 1e-4 1e-3"
    losses=""
    for delta in $deltas; do
      run c $elements $dt $e velocity "$(awk -v d=$delta 'BEGIN { printf "%.12f", 0.5*(1 + d) }')"
      summarize c
      losses="$losses $run_loss"
      if [ "$delta" = 0 ]; then count=$run_impulses; fi
    done
    echo "$losses" | awk -v n=$elements -v dt=$dt -v e=$e -v count=$count '{
      lo = $1; hi = $1; sum = 0
      for (k = 1; k <= NF; k++) { sum += $k; if ($k < lo) lo = $k; if ($k > hi) hi = $k }
      printf "%4d %11s %5s %5d %9.4f %9.4f %9.4f %16s\n", n, dt, e, NF, sum/NF, lo, hi, count }'
  done
done
} | tee "$work/table"
mv "$work/table" "$table"   # only a complete table replaces the committed one
plot_dissipation
echo "resolved_refinement: the study took $(( $(date +%s) - start )) s; wrote $table and $figure"
