# Chapter 12 (construct/misc3.hpp) over arrays: projections against exact rationals (Fraction on
# dyadic input), angles against the exact squared cosine and an analytic construction, the
# orientation conventions, zero vectors (NaN) and bad input.
import math

import numpy as np
import pytest

import locus
from exact import F


def dyadic(rng, shape):
    return rng.integers(-128, 129, size=shape) / 16.0


def test_project_points_exact(rng):
    pts = dyadic(rng, (200, 3))
    n = np.array([0.5, -1.25, 2.0])
    c = 0.375
    q = locus.project_points_to_plane(pts, n, c)
    nn = sum(F(x) * F(x) for x in n)
    for p, got in zip(pts, q):
        f = (sum(F(a) * F(b) for a, b in zip(n, p)) - F(c)) / nn
        want = [F(p[k]) - f * F(n[k]) for k in range(3)]
        assert all(abs(float(F(got[k]) - want[k])) <= 1e-14 * 64 for k in range(3))


def cos2(a, b):
    d = sum(F(x) * F(y) for x, y in zip(a, b))
    return d * d / (sum(F(x) ** 2 for x in a) * sum(F(y) ** 2 for y in b))


def test_angles_exact_cosine(rng):
    a, b = dyadic(rng, (300, 3)), dyadic(rng, (300, 3))
    keep = (np.abs(a).sum(1) > 0) & (np.abs(b).sum(1) > 0)
    a, b = a[keep], b[keep]
    ll = locus.line_line_angles(a, b)
    pp = locus.plane_plane_angles(a, b)
    lp = locus.line_plane_angles(a, b)
    assert np.array_equal(ll, pp)
    for i in range(len(a)):
        c2 = float(cos2(a[i], b[i]))
        assert abs(math.cos(ll[i]) ** 2 - c2) <= 1e-14
        assert abs(math.sin(lp[i]) ** 2 - c2) <= 1e-14
        # orientation: the sign of the dot product decides the side of pi/2 and of 0
        d = sum(F(x) * F(y) for x, y in zip(a[i], b[i]))
        if d > 0:
            assert ll[i] < math.pi / 2 and lp[i] > 0
        elif d < 0:
            assert ll[i] > math.pi / 2 and lp[i] < 0
    acute = locus.line_line_angles(a, b, acute=True)
    np.testing.assert_allclose(acute, np.minimum(ll, math.pi - ll), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(locus.line_plane_angles(a, b, acute=True), np.abs(lp))
    np.testing.assert_allclose(locus.line_line_angles(a, -b), math.pi - ll, rtol=0, atol=4e-15)


def test_angles_analytic(rng):
    theta = np.linspace(0.0, math.pi, 33)
    u = np.array([1.0, 2.0, 2.0]) / 3.0
    w = np.array([2.0, 1.0, -2.0]) / 3.0
    d = np.cos(theta)[:, None] * u + np.sin(theta)[:, None] * w
    got = locus.line_line_angles(np.tile(u, (33, 1)), d)
    np.testing.assert_allclose(got, theta, rtol=0, atol=1e-14)


def test_zero_and_bad_input():
    z = np.zeros((1, 3))
    x = np.array([[1.0, 0.0, 0.0]])
    assert math.isnan(locus.line_line_angles(z, x)[0])
    assert math.isnan(locus.plane_plane_angles(x, z)[0])
    assert math.isnan(locus.line_plane_angles(z, x)[0])
    with pytest.raises(ValueError):
        locus.line_line_angles(np.array([[np.nan, 0, 0]]), x)
    with pytest.raises(ValueError):
        locus.line_line_angles(x, np.zeros((2, 3)))
    with pytest.raises(ValueError):
        locus.project_points_to_plane(x, np.zeros(3), 1.0)
    with pytest.raises(ValueError):
        locus.project_points_to_plane(np.zeros((3, 2)), np.ones(3), 1.0)
