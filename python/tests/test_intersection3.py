# triangles_intersect and ray_triangle_hits against exact rational oracles (exact.py) on random
# triangles in general position, plus touching cases, the watertight rule and bad input.
from fractions import Fraction

import numpy as np
import pytest

import locus
from exact import F, orient3d


def seg_crosses_tri(p, q, a, b, c):
    """General position: the segment pq crosses the triangle abc (exact)."""
    sp, sq = orient3d(a, b, c, p), orient3d(a, b, c, q)
    if sp * sq >= 0:
        return False
    s = [orient3d(p, q, u, w) for u, w in ((a, b), (b, c), (c, a))]
    return all(x > 0 for x in s) or all(x < 0 for x in s)


def tris_cross(t, u):
    return any(seg_crosses_tri(t[i], t[(i + 1) % 3], *u) for i in range(3)) or any(
        seg_crosses_tri(u[i], u[(i + 1) % 3], *t) for i in range(3))


def exact_ray_hit(o, d, tri):
    """(t as a Fraction) of the ray's crossing of the triangle, or None (general position)."""
    a, b, c = tri
    o, d = [F(x) for x in o], [F(x) for x in d]
    A, B, C = ([F(x) for x in p] for p in (a, b, c))
    e1 = [B[i] - A[i] for i in range(3)]
    e2 = [C[i] - A[i] for i in range(3)]
    n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    den = sum(n[i] * d[i] for i in range(3))
    if den == 0:
        return None
    t = sum(n[i] * (A[i] - o[i]) for i in range(3)) / den
    if t < 0:
        return None
    p = [o[i] + t * d[i] for i in range(3)]
    # inside: the three sub-triangle normals agree with n
    for u, w in ((A, B), (B, C), (C, A)):
        x = [w[i] - u[i] for i in range(3)]
        y = [p[i] - u[i] for i in range(3)]
        c3 = [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
        if sum(c3[i] * n[i] for i in range(3)) <= 0:
            return None
    return t


def test_triangles_intersect_random_exact(rng):
    n = 400
    a = rng.random((n, 3, 3))
    b = rng.random((n, 3, 3)) * 0.8 + 0.3
    got = locus.triangles_intersect(a, b)
    want = np.array([tris_cross(a[i], b[i]) for i in range(n)])
    assert got.dtype == np.bool_ and got.shape == (n,)
    assert want.any() and not want.all()
    assert np.array_equal(got, want)
    # symmetric, and invariant under vertex permutations and power-of-two scaling
    assert np.array_equal(locus.triangles_intersect(b, a), want)
    assert np.array_equal(locus.triangles_intersect(a[:, ::-1], b[:, [1, 2, 0]]), want)
    assert np.array_equal(locus.triangles_intersect(a * 2.0**-40, b * 2.0**-40), want)


def test_triangles_intersect_touching():
    t = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    cases = [
        (np.array([[0, 0, 0], [0, 0, 1], [-1, 0, 1.0]]), True),       # common vertex
        (np.array([[0.5, 0.5, 0], [1, 1, 1], [2, 0, 1.0]]), True),    # vertex on the edge
        (np.array([[0.5, 0.5, 1e-300], [1, 1, 1], [2, 0, 1.0]]), False),  # just above it
        (np.array([[0.2, 0.2, 0], [0.3, 0.2, 0], [0.2, 0.3, 0.0]]), True),  # coplanar inside
        (np.array([[2, 2, 0], [3, 2, 0], [2, 3, 0.0]]), False),      # coplanar apart
        (np.array([[0.2, 0.2, 0], [0.2, 0.2, 0], [0.2, 0.2, 0.0]]), True),  # a point inside
    ]
    b = np.array([c for c, _ in cases])
    want = [w for _, w in cases]
    assert locus.triangles_intersect(np.broadcast_to(t, b.shape), b).tolist() == want


def test_ray_triangle_hits_random_exact(rng):
    tris = rng.random((25, 3, 3)) * 2 - 1
    o = rng.random((60, 3)) * 4 - 2
    d = rng.normal(size=(60, 3))
    r = locus.ray_triangle_hits(o, d, tris)
    assert r.status == "ok"
    for i in range(len(o)):
        best = None
        for k in range(len(tris)):
            t = exact_ray_hit(o[i], d[i], tris[k])
            if t is not None and (best is None or t < best[0]):
                best = (t, k)
        if best is None:
            assert not r.hit[i] and r.triangle[i] == -1 and np.isnan(r.t[i])
            continue
        assert r.hit[i] and r.triangle[i] == best[1]
        assert abs(Fraction(float(r.t[i])) - best[0]) <= abs(best[0]) * Fraction(1, 2**40)
        w = r.barycentric[i]
        assert np.isclose(w.sum(), 1.0) and (w >= -1e-12).all()
        assert np.allclose(w @ tris[best[1]], r.point[i], atol=1e-9)
        assert np.allclose(o[i] + r.t[i] * d[i], r.point[i], atol=1e-9)
        n = np.cross(tris[best[1]][1] - tris[best[1]][0], tris[best[1]][2] - tris[best[1]][0])
        assert r.front[i] == (np.dot(d[i], n) < 0)
    assert r.hit.any() and not r.hit.all()


def test_ray_hits_watertight_through_vertices_and_edges():
    v, f = locus.icosphere(1.0, 1)
    # rays from the centre through every vertex and every edge midpoint direction
    edges = {tuple(sorted((a, b))) for x in f.tolist() for a, b in zip(x, x[1:] + x[:1])}
    dirs = np.vstack([v, np.array([v[a] + v[b] for a, b in edges])])
    r = locus.ray_triangle_hits(np.zeros_like(dirs), dirs, v, f)
    assert r.hit.all() and not r.front.any()        # from inside: the back of each face
    assert np.all(np.linalg.norm(r.point, axis=1) <= 1 + 1e-12)
    # the same with the (m, 3, 3) triangle form
    r2 = locus.ray_triangle_hits(np.zeros_like(dirs), dirs, v[f])
    assert r2 == r
    # from outside towards the centre: front hits
    r3 = locus.ray_triangle_hits(dirs * 3, -dirs, v, f)
    assert r3.hit.all() and r3.front.all()


def test_ray_hits_zero_direction_and_empty():
    tri = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0.0]]])
    r = locus.ray_triangle_hits([[0.2, 0.2, 0.0]], [[0, 0, 0.0]], tri)
    assert not r.hit[0]
    r = locus.ray_triangle_hits(np.zeros((0, 3)), np.zeros((0, 3)), tri)
    assert r.hit.shape == (0,) and r.point.shape == (0, 3)
    r = locus.ray_triangle_hits([[0.2, 0.2, 1.0]], [[0, 0, -1.0]], np.zeros((0, 3, 3)))
    assert not r.hit[0] and r.triangle[0] == -1


