#!/usr/bin/env bash
# The result size that --check estimates against the bytes a run writes (every file of
# the result set). The estimate counts the histories and the field (8 bytes a number in
# HDF5, the text widths of the .dat files) but not HDF5's metadata, the spectrum or
# impacts: for a run without impacts it must lie within 50 % of the truth.
# usage: check_size_estimate.sh VIBROBEAM INPUT
set -uo pipefail
vibrobeam=$1; input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$input" "$work/input.nml"
cd "$work"
estimate=$("$vibrobeam" --check input.nml | sed -n 's/^estimated result size: \([0-9.e+]*\) bytes.*/\1/p')
"$vibrobeam" input.nml > /dev/null || { echo "FAIL the run failed"; exit 1; }
written=$(cat $(ls | grep -v -x input.nml) | wc -c)
echo "estimated $estimate bytes, written $written bytes"
awk -v e="$estimate" -v w="$written" 'BEGIN { r = w / e; printf "ratio written/estimated %.3f\n", r; exit !(r >= 0.5 && r <= 1.5) }'
