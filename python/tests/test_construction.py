# locus.construct (the chapter 8 constructions) against exact rational oracles for the counts
# (exact.py's Fraction) and residual checks of every returned circle and line in numpy; touching
# cases on small integers and bad input.
import math

import numpy as np
import pytest

import locus
from exact import F


def tangent_count(c0, r0, c1, r1):
    d2 = (F(c1[0]) - F(c0[0])) ** 2 + (F(c1[1]) - F(c0[1])) ** 2
    a, b = F(r0), F(r1)
    if d2 == 0:
        return None if a == b else 0
    outer = (d2 > (a - b) ** 2) * 2 + (d2 == (a - b) ** 2)
    inner = (d2 > (a + b) ** 2) * 2 + (d2 == (a + b) ** 2)
    return outer + inner


def line_dist(line, p):
    o, d = line[:2], line[2:]
    return abs(d[0] * (p[1] - o[1]) - d[1] * (p[0] - o[0])) / math.hypot(*d)


def test_tangent_lines_of_two_circles(rng):
    cases = [((0, 0), 2, (6, 8), r) for r in (3, 8, 9, 12, 13)]  # 4, 3, 2, 1, 0: exact ties
    for _ in range(100):
        cases.append((tuple(rng.integers(-6, 7, 2)), int(rng.integers(1, 5)),
                      tuple(rng.integers(-6, 7, 2)), int(rng.integers(1, 5))))
    for c0, r0, c1, r1 in cases:
        want = tangent_count(c0, r0, c1, r1)
        res = locus.construct("tangent-2circles", [*c0, r0, *c1, r1])
        if want is None:
            assert res.infinite and len(res.lines) == 0
            continue
        assert len(res.lines) == want, (c0, r0, c1, r1)
        for line in res.lines:
            assert math.isclose(math.hypot(*line[2:]), 1.0, rel_tol=1e-14)
            assert abs(line_dist(line, c0) - r0) < 1e-12 * 16
            assert abs(line_dist(line, c1) - r1) < 1e-12 * 16


def test_circles_of_radius_through_two_points(rng):
    for _ in range(100):
        p, q = rng.integers(-5, 6, 2), rng.integers(-5, 6, 2)
        r = int(rng.integers(1, 6))
        d2 = F(int(q[0] - p[0])) ** 2 + F(int(q[1] - p[1])) ** 2
        res = locus.construct("circle-2pts-r", [*p, *q, r])
        if d2 == 0:
            assert res.infinite
            continue
        want = 2 if d2 < 4 * r * r else (1 if d2 == 4 * r * r else 0)
        assert len(res.circles) == want
        for cx, cy, rr in res.circles:
            assert rr == r
            assert abs(math.hypot(cx - p[0], cy - p[1]) - r) < 1e-13 * 16
            assert abs(math.hypot(cx - q[0], cy - q[1]) - r) < 1e-13 * 16


def test_apollonius_residuals():
    res = locus.construct("apollonius", [0, 0, 1, 8, 0, 2, 3, 7, 1.5])
    assert len(res.circles) == 8 and res.circle_signs.shape == (8, 3)
    inputs = [((0, 0), 1), ((8, 0), 2), ((3, 7), 1.5)]
    for (cx, cy, r), s in zip(res.circles, res.circle_signs):
        for (c, ri), si in zip(inputs, s):
            assert abs(math.hypot(cx - c[0], cy - c[1]) - abs(r + si * ri)) < 1e-11
    # Three equal circles on a line: the two common tangent lines y = +-1.
    res = locus.construct("apollonius", [0, 0, 1, 4, 0, 1, 10, 0, 1])
    assert len(res.lines) == 2
    assert sorted(round(abs(line[1]), 12) for line in res.lines) == [1.0, 1.0]


def test_three_points_and_lines():
    res = locus.construct("circle3pts", [0, 0, 6, 0, 0, 8])
    assert np.allclose(res.circles, [[3, 4, 5]])
    assert len(locus.construct("circle3pts", [0, 0, 1, 1, 3, 3]).circles) == 0
    res = locus.construct("circle3lines", [0, 0, 4, 0, 4, 0, -4, 3, 0, 3, 0, -3])
    assert len(res.circles) == 4 and math.isclose(res.circles[0][2], 1.0)


def test_bad_input():
    with pytest.raises(ValueError):
        locus.construct("circle-2pts-r", [0, 0, 1, 1, float("nan")])
    with pytest.raises(ValueError):
        locus.construct("tangent-2circles", [0, 0, -1, 1, 1, 1])
    with pytest.raises(ValueError):
        locus.construct("no-such-kind", [1, 2])
    with pytest.raises(ValueError):
        locus.construct("bisector", [1, 2, 3])
