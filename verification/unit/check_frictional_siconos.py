#!/usr/bin/python3
"""vibrobeam's 2-D frictional contact solver against Siconos (test
unit.frictional_contact_siconos; docs/method.md, "Frictional contact in two dimensions:
the solver").

usage: check_frictional_siconos.py DRIVER WORK_DIRECTORY

Generates problems u = D r + q (m contacts, (normal, tangent) per contact), has
frictional_contact_driver (DRIVER) solve them through a text file, solves them with
Siconos' numerics (FrictionContactProblem of dimension 2: fc2d NSGS with a tolerance of
1e-15, and the enumeration fc2d_enum for m = 1), and compares the impulses.

Families (seeded, every run the same problems):
* unique: D = B^T B + 0.2 I, mu_max kappa(D) <= 1/2, so the solution is unique
  (docs/method.md, uniqueness) and both codes must give it: |r - r_siconos| below the
  bound derived in `agreement_bound`;
* general: mu in [0, 2], solutions may be several; vibrobeam's must satisfy the Coulomb
  conditions (checked here, independently of the Fortran) and the number of problems on
  which both codes agree is printed;
* semidefinite: D = H H^T of rank m with q = H v (the scheme's structure).
Every problem is built from a chosen solution (a state per contact: separating, sticking
or slipping), so all three states occur.

Exit 0 when every check holds, 1 otherwise, 77 (ctest SKIP_RETURN_CODE) when Siconos'
Python module is missing.
"""
import os
import subprocess
import sys

try:
    import numpy as np
    import siconos.numerics as sn
except ImportError as missing:
    print(f"SKIP: no Siconos for this python3 ({missing}); install Debian's python3-siconos",
          file=sys.stderr)
    sys.exit(77)

EPS = np.finfo(float).eps


def coulomb_violation(d, q, mu, r):
    """Largest violation of the Coulomb conditions by r, relative to the velocity scale
    sigma = max(|q|, |D| |r|) (|D| the largest |D_ij|): Signorini (p >= 0, u_N >= 0,
    min(|D| p, u_N) = 0), the cone (|r_T| <= mu p), stick or slip
    (min(|u_T|, |D| (mu p - |r_T|)) = 0) and slip against the motion (r_T u_T <= 0).
    Returns (rho, sigma)."""
    u = d @ r + q
    d_max = np.abs(d).max()
    sigma = max(np.abs(q).max(), d_max * np.abs(r).max(), np.finfo(float).tiny)
    p, r_t, u_n, u_t = r[0::2], r[1::2], u[0::2], u[1::2]
    terms = [-d_max * p, -u_n, np.minimum(d_max * np.maximum(p, 0), np.maximum(u_n, 0)),
             d_max * (np.abs(r_t) - mu * p),
             np.minimum(np.abs(u_t), d_max * (mu * p - np.abs(r_t))),
             np.where(r_t * u_t > 0, np.minimum(np.abs(u_t), d_max * np.abs(r_t)), 0.0)]
    return max(0.0, max(term.max() for term in terms)) / sigma, sigma


def agreement_bound(d, mu, rho_1, rho_2, sigma):
    """Bound on |r_1 - r_2|_2 for two approximate solutions of a problem with a unique
    solution. A violation rho sigma of a condition on u is a change of q of that size, one
    on r a change of r of rho sigma / |D| (which moves u by at most 2m rho sigma): r_k is
    then the exact solution for q + e_k with |e_k|_2 <= sqrt(2m) (2m + 1) rho_k sigma,
    moved by |dr_k|_2 <= sqrt(2m) rho_k sigma / |D|. For exact solutions of q + e_1 and
    q + e_2 the argument of docs/method.md (uniqueness) gives
    |r_1 - r_2| <= (1 + mu_max) |e_1 - e_2| / (lambda_min (1 - mu_max kappa))."""
    two_m = d.shape[0]
    eigenvalues = np.linalg.eigvalsh(d)
    kappa = eigenvalues[-1] / eigenvalues[0]
    mu_max = mu.max() if mu.size else 0.0
    rho = max(rho_1, EPS) + max(rho_2, EPS)
    e = np.sqrt(two_m) * (two_m + 1) * rho * sigma
    dr = np.sqrt(two_m) * rho * sigma / np.abs(d).max()
    return (1 + mu_max) * e / (eigenvalues[0] * (1 - mu_max * kappa)) + dr


def built_problem(rng, d, mu):
    """q = u* - D r* for a solution (r*, u*) with a random state per contact."""
    m = mu.size
    r, u = np.zeros(2 * m), np.zeros(2 * m)
    for i in range(m):
        state = rng.integers(0, 4)
        if state == 0:                       # separating
            u[2 * i] = rng.uniform(0, 1)
            u[2 * i + 1] = rng.uniform(-1, 1)
        elif state == 1:                     # sticking
            r[2 * i] = rng.uniform(0.1, 1.1)
            r[2 * i + 1] = rng.uniform(-1, 1) * mu[i] * r[2 * i]
        else:                                # slipping
            r[2 * i] = rng.uniform(0.1, 1.1)
            u[2 * i + 1] = rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 1.1)
            r[2 * i + 1] = -mu[i] * r[2 * i] * np.sign(u[2 * i + 1])
    return u - d @ r


