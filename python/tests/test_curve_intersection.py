# line_curve_hits / curve_intersections / curve_self_intersections (Bezier, B-spline, NURBS;
# algebraic, hierarchy, resultant, raster)
# against a dense-sampling oracle in numpy (sign changes of the signed distance from the line,
# crossings of dense polylines with shapely), exact tangencies, the coincident case, swap
# symmetry and bad input.
import numpy as np
import pytest
from shapely.geometry import LineString

import locus

METHODS = ["algebraic", "hierarchy", "raster", "resultant"]


def bezier_points(ctrl, t):
    # de Casteljau, vectorised over t
    b = np.repeat(np.asarray(ctrl, float)[None], len(t), axis=0)
    t = t[:, None]
    while b.shape[1] > 1:
        b = (1 - t[:, None]) * b[:, :-1] + t[:, None] * b[:, 1:]
    return b[:, 0]


def crossings_oracle(ctrl, o, d):
    t = np.linspace(0, 1, 4001)
    p = bezier_points(ctrl, t)
    g = d[0] * (p[:, 1] - o[1]) - d[1] * (p[:, 0] - o[0])
    s = np.sign(g)
    return int(np.count_nonzero(s[1:] != s[:-1])), np.min(np.abs(g)) / np.linalg.norm(d)


@pytest.mark.parametrize("method", METHODS)
def test_line_through_known_points(rng, method):
    checked = 0
    for _ in range(40):
        ctrl = rng.integers(-64, 65, size=(4, 2)) / 16.0
        t0 = rng.uniform(0.1, 0.9)
        o = bezier_points(ctrl, np.array([t0]))[0]
        d = rng.uniform(-1, 1, 2)
        count, _ = crossings_oracle(ctrl, o, d)
        # skip near tangencies and crossings close together (the raster's documented limit)
        t = np.linspace(0, 1, 4001)
        p = bezier_points(ctrl, t)
        g = d[0] * (p[:, 1] - o[1]) - d[1] * (p[:, 0] - o[0])
        idx = np.nonzero(np.sign(g[1:]) != np.sign(g[:-1]))[0]
        a, m, c = np.abs(g[:-2]), np.abs(g[1:-1]), np.abs(g[2:])
        same = (np.sign(g[:-2]) == np.sign(g[1:-1])) & (np.sign(g[1:-1]) == np.sign(g[2:]))
        ext = m[same & (m <= a) & (m <= c)]  # local minima of |distance| without a crossing
        close = idx.size > 1 and np.min(np.abs(np.diff(p[idx], axis=0)).sum(1)) < 0.3
        if (ext.size and ext.min() < 1e-3) or close:
            continue
        r = locus.line_curve_hits(o, d, ctrl, method=method)
        assert r.status == "ok"
        assert len(r.points) == count
        assert np.all(r.multiplicity == 1)
        # on both: the line through param_a, the curve through param_b
        np.testing.assert_allclose(r.points, o + r.param_a[:, None] * d, atol=1e-9)
        np.testing.assert_allclose(r.points, bezier_points(ctrl, r.param_b), atol=1e-9)
        assert np.all(np.diff(r.param_a) >= 0)
        checked += 1
    assert checked >= 20


def test_ray_segment_and_tangency():
    ctrl = [[0, 0.75], [1, 0], [2, -0.75], [3, 1.5]]  # y = 3 (t - 1/2)^2 (t + 1)
    for method in METHODS:
        r = locus.line_curve_hits([-5, 0], [1, 0], ctrl, method=method)
        assert len(r.points) == 1 and r.multiplicity[0] == 2
        assert abs(r.points[0, 0] - 1.5) < 1e-5
        s = locus.line_curve_hits([-5, 0.25], [7, 0.25], ctrl, component="segment", method=method)
        assert len(s.points) == 2 and np.all((0 <= s.param_a) & (s.param_a <= 1))
        q = locus.line_curve_hits([1.0, 0.25], [1, 0], ctrl, component="ray", method=method)
        assert len(q.points) == 1 and q.param_a[0] >= 0


def test_bspline_and_nurbs_dicts():
    spline = {"control": [[0, 0], [0.5, 1], [1.5, 1], [2, 0]], "degree": 2,
              "knots": [0, 0, 0, 0.5, 1, 1, 1]}
    r = locus.line_curve_hits([1, -3], [0, 1], spline)  # x = 1 crosses at the joint, once
    assert len(r.points) == 1 and abs(r.param_b[0] - 0.5) < 1e-12
    # a quarter circle as a NURBS: its crossing with y = x is at radius 1
    w = np.sqrt(0.5)
    arc = {"control": [[1, 0], [1, 1], [0, 1]], "degree": 2, "weights": [1, w, 1],
           "knots": [0, 0, 0, 1, 1, 1]}
    r = locus.line_curve_hits([0, 0], [1, 1], arc)
    assert len(r.points) == 1
    assert abs(np.hypot(*r.points[0]) - 1) < 1e-12


