#!/usr/bin/env python3
"""The roots b_n = beta_n L of the frequency equations of a uniform Euler-Bernoulli beam on
every pair of end supports among clamped, pinned, sliding (rotation held, deflection free)
and free (docs/theory.md section 7; Blevins, "Formulas for natural frequency and mode
shape", 1979, table 8-1), to 22 decimals, for the tests' references (verification/modes).

    clamped-free                 1 + cos b cosh b = 0
    clamped-clamped, free-free   1 - cos b cosh b = 0
    pinned-pinned, sliding-sliding   sin b = 0
    clamped-pinned, pinned-free  tan b - tanh b = 0
    clamped-sliding, sliding-free    tan b + tanh b = 0
    sliding-pinned               cos b = 0

(free-free has two rigid-body modes, pinned-free, sliding-free and sliding-sliding one,
at b = 0, not listed.) How: as scripts/cantilever_roots.py, Python's decimal arithmetic at
60 digits (standard library only); Newton's method on overflow-free forms (cos b -+
1/cosh b, sin b -+ cos b tanh b) from the asymptotic root, until a step is below 1e-50;
each line gives the residual, a check of the printed digits (|f'| is about 1 at a root).

usage: python3 scripts/support_roots.py [COUNT]    (COUNT roots of each equation, default 4)
"""
import sys
from decimal import Decimal, getcontext

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from cantilever_roots import PI, sin_cos  # noqa: E402  (the same 60-digit pi, sin, cos)

getcontext().prec = 60


def hyperbolic(b):
    cosh = (b.exp() + (-b).exp()) / 2
    tanh = (b.exp() - (-b).exp()) / 2 / cosh
    return cosh, tanh


def f_cc(b):
    s, c = sin_cos(b)
    cosh, tanh = hyperbolic(b)
    return c - 1 / cosh, -s + tanh / cosh


def f_cf(b):
    s, c = sin_cos(b)
    cosh, tanh = hyperbolic(b)
    return c + 1 / cosh, -s - tanh / cosh


def f_cp(b):
    s, c = sin_cos(b)
    cosh, tanh = hyperbolic(b)
    return s - c * tanh, c + s * tanh - c / cosh ** 2


def f_cs(b):
    s, c = sin_cos(b)
    cosh, tanh = hyperbolic(b)
    return s + c * tanh, c - s * tanh + c / cosh ** 2


EQUATIONS = [
    ('clamped-free', f_cf, lambda n: (2 * n - 1) * PI / 2 if n > 1 else Decimal('1.875')),
    ('clamped-clamped, free-free', f_cc, lambda n: (2 * n + 1) * PI / 2),
    ('clamped-pinned, pinned-free', f_cp, lambda n: (4 * n + 1) * PI / 4),
    ('clamped-sliding, sliding-free', f_cs, lambda n: (4 * n - 1) * PI / 4),
]


def newton(f, b):
    for _ in range(100):
        value, slope = f(b)
        step = value / slope
        b -= step
        if abs(step) < Decimal(10) ** -50:
            break
    return b, f(b)[0]


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 4
    for name, f, start in EQUATIONS:
        print(name)
        for n in range(1, count + 1):
            b, residual = newton(f, start(n))
            print(f'{n:3d}  {b:.22f}  residual {float(residual):.1e}')
    print('pinned-pinned, sliding-sliding: n pi; sliding-pinned: (n - 1/2) pi')
    for n in range(1, count + 1):
        print(f'{n:3d}  {n * PI:.22f}  {(n - Decimal(1) / 2) * PI:.22f}')


if __name__ == '__main__':
    main()
