#!/usr/bin/env python3
"""The roots b_n = beta_n L of 1 + cos(b) cosh(b) = 0, the frequency equation of the
clamped-free Euler-Bernoulli beam (docs/theory.md section 7), to 22 decimals.

How: Python's decimal arithmetic at 60 significant digits (the standard library only),
pi by Machin's formula pi/4 = 4 arctan(1/5) - arctan(1/239), sin and cos by their Taylor
series after reduction modulo 2 pi, cosh by Decimal.exp; Newton's method on the
overflow-free form g(b) = cos(b) + 1/cosh(b), g'(b) = -sin(b) - tanh(b)/cosh(b), from
(2n - 1) pi/2 (1.875 for n = 1), until a step is below 1e-50. Each line gives n, b_n and
the residual g(b_n), a check of the printed digits: |g'| is about 1 near a root, so the
residual bounds the root's error. These are the roots the verification tests quote
(verification/modes) and from which README's frequency tables are computed.

usage: python3 scripts/cantilever_roots.py [COUNT]    (COUNT roots, default 6)
"""
import sys
from decimal import Decimal, getcontext

getcontext().prec = 60
TINY = Decimal(10) ** -58


def arctan_of_inverse(k):
    """arctan(1/k) for an integer k > 1, by its alternating series."""
    x = Decimal(1) / k
    power, total, n, sign = x, x, 1, 1
    while True:
        power *= x * x
        n += 2
        sign = -sign
        term = power / n
        if term < TINY:
            return total
        total += sign * term


PI = 4 * (4 * arctan_of_inverse(5) - arctan_of_inverse(239))


def sin_cos(x):
    """(sin x, cos x) by the Taylor series of x reduced to [0, 2 pi)."""
    x = x % (2 * PI)
    s, c, term, n = Decimal(0), Decimal(0), Decimal(1), 0
    while abs(term) > TINY or n < 4:
        if n % 4 == 0:
            c += term
        elif n % 4 == 1:
            s += term
        elif n % 4 == 2:
            c -= term
        else:
            s -= term
        n += 1
        term = term * x / n
    return s, c


def root(n):
    """The n-th positive root of cos(b) + 1/cosh(b) = 0."""
    b = Decimal('1.875') if n == 1 else (2 * n - 1) * PI / 2
    for _ in range(100):
        s, c = sin_cos(b)
        cosh = (b.exp() + (-b).exp()) / 2
        tanh = (b.exp() - (-b).exp()) / 2 / cosh
        step = (c + 1 / cosh) / (-s - tanh / cosh)
        b -= step
        if abs(step) < Decimal(10) ** -50:
            break
    s, c = sin_cos(b)
    cosh = (b.exp() + (-b).exp()) / 2
    return b, c + 1 / cosh


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    for n in range(1, count + 1):
        b, residual = root(n)
        print(f'{n:3d}  {b:.22f}  residual {float(residual):.1e}')


if __name__ == '__main__':
    main()
