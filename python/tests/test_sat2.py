# convex_polygons_intersect / convex_polygon_intersection / first_contact against shapely (GEOS)
# on random convex polygons and small-integer touching cases (kinds and areas, the reported
# polygon's area summed in Fractions), analytic moving cases, and bad input.
import numpy as np
import pytest
from fractions import Fraction
from scipy.spatial import ConvexHull
from shapely.geometry import Polygon

import locus


def random_convex(rng, grid):
    while True:
        n = rng.integers(3, 8)
        p = rng.integers(-3, 4, size=(n, 2)).astype(float) if grid else rng.uniform(-2, 2, (n, 2))
        p += rng.integers(-3, 4, size=2) if grid else rng.uniform(-2, 2, 2)
        try:
            h = ConvexHull(p)
        except Exception:
            continue
        return p[h.vertices]


def area(v):
    v = [(Fraction(x), Fraction(y)) for x, y in v]
    return sum(v[i][0] * v[(i + 1) % len(v)][1] - v[i][1] * v[(i + 1) % len(v)][0]
               for i in range(len(v))) / 2


@pytest.mark.parametrize("grid", [False, True])
def test_against_shapely(grid):
    rng = np.random.default_rng(20261204)
    kinds = set()
    for _ in range(200):
        a, b = random_convex(rng, grid), random_convex(rng, grid)
        pa, pb = Polygon(a), Polygon(b)
        meet = locus.convex_polygons_intersect(a, b)
        assert meet == pa.intersects(pb)
        assert meet == locus.convex_polygons_intersect(b[::-1], a)
        r = locus.convex_polygon_intersection(a, b)
        kinds.add(r.kind)
        inter = pa.intersection(pb)
        want = {"Polygon": "polygon", "LineString": "segment", "Point": "point"}.get(
            inter.geom_type, "empty") if not inter.is_empty else "empty"
        assert r.kind == want
        if r.kind == "polygon":
            assert area(r.vertices) > 0
            assert abs(float(area(r.vertices)) - inter.area) <= 1e-12 * max(1.0, inter.area)
    assert {"empty", "polygon"} <= kinds
    if grid:
        assert {"point", "segment"} & kinds


def test_first_contact_cases():
    sq = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], float)
    r = locus.first_contact(sq, [0.5, 0], sq + [4, 0.5], [-0.5, 0], 10)
    assert r.kind == "segment" and r.time == 2.0
    assert np.array_equal(r.points, [[2, -0.5], [2, 1]])
    r = locus.first_contact(sq, [0, 0], sq + [4, 4], [-1, -1], 10)
    assert r.kind == "point" and r.time == 2.0 and np.array_equal(r.points, [[1, 1]])
    r = locus.first_contact(sq, [0, 0], sq + [4, 4], [1, 0], 10)
    assert r.kind == "empty" and r.time is None and r.points.shape == (0, 2)
    assert locus.first_contact(sq, [0, 0], sq, [1, 0], 1).kind == "polygon"


def test_first_contact_against_shapely():
    rng = np.random.default_rng(5)
    checked = 0
    for _ in range(100):
        a, b = random_convex(rng, False), random_convex(rng, False) + rng.uniform(-6, 6, 2)
        va, vb = rng.uniform(-1, 1, 2), rng.uniform(-1, 1, 2) - (b.mean(0) - a.mean(0)) / 4
        r = locus.first_contact(a, va, b, vb, 8.0)
        at = lambda t: Polygon(a + t * va).intersects(Polygon(b + t * vb))
        if r.kind == "empty":
            assert not any(at(t) for t in np.linspace(0, 8, 81)[1:-1] if not at(0))
            continue
        t = r.time
        if t > 1e-9:
            assert not at(t * (1 - 1e-9))
            checked += 1
    assert checked > 10


def test_bad_input():
    sq = np.array([[0, 0], [1, 0], [1, 1]], float)
    with pytest.raises(ValueError):
        locus.convex_polygons_intersect(sq, np.array([[np.nan, 0], [1, 1], [0, 1]]))
    with pytest.raises(ValueError):
        locus.convex_polygon_intersection(sq, np.zeros((0, 2)))
    with pytest.raises(ValueError):
        locus.first_contact(sq, [0, 0], sq, [1, 0], -1.0)
    with pytest.raises(ValueError):
        locus.first_contact(sq, [0, np.inf], sq, [1, 0], 1.0)
