# locus against shapely (GEOS) on seeded data: the same containment answers (points inside,
# on the boundary, outside), and the same distances within a few ulps.
from fractions import Fraction

import numpy as np
import pytest
import shapely.geometry as sg
import shapely.vectorized as sv

import locus


def star(rng, n=40):
    """A simple star-shaped polygon with random radii (counter-clockwise)."""
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    rad = rng.uniform(0.4, 1.0, n)
    return np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=1)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_point_in_polygon_matches_shapely(rng, dtype):
    poly = star(rng).astype(dtype)
    hole = (0.2 * star(rng, 12)).astype(dtype)
    pts = rng.uniform(-1.1, 1.1, (20000, 2)).astype(dtype)
    # points exactly on the boundary: the vertices
    pts = np.concatenate([pts, poly, hole])
    rings = np.concatenate([poly, hole])
    side = locus.point_in_polygon(pts, rings, ring_ends=[len(poly), len(rings)])
    shape = sg.Polygon(poly.astype(np.float64), [hole.astype(np.float64)])
    x, y = pts[:, 0].astype(np.float64), pts[:, 1].astype(np.float64)
    inside = sv.contains(shape, x, y)
    on_boundary = sv.touches(shape, x, y)
    assert np.array_equal(side == 1, inside)
    assert np.array_equal(side == 0, on_boundary)
    assert on_boundary.sum() >= len(poly) + len(hole)  # the boundary cases were exercised
    assert 0 < inside.sum() < len(pts)


def test_point_in_polyhedron_cube(rng):
    # unit cube as 12 outward triangles; the oracle is the coordinate test
    v = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=np.float64)
    hull = locus.convex_hull(v)
    pts = rng.uniform(-0.5, 1.5, (5000, 3))
    pts[:100, 0] = 1.0  # on the x = 1 face plane
    side = locus.point_in_polyhedron(pts, v, hull.triangles)
    inner = np.all((pts > 0) & (pts < 1), axis=1)
    closed = np.all((pts >= 0) & (pts <= 1), axis=1)
    assert np.array_equal(side == 1, inner)
    assert np.array_equal(side >= 0, closed)
    assert (side == 0).any()


def ulps_close(a, b, ulps=4):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    tol = ulps * np.spacing(np.maximum(np.abs(a), np.abs(b)))
    return np.abs(a - b) <= np.maximum(tol, 1e-300)


def sq_close(sq, ref, scale, ulps=8):
    """Squared distances agree within a few ulps of the squared coordinate scale: both sides
    round a constructed closest point, whose error is relative to the coordinates, not to the
    distance (crossing segments: exactly 0 for GEOS, ~1e-30 squared for locus)."""
    return np.abs(np.asarray(sq, dtype=np.float64) - ref**2) <= ulps * np.spacing(
        np.maximum(scale**2, ref**2))


def test_point_triangle_distance_matches_shapely(rng):
    n = 2000
    tris = np.zeros((n, 3, 3))
    tris[:, :, :2] = rng.uniform(-1, 1, (n, 3, 2))  # in the plane z = 0
    pts = np.zeros((n, 3))
    pts[:, :2] = rng.uniform(-2, 2, (n, 2))
    sq = locus.point_triangle_sqr_distances(pts, tris)
    ref = np.array([sg.Point(p[:2]).distance(sg.Polygon(t[:, :2])) for p, t in zip(pts, tris)])
    assert np.all(sq_close(sq, ref, 2.0)), np.max(np.abs(sq - ref**2))
    assert (ref == 0).any() and (ref > 0).any()


def test_segment_segment_distance_matches_shapely(rng):
    n = 2000
    a = np.zeros((n, 2, 3))
    b = np.zeros((n, 2, 3))
    a[:, :, :2] = rng.uniform(-1, 1, (n, 2, 2))
    b[:, :, :2] = rng.uniform(-1, 1, (n, 2, 2))
    sq = locus.segment_segment_sqr_distances(a, b)
    ref = np.array([sg.LineString(s[:, :2]).distance(sg.LineString(t[:, :2]))
                    for s, t in zip(a, b)])
    assert np.all(sq_close(sq, ref, 1.0)), np.max(np.abs(sq - ref**2))
    assert (ref == 0).any() and (ref > 0).any()


def test_point_box_distance_matches_shapely(rng):
    box = np.array([[-0.5, -0.25, 0.0], [0.75, 0.5, 0.0]])
    pts = np.zeros((3000, 3))
    pts[:, :2] = rng.uniform(-2, 2, (3000, 2))
    d = np.sqrt(locus.point_box_sqr_distances(pts, box))
    shape = sg.box(-0.5, -0.25, 0.75, 0.5)
    ref = np.array([sg.Point(p[:2]).distance(shape) for p in pts])
    assert np.all(ulps_close(d, ref))


def exact_crossing(a, b):
    """The intersection point of the lines through segments a and b, in rationals."""
    (p0, p1), (q0, q1) = [[[Fraction(float(c)) for c in v] for v in s] for s in (a, b)]
    d = [p1[0] - p0[0], p1[1] - p0[1]]
    e = [q1[0] - q0[0], q1[1] - q0[1]]
    w = [q0[0] - p0[0], q0[1] - p0[1]]
    den = d[0] * e[1] - d[1] * e[0]
    t = (w[0] * e[1] - w[1] * e[0]) / den
    return [p0[0] + t * d[0], p0[1] + t * d[1]]


def test_segment_intersections_match_shapely(rng):
    n = 3000
    a = rng.uniform(-1, 1, (n, 2, 2))
    b = rng.uniform(-1, 1, (n, 2, 2))
    b[:50] = a[:50, ::-1]  # identical (reversed): collinear overlap
    r = locus.segment_intersections(a, b)
    names = [locus.KIND_NAMES[k] for k in r.kind]
    for i in range(n):
        s, t = sg.LineString(a[i]), sg.LineString(b[i])
        assert (names[i] != "empty") == s.intersects(t), i
        if names[i] == "point":
            # the exact crossing in rationals; the header's bound (segment_segment.hpp):
            # |point - X|inf <= 6 eps max(|X|inf, m), m the largest |coordinate|
            X = exact_crossing(a[i], b[i])
            m = max(np.abs(a[i]).max(), np.abs(b[i]).max())
            bound = 6 * np.finfo(np.float64).eps * max(abs(float(X[0])), abs(float(X[1])), m)
            err = max(abs(Fraction(float(r.points[i, 0, k])) - X[k]) for k in range(2))
            assert err <= Fraction(bound), (i, float(err), bound)
        if names[i] == "segment":
            assert t.equals(s) or s.intersection(t).length > 0
    assert names.count("point") > 0 and names.count("segment") >= 50
