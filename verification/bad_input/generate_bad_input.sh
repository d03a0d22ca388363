#!/usr/bin/env bash
# Writes the input file NAME of a bad-input case that is not a plain text file in git:
# bytes no editor would keep, files too long to read, links and directories. Every byte
# is computed here, deterministically (no /dev/urandom), so a failure reproduces.
# usage: generate_bad_input.sh CASE NAME   (in the directory of the case)
set -euo pipefail
case_name=$1; name=$2

# n bytes of a fixed pseudo-random sequence (a linear congruential generator, the
# constants of Numerical Recipes), every byte value 0..255 possible
pseudo_random_bytes() {
  local n=$1 state=12345 i
  for ((i = 0; i < n; i++)); do
    state=$(( (1664525 * state + 1013904223) % 4294967296 ))
    printf -v hex %02x $(( (state >> 16) & 255 ))
    printf "\\x$hex"
  done
}

# a string of n characters 'a'
letters() { head -c "$1" /dev/zero | tr '\0' 'a'; }

# the scenes of the &forces cases: a table signal read from record.dat, a random signal
# whose density is read from psd.dat (the case writes the file)
table_scene() {
  printf "&forces count = 1, signal(1) = 'table', table(1) = 'record.dat' /\n&output file = 'out/bad.h5' /\n" > "$name"
}
# the scene of the &initial velocity_profile cases: a pinned-free beam of length 1 m whose
# initial velocity is read from profile.dat (the case writes the file)
profile_scene() {
  printf "&beam left_end = 'pinned' /\n&time t_end = 1e-3, dt = 1e-4 /\n" > "$name"
  printf "&initial velocity = 'profile', velocity_profile = 'profile.dat' /\n&output file = 'out/bad.h5' /\n" >> "$name"
}
# the scene of the &obstacles profile cases: a floor over [0.5, 1] m of a 1 m beam whose
# surface is read from floor.dat (the case writes the file)
obstacle_profile_scene() {
  printf "&time t_end = 1e-3, dt = 1e-4 /\n&obstacles count = 1, side(1) = 'below', x_from(1) = 0.5, x_to(1) = 1.0,\n" > "$name"
  printf "           profile(1) = 'floor.dat' /\n&output file = 'out/bad.h5' /\n" >> "$name"
}
psd_table_scene() {
  printf "&time t_end = 0.1, dt = 1e-3 /\n&forces count = 1, signal(1) = 'random', psd_table(1) = 'psd.dat' /\n" > "$name"
  printf "&output file = 'out/bad.h5' /\n" >> "$name"
}

case "$case_name" in
  random_bytes) pseudo_random_bytes 2048 > "$name" ;;
  nul_byte) printf '&mesh elements = 4\0 /\n' > "$name" ;;
  control_character) printf '&mesh elements = 4 \a/\n' > "$name" ;;
  lone_carriage_return) printf '&mesh elements = 4 /\r&time dt = 1e-3 /\n' > "$name" ;;
  non_ascii_outside_comment) printf '&beam length = 1.0 \xcf\x81 /\n' > "$name" ;;
  malformed_utf8_in_comment) printf '! a comment with a stray byte \xff\n&mesh elements = 4 /\n' > "$name" ;;
  malformed_utf8_in_string) printf "&output file = 'out/r\\xc3.h5' /\\n" > "$name" ;;
  overlong_output_path) printf "&output file = '%s.h5' /\n" "$(letters 5000)" > "$name" ;;
  overlong_from_file) printf "&initial from_file = '%s.h5' /\n" "$(letters 4100)" > "$name" ;;
  output_path_too_long_for_suffixes) printf "&output file = 'o/%s%s.h5' /\n" "$(for i in $(seq 1 20); do printf '%s/' "$(letters 200)"; done)" "$(letters 60)" > "$name" ;;
  output_name_too_long) printf "&output file = 'out/%s.h5' /\n" "$(letters 250)" > "$name" ;;
  output_directory_name_too_long) printf "&output file = 'out/%s/r.h5' /\n" "$(letters 300)" > "$name" ;;
  overlong_keyword) printf "&mesh basis = '%s' /\n" "hermite$(letters 100)" > "$name" ;;
  input_too_large) { echo '&mesh elements = 4 /'; for i in $(seq 1 40000); do echo '! padding padding padding padding padding'; done; } > "$name" ;;
  input_is_directory) mkdir "$name" ;;
  initial_profile_not_increasing)
    profile_scene
    printf '# x (m), v (m/s)\n0 0\n0.6 1\n0.5 2\n1 3\n' > profile.dat ;;
  initial_profile_not_a_number)
    profile_scene
    printf '0 0\n0.5 fast\n1 2\n' > profile.dat ;;
  initial_profile_outside_beam)
    profile_scene
    printf '0 0\n0.5 1\n1.5 3\n' > profile.dat ;;
  obstacle_profile_not_increasing)
    obstacle_profile_scene
    printf '0 -1e-3\n0.7 -1e-3\n0.7 -2e-3\n1 -2e-3\n' > floor.dat ;;
  obstacle_profile_not_a_number)
    obstacle_profile_scene
    printf '0 -1e-3\n0.5 low\n1 -2e-3\n' > floor.dat ;;
  obstacle_profile_outside_beam)
    obstacle_profile_scene
    printf '0 -1e-3\n1.2 -2e-3\n' > floor.dat ;;
  obstacle_profile_short)
    obstacle_profile_scene
    printf '0 -1e-3\n0.8 -2e-3\n' > floor.dat ;;
  forces_psd_table_negative)
    psd_table_scene
    printf '10 0\n50 -1\n100 0\n' > psd.dat ;;
  forces_psd_table_above_nyquist)
    psd_table_scene
    printf '10 1\n800 1\n' > psd.dat ;;
  forces_table_not_increasing)
    table_scene
    printf '# t (s), force (N)\n0.0 1.0\n0.5 2.0\n0.4 3.0\n' > record.dat ;;
  forces_table_not_a_number)
    table_scene
    printf '0.0 1.0\n0.5 two\n' > record.dat ;;
  forces_table_one_pair)
    table_scene
    printf '# only one pair\n0.0 1.0\n' > record.dat ;;
  output_is_link_to_input)
    printf "&mesh elements = 4 /\n&time t_end = 1e-3, dt = 1e-4 /\n&output file = 'link.h5' /\n" > "$name"
    ln -s "$name" link.h5 ;;
  output_is_existing_directory)
    printf "&time t_end = 1e-3, dt = 1e-4 /\n&output file = 'earlier' /\n" > "$name"
    mkdir earlier ;;
  windows_line_end_inside_string) printf "&output file = 'a\r\nb.h5' /\r\n" > "$name" ;;
  *) echo "generate_bad_input.sh: unknown case $case_name" >&2; exit 1 ;;
esac
