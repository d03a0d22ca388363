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

# describe_study_run TABLE BUILD_DIR PROGRAM START LOAD_BEFORE: append to TABLE how the study
# ran: the machine, its load average before (LOAD_BEFORE) and after, the seconds since
# START (date +%s), BUILD_DIR's compiler, the BLAS/LAPACK that PROGRAM loads and the
# source's commit (marked when src/ has uncommitted changes).
describe_study_run() {
  local table=$1 tree=$2 program=$3 start=$4 load_before=$5 fortran edits
  fortran=$(sed -n 's/^CMAKE_Fortran_COMPILER:[A-Z]*=//p' "$tree/CMakeCache.txt")
  edits=$([ -z "$(git status --porcelain -- src)" ] || echo ' with uncommitted changes in src/')
  {
    echo "#"
    echo "# machine: $(nproc) processors, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')," \
      "load average before the run: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg);" \
      "the run took $(( $(date +%s) - start )) s"
    echo "# compiler: $("${fortran:-gfortran}" --version | head -1), Release (-O2)"
    echo "# BLAS/LAPACK: $(ldd "$program" | awk '/blas|lapack/ { print $3 }' | xargs -r readlink -f | tr '\n' ' ')"
    echo "# source: git $(git rev-parse --short HEAD)$edits, $(date -u +%Y-%m-%dT%H:%MZ)"
  } >> "$table"
}
