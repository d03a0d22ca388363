#!/usr/bin/env python3
"""Equivalent restitution of the Hunt-Crossley stop f = k p^a max(0, 1 + 3/2 alpha pdot)
for a mass m arriving at speed v (one degree of freedom): e = -pdot(end)/v.
Scaling p = v/omega P, t = T/omega (omega^2 = k/m for a = 1) shows that e depends on
alpha v only (and on a). Integrates with RK4 (2e5 steps per contact, converged to 1e-9)
and solves e(alpha v) = target by bisection. Usage: restitution.py [a] [target e]."""
import sys

def restitution(av, a=1.0, steps=200000):
    # dimensionless: P'' = -P^a max(0, 1 + 1.5 av P'), P(0) = 0, P'(0) = 1
    def acc(p, q):
        return -(max(p, 0.0) ** a) * max(0.0, 1 + 1.5 * av * q)
    p, q, h = 0.0, 1.0, 20.0 / steps
    for _ in range(steps):
        k1p, k1q = q, acc(p, q)
        k2p, k2q = q + 0.5 * h * k1q, acc(p + 0.5 * h * k1p, q + 0.5 * h * k1q)
        k3p, k3q = q + 0.5 * h * k2q, acc(p + 0.5 * h * k2p, q + 0.5 * h * k2q)
        k4p, k4q = q + h * k3q, acc(p + h * k3p, q + h * k3q)
        pn = p + h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p)
        qn = q + h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q)
        if pn < 0:  # left the stop within this step: free flight after, speed constant
            return -qn
        p, q = pn, qn
    return -q

if __name__ == '__main__':
    a = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
    target = float(sys.argv[2]) if len(sys.argv) > 2 else 0.8
    lo, hi = 0.0, 5.0
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if restitution(mid, a, 20000) > target:
            lo = mid
        else:
            hi = mid
    av = 0.5 * (lo + hi)
    print(f"a = {a}: e = {target} at alpha v = {av:.6f} (e check {restitution(av, a):.6f}); "
          f"Hunt-Crossley 1 - e = {1 - target:.4f}, Lankarani-Nikravesh (1 - e^2)/2 = {(1 - target**2) / 2:.4f}")
