# trapezoid_map: the trapezoidal map of non-crossing segments with point location, checked
# against a brute-force search of the returned trapezoids with exact rational orientation.
from fractions import Fraction

import numpy as np
import pytest

import locus


def below(a, b):
    return a[1] < b[1] or (a[1] == b[1] and a[0] > b[0])


def orient(a, b, c):
    a, b, c = ([Fraction(float(x)) for x in p] for p in (a, b, c))
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def inside(points, segments, t, q):
    bottom, top, left, right = (int(x) for x in t)

    def side(s):
        a, b = points[segments[s][0]], points[segments[s][1]]
        if below(b, a):
            a, b = b, a
        return orient(a, b, q)

    return ((bottom < 0 or below(points[bottom], q)) and (top < 0 or below(q, points[top]))
            and (left < 0 or side(left) < 0) and (right < 0 or side(right) > 0))


def star(rng, n):
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    r = rng.uniform(0.5, 1.0, n)
    pts = np.round(np.c_[r * np.cos(ang), r * np.sin(ang)] * 1024) / 1024
    segs = np.c_[np.arange(n), (np.arange(n) + 1) % n]
    return pts, segs


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_point_location_matches_brute_force(rng, dtype):
    pts, segs = star(rng, 25)
    pts = pts.astype(dtype)
    queries = (2 * rng.integers(-2500, 2500, (80, 2)) + 1) / 4096.0
    r = locus.trapezoid_map(pts, segs, queries)
    assert r.status == "ok"
    assert r.trapezoids.shape[1] == 4 and r.located.shape == (80,)
    for q, k in zip(queries, r.located):
        hits = [i for i, t in enumerate(r.trapezoids) if inside(pts, segs, t, q)]
        assert hits == [k]


def test_distinct_endpoints_give_3n_plus_1(rng):
    pts = rng.uniform(-1, 1, (20, 2))
    pts[1::2] = pts[0::2] + 0.01 * rng.uniform(-1, 1, (10, 2))  # short disjoint segments
    segs = np.arange(20).reshape(10, 2)
    assert locus.trapezoid_map(pts, segs).trapezoids.shape == (31, 4)


def test_bad_input():
    pts = np.array([[0, 0], [2, 2], [0, 2], [2, 0]], float)
    with pytest.raises(ValueError, match="invalid_topology"):
        locus.trapezoid_map(pts, [[0, 1], [2, 3]])
    with pytest.raises(ValueError):
        locus.trapezoid_map(pts, [[0, 9]])
    with pytest.raises(ValueError, match="non_finite"):
        locus.trapezoid_map(np.array([[0, 0], [np.nan, 1]]), [[0, 1]])
    with pytest.raises(ValueError):
        locus.trapezoid_map(pts, np.zeros((0, 2), int))
