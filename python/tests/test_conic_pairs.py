# quadratic_curves (general conic pairs), circle_arc and arc_arc. Conics: the count of real common
# points against an mpmath oracle (the resultant in y built exactly in Fractions, its roots at 60
# digits: real when the imaginary part vanishes to 40 digits), every point on both curves;
# closed-form cases (hyperbola-parabola, tangencies, a shared line). Arcs: numpy closed forms.
import numpy as np
import mpmath
import pytest

import locus
from exact import F


def conic_value(q, p):
    x, y = p
    return q[0] * x * x + q[1] * x * y + q[2] * y * y + q[3] * x + q[4] * y + q[5]


def polymul(a, b):
    out = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def polysub(a, b):
    n = max(len(a), len(b))
    a = a + [F(0)] * (n - len(a))
    b = b + [F(0)] * (n - len(b))
    return [x - y for x, y in zip(a, b)]


def real_root_count(p, q):
    """Distinct real x of common points (generic random input: no two share an x)."""
    def parts(k):
        a, b, c, d, e, f = map(F, k)
        return [c], [e, b], [f, d, a]  # in y: c y^2 + (b x + e) y + (a x^2 + d x + f)
    a2, a1, a0 = parts(p)
    b2, b1, b0 = parts(q)
    s = polysub(polymul(a2, b0), polymul(a0, b2))
    res = polysub(polymul(s, s),
                  polymul(polysub(polymul(a2, b1), polymul(a1, b2)),
                          polysub(polymul(a1, b0), polymul(a0, b1))))
    while res and res[-1] == 0:
        res.pop()
    mpmath.mp.dps = 60
    coeffs = [mpmath.mpf(c.numerator) / c.denominator for c in reversed(res)]
    roots = mpmath.polyroots(coeffs, maxsteps=200, extraprec=200)
    return sum(1 for r in roots if abs(mpmath.im(r)) < mpmath.mpf(10) ** -40)


def test_quadratic_curves_counts_against_mpmath(rng):
    n = 60
    q0 = np.round(rng.uniform(-4, 4, (n, 6)) * 64) / 64
    q1 = np.round(rng.uniform(-4, 4, (n, 6)) * 64) / 64
    r = locus.quadratic_curves(q0, q1)
    assert r.status == "ok"
    seen = set()
    for i in range(n):
        k = int(r.count[i])
        assert k == real_root_count(q0[i], q1[i]), i
        seen.add(k)
        assert np.all(r.multiplicity[i, :k] == 1)
        for p in r.points[i, :k]:
            scale = max(1.0, np.abs(p).max()) ** 2 * 8
            assert abs(conic_value(q0[i], p)) < 1e-9 * scale
            assert abs(conic_value(q1[i], p)) < 1e-9 * scale
        assert np.all(np.isnan(r.points[i, k:]))
    assert len(seen) >= 3


def test_quadratic_curves_closed_forms():
    # Hyperbola x^2 - y^2 = 1 and parabola y = x^2 - 3: (+-sqrt 2, -1), (+-sqrt 5, 2).
    r = locus.quadratic_curves([[1, 0, -1, 0, 0, -1]], [[1, 0, 0, 0, -1, -3]])
    assert r.count[0] == 4 and locus.KIND_NAMES[r.kind[0]] == "points"
    want = np.array([[-np.sqrt(5), 2], [-np.sqrt(2), -1], [np.sqrt(2), -1], [np.sqrt(5), 2]])
    np.testing.assert_allclose(r.points[0], want, atol=1e-14)
    # y = x^2 touches the line pair (y + 1)^2 = 4 x^2 at (+-1, 1): two tangencies.
    r = locus.quadratic_curves([[1, 0, 0, 0, -1, 0]], [[-4, 0, 1, 0, 2, 1]])
    assert r.count[0] == 2 and list(r.multiplicity[0, :2]) == [2, 2]
    np.testing.assert_allclose(r.points[0, :2], [[-1, 1], [1, 1]], atol=1e-15)
    # Contact of order 3 at the origin: x^2 + y^2 - 2y and x^2 + xy + y^2 - 2y; a crossing at (0, 2).
    r = locus.quadratic_curves([[1, 0, 1, 0, -2, 0]], [[1, 1, 1, 0, -2, 0]])
    assert sorted(r.multiplicity[0, : r.count[0]]) == [1, 3]
    # (x - y)(x + y - 1) and (x - y)(2x - 3y + 1): the line x = y and the point (2/5, 3/5).
    r = locus.quadratic_curves([[1, 0, -1, -1, 1, 0]], [[2, -5, 3, 1, -1, 0]])
    assert locus.KIND_NAMES[r.kind[0]] == "line" and r.count[0] == 3
    for p in r.points[0, :2]:
        assert abs(p[0] - p[1]) < 1e-15
    np.testing.assert_allclose(r.points[0, 2], [0.4, 0.6], atol=1e-15)
    assert list(r.multiplicity[0, :3]) == [0, 0, 1]
    # Proportional coefficients: coincident; non-finite input raises.
    r = locus.quadratic_curves([[1, 0, 1, 0, 0, -1]], [[2, 0, 2, 0, 0, -2]])
    assert locus.KIND_NAMES[r.kind[0]] == "coincident"
    with pytest.raises(ValueError):
        locus.quadratic_curves([[1, 0, 1, 0, 0, np.nan]], [[1, 0, 1, 0, 0, -1]])


