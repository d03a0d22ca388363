# Sourced by the study scripts (not run on its own): build_release BUILD_DIR TARGET...
# configures BUILD_DIR as a Release build (the project's Release flags; an existing build
# directory is switched to Release), builds the targets and, if that fails, prints the
# build log and exits 1. The log is kept in BUILD_DIR/<first target>_build.log.
build_release() {
  local tree=$1
  shift
  local log=$tree/$1_build.log
  rm -f "$log"
  if ! cmake -S . -B "$tree" -DCMAKE_BUILD_TYPE=Release > /dev/null \
     || ! cmake --build "$tree" -j 2 --target "$@" > "$log" 2>&1; then
    [ -f "$log" ] && cat "$log"
    echo "$(basename "$0"): the build of $* in $tree failed (log above)" >&2
    exit 1
  fi
}
