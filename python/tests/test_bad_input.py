# Bad input raises ValueError with a message naming the function and the problem: NaN/Inf,
# wrong shapes and dtypes, empty arrays, bad indices. Never a crash, never a silent answer.
import numpy as np
import pytest

import locus

POINT_FUNCS_2D = [locus.convex_hull, locus.delaunay, locus.min_circle, locus.min_rect,
                  locus.fit_line, locus.fit_circle, locus.fit_gaussian]
POINT_FUNCS_3D = [locus.convex_hull, locus.delaunay, locus.min_sphere, locus.min_box,
                  locus.fit_line, locus.fit_plane, locus.fit_sphere, locus.fit_gaussian]


def names(fs):
    return [f.__name__ for f in fs]


@pytest.mark.parametrize("f", POINT_FUNCS_2D, ids=names(POINT_FUNCS_2D))
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_non_finite_2d(rng, f, bad, dtype):
    p = rng.random((50, 2)).astype(dtype)
    p[17, 1] = bad
    with pytest.raises(ValueError, match=rf"locus\.{f.__name__}: non_finite_input"):
        f(p)


@pytest.mark.parametrize("f", POINT_FUNCS_3D, ids=names(POINT_FUNCS_3D))
def test_non_finite_3d(rng, f):
    p = rng.random((50, 3))
    p[3, 2] = np.nan
    with pytest.raises(ValueError, match=rf"locus\.{f.__name__}: non_finite_input"):
        f(p)


@pytest.mark.parametrize("f", POINT_FUNCS_2D, ids=names(POINT_FUNCS_2D))
def test_empty(f):
    with pytest.raises(ValueError, match=rf"locus\.{f.__name__}: empty_input"):
        f(np.empty((0, 2)))


@pytest.mark.parametrize("f", [locus.convex_hull, locus.delaunay, locus.min_circle],
                         ids=["convex_hull", "delaunay", "min_circle"])
@pytest.mark.parametrize("shape", [(10,), (10, 4), (10, 1), (2, 5, 2), ()])
def test_wrong_shapes(f, shape):
    with pytest.raises(ValueError, match=rf"locus\.{f.__name__}: points must"):
        f(np.zeros(shape))


@pytest.mark.parametrize("f", [locus.convex_hull, locus.delaunay], ids=["hull", "delaunay"])
def test_wrong_dtypes(f):
    with pytest.raises(ValueError, match="must hold real numbers"):
        f(np.zeros((10, 2), dtype=np.complex128))
    with pytest.raises(ValueError, match="must hold real numbers"):
        f(np.array([["a", "b"], ["c", "d"]]))
    with pytest.raises(ValueError, match="must hold real numbers"):
        f(np.array([[object(), 1]], dtype=object))
    with pytest.raises(ValueError):
        f(None)


def test_integer_and_noncontiguous_inputs_are_converted(rng):
    p = rng.integers(-100, 100, (200, 2))
    r = locus.convex_hull(p)
    ref = locus.convex_hull(p.astype(np.float64))
    assert np.array_equal(r.indices, ref.indices)
    big = rng.random((400, 4))
    view = big[:, ::2]  # non-contiguous (n, 2) view
    assert not view.flags["C_CONTIGUOUS"]
    assert np.array_equal(locus.delaunay(view).triangles,
                          locus.delaunay(np.ascontiguousarray(view)).triangles)
    fortran = np.asfortranarray(rng.random((100, 3)))
    assert np.array_equal(locus.convex_hull(fortran).vertices,
                          locus.convex_hull(np.ascontiguousarray(fortran)).vertices)
    assert locus.min_circle([[0, 0], [2, 0]]).radius == 1.0  # nested lists


def test_degenerate_fits_raise():
    with pytest.raises(ValueError, match="fit_line: degenerate_input"):
        locus.fit_line(np.ones((10, 2)))
    with pytest.raises(ValueError, match="fit_plane: degenerate_input"):
        locus.fit_plane(np.array([[0, 0, 0], [1, 1, 1], [2, 2, 2], [3, 3, 3.0]]))
    with pytest.raises(ValueError, match="polynomial_roots: degenerate_input"):
        locus.polynomial_roots([0.0, 0.0])
    with pytest.raises(ValueError, match="polynomial_roots: non_finite_input"):
        locus.polynomial_roots([1.0, np.nan])


def test_batched_query_inputs(rng):
    poly = np.array([[0, 0], [1, 0], [0, 1.0]])
    pts = rng.random((10, 2))
    pts[4, 0] = np.nan
    with pytest.raises(ValueError, match="point_in_polygon: non_finite_input: points"):
        locus.point_in_polygon(pts, poly)
    with pytest.raises(ValueError, match="polygon needs at least 3"):
        locus.point_in_polygon(rng.random((3, 2)), poly[:2])
    with pytest.raises(ValueError, match="ring_ends must increase"):
        locus.point_in_polygon(rng.random((3, 2)), poly, ring_ends=[2])
    with pytest.raises(ValueError, match="not an index below"):
        locus.point_in_polyhedron(rng.random((3, 3)), rng.random((4, 3)), [[0, 1, 4]])
    with pytest.raises(ValueError, match="must have the same length"):
        locus.point_triangle_sqr_distances(rng.random((5, 3)), rng.random((4, 3, 3)))
    with pytest.raises(ValueError, match=r"triangles must have shape \(3, 3\) or \(n, 3, 3\)"):
        locus.point_triangle_sqr_distances(rng.random((5, 3)), rng.random((5, 2, 3)))
    with pytest.raises(ValueError, match="empty_input"):
        locus.point_box_sqr_distances(np.empty((0, 3)), rng.random((2, 3)))
    seg = rng.random((5, 2, 3))
    seg[2, 1, 0] = np.inf
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.segment_segment_sqr_distances(seg, seg)
    with pytest.raises(ValueError, match=r"shape \(n, 2, 2\)"):
        locus.segment_intersections(rng.random((5, 2, 3)), rng.random((5, 2, 3)))
    with pytest.raises(ValueError, match="same dimension"):
        locus.gjk_distance(rng.random((5, 2)), rng.random((5, 3)))
    with pytest.raises(ValueError, match="empty_input"):
        locus.gjk_distance(np.empty((0, 3)), rng.random((5, 3)))
    with pytest.raises(ValueError, match="method must be"):
        locus.triangulate_polygon(poly, method="magic")
