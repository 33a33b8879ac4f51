# ray_quadric_hits against an exact Fraction oracle (integer data: tangencies, asymptotic
# directions, rulings occur exactly) and ray_torus_hits against dense sign sampling of the torus
# function along each ray (numpy float64, well-separated roots only), plus bad input.
from fractions import Fraction as F

import numpy as np
import pytest

import locus


def quadric_value(a, b, c, x):
    return sum(a[min(i, j)][max(i, j)] * x[i] * x[j] for i in range(3) for j in range(3)) + sum(
        b[i] * x[i] for i in range(3)) + c


def exact_ray_quadric(o, d, a, b, c):
    """(on_surface, [(t, multiplicity)]) for the ray o + t d, t >= 0, exactly."""
    o, d = [F(int(x)) for x in o], [F(int(x)) for x in d]
    a = [[F(int(x)) for x in row] for row in a]
    b, c = [F(int(x)) for x in b], F(int(c))
    q = [quadric_value(a, b, c, [o[i] + t * d[i] for i in range(3)]) for t in (0, 1, -1)]
    C = q[0]
    B = (q[1] - q[2]) / 2
    A = (q[1] + q[2]) / 2 - C
    if all(x == 0 for x in d):
        return False, [(0.0, 1)] if C == 0 else []
    if A == 0:
        if B == 0:
            return C == 0, []
        t = -C / B
        return False, [(float(t), 1)] if t >= 0 else []
    disc = B * B - 4 * A * C
    if disc < 0:
        return False, []
    if disc == 0:
        t = -B / (2 * A)
        return False, [(float(t), 2)] if t >= 0 else []
    s = float(disc) ** 0.5
    roots = sorted([(-float(B) - s) / (2 * float(A)), (-float(B) + s) / (2 * float(A))])
    # Signs of the roots exactly: r >= 0 decided from C, B, A.
    out = []
    for r, lower in zip(roots, (True, False)):
        # r >= 0 exactly from the signs of A q(0) and A q'(0) (q(0) = C, q'(0) = B).
        pa, va = A * C, A * B
        ok = (pa >= 0 and va < 0) if lower else (pa <= 0 or va < 0)
        if ok:
            out.append((0.0 if C == 0 and abs(r) < 1e-12 else r, 1))
    return False, out


def test_ray_quadric_hits_exact_oracle():
    rng = np.random.default_rng(2026)
    n = 300
    for _ in range(4):
        a = rng.integers(-2, 3, (3, 3)).astype(float)
        a = np.triu(a) + np.triu(a, 1).T
        b = rng.integers(-3, 4, 3).astype(float)
        c = float(rng.integers(-4, 5))
        o = rng.integers(-3, 4, (n, 3)).astype(float)
        d = rng.integers(-1, 2, (n, 3)).astype(float)
        r = locus.ray_quadric_hits(o, d, a, b, c)
        for i in range(n):
            whole, hits = exact_ray_quadric(o[i], d[i], a, b, c)
            assert r.on_surface[i] == whole
            if whole:
                continue
            assert r.count[i] == len(hits), (i, o[i], d[i])
            for j, (t, m) in enumerate(hits):
                assert r.multiplicity[i, j] == m
                assert abs(r.t[i, j] - t) <= (1e-6 if m == 2 else 1e-12 * (1 + abs(t)))
            for j in range(r.count[i]):
                x = r.points[i, j]
                assert abs(quadric_value(a, b, c, x)) <= 1e-10 * (1 + np.abs(x).max() ** 2)


def torus_value(p, center, normal, big, small):
    w = p - center
    n = normal / np.linalg.norm(normal)
    g = (w * w).sum(-1) + big * big - small * small
    cr = np.cross(w, n)
    return g * g - 4 * big * big * (cr * cr).sum(-1)


def test_ray_torus_hits_sampling_oracle():
    rng = np.random.default_rng(7)
    center, normal, big, small = np.array([0.2, -0.1, 0.3]), np.array([0.1, 0.2, 1.0]), 2.0, 0.6
    n = 200
    o = rng.uniform(-5, 5, (n, 3))
    d = center - o + rng.uniform(-1.5, 1.5, (n, 3))
    r = locus.ray_torus_hits(o, d, center, normal, big, small)
    ts = np.linspace(0.0, 3.0, 30001)
    compared = 0
    for i in range(n):
        vals = torus_value(o[i] + ts[:, None] * d[i], center, normal, big, small)
        ch = np.nonzero(np.sign(vals[1:]) != np.sign(vals[:-1]))[0]
        roots = ts[ch]
        if len(roots) and (np.min(np.diff(roots), initial=1) < 1e-2 or roots[0] < 1e-2 or roots[-1] > 2.9):
            continue
        if (r.multiplicity[i] > 1).any():
            continue
        compared += 1
        assert r.count[i] == len(roots), i
        assert np.allclose(r.t[i, : r.count[i]], roots, atol=2e-4)
        for j in range(r.count[i]):
            p = r.points[i, j]
            assert abs(torus_value(p, center, normal, big, small)) < 1e-9 * (big + small + np.abs(p).max()) ** 4
            assert abs(np.linalg.norm(r.normals[i, j]) - 1) < 1e-12
    assert compared > 150


def test_bad_input():
    with pytest.raises(ValueError):
        locus.ray_quadric_hits([[np.nan, 0, 0]], [[1, 0, 0]], np.eye(3), [0, 0, 0], -1.0)
    with pytest.raises(ValueError):
        locus.ray_torus_hits([[0, 0, 0]], [[1, 0, 0], [0, 1, 0]], [0, 0, 0], [0, 0, 1], 2.0, 1.0)
    r = locus.ray_torus_hits([[-9, 0, 0]], [[1, 0, 0]], [0, 0, 0], [0, 0, 1], 4.0, 1.0)
    assert r.count[0] == 4
    assert np.allclose(r.t[0], [4, 6, 12, 14])
