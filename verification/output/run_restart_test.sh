#!/usr/bin/env bash
# Checkpoint and restart (docs/output.md, "Checkpoint and restart").
# usage: run_restart_test.sh MODE VIBROBEAM COMPARE_CONTINUED [EDIT_CHECKPOINT]
#   bitwise   for both schemes and both bases, a run to 2T and a run to T continued to 2T
#             (&initial from_file) give bitwise identical histories over the continued
#             part, the same spectrum, contact fractions, statistics and final state
#             (compare_continued); also a scene with a compliant stop, continued inside a
#             compliant episode, and one with the Poincare diagnostics and the Lyapunov
#             exponent
#   refused   a file that does not match the scene is refused with exit status 2, a message
#             naming the group, the variable, the file's value and the scene's, and nothing
#             written: the model (basis, elements, reduction, length), the time scheme, the
#             contact points, the compliant stops and their kind; what may change (rigid
#             obstacle levels, a stop's damping) is accepted; &initial velocity beside
#             from_file draws a warning
#   planes    a beam of two planes (issue 21), rigid and compliant walls in the
#             cross-section (a round hole and a hexagonal one with friction, a level),
#             continued at 0.1524 s inside the statistics window and (compliant) inside a
#             contact with the hexagon: bitwise as in `bitwise`, the wear (/wear,
#             /statistics/wear) and the friction's energy included; then what must match
#             (the planes, inertia_z, the points of the obstacles, a compliant wall) and
#             what may change (a rigid wall moved away; one moved onto the beam is refused)
#   checksum  a checkpoint with one flipped bit (a real, a running sum, the step count) is
#             refused with exit status 2 (edit_checkpoint damages it); one without a
#             checksum (as vibrobeam 0.2.0 wrote them) is continued with a warning
set -uo pipefail
mode=$1; vibrobeam=$2; compare=$3; edit=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failed=0
scene() {  # scene NAME T_END [FROM_FILE], with $scheme and $basis
  sed -e "s|@FILE@|$1.h5|" -e "s|@T_END@|$2|" -e "s|@SCHEME@|$scheme|" -e "s|@BASIS@|$basis|" \
      -e "s|@FROM_FILE@|${3:+, from_file = '$3'}|" "$here/restart.nml.in" > "$1.nml"
}
run() {  # run NAME: exit status 0 expected
  "$vibrobeam" $1.nml > $1.out 2> $1.err || { echo "FAIL $scheme $basis: run $1"; cat $1.err; failed=1; }
}
# refused DESCRIPTION EXPECTED_TEXT SED_EXPRESSION: continued.nml edited by SED_EXPRESSION
# (its output renamed refused.h5) exits with status 2, says EXPECTED_TEXT, prints no
# run-time library report and writes nothing
refused() {
  sed -e "$3" -e "s/continued.h5/refused.h5/" continued.nml > refused.nml
  rm -f refused.h5 refused.out refused.err
  local before after
  before=$(ls -A | sort)
  "$vibrobeam" refused.nml > refused.out 2> refused.err
  local code=$?
  after=$(ls -A | grep -v -x -e refused.out -e refused.err | sort)
  if [ $code -ne 2 ] || ! grep -q -F -- "$2" refused.err || [ "$before" != "$after" ] || \
     grep -q -i -E "backtrace|runtime error|error termination" refused.err; then
    echo "FAIL $1: exit status $code, expected 2 with '$2' and nothing written:"
    cat refused.err
    [ "$before" = "$after" ] || echo "written: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
    failed=1
  else
    echo "refused as expected ($1): $(head -1 refused.err)"
  fi
}
# accepted DESCRIPTION SED_EXPRESSION [EXPECTED_WARNING]: continued.nml edited by
# SED_EXPRESSION continues (exit status 0), with EXPECTED_WARNING on stderr when given
accepted() {
  sed -e "$2" -e "s/continued.h5/accepted.h5/" continued.nml > accepted.nml
  rm -f accepted.h5
  "$vibrobeam" accepted.nml > accepted.out 2> accepted.err
  local code=$?
  if [ $code -ne 0 ] || { [ -n "${3:-}" ] && ! grep -q -F -- "$3" accepted.err; }; then
    echo "FAIL $1: exit status $code, expected 0${3:+ with the warning '$3'}:"
    cat accepted.err
    failed=1
  else
    echo "accepted as expected ($1)${3:+: $(grep -F -- "$3" accepted.err | head -1)}"
  fi
}

