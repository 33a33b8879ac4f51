# ellipsoid_relation: balls with dyadic data against exact Fraction arithmetic (tangencies
# included), a constructed tangency of rotated ellipsoids and its 2^-45 perturbations, random
# rotated ellipsoids against dense sampling (decisive draws), swap symmetry and bad input.
from fractions import Fraction

import numpy as np
import pytest

import locus

SWAP = {"a_contains_b": "b_contains_a", "b_contains_a": "a_contains_b",
        "a_contains_b_touching": "b_contains_a_touching",
        "b_contains_a_touching": "a_contains_b_touching"}
EYE = np.eye(3)


def ball_oracle(c0, r0, c1, r1):
    d2 = sum((Fraction(b) - Fraction(a)) ** 2 for a, b in zip(c0, c1))
    r0, r1 = Fraction(r0), Fraction(r1)
    if d2 == 0 and r0 == r1:
        return "equal"
    out, inner = d2 - (r0 + r1) ** 2, d2 - (r0 - r1) ** 2
    if out > 0:
        return "separated"
    if out == 0:
        return "touching"
    if inner > 0:
        return "overlapping"
    first = "a_contains_b" if r0 > r1 else "b_contains_a"
    return first if inner < 0 else first + "_touching"


def rel(a, b):
    r = locus.ellipsoid_relation(*a, *b)
    assert locus.ellipsoid_relation(*b, *a) == SWAP.get(r, r)
    return r


def test_balls_against_fractions():
    rng = np.random.default_rng(20261205)
    seen = set()
    for i in range(150):
        c0 = rng.integers(-4, 5, 3).astype(float)
        c1 = rng.integers(-4, 5, 3).astype(float)
        r0, r1 = float(rng.integers(1, 7)), float(rng.integers(1, 7))
        mode = i % 7
        if mode < 3:  # 3-4-5: tangent outside, or inside either way
            c1 = c0 + np.array([3.0, 0.0, 4.0])
            r0 = float(rng.integers(1, 5))
            r1 = 5 - r0 if mode == 0 else 5 + r0
            if mode == 2:
                r0, r1 = r1, r0
        if mode == 3:
            c1, r1 = c0.copy(), r0
        want = ball_oracle(c0, r0, c1, r1)
        seen.add(want)
        got = rel((c0 / 8, EYE, np.full(3, r0 / 8)), (c1 / 8, EYE, np.full(3, r1 / 8)))
        assert got == want, (c0, r0, c1, r1)
    assert len(seen) == 8


def test_rotated_tangency():
    axes = np.array([[3.0, 4, 0], [-4, 3, 0], [0, 0, 5]])  # orthogonal, length 5
    e = (np.zeros(3), axes, np.array([50.0, 40, 40]))  # semi-axes 10, 8, 8
    assert rel(e, (np.array([9.0, 12, 0]), EYE, np.full(3, 5.0))) == "touching"
    assert rel(e, (np.array([9.0, 12, 0]), EYE, np.full(3, 5 - 2.0**-45))) == "separated"
    assert rel(e, (np.array([9.0, 12, 0]), EYE, np.full(3, 5 + 2.0**-45))) == "overlapping"
    assert rel(e, (np.array([3.0, 4, 0]), EYE, np.full(3, 5.0))) == "a_contains_b_touching"
    assert rel(e, (np.zeros(3), 2 * axes[[2, 0, 1]], np.array([80.0, 100, 80]))) == "equal"


def sampled(a, b, n=48):
    # b's implicit value on a's boundary x = c + U^-1 (e * w), |w| = 1.
    ca, ua, ea = a
    cb, ub, eb = b
    th, ph = np.meshgrid(np.linspace(0, 2 * np.pi, 2 * n), np.linspace(0, np.pi, n + 1))
    w = np.stack([np.cos(th) * np.sin(ph), np.sin(th) * np.sin(ph), np.cos(ph)], -1).reshape(-1, 3)
    x = ca + np.linalg.solve(ua, (w * ea).T).T
    q = (((x - cb) @ ub.T) / eb) ** 2
    return q.sum(axis=1) - 1


def random_ellipsoid(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return rng.uniform(-1.5, 1.5, 3), q, rng.uniform(0.3, 2, 3)


def test_random_against_sampling():
    rng = np.random.default_rng(7)
    decided = 0
    for _ in range(60):
        a, b = random_ellipsoid(rng), random_ellipsoid(rng)
        got = rel(a, b)
        q = sampled(a, b)
        if q.min() < -0.05 and q.max() > 0.05:
            assert got == "overlapping"
        elif q.max() < -0.05:
            assert got == "b_contains_a"
        elif q.min() > 0.05:
            inside = ((((b[0] - a[0]) @ a[1].T) / a[2]) ** 2).sum() < 1
            assert got == ("a_contains_b" if inside else "separated")
        else:
            continue
        decided += 1
    assert decided > 40


def test_bad_input():
    e = (np.zeros(3), EYE, np.ones(3))
    assert rel(e, (np.zeros(3), EYE, np.array([1.0, 0, 1]))) == "undecided"
    assert rel(e, (np.zeros(3), np.array([[1.0, 0, 0], [2, 0, 0], [0, 0, 1]]), np.ones(3))) == \
        "undecided"
    with pytest.raises(ValueError):
        locus.ellipsoid_relation(np.array([np.nan, 0, 0]), EYE, np.ones(3), *e)
    with pytest.raises(ValueError):
        locus.ellipsoid_relation(np.zeros(3), EYE[:2], np.ones(3), *e)
