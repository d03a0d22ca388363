#!/usr/bin/env bash
# The installed package, as a user gets it: install the build tree into a fresh prefix,
# run the installed program on an installed scene, then configure, build and run a
# separate project (consumer/) that finds the package with find_package(vibrobeam) and
# links vibrobeam::vibrobeam. Only the prefix is on the consumer's search path (no package
# registry), and the consumer checks that it found the prefix's package.
#   usage: run_package_test.sh CMAKE BUILD_DIR WORK_DIR FORTRAN_COMPILER BUILD_TYPE VERSION
set -euo pipefail
cmake=$1 build=$2 work=$3 compiler=$4 build_type=$5 version=$6
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log"
"$prefix/bin/vibrobeam" --version | grep "^vibrobeam $version" > /dev/null \
  || { echo "FAIL: the installed vibrobeam does not report version $version"; exit 1; }
"$prefix/bin/vibrobeam" --check "$prefix/share/vibrobeam/inputs/static_tip_contact.nml" | grep "is valid" > /dev/null \
  || { echo "FAIL: the installed vibrobeam does not accept its installed scene static_tip_contact.nml"; exit 1; }

"$cmake" -S "$here/consumer" -B "$work/consumer" -DCMAKE_Fortran_COMPILER="$compiler" \
  -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
  -Dvibrobeam_expected_version="$version" > "$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; echo "FAIL: the consumer project does not configure"; exit 1; }
grep -F -- "-- vibrobeam $version from $prefix/" "$work/configure.log" \
  || { cat "$work/configure.log"; echo "FAIL: the consumer did not find the package in $prefix"; exit 1; }
"$cmake" --build "$work/consumer" > "$work/build.log" 2>&1 \
  || { cat "$work/build.log"; echo "FAIL: the consumer does not build against the installed package"; exit 1; }
"$work/consumer/static_tip" "$version"
