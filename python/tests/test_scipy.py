# locus against scipy.spatial (Qhull) on seeded random points in general position: the same
# hull vertex sets, the same simplex counts, and every sampled Delaunay simplex checked for an
# empty circumcircle / circumsphere in exact rational arithmetic.
import numpy as np
import pytest
from scipy import spatial

import locus
from exact import incircle, insphere, orient2d, orient3d


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("n", [10, 1000])
def test_hull2_matches_scipy(rng, dtype, n):
    p = rng.random((n, 2)).astype(dtype)
    r = locus.convex_hull(p)
    assert r.status == "ok" and r.dimension == 2
    q = spatial.ConvexHull(p.astype(np.float64))
    assert set(r.indices.tolist()) == set(q.vertices.tolist())
    # counter-clockwise, strictly convex (exact)
    h = p[r.indices]
    for i in range(len(h)):
        assert orient2d(h[i], h[(i + 1) % len(h)], h[(i + 2) % len(h)]) > 0


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_hull3_matches_scipy(rng, dtype):
    p = rng.standard_normal((2000, 3)).astype(dtype)
    r = locus.convex_hull(p)
    assert r.status == "ok" and r.dimension == 3
    q = spatial.ConvexHull(p.astype(np.float64))
    assert set(r.vertices.tolist()) == set(q.vertices.tolist())
    assert len(r.triangles) == len(q.simplices)
    # every point on the inner side of every face (exact; locus: outward, counter-clockwise)
    for t in r.triangles[rng.choice(len(r.triangles), 20, replace=False)]:
        a, b, c = p[t]
        sides = {np.sign(float(orient3d(a, b, c, x))) for x in p[::50]}
        assert sides <= {0.0, 1.0} or sides <= {0.0, -1.0}


def _sample(rng, m, k):
    return rng.choice(m, min(m, k), replace=False)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_delaunay2_empty_circumcircles(rng, dtype):
    p = rng.random((300, 2)).astype(dtype)
    r = locus.delaunay(p)
    assert r.status == "ok" and r.dimension == 2
    assert len(r.triangles) == len(spatial.Delaunay(p.astype(np.float64)).simplices)
    for t in r.triangles[_sample(rng, len(r.triangles), 40)]:
        a, b, c = p[t]
        assert orient2d(a, b, c) > 0  # counter-clockwise
        assert incircle(a, b, c, (a.astype(float) + b + c) / 3) > 0  # the oracle can say inside
        for j, d in enumerate(p):
            if j not in t:
                assert incircle(a, b, c, d) <= 0, (t, j)


def test_delaunay2_cocircular_grid_is_valid(rng):
    # A lattice: every cell's four corners are cocircular; any diagonal is Delaunay.
    g = np.array([(x, y) for x in range(8) for y in range(8)], dtype=np.float64)
    r = locus.delaunay(g)
    assert len(r.triangles) == 2 * 7 * 7
    for t in r.triangles:
        a, b, c = g[t]
        assert orient2d(a, b, c) > 0
        for j, d in enumerate(g):
            if j not in t:
                assert incircle(a, b, c, d) <= 0


def test_delaunay3_empty_circumspheres(rng):
    p = rng.random((200, 3))
    r = locus.delaunay(p)
    assert r.status == "ok" and r.dimension == 3
    assert len(r.tetrahedra) == len(spatial.Delaunay(p).simplices)
    # calibrate the sign convention on a case with a known answer: the centroid of a
    # positively oriented tetrahedron is inside its circumsphere
    t0 = r.tetrahedra[0]
    ref = np.sign(float(insphere(*p[t0], p[t0].mean(axis=0)))) * np.sign(
        float(orient3d(*p[t0])))
    assert ref != 0
    for t in r.tetrahedra[_sample(rng, len(r.tetrahedra), 15)]:
        o = np.sign(float(orient3d(*p[t])))
        assert o == np.sign(float(orient3d(*p[t0])))  # all tetrahedra oriented alike
        for j, e in enumerate(p):
            if j not in t:
                assert np.sign(float(insphere(*p[t], e))) * o != ref, (t, j)


def test_convex_hull_lower_dimensions():
    line = np.array([[0, 0], [1, 1], [2, 2], [3, 3.0]])
    r = locus.convex_hull(line)
    assert r.dimension == 1 and set(r.indices.tolist()) == {0, 3}
    assert locus.convex_hull(np.ones((5, 2))).dimension == 0
    planar = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.5, 0.5, 0]])
    r3 = locus.convex_hull(planar)
    assert r3.dimension == 2 and set(r3.polygon.tolist()) == {0, 1, 2, 3}
