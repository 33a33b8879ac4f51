# ray_triangle_hits on inputs large enough to go through the BVH (spatial/bvh.hpp): every answer
# equals the brute-force path (one ray per call stays below the BVH threshold) and the exact
# rational oracle of exact.py; watertightness on a closed mesh through the BVH.
from fractions import Fraction

import numpy as np

import locus
from test_intersection3 import exact_ray_hit


def test_bvh_path_equals_brute_force_and_exact(rng):
    # a noisy icosphere plus a soup of random triangles: 320 + 100 triangles
    v, f = locus.icosphere(1.5, 2)
    v = v * rng.uniform(0.8, 1.2, size=(len(v), 1))
    soup = rng.random((100, 3, 3)) * 4 - 2
    tris = np.vstack([v[f], soup])
    o = rng.random((200, 3)) * 6 - 3
    d = rng.normal(size=(200, 3))
    d[::4] = v[rng.integers(0, len(v), size=50)] - o[::4]  # aimed exactly at vertices
    big = locus.ray_triangle_hits(o, d, tris)  # 200 x 420 rays x triangles: the BVH
    assert big.hit.sum() > 50
    for i in range(len(o)):
        one = locus.ray_triangle_hits(o[i:i + 1], d[i:i + 1], tris)  # brute force
        assert one.hit[0] == big.hit[i] and one.triangle[0] == big.triangle[i]
        if one.hit[0]:
            assert one.t[0] == big.t[i]
            assert (one.barycentric[0] == big.barycentric[i]).all()
            assert (one.point[0] == big.point[i]).all()
            assert one.front[0] == big.front[i]
    for i in range(0, len(o), 50):  # exact oracle on a sample
        best = None
        for k in range(len(tris)):
            t = exact_ray_hit(o[i], d[i], tris[k])
            if t is not None and (best is None or t < best[0]):
                best = (t, k)
        if best is None:
            assert not big.hit[i]
        else:
            assert big.hit[i]
            assert abs(Fraction(float(big.t[i])) - best[0]) <= abs(best[0]) * Fraction(1, 2**40)


def test_bvh_watertight_on_a_closed_mesh():
    v, f = locus.icosphere(2.0, 3)  # 1280 triangles
    edges = {tuple(sorted((a, b))) for x in f.tolist() for a, b in zip(x, x[1:] + x[:1])}
    dirs = np.vstack([v, np.array([v[a] + v[b] for a, b in edges])])
    r = locus.ray_triangle_hits(np.zeros_like(dirs), dirs, v, f)
    assert r.hit.all()  # no leak through an edge or a vertex
