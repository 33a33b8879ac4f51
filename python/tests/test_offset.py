# offset(region, delta) and offset_polyline(paths, delta) against shapely's buffer (GEOS, an
# independent engine): areas of round and mitre joins on random star polygons (with holes) and
# polylines, within a bound derived from both arc tolerances; valid output by shapely's is_valid;
# float32; bad input.
import numpy as np
import pytest
import shapely.geometry as sg
from shapely.ops import unary_union

import locus

QUAD_SEGS = 16  # shapely's resolution: segments per quarter circle
# shapely 1.8 numbering of join and cap styles (JOIN_STYLE, CAP_STYLE)
ROUND, MITRE = 1, 2
FLAT, SQUARE = 2, 3


def star(rng, n, center=(0.0, 0.0), r_lo=0.5, r_hi=1.0):
    """A simple polygon star-shaped around center: jittered angles, gaps below pi (n >= 4)."""
    a = (np.arange(n) + rng.uniform(0.0, 0.8, n)) * (2 * np.pi / n)
    r = rng.uniform(r_lo, r_hi, n)
    return np.column_stack([center[0] + r * np.cos(a), center[1] + r * np.sin(a)])


def to_shapely(result):
    return [sg.Polygon(rings[0], rings[1:]) for rings in result.polygons]


def check_valid(result):
    polys = to_shapely(result)
    for p in polys:
        assert p.is_valid
        assert p.exterior.is_ccw
        for h in p.interiors:
            assert not h.is_ccw
    if polys:
        total = sum(p.area for p in polys)
        assert abs(unary_union(polys).area - total) <= 1e-9 * max(1.0, total)
    return sum(p.area for p in polys)


def geos_tolerance(d):
    """The gap between GEOS's chords (quad_segs per quarter turn, vertices on the circle) and
    the arc."""
    return abs(d) * (1 - np.cos(np.pi / (4 * QUAD_SEGS)))


@pytest.mark.parametrize("seed", range(6))
def test_round_joins_match_shapely_buffer(seed):
    rng = np.random.default_rng(seed)
    outer = star(rng, int(rng.integers(6, 12)))
    hole = star(rng, int(rng.integers(4, 7)), r_lo=0.1, r_hi=0.3)[::-1]
    shape = sg.Polygon(outer, [hole])
    for d in (0.15, -0.1, 0.3, -0.05):
        tol = geos_tolerance(d)
        r = locus.offset([outer, hole], d, join="round", arc_tolerance=tol)
        area = check_valid(r)
        expect = shape.buffer(d, resolution=QUAD_SEGS, join_style=ROUND).area
        # Both lie between the exact offsets by |d| - tol and |d|: their areas differ by at most
        # tol times the perimeter of the larger one.
        bound = tol * (shape.length + 2 * np.pi * abs(d)) + 1e-9
        assert abs(area - expect) <= bound, (d, area, expect, bound)


@pytest.mark.parametrize("seed", range(6))
def test_mitre_joins_match_shapely_buffer(seed):
    rng = np.random.default_rng(100 + seed)
    outer = star(rng, int(rng.integers(5, 10)))
    shape = sg.Polygon(outer)
    for d in (0.1, -0.08, 0.25):
        # A limit no corner of these stars reaches: both sides keep every miter.
        r = locus.offset(outer, d, join="miter", miter_limit=100.0)
        area = check_valid(r)
        expect = shape.buffer(d, join_style=MITRE, mitre_limit=100.0).area
        assert area == pytest.approx(expect, rel=1e-9, abs=1e-12), d


def test_polylines_match_shapely_buffer():
    rng = np.random.default_rng(7)
    for trial in range(6):
        path = rng.uniform(-1, 1, (int(rng.integers(2, 6)), 2))
        d = 0.1 + 0.1 * trial
        tol = geos_tolerance(d)
        for end, cap in (("round", ROUND), ("square", SQUARE), ("butt", FLAT)):
            if end == "butt":
                # Where a segment shorter than delta meets a turn, flat-capped buffers are
                # construction-defined (GEOS traces offset curves, locus unites rectangles and
                # joins): compare where the segments are long enough for both to agree.
                seg = np.linalg.norm(np.diff(path, axis=0), axis=1)
                d = min(d, 0.5 * seg.min())
                tol = geos_tolerance(d)
            r = locus.offset_polyline(path, d, end=end, arc_tolerance=tol)
            area = check_valid(r)
            line = sg.LineString(path)
            expect = line.buffer(d, resolution=QUAD_SEGS, cap_style=cap, join_style=ROUND).area
            bound = tol * (2 * line.length + 2 * np.pi * d) + 1e-9
            assert abs(area - expect) <= bound, (trial, end, area, expect)


def test_shapes_float32_and_bad_input():
    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=np.float32)
    r = locus.offset(square, 0.5, join="miter")
    assert r.polygons[0][0].dtype == np.float32
    assert check_valid(r) == pytest.approx(9.0)
    # A multipolygon in the layout of BooleanResult.polygons; deflating it away leaves nothing.
    two = [[square.astype(float)], [square.astype(float) + [5.0, 0.0]]]
    assert len(locus.offset(two, 0.5).polygons) == 2
    assert len(locus.offset(two, 2.0).polygons) == 1
    assert locus.offset(two, -1.0).polygons == []
    assert locus.offset([], 1.0).polygons == []
    loop = locus.offset_polyline(square.astype(float), 0.5, join="miter", closed=True)
    assert check_valid(loop) == pytest.approx(9.0 - 1.0)
    with pytest.raises(ValueError):
        locus.offset(square, float("nan"))
    with pytest.raises(ValueError):
        locus.offset(np.array([[0, 0], [np.inf, 0], [1, 1]]), 1.0)
    with pytest.raises(ValueError):
        locus.offset(square, 1.0, join="bevel")
    with pytest.raises(ValueError):
        locus.offset(square, 1.0, join="miter", miter_limit=0.5)
    with pytest.raises(ValueError):
        locus.offset_polyline(square, 1.0, end="arrow")
