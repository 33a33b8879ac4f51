# convex_partition, bsp_classify and bsp_partition against shapely (an independent geometry
# engine): the pieces tile the polygon, each piece is convex, the BSP answers match shapely's
# contains / touches on integer-grid input where boundary cases really occur.
import itertools

import numpy as np
import pytest
import shapely.geometry as sg

import locus


def star(rng, n, r_lo=0.5):
    """A simple polygon star-shaped around the origin: random radii at jittered angles, the
    gaps between consecutive angles below pi (n >= 4)."""
    a = (np.arange(n) + rng.uniform(0.0, 0.8, n)) * (2 * np.pi / n)
    r = rng.uniform(r_lo, 1.0, n)
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


# inside every star of >= 8 vertices (edges stay farther than 0.5 cos(0.9 pi / 4) from 0)
HOLE = np.array([[-0.2, -0.2], [-0.2, 0.2], [0.2, 0.2], [0.2, -0.2]])


def check_tiling(r, outer, holes):
    poly = sg.Polygon(outer, holes)
    pts = np.asarray(r.points, dtype=np.float64)
    np.testing.assert_array_equal(pts, np.concatenate([outer, *holes]).astype(r.points.dtype))
    pieces = [sg.Polygon(pts[idx]) for idx in r.pieces]
    assert len(pieces) == len(r.piece_ends) >= 1
    tol = 1e-9 if r.points.dtype == np.float64 else 1e-4
    for q, idx in zip(pieces, r.pieces):
        assert len(idx) >= 3
        assert q.exterior.is_ccw or q.area == 0
        assert q.area > 0
        # convex: the piece fills its convex hull
        assert q.convex_hull.area - q.area <= tol * q.area
    for a, b in itertools.combinations(pieces, 2):
        assert a.intersection(b).area <= tol * poly.area
    union = pieces[0]
    for q in pieces[1:]:
        union = union.union(q)
    assert abs(union.area - poly.area) <= tol * poly.area
    assert union.symmetric_difference(poly).area <= tol * poly.area
    for d in r.diagonals:
        assert d[0] < len(pts) and d[1] < len(pts) and d[0] != d[1]


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("method", ["hertel_mehlhorn", "minimum"])
def test_convex_partition_tiles_polygon(rng, dtype, method):
    for _ in range(20):
        outer = star(rng, int(rng.integers(4, 25))).astype(dtype)
        r = locus.convex_partition(outer, method=method)
        assert r.status == "ok"
        assert r.points.dtype == dtype
        check_tiling(r, outer, [])


def test_convex_partition_with_holes(rng):
    for _ in range(10):
        outer = star(rng, int(rng.integers(8, 30)))
        hole = HOLE * rng.uniform(0.5, 1.0)
        r = locus.convex_partition(outer, [hole])
        check_tiling(r, outer, [hole])
        assert len(r.pieces) >= 2  # a hole cannot sit inside a single convex piece