case $mode in
bitwise)
  for scheme in velocity position; do
    for basis in hermite bspline; do
      scene full 0.2
      scene half 0.1
      scene continued 0.2 half.h5
      for name in full half continued; do run $name; done
      echo "$scheme, $basis:"
      "$compare" full.h5 continued.h5 || failed=1
    done
  done

  # a compliant stop with its force statistics, the checkpoint taken inside a compliant
  # episode (the force is nonzero at t = 0.1712 s) and inside the statistics window
  base="$here/statistics_compliant.nml"
  sed -e "s/'statistics.h5'/'full_compliant.h5'/" "$base" > full_compliant.nml
  sed -e "s/'statistics.h5'/'half_compliant.h5'/" -e "s/t_end = 0.3/t_end = 0.1712/" "$base" > half_compliant.nml
  { sed -e "s/'statistics.h5'/'continued_compliant.h5'/" "$base"; echo "&initial from_file = 'half_compliant.h5' /"; } \
    > continued_compliant.nml
  scheme=velocity; basis=hermite
  for name in full half continued; do run ${name}_compliant; done
  echo "compliant stop:"
  "$compare" full_compliant.h5 continued_compliant.h5 || failed=1

  # the Poincare diagnostics (docs/statistics.md, "Period, Lyapunov exponent and the 0-1
  # test") with &output lyapunov: the load at 4000 rad/s gives 108 samples in the window,
  # so that the 0-1 test is computed (>= 100) and every accumulator is carried across
  scheme=velocity; basis=hermite
  scene full 0.2
  scene half 0.1
  scene continued 0.2 half.h5
  for name in full half continued; do
    sed -e "s/distributed_frequency = 150/distributed_frequency = 4000/" -e "s/measure_from = 0.03/measure_from = 0.03, lyapunov = .true./" \
        -e "s/'$name.h5'/'${name}_lyapunov.h5'/" -e "s/'half.h5'/'half_lyapunov.h5'/" $name.nml > ${name}_lyapunov.nml
    run ${name}_lyapunov
  done
  echo "Poincare diagnostics with the Lyapunov exponent:"
  "$compare" full_lyapunov.h5 continued_lyapunov.h5 || failed=1
  ;;