def test_circle_arc_closed_forms():
    # Unit circles at the origin and at (1, 0) meet at (1/2, +-sqrt3/2): angles 2pi/3 and 4pi/3 on
    # the second circle.
    z = np.zeros((2, 2))
    c1 = np.array([[1.0, 0.0], [1.0, 0.0]])
    r = locus.circle_arc(z, [1.0, 1.0], c1, [1.0, 1.0], [np.pi / 2, -np.pi / 2], [np.pi, np.pi])
    assert r.count[0] == 2 and r.count[1] == 0
    got = r.points[0, :2][np.argsort(r.points[0, :2, 1])]
    np.testing.assert_allclose(got, [[0.5, -np.sqrt(3) / 2], [0.5, np.sqrt(3) / 2]], atol=1e-15)
    assert np.all(r.multiplicity[0, :2] == 1)
    # An arc of the circle itself: kind arc, start, middle, end.
    r = locus.circle_arc([[0.0, 0.0]], [2.0], [[0.0, 0.0]], [2.0], [0.0], [np.pi / 2])
    assert locus.KIND_NAMES[r.kind[0]] == "arc" and r.count[0] == 3
    np.testing.assert_allclose(r.points[0, :3], [[2, 0], [np.sqrt(2), np.sqrt(2)], [0, 2]],
                               atol=1e-14)
    with pytest.raises(ValueError):
        locus.circle_arc([[0.0, 0.0]], [1.0], [[1.0, 0.0]], [1.0], [0.0], [-1.0])


def test_arc_arc_closed_forms(rng):
    # Random arcs of two crossing circles: a point is reported exactly when its angle lies in
    # both arcs (angles kept away from the arc ends).
    n = 200
    t = rng.uniform(0, 2 * np.pi, (n, 2))
    s = rng.uniform(0.1, 2 * np.pi - 0.1, (n, 2))
    z = np.zeros((n, 2))
    c1 = np.tile([1.0, 0.0], (n, 1))
    r = locus.arc_arc(z, np.ones(n), t[:, 0], s[:, 0], c1, np.ones(n), t[:, 1], s[:, 1])
    pts = np.array([[0.5, np.sqrt(3) / 2], [0.5, -np.sqrt(3) / 2]])
    for i in range(n):
        want = []
        near_end = False
        for p in pts:
            inside = True
            for k, c in enumerate((np.zeros(2), np.array([1.0, 0.0]))):
                ang = np.arctan2(p[1] - c[1], p[0] - c[0])
                off = (ang - t[i, k]) % (2 * np.pi)
                near_end |= min(abs(off), abs(off - s[i, k]), abs(2 * np.pi - off)) < 1e-9
                inside &= off <= s[i, k]
            if inside:
                want.append(p)
        if near_end:
            continue
        assert r.count[i] == len(want), i
        for p in r.points[i, : r.count[i]]:
            assert min(np.abs(p - w).max() for w in want) < 1e-14
    # Two arcs of one circle overlapping in one piece.
    r = locus.arc_arc([[0.0, 0.0]], [1.0], [0.0], [np.pi], [[0.0, 0.0]], [1.0], [np.pi / 2],
                      [np.pi])
    assert locus.KIND_NAMES[r.kind[0]] == "arc" and r.count[0] == 3
    np.testing.assert_allclose(r.points[0, 0], [0, 1], atol=1e-15)
    np.testing.assert_allclose(r.points[0, 2], [-1, 0], atol=1e-15)
