#!/usr/bin/env bash
# The python3 that has h5py (Debian python3-h5py): `python3` on the PATH, else
# /usr/bin/python3 (a PATH may put another python3 first).
#   python_h5py.sh                  print its path; exit 77 when there is none
#   python_h5py.sh SCRIPT ARGS...   run SCRIPT with it; exit 77 (ctest SKIP_RETURN_CODE)
#                                   when there is none
for candidate in python3 /usr/bin/python3; do
  if command -v "$candidate" > /dev/null && "$candidate" -c 'import h5py' 2> /dev/null; then
    [ $# -eq 0 ] && { command -v "$candidate"; exit 0; }
    exec "$candidate" "$@"
  fi
done
echo "SKIP: no python3 with h5py (Debian package python3-h5py)" >&2
exit 77