refused)
  scheme=velocity; basis=hermite
  scene half 0.1
  scene continued 0.2 half.h5
  run half
  # the same scene as a reduced model with as many unknowns as the full one (J = 16: the
  # tip's contact displacement and 15 fixed-interface modes), with compliant stops, and a
  # static result
  sed -e "s/elements = 8,/elements = 8, reduction = 'craig-bampton', reduction_modes = 15,/" \
      -e "s/half.h5/reduced.h5/" half.nml > reduced.nml
  sed -e "s/level_from(1) = -1e-3,/level_from(1) = -1e-3, stiffness(1) = 1e5,/" -e "s/half.h5/compliant.h5/" \
      half.nml > compliant.nml
  { sed -e "s/half.h5/static.h5/" -e "/velocity = 'mode'/d" half.nml; echo "&analysis kind = 'static' /"; } \
    > static.nml
  for name in reduced compliant static; do run $name; done

  # the model and the time scheme: the state's unknowns and what they mean
  refused 'another mesh' 'mesh.elements is 8 in the file and 16 in this scene' "s/elements = 8/elements = 16/"
  refused 'another basis' "mesh.basis is 'hermite' in the file and 'bspline' in this scene" \
    "s/basis = 'hermite'/basis = 'bspline'/"
  refused 'a reduced run continued by the full model' \
    "mesh.reduction is 'craig-bampton' in the file and 'none' in this scene" "s/half.h5/reduced.h5/"
  refused 'another length' 'beam.length is 0.5 in the file and 0.6 in this scene' "s/length = 0.5,/length = 0.6,/"
  refused 'another damping' 'beam.rayleigh_mass is 2 in the file and 3 in this scene' \
    "s/rayleigh_mass = 2/rayleigh_mass = 3/"
  refused 'another scheme' "time.scheme is 'velocity' in the file and 'position' in this scene" \
    "s/scheme = 'velocity'/scheme = 'position'/"
  refused 'another time step' 'time.dt is 2e-5 in the file and 1e-5 in this scene' "s/dt = 2e-5/dt = 1e-5/"
  refused 'another theta' 'time.theta is 0.5 in the file and 0.75 in this scene' "s/dt = 2e-5,/dt = 2e-5, theta = 0.75,/"
  refused 'another gamma' 'time.gamma is 0.5 in the file and 1 in this scene' "s/dt = 2e-5,/dt = 2e-5, gamma = 1,/"
  # the contact points
  refused 'both stops moved to another node' 'contact point 1 x is 0.5 in the file and 0.4375 in this scene' \
    "s/x_from(1) = 0.5/x_from(1) = 0.4375/; s/x_from(2) = 0.5/x_from(2) = 0.4375/"
  refused 'one stop moved' 'contact points is 1 in the file and 2 in this scene' "s/x_from(1) = 0.5/x_from(1) = 0.4375/"
  # the compliant stops: their kind, place, level, stiffness and exponent
  refused 'a rigid stop made compliant' 'obstacles.stiffness(1) is 0 in the file and 100000 in this scene' \
    "s/level_from(1) = -1e-3,/level_from(1) = -1e-3, stiffness(1) = 1e5,/"
  refused 'a compliant stop made rigid' 'obstacles.stiffness(1) is 100000 in the file and 0 in this scene' \
    "s/half.h5/compliant.h5/"
  refused 'a stiffer compliant stop' 'obstacles.stiffness(1) is 100000 in the file and 200000 in this scene' \
    "s/half.h5/compliant.h5/; s/level_from(1) = -1e-3,/level_from(1) = -1e-3, stiffness(1) = 2e5,/"
  refused 'a compliant stop moved' 'obstacles.level_from(1) is -0.001 in the file and -9e-4 in this scene' \
    "s/half.h5/compliant.h5/; s/level_from(1) = -1e-3,/level_from(1) = -0.9e-3, stiffness(1) = 1e5,/"
  refused 'a compliant stop with another exponent' 'obstacles.exponent(1) is 1 in the file and 1.5 in this scene' \
    "s/half.h5/compliant.h5/; s/level_from(1) = -1e-3,/level_from(1) = -1e-3, stiffness(1) = 1e5, exponent(1) = 1.5,/"
  refused 'a compliant stop added' 'obstacles.count is 2 in the file and 3 in this scene' \
    "s/count = 2,/count = 3, side(3) = 'above', x_from(3) = 0.5, level_from(3) = 2e-3, stiffness(3) = 1e5,/"
  # what the file is
  refused 'a static result' 'holds no checkpoint' "s/half.h5/static.h5/"
  refused 'an end before the checkpoint' 't_end = 0.05 s is not after the checkpoint' "s/t_end = 0.2/t_end = 0.05/"
  refused 'the output is the file continued' 'is the file that &initial from_file continues' "s/continued.h5/half.h5/"
  refused 'the stops moved onto the beam position' 'outside the changed obstacles there' \
    "s/level_from(1) = -1e-3/level_from(1) = -1e-9/; s/level_from(2) = 1e-3/level_from(2) = 1e-9/"
  # what may change; the initial state beside from_file is ignored, with a warning
  accepted 'the initial velocity given beside from_file' '' \
    "&initial velocity is ignored: from_file continues the state of its checkpoint"
  accepted 'the rigid stops moved apart' "s/level_from(1) = -1e-3/level_from(1) = -2e-3/; s/level_from(2) = 1e-3/level_from(2) = 2e-3/"
  accepted 'a compliant stop with damping' \
    "s/half.h5/compliant.h5/; s/level_from(1) = -1e-3,/level_from(1) = -1e-3, stiffness(1) = 1e5, damping(1) = 0.5,/"
  ;;

