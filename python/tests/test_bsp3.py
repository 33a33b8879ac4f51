# mesh_boolean (BSP-tree booleans of closed triangle meshes) against independent oracles: exact
# volumes of booleans of dyadic boxes, and for two random convex polyhedra the volume of their
# intersection from scipy (HalfspaceIntersection + ConvexHull), with inclusion-exclusion for
# union and difference; bad input raises ValueError.
import numpy as np
import pytest
from scipy.spatial import ConvexHull, HalfspaceIntersection

import locus

QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
BOX_F = np.array([[q[0], q[1], q[2]] for q in QUADS] + [[q[0], q[2], q[3]] for q in QUADS])


def box(lo, hi, dtype=np.float64):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    v = np.array([[hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]]
                  for i in range(8)], dtype=dtype)
    return v, BOX_F


def volume(v, f):
    v = np.asarray(v, np.float64)
    return float(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]])).sum() / 6)


def convex(rng, centre):
    pts = rng.normal(size=(20, 3)) + centre
    hull = ConvexHull(pts)
    f = hull.simplices.copy()
    c = pts[hull.vertices].mean(axis=0)
    for t in f:  # outward: the centroid is behind every face
        n = np.cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]])
        if np.dot(n, c - pts[t[0]]) > 0:
            t[1], t[2] = t[2], t[1]
    return pts, f, hull


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_dyadic_boxes_exact_volumes(dtype):
    rng = np.random.default_rng(7)
    for _ in range(10):
        lo = rng.integers(0, 8, size=(2, 3)) / 4
        size = rng.choice([0.5, 1.0, 2.0], size=(2, 3))
        a, b = box(lo[0], lo[0] + size[0], dtype), box(lo[1], lo[1] + size[1], dtype)
        va, vb = size[0].prod(), size[1].prod()
        overlap = np.clip(np.minimum(lo[0] + size[0], lo[1] + size[1]) - np.maximum(lo[0], lo[1]),
                          0, None).prod()
        for op, want in [("union", va + vb - overlap), ("intersection", overlap),
                         ("difference", va - overlap), ("xor", va + vb - 2 * overlap)]:
            r = locus.mesh_boolean(op, a, b)
            assert r.status == "ok"
            assert r.vertices.dtype == dtype
            assert r.triangles.shape[1] == 3
            assert volume(r.vertices, r.triangles) == want


def test_convex_polyhedra_against_scipy():
    rng = np.random.default_rng(11)
    for _ in range(4):
        va_, fa, ha = convex(rng, [0, 0, 0])
        vb_, fb, hb = convex(rng, rng.uniform(-1, 1, 3))
        halfspaces = np.vstack([ha.equations, hb.equations])
        inner = None
        # an interior point of the intersection, if any: Chebyshev centre by scipy's linprog
        from scipy.optimize import linprog
        norms = np.linalg.norm(halfspaces[:, :3], axis=1)
        lp = linprog(np.r_[0, 0, 0, -1], A_ub=np.c_[halfspaces[:, :3], norms],
                     b_ub=-halfspaces[:, 3], bounds=[(None, None)] * 3 + [(0, None)])
        vi = 0.0
        if lp.status == 0 and lp.x[3] > 1e-6:
            inner = lp.x[:3]
            vi = ConvexHull(HalfspaceIntersection(halfspaces, inner).intersections).volume
        va, vb = ha.volume, hb.volume
        got = {op: volume(*(lambda r: (r.vertices, r.triangles))(
            locus.mesh_boolean(op, (va_, fa), (vb_, fb)))) for op in
            ("union", "intersection", "difference", "xor")}
        assert got["intersection"] == pytest.approx(vi, rel=1e-9, abs=1e-12)
        assert got["xor"] == pytest.approx(va + vb - 2 * vi, rel=1e-9)
        assert got["union"] == pytest.approx(va + vb - vi, rel=1e-9)
        assert got["difference"] == pytest.approx(va - vi, rel=1e-9, abs=1e-12)


def test_degenerate_and_bad_input():
    a = box([0, 0, 0], [1, 1, 1])
    b = box([1, 0, 0], [2, 1, 1])
    r = locus.mesh_boolean("union", a, b)
    assert volume(r.vertices, r.triangles) == 2
    assert len(locus.mesh_boolean("intersection", a, b).triangles) == 0
    assert len(locus.mesh_boolean("difference", a, a).triangles) == 0
    empty = (np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64))
    r = locus.mesh_boolean("union", a, empty)
    assert r.status == "empty_input"
    assert volume(r.vertices, r.triangles) == 1
    with pytest.raises(ValueError, match="op must be"):
        locus.mesh_boolean("nand", a, b)
    nan = (a[0].copy(), a[1])
    nan[0][3, 1] = np.nan
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.mesh_boolean("union", a, nan)
    with pytest.raises(ValueError, match="index"):
        locus.mesh_boolean("union", a, (a[0], a[1] + 8))
    with pytest.raises(ValueError):
        locus.mesh_boolean("union", a, a[0])


def directed_edges(tris):
    e = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    return {tuple(x): c for x, c in zip(*np.unique(e, axis=0, return_counts=True))}


def test_convex_polyhedra_watertight():
    # every edge used exactly once in each direction (union, intersection, difference of random
    # convex polyhedra: no T-junction, no crack, although the cut points are rounded)
    rng = np.random.default_rng(12)
    for _ in range(3):
        va_, fa, _ = convex(rng, [0, 0, 0])
        vb_, fb, _ = convex(rng, rng.uniform(-0.8, 0.8, 3))
        for op in ("union", "intersection", "difference"):
            r = locus.mesh_boolean(op, (va_, fa), (vb_, fb))
            count = directed_edges(r.triangles)
            assert all(c == 1 and count.get((j, i)) == 1 for (i, j), c in count.items()), op
