#!/usr/bin/env bash
# The python3 that has Siconos' numerics (Debian python3-siconos, installed for
# /usr/bin/python3): `python3` on the PATH, else /usr/bin/python3.
#   python_siconos.sh SCRIPT ARGS...   run SCRIPT with it; exit 77 (ctest SKIP_RETURN_CODE)
#                                      with a message when there is none
for candidate in python3 /usr/bin/python3; do
  if command -v "$candidate" > /dev/null && "$candidate" -c 'import numpy, siconos.numerics' 2> /dev/null; then
    exec "$candidate" "$@"
  fi
done
echo "SKIP: no python3 with Siconos (Debian package python3-siconos)" >&2
exit 77
