# The type stub python/locus.pyi names exactly the module's public functions and classes
# (mypy is not installed; this keeps the stub honest), and every function has a docstring.
import ast
import pathlib

import numpy as np

import locus

STUB = pathlib.Path(__file__).resolve().parent.parent / "locus.pyi"


def stub_names():
    tree = ast.parse(STUB.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return {n for n in names if not n.startswith("_") or n == "_input_address"} - {"__version__"}


def module_names():
    return {n for n in dir(locus) if not n.startswith("__")}


def test_stub_matches_module():
    assert stub_names() == module_names()


def test_stub_class_fields_exist(rng):
    # each result class in the stub lists the attributes a real result carries
    tree = ast.parse(STUB.read_text())
    fields = {n.name: {a.target.id for a in n.body if isinstance(a, ast.AnnAssign)}
              for n in tree.body if isinstance(n, ast.ClassDef)}
    p2, p3 = rng.random((30, 2)), rng.random((30, 3))
    samples = [locus.convex_hull(p2), locus.convex_hull(p3), locus.delaunay(p2),
               locus.delaunay(p3), locus.min_circle(p2), locus.min_sphere(p3), locus.min_rect(p2),
               locus.min_box(p3), locus.fit_line(p2), locus.fit_plane(p3), locus.fit_circle(p2),
               locus.fit_gaussian(p2), locus.polynomial_roots([1.0, 2.0]),
               locus.gjk_distance(p2, p2 + 2), locus.penetration(p3, p3),
               locus.segment_intersections(p2[:4].reshape(2, 2, 2), p2[4:8].reshape(2, 2, 2)),
               locus.triangulate_polygon(np.array([[0, 0], [1, 0], [0, 1.0]])),
               locus.constrained_delaunay(p2, [[0, 1]]),
               locus.curve_intersections(p2[:4], p2[4:8]),
               locus.plane_surface_hermite([0, 0, 1], 0.5, rng.random((3, 3, 3)), t=[0.5]),
               locus.read_wkt("POLYGON ((0 0, 1 0, 0 1, 0 0))")[0]]
    for r in samples:
        name = type(r).__name__
        assert set(vars(r)) == fields[name] | {"status"}, name


def test_docstrings():
    for n in module_names():
        obj = getattr(locus, n)
        if callable(obj):
            assert obj.__doc__ and len(obj.__doc__) > 20, n
