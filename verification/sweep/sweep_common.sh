# Helpers of the sweep test scripts (sourced, not run): they expect `here` (this folder),
# `vibrobeam`, `compare` (compare_sweep) and `failed` to be set by the script.

# scene NAME FREQUENCY SCHEME T_END OUTPUT SWEEP: write NAME.nml, the scene of scene.nml.in
# writing NAME.h5
scene() {
  sed -e "s|@FILE@|$1.h5|" -e "s|@FREQUENCY@|$2|" -e "s|@SCHEME@|$3|" -e "s|@T_END@|$4|" \
      -e "s|@OUTPUT@|$5|" -e "s|@SWEEP@|$6|" "$here/scene.nml.in" > "$1.nml"
}

# run NAME [ENVIRONMENT...]: run vibrobeam on NAME.nml, exit status 0 expected
run() {
  local name=$1; shift
  if ! env "$@" "$vibrobeam" "$name.nml" > "$name.out" 2> "$name.err"; then
    echo "FAIL: vibrobeam $name.nml"; cat "$name.err"; failed=1
  fi
}

# expect DESCRIPTION COMMAND...: record a failure when the command fails
expect() {
  local description=$1; shift
  if ! "$@"; then echo "FAIL $description"; failed=1; fi
}

# says FILE TEXT: FILE holds TEXT (fixed string)
says() { grep -q -F -- "$2" "$1" || { echo "  $1 does not say '$2':"; cat "$1"; return 1; }; }

# exit_is STATUS EXPECTED
exit_is() { [ "$1" -eq "$2" ] || { echo "  exit status $1, expected $2"; return 1; }; }

# statuses FILE: /sweep/status of a sweep file, every point's, comma separated
statuses() { h5dump -A 0 -d /sweep/status -y -w 0 "$1" | sed -n '/DATA {/,/}/{/DATA {/d;/}/d;p;}' | tr -d ' \n'; }

# run_status FILE: /run status of a result file
run_status() { h5dump -a /run/status "$1" 2> /dev/null | sed -n 's/.*(0): *"\(.*\)".*/\1/p'; }
