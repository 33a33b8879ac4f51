# planar_polygon_pieces: every piece of a segment, ray or line in a filled polygon of a plane
# (intersection/segment_polygon.hpp intersection_pieces). Oracle: shapely's intersection of the
# polygon with the segment in the plane z = 0 (pieces merged along the segment), on integer data.
import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, Polygon

import locus

COMB = np.array([[0, 0], [7, 0], [7, 3], [6, 3], [6, 1], [5, 1], [5, 3], [4, 3], [4, 1], [3, 1],
                 [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]], float)
SPIRAL = np.array([[0, 0], [5, 0], [5, 5], [0, 5], [0, 2], [3, 2], [3, 3], [1, 3], [1, 4],
                   [4, 4], [4, 1], [0, 1]], float)


def star(rng):
    n = int(rng.integers(5, 12))
    ang = np.sort(rng.uniform(0, 2 * np.pi, n))
    r = rng.uniform(1, 6, n)
    pts = np.round(np.c_[3 + r * np.cos(ang), 3 + r * np.sin(ang)])
    return pts


def shapely_pieces(poly, p, q):
    """Intervals (t0, t1) along p + t (q - p) of the closed polygon's common set, merged."""
    g = Polygon(poly).intersection(LineString([p[:2], q[:2]]))
    d = (q - p)[:2]
    dd = d @ d
    ivs = []
    for part in getattr(g, "geoms", [g]):
        if part.is_empty:
            continue
        ts = [float((np.asarray(c) - p[:2]) @ d / dd) for c in part.coords]
        ivs.append((min(ts), max(ts)))
    ivs.sort()
    merged = []
    for a, b in ivs:
        if merged and a <= merged[-1][1] + 1e-12:
            merged[-1] = (merged[-1][0], max(merged[-1][1], b))
        else:
            merged.append((a, b))
    return merged


@pytest.mark.parametrize("shape", ["comb", "spiral", "star"])
def test_segments_against_shapely(rng, shape):
    compared = multi = 0
    for _ in range(60):
        poly = {"comb": COMB, "spiral": SPIRAL}.get(shape)
        if poly is None:
            poly = star(rng)
            if not Polygon(poly).is_valid:
                continue
        p = np.r_[rng.integers(-1, 9, 2), 0].astype(float)
        q = np.r_[rng.integers(-1, 9, 2), 0].astype(float)
        if np.array_equal(p, q):
            continue
        r = locus.planar_polygon_pieces(poly, p, q)
        want = shapely_pieces(poly, p, q)
        assert r.status == "ok"
        got = [(a, b) for a, b in r.t]
        assert len(got) == len(want), (poly.tolist(), p, q, got, want)
        np.testing.assert_allclose(np.array(got).reshape(-1, 2), np.array(want).reshape(-1, 2),
                                   atol=1e-12)
        for k, (a, b) in zip(r.kind, want):
            assert k == (2 if b > a else 1)
        np.testing.assert_allclose(r.points[..., :2], r.st, atol=1e-12)
        np.testing.assert_allclose(r.points[..., 2], 0)
        compared += 1
        multi += len(got) > 1
    assert compared > 40
    if shape != "star":
        assert multi > 5


def test_line_ray_and_tilted_frame():
    # The comb's teeth along y = 2: four pieces for the line, three for a ray from x = 1.5.
    line = locus.planar_polygon_pieces(COMB, [0, 2, 0], [1, 0, 0], kind="line")
    np.testing.assert_array_equal(line.kind, [2, 2, 2, 2])
    np.testing.assert_allclose(line.t, [[0, 1], [2, 3], [4, 5], [6, 7]])
    ray = locus.planar_polygon_pieces(COMB, [1.5, 2, 0], [1, 0, 0], kind="ray")
    np.testing.assert_allclose(ray.t, [[0.5, 1.5], [2.5, 3.5], [4.5, 5.5]])
    # A tilted plane: normal (1, 2, 2) / 8 (exact), u and v the rows (2, 1, -2) / 3 and
    # (2, -2, 1) / 3 (rounded); the line (5, -2, 5) + t (2, 1, -2) lies exactly in the plane and
    # maps near the comb scaled by 3 along st = (3 t, 6).
    frame = np.array([[1, 2, 3], [2 / 3, 1 / 3, -2 / 3], [2 / 3, -2 / 3, 1 / 3],
                      [1 / 8, 2 / 8, 2 / 8]])
    tilted = locus.planar_polygon_pieces(3 * COMB, [5, -2, 5], [2, 1, -2], kind="line",
                                         frame=frame)
    np.testing.assert_array_equal(tilted.kind, [2, 2, 2, 2])
    np.testing.assert_allclose(tilted.t, [[0, 1], [2, 3], [4, 5], [6, 7]], atol=1e-12)
    np.testing.assert_allclose(tilted.points, np.array([5, -2, 5]) + tilted.t[..., None] *
                               np.array([2, 1, -2]), atol=1e-12)
    # A touching point: the spiral's outer corner (5, 5) met by the diagonal from outside.
    touch = locus.planar_polygon_pieces(SPIRAL, [4, 6, 0], [6, 4, 0])
    np.testing.assert_array_equal(touch.kind, [1])
    np.testing.assert_allclose(touch.st[0, 0], [5, 5])


def test_bad_input():
    with pytest.raises(ValueError):
        locus.planar_polygon_pieces(COMB, [0, 0, np.nan], [1, 0, 0])
    with pytest.raises(ValueError):
        locus.planar_polygon_pieces(np.zeros((0, 2)), [0, 0, 0], [1, 0, 0])
    with pytest.raises(ValueError):
        locus.planar_polygon_pieces(COMB, [0, 0, 0], [1, 0, 0], kind="curve")
    with pytest.raises(ValueError):
        locus.planar_polygon_pieces(COMB, [0, 0, 0], [1, 0, 0], frame=np.zeros((4, 3)))
    # Crossing the plane: the crossing point only.
    r = locus.planar_polygon_pieces(COMB, [0.5, 0.5, -1], [0.5, 0.5, 1])
    np.testing.assert_array_equal(r.kind, [1])
    np.testing.assert_allclose(r.t[0], [0.5, 0.5])
    assert shapely.__version__