def test_bad_input():
    t = np.zeros((2, 3, 3))
    with pytest.raises(ValueError, match="same number"):
        locus.triangles_intersect(t, t[:1])
    with pytest.raises(ValueError, match="shape"):
        locus.triangles_intersect(t[:, :2], t[:, :2])
    nan = t.copy()
    nan[1, 2, 0] = np.nan
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.triangles_intersect(t, nan)
    with pytest.raises(ValueError, match="real numbers"):
        locus.triangles_intersect(t.astype(complex), t)
    with pytest.raises(ValueError, match="None"):
        locus.triangles_intersect(None, t)
    o = np.zeros((2, 3))
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.ray_triangle_hits(o, [[np.inf, 0, 0], [1, 0, 0]], t)
    with pytest.raises(ValueError, match="same number of rows"):
        locus.ray_triangle_hits(o, o[:1], t)
    with pytest.raises(ValueError, match="not an index below"):
        locus.ray_triangle_hits(o, o, np.zeros((3, 3)), [[0, 1, 3]])
    with pytest.raises(ValueError, match="shape"):
        locus.ray_triangle_hits(o, o, np.zeros((3, 3)))


def exact_slab(o, d, lo, hi, t_max):
    """[t0, t1] (Fractions) of o + t d inside the box for t in [0, t_max], or None; d holds
    Fractions (a segment's p1 - p0, exact)."""
    t0, t1 = Fraction(0), t_max
    for k in range(3):
        ok, dk, a, b = F(o[k]), d[k], F(lo[k]), F(hi[k])
        if dk == 0:
            if ok < a or ok > b:
                return None
            continue
        u, w = (a - ok) / dk, (b - ok) / dk
        if u > w:
            u, w = w, u
        t0 = max(t0, u)
        t1 = w if t1 is None else min(t1, w)
    if t1 is not None and t0 > t1:
        return None
    return t0, t1


def close(x, t):
    return abs(Fraction(float(x)) - t) <= (abs(t) + 1) * Fraction(1, 2**44)


@pytest.mark.parametrize("segment", [False, True])
def test_box_hits_exact(rng, segment):
    n = 400
    c = rng.random((n, 3)) * 2 - 1
    e = rng.random((n, 3)) * 0.6
    boxes = np.stack([c - e, c + e], axis=1)
    o = rng.random((n, 3)) * 4 - 2
    d = rng.normal(size=(n, 3))
    # axis-parallel directions and rays starting on a face, exactly
    d[:40, 1:] = 0
    o[40:80] = boxes[40:80, 0]
    p1 = o + d
    if segment:
        r = locus.segment_box_hits(np.stack([o, p1], axis=1), boxes)
    else:
        r = locus.ray_box_hits(o, d, boxes)
    for i in range(n):
        di = [F(p1[i, k]) - F(o[i, k]) if segment else F(d[i, k]) for k in range(3)]
        want = exact_slab(o[i], di, boxes[i, 0], boxes[i, 1], Fraction(1) if segment else None)
        assert r.hit[i] == (want is not None), i
        if want is None:
            assert np.isnan(r.t_enter[i]) and np.isnan(r.t_exit[i])
        else:
            assert close(r.t_enter[i], want[0]) and close(r.t_exit[i], want[1]), i
    assert r.hit[40:80].all() and r.hit.any() and not r.hit.all()


def test_box_hits_touching_and_bad_input():
    box = np.array([[[0, 0, 0], [1, 1, 1.0]]] * 3)
    o = np.array([[-1, 1, 0.5], [-1, 1 + 2.0**-52, 0.5], [0.5, 0.5, 0.5]])
    d = np.array([[1, 0, 0], [1, 0, 0], [0, 0, 0.0]])
    r = locus.ray_box_hits(o, d, box)
    assert r.hit.tolist() == [True, False, True]     # grazing a face counts; just above: no
    assert r.t_enter[0] == 1 and r.t_exit[0] == 2
    assert r.t_enter[2] == r.t_exit[2] == 0          # a zero direction: its origin
    empty = np.array([[[1, 0, 0], [0, 1, 1.0]]])
    assert not locus.ray_box_hits([[0.5, 0.5, -1]], [[0, 0, 1.0]], empty).hit[0]
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.ray_box_hits(o, d, np.where(box == 1, np.nan, box))
    with pytest.raises(ValueError, match="same number"):
        locus.ray_box_hits(o, d, box[:2])
    with pytest.raises(ValueError, match="shape"):
        locus.segment_box_hits(o, box)