def make_problems():
    rng = np.random.default_rng(20261127)
    problems = []
    for m in (1, 2, 3, 4, 5, 10, 20, 30, 50):
        for _ in range(4):
            b = rng.uniform(-1, 1, (2 * m, 2 * m)) / np.sqrt(2 * m)
            d = b.T @ b + 0.2 * np.eye(2 * m)
            d = 0.5 * (d + d.T)
            eigenvalues = np.linalg.eigvalsh(d)
            kappa = eigenvalues[-1] / eigenvalues[0]
            mu = rng.uniform(0, 0.5 / kappa, m)
            mu[rng.uniform(size=m) < 0.15] = 0.0
            problems.append(('unique', d, built_problem(rng, d, mu), mu))
            mu = rng.uniform(0, 2, m)
            problems.append(('general', d, built_problem(rng, d, mu), mu))
        h = rng.uniform(-1, 1, (2 * m, m))
        problems.append(('semidefinite', h @ h.T, h @ rng.uniform(-1, 1, m), rng.uniform(0, 2, m)))
    return problems


def write_problems(path, problems):
    with open(path, 'w') as handle:
        handle.write(f"{len(problems)}\n")
        for _, d, q, mu in problems:
            handle.write(f"{mu.size}\n")
            handle.write(' '.join(repr(float(x)) for x in mu) + '\n')
            handle.write(' '.join(repr(float(x)) for x in q) + '\n')
            for row in d:
                handle.write(' '.join(repr(float(x)) for x in row) + '\n')


def read_results(path, problems):
    results = []
    with open(path) as handle:
        for _, _, q, _ in problems:
            stat, pivots = (int(word) for word in handle.readline().split())
            impulse = np.array([float(word) for word in handle.readline().split()])
            results.append((stat, pivots, impulse.reshape(q.shape)))
    return results


def siconos_solve(d, q, mu, solver):
    problem = sn.FrictionContactProblem(2, mu.size, d, q, mu)
    options = sn.SolverOptions(solver)
    if solver == sn.SICONOS_FRICTION_2D_NSGS:
        options.dparam[sn.SICONOS_DPARAM_TOL] = 1e-15
        options.iparam[sn.SICONOS_IPARAM_MAX_ITER] = 100000
    r, u = np.zeros(q.size), np.zeros(q.size)
    info = sn.fc2d_driver(problem, r, u, options)
    return info, r


def main():
    driver, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    problems = make_problems()
    problems_path = os.path.join(work, 'frictional_problems.txt')
    results_path = os.path.join(work, 'frictional_results.txt')
    write_problems(problems_path, problems)
    subprocess.run([driver, problems_path, results_path], check=True)
    results = read_results(results_path, problems)

    failures = 0
    worst = {}
    agree_general = compared_general = 0
    print(f"{'family':>12} {'m':>3} {'reference':>9} {'rho vibrobeam':>14} {'rho siconos':>12} "
          f"{'|dr|':>10} {'bound':>10}")
    for (family, d, q, mu), (stat, pivots, r) in zip(problems, results):
        m = mu.size
        rho, sigma = coulomb_violation(d, q, mu, r)
        # vibrobeam's own check is rho <= 1e-10; a solver result must hold it
        if stat != 0 or rho > 1e-10:
            print(f"FAIL {family} m = {m}: stat {stat}, Coulomb violation {rho:.2e} > 1e-10")
            failures += 1
            continue
        worst[family + ' rho'] = max(worst.get(family + ' rho', 0.0), rho / 1e-10)
        references = [('nsgs', sn.SICONOS_FRICTION_2D_NSGS)]
        if m == 1:   # Siconos' enumeration returns info 1 on most problems with m >= 2
            references.append(('enum', sn.SICONOS_FRICTION_2D_ENUM))
        for name, solver in references:
            info, r_siconos = siconos_solve(d, q, mu, solver)
            rho_siconos, _ = coulomb_violation(d, q, mu, r_siconos)
            if info != 0 or rho_siconos > 1e-8:
                print(f"{family:>12} {m:3d} {name:>9} Siconos did not solve it "
                      f"(info {info}, Coulomb violation {rho_siconos:.1e}): not compared")
                if family == 'unique':
                    failures += 1   # a unique problem is the comparison: it must happen
                continue
            difference = np.linalg.norm(r - r_siconos)
            if family == 'general':
                compared_general += 1
                agree_general += difference <= 1e-8 * max(1.0, np.linalg.norm(r))
                continue
            if family == 'semidefinite':
                continue        # r need not be unique when D is singular: only rho above
            bound = agreement_bound(d, mu, rho, rho_siconos, sigma)
            print(f"{family:>12} {m:3d} {name:>9} {rho:14.2e} {rho_siconos:12.2e} "
                  f"{difference:10.2e} {bound:10.2e}")
            worst['unique |dr|/bound'] = max(worst.get('unique |dr|/bound', 0.0), difference / bound)
            if difference > bound:
                print(f"FAIL unique m = {m} against {name}: |r - r_siconos| = {difference:.3e} "
                      f"> bound {bound:.3e}")
                failures += 1
    print(f"general (mu in [0, 2], possibly several solutions): vibrobeam and Siconos NSGS/enum agree "
          f"to 1e-8 on {agree_general} of {compared_general} comparisons; every vibrobeam result "
          f"satisfies the Coulomb conditions")
    for key, value in sorted(worst.items()):
        print(f"largest {key} (/ tolerance): {value:.3e}")
    print(f"check_frictional_siconos: {len(problems)} problems, {failures} failures")
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