def test_minimum_is_at_most_hertel_mehlhorn(rng):
    for _ in range(20):
        outer = star(rng, int(rng.integers(5, 20)), r_lo=0.2)
        hm = locus.convex_partition(outer)
        mn = locus.convex_partition(outer, method="minimum")
        # reflex vertices (shapely orientation, independent of locus): the minimum needs at
        # least ceil(r / 2) + 1 pieces, Hertel-Mehlhorn at most 2r + 1
        ccw = sg.Polygon(outer).exterior.is_ccw
        reflex = 0
        for i in range(len(outer)):
            a, b, c = outer[i - 1], outer[i], outer[(i + 1) % len(outer)]
            cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            reflex += (cross < 0) if ccw else (cross > 0)
        assert -(-reflex // 2) + 1 <= len(mn.pieces) <= len(hm.pieces) <= 2 * reflex + 1


def test_convex_polygon_is_one_piece():
    a = np.linspace(0, 2 * np.pi, 12, endpoint=False)
    outer = np.column_stack([np.cos(a), np.sin(a)])[::-1]  # clockwise input
    for method in ["hertel_mehlhorn", "minimum"]:
        r = locus.convex_partition(outer, method=method)
        assert len(r.pieces) == 1 and len(r.diagonals) == 0
        assert sorted(r.pieces[0]) == list(range(12))


def test_minimum_direct_limit_exceeded_is_best_so_far(rng):
    outer = star(rng, 80)
    r = locus.convex_partition(outer, method="minimum_direct")
    assert r.status == "limit_exceeded"
    check_tiling(r, outer, [])


def test_minimum_keil_matches_direct_and_has_no_cap(rng):
    # Keil's programme (method='minimum') against the direct one on small polygons, then on a
    # polygon above the direct programme's 64-vertex cap.
    for n in [6, 12, 20, 30]:
        outer = star(rng, n, 0.2)
        keil = locus.convex_partition(outer, method="minimum")
        direct = locus.convex_partition(outer, method="minimum_direct")
        assert keil.status == "ok" and direct.status == "ok"
        assert len(keil.pieces) == len(direct.pieces)
        check_tiling(keil, outer, [])
    outer = star(rng, 200, 0.2)
    r = locus.convex_partition(outer, method="minimum")
    assert r.status == "ok"
    check_tiling(r, outer, [])
    assert len(r.pieces) <= len(locus.convex_partition(outer).pieces)
    with pytest.raises(ValueError):
        locus.convex_partition(outer, method="keil")


# An integer-grid polygon with a hole: a comb (reflex vertices, collinear edges) around a square
# hole. Grid queries at step 1/2 hit vertices, edges and the lines extending them.
COMB = np.array([[0, 0], [8, 0], [8, 6], [6, 6], [6, 3], [5, 3], [5, 6], [3, 6], [3, 3], [2, 3],
                 [2, 6], [0, 6]], dtype=np.float64)
COMB_HOLE = np.array([[1, 1], [1, 2], [4, 2], [4, 1]], dtype=np.float64)


def shapely_side(poly, p):
    pt = sg.Point(p)
    if poly.contains(pt):
        return 1
    return 0 if poly.touches(pt) else -1


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_bsp_classify_matches_shapely(dtype):
    poly = sg.Polygon(COMB, [COMB_HOLE])
    g = np.arange(-1.0, 9.5, 0.5)
    q = np.array([[x, y] for x in g for y in g], dtype=dtype)
    side = locus.bsp_classify([COMB.astype(dtype), COMB_HOLE.astype(dtype)], q)
    assert side.dtype == np.int8 and side.shape == (len(q),)
    want = np.array([shapely_side(poly, p) for p in q])
    np.testing.assert_array_equal(side, want)
    assert (want == 0).sum() > 20 and (want == 1).sum() > 20  # the boundary cases are exercised


def test_bsp_classify_random_star(rng):
    outer = star(rng, 40)
    q = rng.uniform(-1.1, 1.1, (2000, 2))
    poly = sg.Polygon(outer, [HOLE])
    side = locus.bsp_classify([outer, HOLE], q)
    want = np.array([shapely_side(poly, p) for p in q])
    np.testing.assert_array_equal(side, want)
    # a single (n, 2) array is one ring; the vertices themselves are on the boundary
    np.testing.assert_array_equal(locus.bsp_classify(outer, outer), 0)


def test_bsp_partition_matches_shapely(rng):
    poly = sg.Polygon(COMB, [COMB_HOLE])
    # grid segments (along edges and through vertices) and random ones
    grid = rng.integers(-1, 10, (150, 2, 2)).astype(np.float64)
    grid = grid[np.any(grid[:, 0] != grid[:, 1], axis=1)]
    segs = np.concatenate([grid, rng.uniform(-1, 9, (50, 2, 2)),
                           [[[0, 0], [8, 0]], [[8, 0], [-1, 0]], [[2, 3], [6, 3]]]])
    r = locus.bsp_partition([COMB, COMB_HOLE], segs)
    assert r.status == "ok"
    assert r.pieces.shape == (len(r.location), 2, 2) and r.location.dtype == np.int8
    assert set(np.unique(r.location)) <= {-2, -1, 1, 2}
    assert {-2, -1, 1, 2} <= set(np.unique(r.location))  # every kind occurs
    np.testing.assert_array_equal(np.unique(r.segment), np.arange(len(segs)))
    for i, s in enumerate(segs):
        mine = np.flatnonzero(r.segment == i)
        pieces = r.pieces[mine]
        # the pieces run from p0 to p1 without gaps
        np.testing.assert_allclose(pieces[0, 0], s[0], atol=1e-12)
        np.testing.assert_allclose(pieces[-1, 1], s[1], atol=1e-12)
        np.testing.assert_allclose(pieces[1:, 0], pieces[:-1, 1], atol=1e-12)
        d = s[1] - s[0]
        left = np.array([-d[1], d[0]]) / np.linalg.norm(d)
        for p, loc in zip(pieces, r.location[mine]):
            mid = (p[0] + p[1]) / 2
            line = sg.LineString(p)
            tol = 1e-9 * line.length  # cut points are rounded
            assert line.length > 0
            on_boundary = line.intersection(poly.boundary).length
            # a piece may touch the boundary at isolated points (through a vertex), no more
            if abs(loc) == 2:
                assert on_boundary >= line.length - tol
                # same direction as the boundary edge: the interior is on the left
                eps = 1e-6
                assert shapely_side(poly, mid + eps * left) == (1 if loc == 2 else -1)
                assert shapely_side(poly, mid - eps * left) == (-1 if loc == 2 else 1)
            elif loc == 1:
                assert on_boundary <= tol and line.difference(poly).length <= tol
            else:
                assert line.intersection(poly).length <= tol


def test_bad_input():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.convex_partition(np.array([[0, 0], [1, 0], [np.nan, 1.0]]))
    with pytest.raises(ValueError, match="method"):
        locus.convex_partition(sq, method="magic")
    with pytest.raises(ValueError, match="invalid_input"):
        locus.convex_partition(sq * 4, [sq + 1], method="minimum")
    with pytest.raises(ValueError, match="list of"):
        locus.convex_partition(sq * 4, sq + 1)
    with pytest.raises(ValueError, match="columns"):
        locus.convex_partition(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="empty_input"):
        locus.convex_partition(np.zeros((0, 2)))
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.bsp_classify(sq, [[0.5, np.inf]])
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.bsp_classify([[0, 0], [1, 0], [np.nan, 1]], [[0.5, 0.5]])
    with pytest.raises(ValueError, match="degenerate_input"):
        locus.bsp_classify([[0, 0], [1, 0], [2, 0]], [[0.5, 0.5]])
    with pytest.raises(ValueError, match="empty_input"):
        locus.bsp_classify([], [[0.5, 0.5]])
    with pytest.raises(ValueError, match="columns"):
        locus.bsp_classify(sq, [[0.5, 0.5, 0.5]])
    with pytest.raises(ValueError, match="equal ends"):
        locus.bsp_partition(sq, [[[0.5, 0.5], [0.5, 0.5]]])
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.bsp_partition(sq, [[[0.5, 0.5], [np.nan, 0.5]]])
    with pytest.raises(ValueError, match="3-d array"):
        locus.bsp_partition(sq, [[0.5, 0.5], [1, 1]])
    with pytest.raises(ValueError):
        locus.bsp_partition(None, [[[0.5, 0.5], [1, 1]]])


def test_result_fields_match_stub():
    import ast
    import pathlib
    stub = pathlib.Path(__file__).resolve().parent.parent / "locus.pyi"
    tree = ast.parse(stub.read_text())
    fields = {n.name: {a.target.id for a in n.body if isinstance(a, ast.AnnAssign)}
              for n in tree.body if isinstance(n, ast.ClassDef)}
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])
    for r in [locus.convex_partition(sq), locus.bsp_partition(sq, [[[0, 0], [2, 2.0]]])]:
        assert set(vars(r)) == fields[type(r).__name__] | {"status"}


