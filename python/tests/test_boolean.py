# boolean(op, a, b) against shapely (GEOS, an independent engine): areas of every operation on
# random star polygons and polygons with holes, valid output (shapely's is_valid, outer rings
# counter-clockwise), fill rules on a self-intersecting ring, float32, bad input.
import numpy as np
import pytest
import shapely.geometry as sg
from shapely.ops import unary_union

import locus

OPS = {
    "intersection": lambda a, b: a.intersection(b),
    "union": lambda a, b: a.union(b),
    "difference": lambda a, b: a.difference(b),
    "xor": lambda a, b: a.symmetric_difference(b),
}


def star(rng, n, center=(0.0, 0.0), r_lo=0.5, r_hi=1.0):
    """A simple polygon star-shaped around center: jittered angles, gaps below pi (n >= 4)."""
    a = (np.arange(n) + rng.uniform(0.0, 0.8, n)) * (2 * np.pi / n)
    r = rng.uniform(r_lo, r_hi, n)
    return np.column_stack([center[0] + r * np.cos(a), center[1] + r * np.sin(a)])


def to_shapely(result):
    polys = [sg.Polygon(rings[0], rings[1:]) for rings in result.polygons]
    return polys


def check_valid(result):
    polys = to_shapely(result)
    for p in polys:
        assert p.is_valid
        assert p.exterior.is_ccw
        for h in p.interiors:
            assert not h.is_ccw
    # interiors pairwise disjoint: the areas add up to the area of the union
    if polys:
        assert abs(unary_union(polys).area - sum(p.area for p in polys)) <= 1e-9 * max(
            1.0, sum(p.area for p in polys)
        )
    return polys


@pytest.mark.parametrize("seed", range(12))
def test_areas_match_shapely(seed):
    rng = np.random.default_rng(seed)
    outer_a, outer_b = star(rng, 9), star(rng, 11, center=rng.uniform(-0.6, 0.6, 2))
    hole_a = star(rng, 6, r_lo=0.1, r_hi=0.35)[::-1]
    a = [outer_a, hole_a]
    sa, sb = sg.Polygon(outer_a, [hole_a]), sg.Polygon(outer_b)
    for op, ref in OPS.items():
        r = locus.boolean(op, a, outer_b)
        assert r.status == "ok"
        polys = check_valid(r)
        expected = ref(sa, sb).area
        assert abs(sum(p.area for p in polys) - expected) <= 1e-9, (op, seed)


def test_touching_and_shared_edges():
    sq = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    r = locus.boolean("union", sq, sq + [2, 0])
    assert len(r.polygons) == 1 and len(r.polygons[0][0]) == 4
    r = locus.boolean("union", sq, sq + [2, 2])
    assert len(r.polygons) == 2  # touching at a vertex: two polygons
    check_valid(r)
    assert locus.boolean("intersection", sq, sq + [2, 0]).polygons == []
    r = locus.boolean("difference", sq, [])
    assert len(r.polygons) == 1


def test_fill_rules_on_a_self_intersecting_ring():
    # A pentagram: even-odd leaves the centre pentagon out, non-zero fills it.
    k = np.arange(5) * 4 * np.pi / 5 + np.pi / 2
    star5 = np.column_stack([np.cos(k), np.sin(k)])
    eo = locus.boolean("union", star5, [], fill_rule="even_odd")
    nz = locus.boolean("union", star5, [], fill_rule="non_zero")
    a_eo = sum(p.area for p in check_valid(eo))
    a_nz = sum(p.area for p in check_valid(nz))
    inner = sg.Polygon(star5).buffer(0)  # GEOS repairs a pentagram to its outline
    assert abs(a_nz - inner.area) <= 1e-9
    assert len(eo.polygons) == 5 and a_eo < a_nz


def test_float32_and_grid():
    rng = np.random.default_rng(7)
    a, b = star(rng, 8).astype(np.float32), star(rng, 8, center=(0.3, 0.2)).astype(np.float32)
    r = locus.boolean("xor", a, b)
    assert all(ring.dtype == np.float32 for p in r.polygons for ring in p)
    check_valid(r)
    assert r.grid == 2.0**-24
    coarse = locus.boolean("xor", a.astype(np.float64), b.astype(np.float64), grid_bits=6)
    check_valid(coarse)
    assert coarse.grid == 2.0**-6


def test_bad_input():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    with pytest.raises(ValueError, match="non_finite"):
        locus.boolean("union", sq, np.array([[0, 0], [np.nan, 0], [1, 1]]))
    with pytest.raises(ValueError, match="op must be"):
        locus.boolean("merge", sq, sq)
    with pytest.raises(ValueError, match="fill_rule"):
        locus.boolean("union", sq, sq, fill_rule="odd")
    with pytest.raises(ValueError):
        locus.boolean("union", sq, sq, grid_bits=99)
    with pytest.raises(ValueError):
        locus.boolean("union", None, sq)
