#!/usr/bin/env python3
"""A beam of two planes on a flat stop with Coulomb friction: vibrobeam against Siconos
(issue 21, "Friction against an independent solver").

usage: check_friction_siconos.py DRIVER SCENE.nml WORK_DIR

DRIVER (friction_siconos_driver) steps the scene with vibrobeam and writes its discrete
model (M and K of one plane, the unit point load, U0, V0, the load, the stop, mu, e, dt)
and the tip's history. This script steps the same discrete system with Siconos 4.x:
a LagrangianLinearTIDS of 2J unknowns (y then z, M and K block diagonal), the constant
load F (cos a, sin a) on the tip's point-load vector, one LagrangianLinearTIR with the
normal row (the tip's y, against the level) and the tangent row (the tip's z), a
NewtonImpactFrictionNSL(e, 0, mu, 2), MoreauJeanOSI(1/2) and a FrictionContact(2)
one-step problem (NSGS to 1e-14). Both schemes are the velocity (Moreau-Jean) scheme with
Newton's law on every active point and Coulomb's at V^{n+1}, so every step must agree:
the tip's y and z within 1e-9 of the gap (the issue's criterion) at every step, with the
stop held, in stick and in slip phases (counted and required).
Exit 0 when every check holds, 1 otherwise, 77 without Siconos (python_siconos.sh).
"""
import os
import subprocess
import sys

import numpy as np
import siconos.kernel as sk
import siconos.numerics as sn


def read_model(path):
    with open(path) as handle:
        j, kd, tip = (int(word) for word in handle.readline().split())
        mass = np.zeros((j, j))
        stiffness = np.zeros((j, j))
        for matrix in (mass, stiffness):
            for col in range(j):
                values = [float(word) for word in handle.readline().split()]
                for offset, value in enumerate(values):
                    if col + offset < j:
                        matrix[col + offset, col] = value
                        matrix[col, col + offset] = value
        point = np.array([float(handle.readline()) for _ in range(j)])
        u0 = np.array([float(handle.readline()) for _ in range(2 * j)])
        v0 = np.array([float(handle.readline()) for _ in range(2 * j)])
        words = handle.readline().split()
    force, share_y, share_z, level, side, mu, restitution, dt = (float(w) for w in words[:8])
    steps = int(words[8])
    return dict(j=j, tip=tip - 1, mass=mass, stiffness=stiffness, point=point, u0=u0, v0=v0, force=force,
                shares=(share_y, share_z), level=level, side=side, mu=mu, e=restitution, dt=dt, steps=steps)


def siconos_history(m):
    j = m['j']
    zero = np.zeros((j, j))
    mass = np.block([[m['mass'], zero], [zero, m['mass']]])
    stiffness = np.block([[m['stiffness'], zero], [zero, m['stiffness']]])
    beam = sk.LagrangianLinearTIDS(m['u0'], m['v0'], mass)
    beam.setKPtr(stiffness)
    load = np.concatenate([m['shares'][0] * m['point'], m['shares'][1] * m['point']]) * m['force']
    beam.setFExtPtr(load)
    rows = np.zeros((2, 2 * j))
    rows[0, m['tip']] = m['side']          # the normal gap side (y - level) >= 0 (below)
    rows[1, j + m['tip']] = 1.0            # the tangent: the tip's z (vibrobeam's t = (-h_z, h_y))
    relation = sk.LagrangianLinearTIR(rows, [-m['side'] * m['level'], 0.0])
    law = sk.NewtonImpactFrictionNSL(m['e'], 0.0, m['mu'], 2)
    interaction = sk.Interaction(law, relation)
    system = sk.NonSmoothDynamicalSystem(0.0, m['steps'] * m['dt'])
    system.insertDynamicalSystem(beam)
    system.link(interaction, beam)
    integrator = sk.MoreauJeanOSI(0.5)
    problem = sk.FrictionContact(2, sn.SICONOS_FRICTION_2D_NSGS)
    problem.numericsSolverOptions().iparam[0] = 100000
    problem.numericsSolverOptions().dparam[0] = 1e-14
    simulation = sk.TimeStepping(system, sk.TimeDiscretisation(0.0, m['dt']), integrator, problem)
    history = np.zeros((m['steps'], 5))
    for n in range(m['steps']):
        simulation.computeOneStep()
        q = beam.q()
        v = beam.velocity()
        history[n] = (simulation.nextTime(), q[m['tip']], q[j + m['tip']], v[m['tip']], v[j + m['tip']])
        simulation.nextStep()
    return history


def main():
    driver, scene, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    model_file = os.path.join(work, 'model.txt')
    history_file = os.path.join(work, 'vibrobeam.txt')
    subprocess.run([driver, scene, model_file, history_file], check=True)
    m = read_model(model_file)
    ours = np.loadtxt(history_file)
    theirs = siconos_history(m)
    gap = abs(m['level'])
    failures = 0
    # y and z of the tip at every step, within 1e-9 of the gap
    deviation = np.max(np.abs(ours[:, 1:3] - theirs[:, 1:3]), axis=1)
    worst = int(np.argmax(deviation))
    print(f'largest |tip (y, z) vibrobeam - Siconos| = {deviation[worst]:.3e} m = {deviation[worst] / gap:.3e} of '
          f'the gap, at step {worst + 1} (t = {ours[worst, 0]:.5f} s)')
    if deviation[worst] > 1e-9 * gap:
        print('FAIL: the tip differs from Siconos by more than 1e-9 of the gap')
        failures += 1
    # the phases the comparison went through: held steps (p > 0), sticking (|v_z| ~ 0)
    # or slipping among them
    held = ours[:, 5] > 0
    speed_scale = np.max(np.abs(ours[:, 4]))
    stick = held & (np.abs(ours[:, 4]) <= 1e-9 * speed_scale)
    slip = held & ~stick
    print(f'{int(held.sum())} held steps: {int(stick.sum())} sticking, {int(slip.sum())} slipping; '
          f'impacts (held after free) {int(np.sum(held[1:] & ~held[:-1]) + held[0])}')
    for name, count in (('held', held.sum()), ('sticking', stick.sum()), ('slipping', slip.sum())):
        if count < 10:
            print(f'FAIL: fewer than 10 {name} steps: the comparison does not cover that phase')
            failures += 1
    # friction at work: somewhere |r_T| reaches mu p (slip) and somewhere stays below (stick)
    ratio = np.abs(ours[held, 6]) / (m['mu'] * ours[held, 5])
    print(f'|r_T| / (mu p) over the held steps: from {ratio.min():.3f} to {ratio.max():.3f}')
    print(f'check_friction_siconos: {failures} failure(s)')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
