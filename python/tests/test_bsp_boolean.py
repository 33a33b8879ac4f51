# bsp_boolean against shapely (an independent geometry engine) as the area oracle: the area
# enclosed by the result's edges and its loops equals shapely's area of the same operation on
# random star polygons with a hole and on integer-grid polygons with shared edges; the
# lower-dimensional parts of an intersection (shared edge, touching vertex) are reported.
import numpy as np
import pytest
import shapely.geometry as sg

import locus


def star(rng, n, center, scale):
    a = (np.arange(n) + rng.uniform(0.0, 0.8, n)) * (2 * np.pi / n)
    r = rng.uniform(0.5, 1.0, n)
    return np.column_stack([r * np.cos(a), r * np.sin(a)]) * scale + center


HOLE = np.array([[-0.2, -0.2], [-0.2, 0.2], [0.2, 0.2], [0.2, -0.2]])


def edge_area(edges):
    p, q = edges[:, 0, :].astype(np.float64), edges[:, 1, :].astype(np.float64)
    return 0.5 * float(np.sum(p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0]))


def loop_area(loops):
    total = 0.0
    for ring in loops:
        r = ring.astype(np.float64)
        total += 0.5 * float(np.sum(r[:, 0] * np.roll(r[:, 1], -1) - r[:, 1] * np.roll(r[:, 0], -1)))
    return total


def shapely_op(op, a, b):
    return {"intersection": a.intersection, "union": a.union, "difference": a.difference,
            "xor": a.symmetric_difference}[op](b)


OPS = ["intersection", "union", "difference", "xor"]


@pytest.mark.parametrize("op", OPS)
def test_random_stars_match_shapely(rng, op):
    for _ in range(10):
        outer_a = star(rng, 16, (0.0, 0.0), 1.0)
        center_b = rng.uniform(-0.8, 0.8, 2)
        outer_b = star(rng, 12, center_b, 1.0)
        hole_b = HOLE * 0.5 + center_b
        r = locus.bsp_boolean(op, [outer_a, HOLE], [outer_b, hole_b])
        sa, sb = sg.Polygon(outer_a, [HOLE]), sg.Polygon(outer_b, [hole_b])
        want = shapely_op(op, sa, sb).area
        assert r.closed
        assert r.edges.shape[1:] == (2, 2) and len(r.operand) == len(r.edges)
        assert abs(edge_area(r.edges) - want) <= 1e-9
        assert abs(loop_area(r.loops) - want) <= 1e-9


def test_float32_runs_float(rng):
    a = star(rng, 10, (0.0, 0.0), 1.0).astype(np.float32)
    b = star(rng, 10, (0.3, 0.1), 1.0).astype(np.float32)
    r = locus.bsp_boolean("union", a, b)
    assert r.edges.dtype == np.float32
    want = sg.Polygon(a).union(sg.Polygon(b)).area
    assert abs(edge_area(r.edges) - want) <= 1e-5


def test_shared_edge_and_touching_vertex():
    a = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=np.float64)
    b = a + [2, 0]  # shares the edge x = 2 (opposite directions)
    r = locus.bsp_boolean("intersection", a, b)
    assert len(r.edges) == 0 and len(r.loops) == 0
    assert r.segments.shape == (1, 2, 2)
    np.testing.assert_array_equal(np.sort(r.segments[0][:, 1]), [0, 2])
    np.testing.assert_array_equal(r.segments[0][:, 0], [2, 2])
    u = locus.bsp_boolean("union", a, b)
    assert len(u.loops) == 1 and loop_area(u.loops) == 8.0
    c = a + [2, 2]  # touches a at (2, 2) only
    t = locus.bsp_boolean("intersection", a, c)
    assert len(t.edges) == 0 and len(t.segments) == 0
    np.testing.assert_array_equal(t.points, [[2, 2]])


def test_grid_polygons_match_shapely(rng):
    for _ in range(40):
        polys = []
        for _k in range(2):
            x0, y0 = rng.integers(0, 3, 2)
            x1, y1 = x0 + rng.integers(1, 3), y0 + rng.integers(1, 3)
            polys.append(np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=np.float64))
        for op in OPS:
            r = locus.bsp_boolean(op, polys[0], polys[1])
            want = shapely_op(op, sg.Polygon(polys[0]), sg.Polygon(polys[1])).area
            assert edge_area(r.edges) == want
            assert r.closed


def test_bad_input():
    a = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=np.float64)
    with pytest.raises(ValueError):
        locus.bsp_boolean("intersection", a, np.array([[0, 0], [np.nan, 1], [1, 1]]))
    with pytest.raises(ValueError):
        locus.bsp_boolean("nand", a, a)
    # a zero-area operand is the empty set
    flat = np.array([[0, 0], [1, 1], [2, 2]], dtype=np.float64)
    assert edge_area(locus.bsp_boolean("union", a, flat).edges) == 4.0
    assert len(locus.bsp_boolean("intersection", a, flat).edges) == 0
