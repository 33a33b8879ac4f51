# sat3_test / sat3_first_contact: stationary answers against scipy's exact-enough LP feasibility
# (a point in both hulls), analytic moving cases (face-face, vertex-face, passing by), swap
# symmetry and bad input.
import numpy as np
import pytest
from scipy.optimize import linprog

import locus


def lp_intersect(a, b):
    # Feasibility of sum l_i a_i = sum m_j b_j, sum l = sum m = 1, l, m >= 0; returns None when
    # the LP's margin is too thin to trust (near-touching).
    n, m = len(a), len(b)
    A = np.zeros((5, n + m))
    A[:3, :n] = a.T
    A[:3, n:] = -b.T
    A[3, :n] = 1
    A[4, n:] = 1
    r = linprog(np.zeros(n + m), A_eq=A, b_eq=[0, 0, 0, 1, 1], bounds=(0, None), method="highs")
    return r.status == 0


def cube(lo, side=1.0):
    return np.array([[lo[0] + side * (k & 1), lo[1] + side * ((k >> 1) & 1),
                      lo[2] + side * ((k >> 2) & 1)] for k in range(8)], dtype=float)


def test_random_against_lp():
    rng = np.random.default_rng(20261204)
    agree = 0
    for _ in range(150):
        a = rng.uniform(-1, 1, (rng.integers(4, 9), 3))
        b = rng.uniform(-1, 1, (rng.integers(4, 9), 3)) + rng.uniform(-1.8, 1.8, 3)
        got = locus.sat3_test(a, b)
        assert got == locus.sat3_test(b, a)
        # A clear margin either way: shrink / grow b about its centroid by 1e-6.
        c = b.mean(axis=0)
        inner, outer = c + (b - c) * (1 - 1e-6), c + (b - c) * (1 + 1e-6)
        if lp_intersect(a, inner) == lp_intersect(a, outer):
            assert got == lp_intersect(a, b)
            agree += 1
    assert agree > 140


def test_touching_and_moving():
    a = cube([0, 0, 0])
    assert locus.sat3_test(a, cube([1, 0.25, -0.5]))
    assert not locus.sat3_test(a, cube([1 + 2.0**-20, 0.25, -0.5]))
    r = locus.sat3_first_contact(a, [0, 0, 0], cube([4, 0.5, 0.25]), [-2, 0, 0], 10.0)
    assert r.kind == "polygon"
    assert r.time == pytest.approx(1.5, abs=1e-14)
    assert r.points.shape == (4, 3)
    assert np.allclose(r.points[:, 0], 1.0)
    tet = np.array([[3, 0.5, 0.5], [4, 0, 0], [4, 1, 0], [4, 0.5, 1]])
    r = locus.sat3_first_contact(a, [0, 0, 0], tet, [-1, 0, 0], 5.0)
    assert r.kind == "point" and r.time == pytest.approx(2.0)
    assert np.allclose(r.points[0], [1, 0.5, 0.5])
    r = locus.sat3_first_contact(a, [0, 0, 0], tet, [0, -1, 0], 5.0)
    assert r.kind == "empty" and r.time is None and r.points.shape == (0, 3)
    r = locus.sat3_first_contact(a, [0, 0, 0], cube([0.5, 0.5, 0.5]), [0, 0, 0], 1.0)
    assert r.kind == "overlap" and r.time == 0.0


def test_bad_input():
    a = cube([0, 0, 0])
    with pytest.raises(ValueError):
        locus.sat3_test(a, np.array([[0, 0, 0], [1, 1, 1.0]]))
    with pytest.raises(ValueError):
        locus.sat3_test(a, np.array([[0, 0, np.nan], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]]))
    with pytest.raises(ValueError):
        locus.sat3_first_contact(a, [0, 0, 0], a, [0, 0, 0], -1.0)
    with pytest.raises(ValueError):
        locus.sat3_first_contact(a, [0, 0], a, [0, 0, 0], 1.0)
