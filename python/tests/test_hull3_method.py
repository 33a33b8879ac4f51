# SPDX-License-Identifier: BSL-1.0
"""convex_hull(method=...) in 3D: the divide-and-conquer hull against scipy (Qhull) and the
other methods; bad method names."""
import numpy as np
import pytest
from scipy.spatial import ConvexHull

import locus


def facet_sets(points, triangles):
    """Triangles merged into facets by their exact plane (integer input: exact in float64)."""
    p = np.asarray(points, dtype=np.float64)
    out = set()
    for t in triangles:
        a, b, c = p[t[0]], p[t[1]], p[t[2]]
        n = np.cross(b - a, c - a)
        on = np.nonzero(np.abs((p - a) @ n) == 0)[0]
        out.add(tuple(sorted(int(i) for i in on)))
    return out


@pytest.mark.parametrize("n", [4, 10, 50, 500])
def test_divide_and_conquer_matches_scipy(rng, n):
    p = rng.standard_normal((n, 3))
    r = locus.convex_hull(p, method="divide_and_conquer")
    assert r.dimension == 3
    ref = ConvexHull(p)
    assert np.array_equal(r.vertices, np.sort(ref.vertices))
    # General position: the triangulation is unique, the same as the default method's.
    q = locus.convex_hull(p)
    canon = lambda tris: sorted(tuple(np.roll(t, -int(np.argmin(t)))) for t in tris)
    assert canon(r.triangles) == canon(q.triangles)
    # Outward orientation: every point behind every face.
    a, b, c = (p[r.triangles[:, k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    assert np.all(np.einsum("fk,nk->fn", normals, p) - np.einsum("fk,fk->f", normals, a)[:, None]
                  <= 1e-12)


def test_integer_grid_all_methods_agree(rng):
    p = rng.integers(0, 5, size=(300, 3)).astype(np.float64)
    results = [locus.convex_hull(p, method=m)
               for m in ("quickhull", "incremental", "divide_and_conquer")]
    for r in results[1:]:
        assert np.array_equal(r.vertices, results[0].vertices)
        assert facet_sets(p, r.triangles) == facet_sets(p, results[0].triangles)
    # Qhull names any of several duplicates: compare the vertices as points.
    as_points = lambda idx: {tuple(p[i]) for i in idx}
    assert as_points(results[0].vertices) == as_points(ConvexHull(p).vertices)


def test_flat_input():
    p = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.5, 0.5, 0]])
    r = locus.convex_hull(p, method="divide_and_conquer")
    assert r.dimension == 2
    assert sorted(r.vertices) == [0, 1, 2, 3]


def test_method_names():
    p = np.eye(3).tolist() + [[0, 0, 0]]
    with pytest.raises(ValueError):
        locus.convex_hull(p, method="gift_wrapping")
    with pytest.raises(ValueError):
        locus.convex_hull([[0, 0], [1, 0], [0, 1]], method="quickhull")  # a 3D-only name
    r2 = locus.convex_hull([[0, 0], [1, 0], [0, 1], [0.2, 0.2]], method="divide_and_conquer")
    assert sorted(r2.indices) == [0, 1, 2]
