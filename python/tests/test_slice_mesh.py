# slice_mesh (intersection/plane_mesh.hpp) against an oracle written here: the crossings of the
# mesh edges with the plane, computed in Python, and for convex solids the convex hull of those
# crossings (scipy) as the expected cross-section.
import numpy as np
import pytest
from scipy.spatial import ConvexHull

import locus


def edge_crossings(v, faces, n, c):
    """Points where mesh edges cross the plane n.x = c (endpoints strictly on opposite sides),
    and the vertices lying on it."""
    out = [p for p in v if p @ n == c]
    edges = set()
    for f in faces:
        f = [int(i) for i in f]
        for a, b in zip(f, f[1:] + f[:1]):
            edges.add((min(a, b), max(a, b)))
    for a, b in edges:
        da, db = v[a] @ n - c, v[b] @ n - c
        if da * db < 0:
            out.append(v[a] + da / (da - db) * (v[b] - v[a]))
    return np.array(out)


def shoelace_xy(p):
    x, y = p[:, 0], p[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


@pytest.mark.parametrize("height", [-0.35, 0.0, 0.123, 0.4])
def test_convex_solid_section_is_the_hull_of_the_edge_crossings(height):
    v, f = locus.icosphere(0.5, 2)
    n = np.array([0.0, 0.0, 1.0])
    s = locus.slice_mesh(v, f, n, height)
    assert s.status == "ok"
    assert len(s.polylines) == 1 and bool(s.closed[0])
    loop = s.polylines[0]
    assert loop.shape[1] == 3 and np.allclose(loop[:, 2], height, atol=1e-15)
    hull = ConvexHull(edge_crossings(v, f, n, height)[:, :2])
    # The outward-oriented solid's outer loop runs counter-clockwise seen from +z.
    assert shoelace_xy(loop) == pytest.approx(hull.volume, rel=1e-12)


def test_torus_gives_two_loops_with_opposite_turns():
    v, f = locus.torus(1.0, 0.3, 24, 12)
    s = locus.slice_mesh(v, f, [0.0, 0.0, 1.0], 0.01)
    assert len(s.polylines) == 2 and all(s.closed)
    areas = sorted(shoelace_xy(p) for p in s.polylines)
    assert areas[0] < 0 < areas[1]  # the hole runs clockwise
    # Vertical cut through the axis: two separate tube sections.
    s = locus.slice_mesh(v, f, [1.0, 0.0, 0.0], 0.0)
    assert len(s.polylines) == 2 and all(s.closed)


def test_every_point_lies_on_a_crossed_edge():
    v, f = locus.uv_sphere(2.0, 12, 7)
    n = np.array([0.3, -0.5, 0.8])
    s = locus.slice_mesh(v, f, n, 0.2)
    pts = np.concatenate(s.polylines)
    expected = edge_crossings(v, f, n, 0.2)
    for p in pts:
        assert np.min(np.linalg.norm(expected - p, axis=1)) < 1e-12


def test_open_mesh_gives_open_chains_and_float32_stays_float32():
    v, faces = locus.hexahedron()
    faces = np.asarray(faces)
    for removed in range(len(faces)):
        f = np.delete(faces, removed, axis=0)
        s = locus.slice_mesh(v.astype(np.float32), f, [0.0, 0.0, 1.0], 0.1)
        assert s.polylines[0].dtype == np.float32
        assert len(s.polylines) == 1
        # Removing a side face (one spanning z) opens the section into a chain.
        removed_is_side = np.ptp(v[faces[removed]][:, 2]) > 0
        assert bool(s.closed[0]) == (not removed_is_side)
        # The box's quads are split into fans, so the chain also crosses their diagonals; every
        # point lies on the square of half side |vertex coordinate| at z = 0.1.
        p = s.polylines[0].astype(np.float64)
        half = float(np.max(np.abs(v[:, 0])))
        assert np.allclose(np.max(np.abs(p[:, :2]), axis=1), half, rtol=1e-6)
        assert np.allclose(p[:, 2], 0.1, rtol=1e-6)


def test_plane_missing_the_mesh_gives_no_polyline():
    v, f = locus.icosahedron()
    s = locus.slice_mesh(v, f, [0.0, 0.0, 1.0], 10.0)
    assert s.status == "ok" and s.polylines == [] and s.closed.shape == (0,)


def test_bad_input_raises():
    v, f = locus.tetrahedron()
    with pytest.raises(ValueError, match="degenerate_input"):
        locus.slice_mesh(v, f, [0.0, 0.0, 0.0], 0.0)
    bad = v.copy()
    bad[0, 0] = np.nan
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.slice_mesh(bad, f, [0.0, 0.0, 1.0], 0.0)
    with pytest.raises(ValueError):
        locus.slice_mesh(v, [[0, 1, 7]], [0.0, 0.0, 1.0], 0.0)
    with pytest.raises(ValueError, match="empty_input"):
        locus.slice_mesh(v, np.zeros((0, 3), dtype=np.int64), [0.0, 0.0, 1.0], 0.0)
