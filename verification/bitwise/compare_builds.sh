#!/usr/bin/env bash
# Run every bundled input (inputs/*.nml) and every scene of the test suite
# (verification/*/*.nml) with two builds of vibrobeam and compare what they leave: the exit
# status, every HDF5 result file, bitwise (compare_results.py), and every text file, byte
# for byte after the run-id line. For changes that must not move any result (a refactoring;
# CONTRIBUTING.md, "Architecture"); run it with the build before and after the change:
#
#   bash verification/bitwise/compare_builds.sh OLD/vibrobeam NEW/vibrobeam [SCENE.nml ...]
#
# A change that adds input variables lists their defaults in every result: name them in
# VIBROBEAM_NEW_INPUTS (e.g. VIBROBEAM_NEW_INPUTS='forces.') to leave them out of the
# comparison (compare_results.py); one that adds outputs names their paths in
# VIBROBEAM_NEW_OUTPUTS (compare_results.py says how they are matched).
#
# Scenes that need files the test harness writes first (from_file of an earlier run) run as
# they are: both builds must then fail alike. Prints one line per scene and a summary;
# exit 0 when every scene agrees, 1 otherwise. Needs python3 with h5py.
set -uo pipefail
old=$(readlink -f "$1") new=$(readlink -f "$2")
shift 2
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
python=$("$here/../support/python_h5py.sh" 2> /dev/null) ||
  { echo "compare_builds: no python3 with h5py (Debian python3-h5py)"; exit 2; }
if [ $# -gt 0 ]; then scenes=("$@"); else scenes=("$top"/inputs/*.nml "$top"/verification/*/*.nml); fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
same=0 differ=0
for scene in "${scenes[@]}"; do
  name=$(basename "$(dirname "$scene")")/$(basename "$scene" .nml)
  scene_path=$(readlink -f "$scene")
  rm -rf "$work/old" "$work/new"
  mkdir -p "$work/old" "$work/new"
  for side in old new; do
    binary=$old; [ $side = new ] && binary=$new
    # the scene where it lies (the files it names, a load's table, are beside it), its
    # results in the work directory
    (cd "$work/$side" && timeout 300 "$binary" "$scene_path" > stdout.txt 2> stderr.txt; echo $? > status.txt)
  done
  problems=()
  [ "$(cat "$work/old/status.txt")" = "$(cat "$work/new/status.txt")" ] ||
    problems+=("exit status $(cat "$work/old/status.txt") -> $(cat "$work/new/status.txt")")
  while IFS= read -r file; do
    relative=${file#"$work/old/"}
    if [ ! -e "$work/new/$relative" ]; then problems+=("$relative missing"); continue; fi
    case "$relative" in
      *.h5) "$python" "$here/compare_results.py" "$file" "$work/new/$relative" > "$work/diff.txt" ||
              problems+=("$relative: $(head -3 "$work/diff.txt" | tr '\n' ' ')") ;;
      *.dat) "$python" "$here/compare_results.py" --text "$file" "$work/new/$relative" > /dev/null ||
               problems+=("$relative differs") ;;
    esac
  done < <(find "$work/old" -type f \( -name '*.h5' -o -name '*.dat' \) | sort)
  extra=$(cd "$work/new" && find . -type f \( -name '*.h5' -o -name '*.dat' \) | while read -r f; do
            [ -e "$work/old/$f" ] || echo "$f"; done)
  [ -z "$extra" ] || problems+=("only in the new run: $extra")
  if [ ${#problems[@]} -eq 0 ]; then
    same=$((same + 1)); echo "same     $name (exit $(cat "$work/old/status.txt"))"
  else
    differ=$((differ + 1)); echo "DIFFERS  $name: ${problems[*]}"
  fi
done
echo "compare_builds: $same scene(s) identical, $differ differ"
[ $differ -eq 0 ]
