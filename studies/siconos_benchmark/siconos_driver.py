#!/usr/bin/python3
"""Siconos side of the side-by-side benchmark (REPORT.md beside this file).

Steps vibrobeam's discrete beam (M, K and the load vector written by export_model) with
Siconos 4.x's MoreauJeanOSI (theta = 1/2) and an LCP one-step problem, two tip stops at
+-gap as LagrangianLinearTIR relations with Newton's impact law (restitution e on every
active point, as vibrobeam's separating_points = 'restitution'), from rest.

usage: siconos_driver.py MODEL_FILE GAP LOAD DT STEPS E TIP_OUTPUT
Prints "seconds_per_step <s>" (the stepping loop only); writes t and the tip displacement
after every step to TIP_OUTPUT.
"""
import sys
import time

import numpy as np
import siconos.kernel as sk


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
        force = np.array([float(handle.readline()) for _ in range(j)])
    return mass, stiffness, force, tip - 1


def main():
    model_file, gap, load, dt, steps, restitution, output = sys.argv[1:8]
    gap, load, dt, restitution = float(gap), float(load), float(dt), float(restitution)
    steps = int(steps)
    mass, stiffness, force, tip = read_model(model_file)
    j = mass.shape[0]
    beam = sk.LagrangianLinearTIDS(np.zeros(j), np.zeros(j), mass)
    beam.setKPtr(stiffness)
    beam.setFExtPtr(load * force)
    law = sk.NewtonImpactNSL(restitution)
    row = np.zeros((1, j))
    row[0, tip] = 1.0
    below = sk.Interaction(law, sk.LagrangianLinearTIR(row, [gap]))    # u_tip + gap >= 0
    above = sk.Interaction(law, sk.LagrangianLinearTIR(-row, [gap]))   # gap - u_tip >= 0
    system = sk.NonSmoothDynamicalSystem(0.0, steps * dt)
    system.insertDynamicalSystem(beam)
    system.link(below, beam)
    system.link(above, beam)
    integrator = sk.MoreauJeanOSI(0.5)
    simulation = sk.TimeStepping(system, sk.TimeDiscretisation(0.0, dt), integrator, sk.LCP())
    tip_history = np.zeros((steps, 2))
    start = time.perf_counter()
    for n in range(steps):
        simulation.computeOneStep()
        tip_history[n] = (simulation.nextTime(), beam.q()[tip])
        simulation.nextStep()
    elapsed = time.perf_counter() - start
    np.savetxt(output, tip_history, fmt='%.17e')
    print(f"seconds_per_step {elapsed / steps:.6e}")


if __name__ == '__main__':
    main()