@pytest.mark.parametrize("method", METHODS)
def test_curve_curve_against_shapely(rng, method):
    checked = 0
    for _ in range(25):
        a = rng.integers(-64, 65, size=(4, 2)) / 16.0
        b = rng.integers(-64, 65, size=(4, 2)) / 16.0
        t = np.linspace(0, 1, 600)
        pa, pb = bezier_points(a, t), bezier_points(b, t)
        inter = LineString(pa).intersection(LineString(pb))
        pts = [] if inter.is_empty else [g for g in getattr(inter, "geoms", [inter])]
        if any(g.geom_type != "Point" for g in pts):
            continue
        pts = np.array([[g.x, g.y] for g in pts]).reshape(-1, 2)
        if len(pts) > 1 and min(np.linalg.norm(pts[i] - pts[j]) for i in range(len(pts))
                                for j in range(i + 1, len(pts))) < 0.3:
            continue
        coarse = LineString(bezier_points(a, t[::3])).intersection(LineString(bezier_points(b, t[::3])))
        if len(getattr(coarse, "geoms", [coarse] if not coarse.is_empty else [])) != len(pts):
            continue
        r = locus.curve_intersections(a, b, method=method)
        assert len(r.points) == len(pts)
        np.testing.assert_allclose(r.points, bezier_points(a, r.param_a), atol=1e-9)
        np.testing.assert_allclose(r.points, bezier_points(b, r.param_b), atol=1e-9)
        s = locus.curve_intersections(b, a, method=method)
        assert len(s.points) == len(r.points)
        np.testing.assert_allclose(np.sort(s.param_b), np.sort(r.param_a), atol=1e-9)
        checked += 1
    assert checked >= 10


def test_coincident_and_tangent_curves():
    up = [[0, 1], [1, -1], [2, 1]]
    r = locus.curve_intersections(up, up[::-1])
    assert r.kind == "coincident" and len(r.points) == 2
    t = locus.curve_intersections(up, [[0, -1], [1, 1], [2, -1]])
    assert len(t.points) == 1 and t.multiplicity[0] == 2


def test_resultant_matches_subdivision():
    rng = np.random.default_rng(11)
    compared = 0
    for _ in range(30):
        a, b = rng.integers(-32, 33, (4, 2)) / 8.0, rng.integers(-32, 33, (3, 2)) / 8.0
        sub = locus.curve_intersections(a, b)
        res = locus.curve_intersections(a, b, method="resultant")
        if any(m != 1 for m in sub.multiplicity):
            continue
        assert len(res.points) == len(sub.points)
        np.testing.assert_allclose(res.param_a, sub.param_a, atol=1e-9)
        np.testing.assert_allclose(res.param_b, sub.param_b, atol=1e-9)
        compared += len(sub.points)
    assert compared >= 10


def test_shared_stretch_and_self_intersections():
    c = np.array([[0, 0], [1, 3], [2, -2], [3, 1.0]])
    # The left half of c by de Casteljau at 1/2: they share c's [0, 1/2].
    half = np.array([c[0], (c[0] + c[1]) / 2, (c[0] + 2 * c[1] + c[2]) / 4,
                     (c[0] + 3 * c[1] + 3 * c[2] + c[3]) / 8])
    for method in ("algebraic", "resultant"):
        r = locus.curve_intersections(c, half, method=method)
        assert r.kind == "coincident" and list(r.multiplicity) == [0, 0]
        np.testing.assert_allclose(r.param_a, [0, 0.5], atol=1e-9)
        np.testing.assert_allclose(r.param_b, [0, 1], atol=1e-9)
    # A loop symmetric about x = 1.5: its double point at parameters s and 1 - s.
    loop = [[0, 0], [4, 3], [-1, 3], [3, 0]]
    s = locus.curve_self_intersections(loop)
    assert s.kind == "point" and s.multiplicity[0] == 1
    assert s.param_a[0] < s.param_b[0]
    np.testing.assert_allclose(s.param_a[0] + s.param_b[0], 1.0, atol=1e-9)
    np.testing.assert_allclose(s.points[0], bezier_points(loop, s.param_b)[0], atol=1e-9)
    assert len(locus.curve_self_intersections([[0, 0], [1, 1], [2, 0]]).points) == 0
    with pytest.raises(ValueError):
        locus.curve_self_intersections([[0, 0], [np.nan, 1], [2, 0]])
    with pytest.raises(ValueError):
        locus.curve_self_intersections(loop, method="guess")


def test_bad_input():
    ctrl = [[0, 0], [1, 1], [2, 0]]
    with pytest.raises(ValueError):
        locus.line_curve_hits([0, np.nan], [1, 0], ctrl)
    with pytest.raises(ValueError):
        locus.line_curve_hits([0, 0], [1, 0], [[0, 0], [np.inf, 1]])
    with pytest.raises(ValueError):
        locus.line_curve_hits([0, 0], [1, 0], ctrl, method="guess")
    with pytest.raises(ValueError):
        locus.line_curve_hits([0, 0], [1, 0], ctrl, component="plane")
    with pytest.raises(ValueError):
        locus.curve_intersections({"control": ctrl, "degree": 5, "knots": [0, 1]}, ctrl)
    assert len(locus.line_curve_hits([0, 5], [1, 0], ctrl).points) == 0
