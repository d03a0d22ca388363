#!/usr/bin/env bash
# Tables of the statistics convergence study from runs.dat (written by run_study.sh):
# convergence_<scene>.txt, one per scene, and the plot data convergence_<scene>_<path>.dat.
#
#   bash tables.sh runs.dat
#
# For every refinement path and statistic, each level's value x_k with its batch-means
# standard error s_k (docs/statistics.md), the difference to the level before,
# d_k = x_k - x_{k-1}, and z_k = |d_k| / sqrt(s_k^2 + s_{k-1}^2): the difference in units
# of its own sampling uncertainty. Only z > 2 is a resolved difference. Where two
# successive differences are both resolved, the observed order p = log2(|d_{k-1}|/|d_k|)
# (per halving of dt on the joint and dt paths, per doubling of N on the N path).
# The replicate rows compare a run whose forcing amplitude differs by a relative 1e-6
# with the run as given, at the same resolution.
set -euo pipefail
data=${1:-runs.dat}
here=$(cd "$(dirname "$0")" && pwd)
names=(displacement_rms velocity_rms impact_rate episode_rate episode_impulse_mean episode_impulse_max
   contact_fraction contact_force power_input power_impacts power_damping power_dissipated)
for scene in $(awk '!/^#/{print $1}' "$data" | sort -u); do
   out=$here/convergence_$scene.txt
   {
      echo "# Statistics convergence, scene $scene (written by tables.sh from runs.dat; REPORT.md explains)"
      echo "# value: the statistic over the window (160 forcing periods after 40); se: its batch-means"
      echo "# standard error; d: change from the level above; z = |d|/sqrt(se^2 + se_above^2) (z < 2: not"
      echo "# resolved); p: observed order log2(|d_above|/|d|) where both are resolved; rel: (value -"
      echo "# finest)/finest of the path, in %. om_dt: omega_max*dt of the mesh's highest mode."
      for path in joint dt N; do
         for j in "${!names[@]}"; do
            awk -v scene="$scene" -v path="$path" -v j="$j" -v name="${names[$j]}" '
               $1 == scene && $2 == path && $5 == 0 { n++; N[n] = $3; dt[n] = $4; om[n] = $7; x[n] = $(10 + 2*j); s[n] = $(11 + 2*j) }
               END {
                  printf "\n## path %s, %s\n", path, name
                  printf "%5s %9s %9s %14s %11s %12s %7s %6s %8s\n", "N", "dt", "om_dt", "value", "se", "d", "z", "p", "rel%"
                  fin = x[n]
                  for (k = 1; k <= n; k++) {
                     dd = ""; zz = ""; pp = ""
                     if (k > 1) {
                        d[k] = x[k] - x[k-1]; sd = sqrt(s[k]^2 + s[k-1]^2)
                        z[k] = (sd > 0) ? ((d[k] < 0 ? -d[k] : d[k])/sd) : (d[k] == 0 ? 0 : 1e9)
                        dd = sprintf("%12.4e", d[k]); zz = sprintf("%7.1f", z[k])
                        if (k > 2 && z[k] > 2 && z[k-1] > 2) pp = sprintf("%6.2f", log((d[k-1] < 0 ? -d[k-1] : d[k-1])/(d[k] < 0 ? -d[k] : d[k]))/log(2))
                     }
                     rel = (fin != 0) ? 100*(x[k] - fin)/fin : 0
                     printf "%5d %9s %9.3g %14.6e %11.3e %12s %7s %6s %8.2f\n", N[k], dt[k], om[k], x[k], s[k], dd, zz, pp, rel
                  }
               }' "$data"
         done
         awk -v scene="$scene" -v path="$path" '
            $1 == scene && $2 == path && $5 == 0 { n++; N[n] = $3; dt[n] = $4; f[n] = $34; b[n] = $35 }
            END {
               printf "\n## path %s, peak_frequency (Hz; resolution: the bin width)\n", path
               printf "%5s %9s %12s %10s\n", "N", "dt", "peak (Hz)", "bin (Hz)"
               for (k = 1; k <= n; k++) printf "%5d %9s %12.5f %10.4f\n", N[k], dt[k], f[k], b[k]
            }' "$data"
      done
      echo
      echo "## replicates: forcing amplitude x (1 + 1e-6), same N and dt"
      for j in "${!names[@]}"; do
         awk -v scene="$scene" -v j="$j" -v name="${names[$j]}" '
            $1 == scene && $2 != "rep" { key = $3 " " $4; x[key] = $(10 + 2*j); s[key] = $(11 + 2*j) }
            $1 == scene && $2 == "rep" { n++; K[n] = $3 " " $4; y[n] = $(10 + 2*j); t[n] = $(11 + 2*j) }
            END {
               for (k = 1; k <= n; k++) {
                  d = y[k] - x[K[k]]; sd = sqrt(t[k]^2 + s[K[k]]^2)
                  printf "%-22s N dt = %-10s value %14.6e se %10.3e  replicate %14.6e se %10.3e  d %11.3e  z %6.1f\n", \
                     name, K[k], x[K[k]], s[K[k]], y[k], t[k], d, (sd > 0 ? (d < 0 ? -d : d)/sd : 0)
               }
            }' "$data"
      done
   } > "$out"
   # Plot data: per path, one row per level: N dt, then value/finest and se/finest of each statistic.
   for path in joint dt N; do
      awk -v scene="$scene" -v path="$path" '
         $1 == scene && $2 == path && $5 == 0 { n++; row[n] = $0 }
         END {
            split(row[n], f)
            print "# N dt, then for each statistic of runs.dat: value/value_finest, se/|value_finest|; impacts/episodes"
            for (k = 1; k <= n; k++) {
               split(row[k], a); printf "%d %s", a[3], a[4]
               for (j = 0; j < 12; j++) {
                  v = f[10 + 2*j]; if (v == 0) v = 1
                  printf " %.6g %.6g", a[10 + 2*j]/v, a[11 + 2*j]/(v < 0 ? -v : v)
               }
               printf " %.6g\n", (a[16] > 0 ? a[14]/a[16] : 0)
            }
         }' "$data" > "$here/convergence_${scene}_${path}.dat"
   done
done
