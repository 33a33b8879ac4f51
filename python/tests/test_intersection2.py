# circle_circle against an exact rational oracle for the count (exact.py's Fraction), the
# constructed points checked on both circles, touching cases on small integers and bad input.
import numpy as np
import pytest

import locus
from exact import F


def exact_count(c0, r0, c1, r1):
    """(kind name, count) from exact comparisons of |c1 - c0|^2 with (r0 +- r1)^2."""
    dx, dy = F(c1[0]) - F(c0[0]), F(c1[1]) - F(c0[1])
    d2 = dx * dx + dy * dy
    a, b = F(r0), F(r1)
    if d2 == 0:
        if a == b:
            return ("point", 1) if a == 0 else ("coincident", 0)
        return ("empty", 0)
    if d2 > (a + b) ** 2 or d2 < (a - b) ** 2:
        return ("empty", 0)
    if d2 == (a + b) ** 2 or d2 == (a - b) ** 2:
        return ("point", 1)
    return ("points", 2)


def check(c0, r0, c1, r1):
    r = locus.circle_circle(c0, r0, c1, r1)
    assert r.status == "ok"
    for i in range(len(r0)):
        kind, count = exact_count(c0[i], r0[i], c1[i], r1[i])
        assert locus.KIND_NAMES[r.kind[i]] == kind, i
        assert r.count[i] == count, i
        for j in range(2):
            if j < count:
                p = r.points[i, j]
                m = max(np.abs(c0[i]).max(), np.abs(c1[i]).max(), r0[i], r1[i], 1e-300)
                tol = 64 * np.finfo(float).eps * m + (np.sqrt(np.finfo(float).eps) * m
                                                       if count == 1 else 0)
                assert abs(np.linalg.norm(p - c0[i]) - r0[i]) <= tol
                assert abs(np.linalg.norm(p - c1[i]) - r1[i]) <= tol
                assert r.multiplicity[i, j] == (2 if count == 1 else 1)
            else:
                assert np.isnan(r.points[i, j]).all() and r.multiplicity[i, j] == 0
    return r


def test_random_against_exact_count(rng):
    n = 500
    c0, c1 = rng.random((n, 2)) * 4, rng.random((n, 2)) * 4
    r0, r1 = rng.random(n) * 2, rng.random(n) * 2
    r = check(c0, r0, c1, r1)
    assert set(r.count.tolist()) == {0, 2}
    # power-of-two scaling and swapping keep the decisions
    s = locus.circle_circle(c0 * 2.0**-30, r0 * 2.0**-30, c1 * 2.0**-30, r1 * 2.0**-30)
    assert np.array_equal(s.count, r.count) and np.array_equal(s.kind, r.kind)
    w = locus.circle_circle(c1, r1, c0, r0)
    assert np.array_equal(w.count, r.count)


def test_touching_on_integers(rng):
    cases = [((0, 0), 1, (2, 0), 1), ((0, 0), 2, (1, 0), 1), ((0, 0), 5, (3, 4), 10),
             ((0, 0), 3, (0, 0), 3), ((1, 1), 0, (1, 1), 0), ((0, 0), 1, (0, 0), 2),
             ((0, 0), 5, (6, 8), 5), ((0, 0), 0, (3, 4), 5), ((0, 0), 1, (3, 0), 1)]
    c0 = np.array([c[0] for c in cases], float)
    r0 = np.array([c[1] for c in cases], float)
    c1 = np.array([c[2] for c in cases], float)
    r1 = np.array([c[3] for c in cases], float)
    r = check(c0, r0, c1, r1)
    assert r.count.tolist() == [1, 1, 1, 0, 1, 0, 1, 1, 0]
    assert np.allclose(r.points[0, 0], [1, 0]) and np.allclose(r.points[1, 0], [2, 0])
    # rigid motion by an integer translation keeps every decision
    t = rng.integers(-50, 50, size=2).astype(float)
    assert np.array_equal(locus.circle_circle(c0 + t, r0, c1 + t, r1).count, r.count)


def test_bad_input():
    c, r = np.zeros((2, 2)), np.ones(2)
    with pytest.raises(ValueError, match="negative radius"):
        locus.circle_circle(c, -r, c, r)
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.circle_circle(c, [1.0, np.nan], c, r)
    with pytest.raises(ValueError, match="same length"):
        locus.circle_circle(c, r, c[:1], r)
    with pytest.raises(ValueError, match="shape"):
        locus.circle_circle(np.zeros((2, 3)), r, c, r)
    with pytest.raises(ValueError, match="None"):
        locus.circle_circle(None, r, c, r)
    e = locus.circle_circle(np.zeros((0, 2)), np.zeros(0), np.zeros((0, 2)), np.zeros(0))
    assert e.count.shape == (0,) and e.points.shape == (0, 2, 2)