planes)
  # planes_scene NAME T_END KIND [FROM_FILE]: restart_planes.nml.in with rigid or
  # compliant walls
  planes_scene() {
    local walls=('' '' '')
    [ "$3" = compliant ] && walls=('stiffness(1) = 1e6, damping(1) = 5,' 'stiffness(2) = 1e6, damping(2) = 5,' \
                                   'stiffness(3) = 1e6, damping(3) = 5,')
    sed -e "s|@FILE@|$1.h5|" -e "s|@T_END@|$2|" -e "s|@KIND@|$3|" -e "s|@T_HALF@|0.1524|" \
        -e "s|@STOP1@|${walls[0]}|" -e "s|@STOP2@|${walls[1]}|" -e "s|@STOP3@|${walls[2]}|" \
        -e "s|@FROM_FILE@|${4:+, from_file = '$4'}|" "$here/restart_planes.nml.in" > "$1.nml"
  }
  scheme=velocity; basis=hermite
  for kind in rigid compliant; do
    planes_scene full 0.3 $kind
    planes_scene half 0.1524 $kind
    planes_scene continued 0.3 $kind half.h5
    for name in full half continued; do run $name; done
    echo "two planes, $kind walls:"
    "$compare" full.h5 continued.h5 || failed=1
    [ $kind = compliant ] && break
    # what must match, and what may change (rigid walls)
    refused 'a z plane of its own' 'beam.inertia_z is not given in the file and 3e-9 in this scene' \
      "s/planes = 2/planes = 2, inertia_z = 3e-9/"
    refused 'a hole moved along the beam' \
      'point of the obstacles 1 x is 0.39999999999999997 in the file and 0.5 in this scene' \
      "s/x_from(1) = 0.4/x_from(1) = 0.5/"
    refused 'a rigid hole shrunk onto the beam' 'is outside the circle of &obstacles 1' \
      "s/radius(1) = 0.25e-3/radius(1) = 1e-6/"
    accepted 'a rigid hole widened' "s/radius(1) = 0.25e-3/radius(1) = 0.3e-3/"
  done
  # a compliant wall keeps its size (its spring's energy is part of the checkpoint)
  refused 'a compliant hole widened' 'obstacles.radius(1) is 2.5e-4 in the file and 3e-4 in this scene' \
    "s/radius(1) = 0.25e-3/radius(1) = 0.3e-3/"
  # a planar checkpoint (restart.nml.in's two tip stops) continued by a beam of two planes
  scene half 0.1
  scene continued 0.2 half.h5
  run half
  refused 'a planar checkpoint continued in two planes' 'beam.planes is 1 in the file and 2 in this scene' \
    "s/rayleigh_mass = 2/rayleigh_mass = 2, planes = 2/"
  ;;

checksum)
  scheme=velocity; basis=hermite
  scene half 0.1
  scene continued 0.2 half.h5
  run half
  cp half.h5 pristine.h5
  # damaged DESCRIPTION EDIT_ARGUMENTS...: a copy of half.h5 damaged by edit_checkpoint is
  # refused, naming the checksum
  damaged() {
    local description=$1
    shift
    cp pristine.h5 half.h5
    "$edit" half.h5 "$@" || { echo "FAIL $description: edit_checkpoint $*"; failed=1; return; }
    refused "$description" 'fails its checksum' ''
  }
  damaged 'the last bit of one displacement' flip stepper.u 3 0
  damaged 'the sign of one velocity' flip stepper.v 7 63
  damaged 'an exponent bit of a running energy sum' flip stepper.energy_sums 2 52
  damaged 'the step count' flip stepper.steps 1 0
  damaged 'the spectrum buffer' flip spectrum.buffer 1 40
  cp pristine.h5 half.h5
  accepted 'the undamaged checkpoint' ''
  "$edit" half.h5 drop-checksum || { echo "FAIL edit_checkpoint drop-checksum"; failed=1; }
  accepted 'a checkpoint without a checksum (vibrobeam 0.2.0)' '' 'carries no checksum'
  ;;

*)
  echo "unknown mode $mode"; exit 2 ;;
esac
exit $failed
