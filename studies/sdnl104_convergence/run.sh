#!/bin/sh
# SDNL104 under refinement: the published case (verification/published/sdnl104_compliant.nml,
# N = 10, dt = 1e-4 s, the 'mean' rule) with N = 10 .. 160 and dt = 1e-4 .. 6.25e-6 s, and
# the 'gradient' rule at the finest level: tip displacement at 0.1315 s, tip velocity at
# 0.1566 s, kinetic energy at 0.16 s. Writes results.txt.
# Usage: sh studies/sdnl104_convergence/run.sh BUILD_DIR   (about 1 minute on 2 cores)
set -eu
bin=${1:-build}/vibrobeam
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
out="$here/results.txt"
echo "# N dt(s) rule u_tip(0.1315)(m) v_tip(0.1566)(m/s) KE(0.16)(J)" > "$out"
for case in 10:1e-4:mean 20:1e-4:mean 40:1e-4:mean 80:1e-4:mean 10:5e-5:mean 10:2.5e-5:mean 10:1.25e-5:mean \
            20:5e-5:mean 40:2.5e-5:mean 80:1.25e-5:mean 160:6.25e-6:mean 160:6.25e-6:gradient 80:1.25e-5:gradient; do
  n=$(echo $case | cut -d: -f1); dt=$(echo $case | cut -d: -f2); rule=$(echo $case | cut -d: -f3)
  sed -e "s/elements = 10/elements = $n/" -e "s/dt = 1e-4, compliant_rule = 'mean'/dt = $dt, compliant_rule = '$rule'/" \
      -e "s|file = 'sdnl104_compliant.h5'|file = '$work/s.h5'|" "$here/../../verification/published/sdnl104_compliant.nml" > "$work/s.nml"
  "$bin" "$work/s.nml" > /dev/null 2>&1
  awk -v n=$n -v dt=$dt -v r=$rule 'FNR == 1 { f++ } /^#/ { next }
    f == 1 { if (($1 - 0.1315)^2 < (dt/10)^2) u = $2; if (($1 - 0.1566)^2 < (dt/10)^2) v = $3 }
    f == 2 { ke = $2 }
    END { printf "%4d %-8s %-8s %.9e %.9e %.12e\n", n, dt, r, u, v, ke }' "$work/s_tip.dat" "$work/s_energy.dat" >> "$out"
done
rm -rf "$work"
cat "$out"