def exact_segment_circle_count(p0, p1, c, r):
    """Distinct roots in [0, 1] of q(t) = |p0 + t (p1 - p0) - c|^2 - r^2, exactly."""
    d = [F(p1[k]) - F(p0[k]) for k in range(2)]
    w = [F(p0[k]) - F(c[k]) for k in range(2)]
    A = d[0] ** 2 + d[1] ** 2
    B = 2 * (d[0] * w[0] + d[1] * w[1])
    C = w[0] ** 2 + w[1] ** 2 - F(r) ** 2
    if A == 0:
        return 1 if C == 0 else 0
    D = B * B - 4 * A * C
    if D < 0:
        return 0

    def ge(s, bound):  # (-B + s sqrt(D)) / (2A) >= bound
        K = 2 * A * bound + B
        return (K <= 0 or D >= K * K) if s > 0 else (K <= 0 and D <= K * K)

    def le(s, bound):  # (-B + s sqrt(D)) / (2A) <= bound
        K = 2 * A * bound + B
        return (K >= 0 and D <= K * K) if s > 0 else (K >= 0 or D >= K * K)

    signs = [1] if D == 0 else [-1, 1]
    return sum(1 for s in signs if ge(s, 0) and le(s, 1))


def test_segment_circle_exact(rng):
    n = 600
    p0, p1 = rng.random((n, 2)) * 4 - 2, rng.random((n, 2)) * 4 - 2
    c, rad = rng.random((n, 2)) - 0.5, rng.random(n) * 1.5
    p1[:50] = p0[:50]                               # zero-length segments
    r = locus.segment_circle(np.stack([p0, p1], axis=1), c, rad)
    for i in range(n):
        count = exact_segment_circle_count(p0[i], p1[i], c[i], rad[i])
        assert r.count[i] == count, i
        for j in range(count):
            q = r.points[i, j]
            assert abs(np.linalg.norm(q - c[i]) - rad[i]) <= 1e-12
        if count == 2:
            along = (r.points[i] - p0[i]) @ (p1[i] - p0[i])
            assert along[0] <= along[1]
    assert {0, 1, 2} <= set(r.count.tolist())
    # tangent and end-point cases on integers
    seg = np.array([[[-2, 1], [2, 1]], [[0, 0], [1, 0]], [[0, 0], [3, 0]], [[1, 0], [1, 0]]], float)
    r = locus.segment_circle(seg, np.zeros((4, 2)), np.ones(4))
    assert r.count.tolist() == [1, 1, 1, 1] and r.multiplicity[0, 0] == 2
    assert np.array_equal(r.points[2, 0], [1, 0])
    with pytest.raises(ValueError, match="shape"):
        locus.segment_circle(np.zeros((2, 2)), np.zeros((2, 2)), np.ones(2))
    with pytest.raises(ValueError, match="negative radius"):
        locus.segment_circle(seg, np.zeros((4, 2)), -np.ones(4))
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.segment_circle(seg, np.full((4, 2), np.inf), np.ones(4))


def ellipse_residual(p, c, angle, e):
    # (x/a)^2 + (y/b)^2 - 1 in the ellipse's frame, for points p (..., 2)
    u = np.array([np.cos(angle), np.sin(angle)])
    d = p - c
    return (d @ u / e[0]) ** 2 + ((d @ np.array([-u[1], u[0]])) / e[1]) ** 2 - 1


def sampled_crossings(c0, a0, e0, c1, a1, e1, samples=2048):
    # the sign changes of the second ellipse's residual around the first ellipse, or None when
    # the pair is near tangency (a dip of |residual| below 0.05 away from a crossing, or two
    # crossings within 8 samples): those are not counted reliably by sampling
    s = np.linspace(0, 2 * np.pi, samples, endpoint=False)
    u = np.array([np.cos(a0), np.sin(a0)])
    v = np.array([-u[1], u[0]])
    pts = c0 + np.outer(e0[0] * np.cos(s), u) + np.outer(e0[1] * np.sin(s), v)
    f = ellipse_residual(pts, c1, a1, e1)
    cross = np.sign(f) != np.sign(np.roll(f, -1))
    beside = cross | np.roll(cross, 1)
    g = np.abs(f)
    dip = (g <= np.roll(g, 1)) & (g <= np.roll(g, -1)) & (g < 0.05) & ~beside
    at = np.flatnonzero(cross)
    if np.any(dip) or (len(at) > 1 and np.min(np.diff(np.append(at, at[0] + samples))) < 8):
        return None
    return len(at)


