#!/usr/bin/env bash
# The chaos diagnostics of issue 20, item 3, measured (studies/chaos_diagnostics/REPORT.md):
#  twins    why two runs 1e-9 m apart do not separate where the 0-1 test says chaos: the
#           rattling beam at 276 rad/s with rigid and with compliant stops, at dt = 4e-5,
#           2e-5, 1e-5 and 5e-6 s: the twins' separation (twin_runs, 100 periods to
#           settle, 400 measured) for tip perturbations of 1e-9 to 1e-6 m, the tangent's
#           exponent, and K and the exponent of a vibrobeam run of the same windows
#           (twins.txt);
#  diagram  the rattling beam's bifurcation diagram, 61 frequencies from 100 to 340 rad/s,
#           settled 400 periods and measured 400, every Poincare sample kept and the
#           Lyapunov exponent on, with rigid stops and with compliant ones: the period, K
#           and the exponent of every point against the period the diagram shows
#           (diagram_rigid.txt, diagram_compliant.txt: diagram_table.py);
#  cost     the Lyapunov exponent's cost per step against a plain run (farm-bench, medians
#           of 5 pairs and the median of their ratios): the rattling beam at 276 rad/s
#           (N = 16 rigid and compliant, N = 128 rigid) and a floor under the whole beam
#           shaken at its base (48 contact points, many held at once) (cost.txt).
# usage: studies/chaos_diagnostics/chaos_diagnostics.sh [BUILD_DIR] [twins|diagram|cost ...]
#        (all three without a part named; about 30 minutes on a busy 2-core machine)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
shift || true
parts=${*:-twins diagram cost}
here=studies/chaos_diagnostics
source scripts/build_release.sh
build_release "$build" vibrobeam twin_runs
vibrobeam=$(readlink -f "$build/vibrobeam")
twin_runs=$(readlink -f "$build/studies/chaos_diagnostics/twin_runs")
python=$(verification/support/python_h5py.sh)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run_window SCENE DT: a vibrobeam run of SCENE at DT over 100 + 400 forcing periods
# (276 rad/s), the last 400 measured, with the Lyapunov exponent: its summary's second line
run_window() {
  local period t_end measure_from
  period=$(awk 'BEGIN { printf "%.17g", 2 * atan2(0, -1) / 276 }')
  t_end=$(awk -v p="$period" -v dt="$2" 'BEGIN { printf "%.17g", dt * int(500 * p / dt + 0.5) }')
  measure_from=$(awk -v p="$period" -v dt="$2" 'BEGIN { printf "%.17g", dt * int(100 * p / dt + 0.5) }')
  sed -e "s|t_end = 1, dt = 2e-5|t_end = $t_end, dt = $2|" \
      -e "s|^&output .*|\\&output file = '$work/window.h5', text = .false., every = 1000, measure_from = $measure_from, lyapunov = .true. /|" \
      "$here/$1.nml" > "$work/window.nml"
  "$vibrobeam" "$work/window.nml" 2> /dev/null | sed -n 2p
}

if [[ " $parts " == *" twins "* ]]; then
  start=$(date +%s); load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  {
    echo "# twin runs (twin_runs): the rattling beam at 276 rad/s, 100 periods to settle, 400 measured"
    for stops in rigid compliant; do
      for dt in 4e-5 2e-5 1e-5 5e-6; do
        echo
        echo "## $stops stops, dt = $dt s"
        echo "vibrobeam over the same windows: $(run_window rattling_276_$stops $dt)"
        if [ $stops = rigid ]; then
          "$twin_runs" "$here/rattling_276_$stops.nml" $dt 100 400 1e-9 1e-8 1e-7 1e-6
        else
          "$twin_runs" "$here/rattling_276_$stops.nml" $dt 100 400 1e-9 1e-12 1e-15
        fi
      done
    done
  } | tee "$here/twins.txt"
  describe_study_run "$here/twins.txt" "$build" "$twin_runs" "$start" "$load_before"
fi

