# Sourced by the study scripts (not run on its own): build_release BUILD_DIR TARGET...
# configures BUILD_DIR as a Release build with the study programs (the project's Release
# flags, VIBROBEAM_STUDIES=ON; an existing build directory is switched to both), builds
# the targets and, if that fails, prints the build log and exits 1. The log is kept in BUILD_DIR/<first target>_build.log.
build_release() {
  local tree=$1
  shift
  local log=$tree/$1_build.log
  rm -f "$log"
  local source_dir
  source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  if ! cmake -S "$source_dir" -B "$tree" -DCMAKE_BUILD_TYPE=Release -DVIBROBEAM_STUDIES=ON > /dev/null; then
    echo "$(basename "$0"): configuring $tree failed (cmake's message above)" >&2
    exit 1
  fi
  if ! cmake --build "$tree" -j 2 --target "$@" > "$log" 2>&1; then
    cat "$log"
    echo "$(basename "$0"): the build of $* in $tree failed (log above)" >&2
    exit 1
  fi
}