def test_ellipse_ellipse_points_lie_on_both_and_counts_match_sampling(rng):
    n = 200
    c0, c1 = rng.uniform(-1, 1, (n, 2)), rng.uniform(-1, 1, (n, 2))
    a0, a1 = rng.uniform(0, np.pi, n), rng.uniform(0, np.pi, n)
    e0, e1 = rng.uniform(0.3, 2, (n, 2)), rng.uniform(0.3, 2, (n, 2))
    r = locus.ellipse_ellipse(c0, a0, e0, c1, a1, e1)
    checked, counts = 0, set()
    for i in range(n):
        k = int(r.count[i])
        assert np.all(np.isnan(r.points[i, k:])) and np.all(r.multiplicity[i, k:] == 0)
        for p in r.points[i, :k]:
            assert abs(ellipse_residual(p, c0[i], a0[i], e0[i])) < 1e-9
            assert abs(ellipse_residual(p, c1[i], a1[i], e1[i])) < 1e-9
        expected = sampled_crossings(c0[i], a0[i], e0[i], c1[i], a1[i], e1[i])
        if expected is None:
            continue
        checked += 1
        counts.add(expected)
        assert k == expected, (i, k, expected)
        assert np.all(r.multiplicity[i, :k] == 1)
        assert r.kind[i] == (0 if k == 0 else 2)
    assert checked >= 150 and {0, 2, 4} <= counts


def test_ellipse_ellipse_known_cases():
    z = np.zeros((1, 2))
    # a 2:1 ellipse and its quarter turn: 4 crossings at (+-2/sqrt5, +-2/sqrt5)
    r = locus.ellipse_ellipse(z, [0.0], [[2, 1]], z, [np.pi / 2], [[2, 1]])
    assert r.count[0] == 4 and r.kind[0] == 2
    assert np.allclose(np.abs(r.points[0]), 2 / np.sqrt(5), atol=1e-12)
    # touching at (2, 0) from outside, and the same ellipse (coincident)
    r = locus.ellipse_ellipse(np.zeros((2, 2)), [0.0, 0.3], [[2, 1], [2, 1]], [[4, 0], [0, 0]],
                              [0.0, 0.3], [[2, 1], [2, 1]])
    assert r.count[0] == 1 and r.multiplicity[0, 0] == 2 and r.kind[0] == 1
    assert np.allclose(r.points[0, 0], [2, 0], atol=1e-7)
    assert locus.KIND_NAMES[r.kind[1]] == "coincident" and r.count[1] == 0
    with pytest.raises(ValueError, match="extent"):
        locus.ellipse_ellipse(z, [0.0], [[2, 0]], z, [0.0], [[1, 1]])
    with pytest.raises(ValueError, match="non_finite"):
        locus.ellipse_ellipse(z, [np.nan], [[2, 1]], z, [0.0], [[1, 1]])


def test_circle_ellipse_against_sampling(rng):
    n = 200
    c0, c1 = rng.uniform(-1, 1, (n, 2)), rng.uniform(-1, 1, (n, 2))
    r0, a1, e1 = rng.uniform(0.3, 2, n), rng.uniform(0, np.pi, n), rng.uniform(0.3, 2, (n, 2))
    r = locus.circle_ellipse(c0, r0, c1, a1, e1)
    checked, counts = 0, set()
    for i in range(n):
        k = int(r.count[i])
        assert np.all(np.isnan(r.points[i, k:]))
        for p in r.points[i, :k]:
            assert abs(np.linalg.norm(p - c0[i]) / r0[i] - 1) < 1e-9
            assert abs(ellipse_residual(p, c1[i], a1[i], e1[i])) < 1e-9
        expected = sampled_crossings(c0[i], 0.0, (r0[i], r0[i]), c1[i], a1[i], e1[i])
        if expected is None:
            continue
        checked += 1
        counts.add(expected)
        assert k == expected and np.all(r.multiplicity[i, :k] == 1), (i, k, expected)
    assert checked >= 150 and {0, 2, 4} <= counts
    # a circle of radius 1 inside the 2:1 ellipse touches it at (0, +-1); radius 0 is a point
    z = np.zeros((2, 2))
    t = locus.circle_ellipse(z, [1.0, 0.0], [[0, 0], [2, 0]], [0.0, 0.0], [[2, 1], [2, 1]])
    assert t.count[0] == 2 and np.all(t.multiplicity[0, :2] == 2)
    assert np.allclose(np.sort(t.points[0, :2, 1]), [-1, 1], atol=1e-7)
    assert t.count[1] == 1 and np.allclose(t.points[1, 0], [0, 0])
    with pytest.raises(ValueError, match="radius"):
        locus.circle_ellipse(z[:1], [-1.0], z[:1], [0.0], [[1, 1]])