if [[ " $parts " == *" diagram "* ]]; then
  for stops in rigid compliant; do
    start=$(date +%s); load_before=$(cut -d' ' -f1-3 /proc/loadavg)
    sed -e "s|'diagram_$stops.h5'|'$work/diagram_$stops.h5', text = .false.|" "$here/diagram_$stops.nml" \
      > "$work/diagram_$stops.nml"
    /usr/bin/time -f "%e s wall, %U s user" -o "$work/time.txt" "$vibrobeam" "$work/diagram_$stops.nml"
    { "$python" "$here/diagram_table.py" "$work/diagram_$stops.h5"; echo "# run: $(cat "$work/time.txt")"; } |
      tee "$here/diagram_$stops.txt"
    describe_study_run "$here/diagram_$stops.txt" "$build" "$vibrobeam" "$start" "$load_before"
  done
fi

if [[ " $parts " == *" cost "* ]]; then
  # scene NAME SOURCE ELEMENTS T_END LYAPUNOV: SOURCE (a scene of this folder) with N
  # elements over T_END s, nothing written but the result's statistics; the runs are long
  # enough (0.5 to 3 s) for the set-up (a few ms) not to count
  scene() {
    sed -e "s|elements = 16|elements = $3|" -e "s|t_end = 1,|t_end = $4,|" \
        -e "s|^&output .*|\\&output file = '$work/$1.h5', text = .false., every = 100000, lyapunov = $5 /|" \
        "$here/$2.nml" > "$work/$1.nml"
  }
  scene rigid16 rattling_276_rigid 16 8 .false.
  scene rigid16_l rattling_276_rigid 16 8 .true.
  scene compliant16 rattling_276_compliant 16 4 .false.
  scene compliant16_l rattling_276_compliant 16 4 .true.
  scene rigid128 rattling_276_rigid 128 1 .false.
  scene rigid128_l rattling_276_rigid 128 1 .true.
  # the hard case: a floor under the whole beam (a contact point at each of its 48 nodes,
  # many of them held in the same steps), shaken at its base near mode 1
  floor() {
    cat > "$work/$1.nml" <<NML
&beam      length = 0.5, youngs_modulus = 210e9, density = 7850, area = 2e-4,
           inertia = 1.6666666666666667e-9, rayleigh_mass = 1.8109, rayleigh_stiffness = 6.5532e-6 /
&mesh      elements = 48 /
&obstacles count = 1, side(1) = 'below', x_from(1) = 0.0, x_to(1) = 0.5, level_from(1) = -2e-4 /
&impact    restitution = 0.5 /
&time      t_end = 0.3, dt = 1e-5 /
&load      base_acceleration = 20, base_frequency = 200 /
&output    file = '$work/$1.h5', text = .false., every = 100000, lyapunov = $2 /
NML
  }
  floor floor .false.
  floor floor_l .true.
  start=$(date +%s); load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  {
    echo "# the Lyapunov exponent's cost: farm-bench, 5 pairs each (A with &output lyapunov, B without), processor"
    echo "# time per step = the median cpu seconds over the run's steps (set-up included, a few ms)"
    for case in rigid16 compliant16 rigid128 floor; do
      echo
      "$vibrobeam" "$work/${case}_l.nml" > "$work/summary.txt" 2> /dev/null
      steps=$(sed -n 's/^vibrobeam: \([0-9]*\) steps.*/\1/p' "$work/summary.txt")
      echo "## $case: $(grep -o 'elements = [0-9]*' "$work/$case.nml"), $steps steps"
      tail -1 "$work/summary.txt"
      farm-bench -n 5 --timeout 1800 --vs "$vibrobeam $work/$case.nml" -- "$vibrobeam" "$work/${case}_l.nml" 2>&1 |
        tee "$work/bench.txt"
      awk -v n="$steps" '$1 == "A" && $2 == "cpu" { a = $4 } $1 == "B" && $2 == "cpu" { b = $4 }
        $1 == "A/B" && $2 == "cpu" { r = $4 }
        END { printf "per step: A %.3f us, B %.3f us, A/B %s (medians)\n", 1e6 * a / n, 1e6 * b / n, r }' "$work/bench.txt"
    done
  } | tee "$here/cost.txt"
  describe_study_run "$here/cost.txt" "$build" "$vibrobeam" "$start" "$load_before"
fi