def surface_points(control, ku, kv, du, dv, uv):
    """Tensor-product B-spline evaluation by scipy (independent of locus)."""
    from scipy.interpolate import BSpline
    out = []
    for u, v in uv:
        col = BSpline(ku, control, du)(u)  # (cols, N): the net collapsed along u
        out.append(BSpline(kv, col, dv)(v))
    return np.array(out)


def random_knots(rng, n, d):
    inner = np.sort(rng.uniform(0, 1, n - d - 1))
    return np.concatenate([np.zeros(d + 1), inner, np.ones(d + 1)])


@pytest.mark.parametrize("dim", [2, 3])
def test_bspline_surface_insert_knot_keeps_surface(rng, dim):
    for _ in range(10):
        du, dv = int(rng.integers(1, 4)), int(rng.integers(1, 4))
        rows, cols = du + int(rng.integers(1, 5)), dv + int(rng.integers(1, 5))
        control = rng.uniform(-1, 1, (rows, cols, dim))
        ku, kv = random_knots(rng, rows, du), random_knots(rng, cols, dv)
        direction = ["u", "v"][int(rng.integers(2))]
        t, times = float(rng.uniform(0, 1)), int(rng.integers(1, 4))
        c2, ku2, kv2 = locus.bspline_surface_insert_knot(control, ku, kv, du, dv, t,
                                                         direction=direction, times=times)
        d = du if direction == "u" else dv
        added = min(times, d)  # t is a new knot (probability one); multiplicity capped at d
        if direction == "u":
            assert c2.shape == (rows + added, cols, dim) and np.array_equal(kv2, kv)
            assert np.count_nonzero(ku2 == t) == added and len(ku2) == len(ku) + added
        else:
            assert c2.shape == (rows, cols + added, dim) and np.array_equal(ku2, ku)
            assert np.count_nonzero(kv2 == t) == added and len(kv2) == len(kv) + added
        uv = rng.uniform(0, 1, (20, 2))
        np.testing.assert_allclose(surface_points(c2, ku2, kv2, du, dv, uv),
                                   surface_points(control, ku, kv, du, dv, uv), atol=1e-12)


def test_bspline_surface_insert_knot_bad_input(rng):
    control = rng.uniform(-1, 1, (4, 4, 3))
    k = random_knots(rng, 4, 2)
    with pytest.raises(ValueError, match="invalid_input"):
        locus.bspline_surface_insert_knot(control, k[:-1], k, 2, 2, 0.5)
    with pytest.raises(ValueError, match="invalid_input"):
        locus.bspline_surface_insert_knot(control, k[::-1], k, 2, 2, 0.5)
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.bspline_surface_insert_knot(control, k, k, 2, 2, np.nan)
    bad = control.copy()
    bad[1, 2, 0] = np.inf
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.bspline_surface_insert_knot(bad, k, k, 2, 2, 0.5)
    with pytest.raises(ValueError, match="direction"):
        locus.bspline_surface_insert_knot(control, k, k, 2, 2, 0.5, direction="w")
    with pytest.raises(ValueError, match="times"):
        locus.bspline_surface_insert_knot(control, k, k, 2, 2, 0.5, times=0)
    with pytest.raises(ValueError, match="3-d array"):
        locus.bspline_surface_insert_knot(control[0], k, k, 2, 2, 0.5)
