"""The bilinear oscillator of free_bilinear.nml and its closed-form period, shared by
check_bilinear_period.py (single orbits) and check_backbone.py (the backbone).

The scene is a one-unknown cantilever condensed on its tip: mass m = 33/140 rho A L and
stiffness k = 3 EI/L^3, a stop of stiffness k_s (exponent 1) at the gap g above it
(docs/method.md, "Autonomous periodic orbits", "The bilinear reference"):
  w0 = sqrt(k/m), w1 = sqrt((k + k_s)/m), q_e = k_s g/(k + k_s),
  t_c = arccos((g - q_e)/(A - q_e))/w1            (from q = A down to the stop),
  v_g = (A - q_e) w1 sin(w1 t_c),  B = sqrt(g^2 + (v_g/w0)^2),
  T = 2 t_c + 2 (pi - arccos(g/B))/w0,
and below the gap (A <= g) the free oscillator's 2 pi/w0, which the trapezoidal rule of P
steps makes the discrete T = 2 P tan(pi/P)/w0 (docs/method.md, "The linear reference").
"""
import math
import os
import re
import sys


def from_command_line(argv):
    """The arguments VIBROBEAM SCENE.nml [STIFFNESS_FACTOR] of the checks that use this
    reference: the program's path, the scene's text and its oscillator (k_s times the
    factor, default 1)."""
    vibrobeam, scene = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    factor = float(argv[3]) if len(argv) > 3 else 1.0
    text = open(scene).read()
    return vibrobeam, text, BilinearOscillator(text, factor)


class BilinearOscillator:
    """The numbers of a bilinear scene's text (its first occurrences), k_s times `factor`."""

    def __init__(self, text, factor=1.0):
        self.text = text
        E, rho, area, inertia, length = (self.number(n) for n in ('youngs_modulus', 'density', 'area', 'inertia',
                                                                   'length'))
        self.k = 3 * E * inertia / length**3
        self.m = 33.0 / 140.0 * rho * area * length
        self.ks = self.number('stiffness(1)') * factor
        self.g = self.number('level_from(1)')
        self.w0 = math.sqrt(self.k / self.m)
        self.w1 = math.sqrt((self.k + self.ks) / self.m)

    def number(self, name):
        """The value of `name` in the scene (first occurrence)."""
        match = re.search(r'\b' + re.escape(name) + r'\s*=\s*([-+0-9.eE]+)', self.text)
        return float(match.group(1))

    def period(self, amplitude):
        """The closed-form period at the tip amplitude `amplitude` (module doc)."""
        g, k, ks, w0, w1 = self.g, self.k, self.ks, self.w0, self.w1
        if amplitude <= g:
            return 2 * math.pi / w0
        qe = ks * g / (k + ks)
        tc = math.acos((g - qe) / (amplitude - qe)) / w1
        vg = (amplitude - qe) * w1 * math.sin(w1 * tc)
        b = math.hypot(g, vg / w0)
        return 2 * tc + 2 * (math.pi - math.acos(g / b)) / w0

    def free_amplitude(self, amplitude):
        """B, the amplitude of the free arc of the orbit of tip amplitude `amplitude` > g."""
        qe = self.ks * self.g / (self.k + self.ks)
        tc = math.acos((self.g - qe) / (amplitude - qe)) / self.w1
        vg = (amplitude - qe) * self.w1 * math.sin(self.w1 * tc)
        return math.hypot(self.g, vg / self.w0)

    def leading_bound(self, period, steps):
        """The trapezoidal rule's leading phase error of the stiffer arc, T (w1 T/P)^2/12,
        times 1.1 (the expansion's next terms: check_bilinear_period.py)."""
        return 1.1 * period * (self.w1 * period / steps)**2 / 12

    def discrete_linear(self, steps, tolerance):
        """Below the gap: the discrete linear period 2 P tan(pi/P)/w0 and its round-off
        bound c (tol + 2 noise)/(2 pi cos^2(pi/P)) T, c = sqrt(2) (the energy norm at the
        guess against the mode's own), noise = 8 eps P (one evaluation's round-off)."""
        expected = 2 * steps * math.tan(math.pi / steps) / self.w0
        noise = 8 * sys.float_info.epsilon * steps
        bound = math.sqrt(2) * (tolerance + 2 * noise) / (2 * math.pi * math.cos(math.pi / steps)**2) * expected
        return expected, bound

    def reference(self, amplitude, steps, tolerance):
        """The period the run at `amplitude`, P = `steps`, must meet and its bound: the
        discrete linear one below the gap, the closed form with the leading-order bound
        above it."""
        if amplitude <= self.g:
            return self.discrete_linear(steps, tolerance)
        expected = self.period(amplitude)
        return expected, self.leading_bound(expected, steps)
