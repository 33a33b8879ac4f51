# Mesh functions (check_mesh, self_intersections, orient_consistently, the generators,
# read_mesh / write_mesh) against independent oracles written here: a brute-force topology
# checker over Python sets and dicts, and an exact segment-triangle crossing test in rationals.
import ast
import pathlib

import numpy as np
import pytest

import locus
from exact import orient3d

GENERATORS = {
    "tetrahedron": lambda: locus.tetrahedron(),
    "hexahedron": lambda: locus.hexahedron(),
    "octahedron": lambda: locus.octahedron(),
    "dodecahedron": lambda: locus.dodecahedron(),
    "dodecahedron_tri": lambda: locus.dodecahedron(triangulate=True),
    "icosahedron": lambda: locus.icosahedron(),
    "uv_sphere": lambda: locus.uv_sphere(2.0, 12, 7),
    "icosphere": lambda: locus.icosphere(0.5, 2),
    "torus": lambda: locus.torus(1.0, 0.3, 16, 9),
    "cylinder": lambda: locus.cylinder(1.0, 3.0, 11),
    "cone": lambda: locus.cone(1.5, 2.0, 9),
}


def face_lists(faces):
    return [[int(i) for i in f] for f in faces]


# ---- the brute-force topology oracle -------------------------------------------------------


def topology(n, faces):
    faces = face_lists(faces)
    edge_faces = {}
    for fi, f in enumerate(faces):
        for a, b in zip(f, f[1:] + f[:1]):
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(fi)
    boundary = sorted(e for e, fs in edge_faces.items() if len(fs) == 1)
    non_manifold = sorted(e for e, fs in edge_faces.items() if len(fs) > 2)
    used = {v for f in faces for v in f}
    # fans around each vertex: faces joined across edges {v, w} with exactly two faces
    nm_vertices = []
    for v in sorted(used):
        around = [fi for fi, f in enumerate(faces) if v in f]
        parent = {fi: fi for fi in around}

        def find(x):
            while parent[x] != x:
                x = parent[x]
            return x

        for e, fs in edge_faces.items():
            if v in e and len(fs) == 2:
                parent[find(fs[0])] = find(fs[1])
        if len({find(fi) for fi in around}) > 1:
            nm_vertices.append(v)
    # face components across shared edges
    parent = list(range(len(faces)))

    def root(x):
        while parent[x] != x:
            x = parent[x]
        return x

    for fs in edge_faces.values():
        for g in fs[1:]:
            parent[root(g)] = root(fs[0])
    comps = len({root(i) for i in range(len(faces))})
    # orientability: propagate a sign per face across two-face edges
    sign = {}
    orientable = True
    for start in range(len(faces)):
        if start in sign:
            continue
        sign[start] = 1
        stack = [start]
        while stack:
            f = stack.pop()
            fv = faces[f]
            for a, b in zip(fv, fv[1:] + fv[:1]):
                fs = edge_faces[(min(a, b), max(a, b))]
                if len(fs) != 2:
                    continue
                g = fs[0] if fs[1] == f else fs[1]
                gv = faces[g]
                same_dir = any((x, y) == (a, b) for x, y in zip(gv, gv[1:] + gv[:1]))
                want = -sign[f] if same_dir else sign[f]
                if g not in sign:
                    sign[g] = want
                    stack.append(g)
                elif sign[g] != want:
                    orientable = False
    return dict(
        boundary=boundary,
        non_manifold=non_manifold,
        nm_vertices=nm_vertices,
        isolated=sorted(set(range(n)) - used),
        components=comps,
        orientable=orientable,
        closed=bool(faces) and not boundary,
        manifold=not non_manifold and not nm_vertices,
        euler=n - len(edge_faces) + len(faces),
    )


def assert_matches_oracle(vertices, faces, tolerance=0.0):
    r = locus.check_mesh(vertices, faces, tolerance)
    o = topology(len(vertices), faces)
    assert r.status == "ok"
    assert [tuple(e) for e in r.boundary_edges.tolist()] == o["boundary"]
    assert [tuple(e) for e in r.non_manifold_edges.tolist()] == o["non_manifold"]
    assert r.non_manifold_vertices.tolist() == o["nm_vertices"]
    assert r.isolated_vertices.tolist() == o["isolated"]
    assert r.components == o["components"]
    assert r.orientable == o["orientable"]
    assert r.closed == o["closed"]
    assert r.manifold == o["manifold"]
    assert r.euler_characteristic == o["euler"]
    assert r.face_count == len(faces) and r.vertex_count == len(vertices)
    return r


# ---- exact oracle for self-intersections of faces with no common vertex --------------------


def seg_crosses_tri(p, q, a, b, c):
    """General position: the open segment pq crosses the triangle abc (exact)."""
    sp, sq = orient3d(a, b, c, p), orient3d(a, b, c, q)
    if sp * sq >= 0:
        return False
    s = [orient3d(p, q, u, w) for u, w in ((a, b), (b, c), (c, a))]
    return all(x > 0 for x in s) or all(x < 0 for x in s)


def tris_cross(t, u):
    return any(seg_crosses_tri(t[i], t[(i + 1) % 3], *u) for i in range(3)) or any(
        seg_crosses_tri(u[i], u[(i + 1) % 3], *t) for i in range(3))


# ---- tests ---------------------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(GENERATORS))
def test_generators_against_oracle(name):
    v, f = GENERATORS[name]()
    assert v.dtype == np.float64 and v.shape[1] == 3
    tol = 1e-12 if name in ("dodecahedron", "hexahedron", "cylinder", "cone") else 0.0
    r = assert_matches_oracle(v, f, tol)
    assert r.closed and r.manifold and r.orientable and r.components == 1
    assert r.euler_characteristic == (0 if name == "torus" else 2)
    assert len(r.self_intersections) == 0 and len(r.degenerate_faces) == 0
    assert r.kind in ("polyhedron", "polytope")
    if name in ("tetrahedron", "octahedron", "icosahedron", "hexahedron", "dodecahedron"):
        assert r.kind == "polytope" and r.convex
    if name == "torus":
        assert r.kind == "polyhedron" and not r.convex


def test_generator_counts():
    assert [len(x) for x in locus.tetrahedron()] == [4, 4]
    assert locus.hexahedron()[1].shape == (6, 4)
    assert locus.dodecahedron()[1].shape == (12, 5)
    assert locus.dodecahedron(True)[1].shape == (36, 3)
    assert locus.icosahedron()[1].shape == (20, 3)
    for levels in range(3):
        v, f = locus.icosphere(2.0, levels)
        assert f.shape == (20 * 4**levels, 3)
        assert np.allclose(np.linalg.norm(v, axis=1), 2.0)
    v, f = locus.cylinder(1.0, 3.0, 7)
    assert isinstance(f, list) and sorted({len(x) for x in f}) == [3, 7]
    assert np.allclose(np.sort(np.unique(v[:, 2])), [-1.5, 1.5])


@pytest.mark.parametrize("name", ["tetrahedron", "octahedron", "icosahedron", "icosphere"])
def test_generators_outward(name):
    # outward orientation: the signed volume (divergence theorem) is positive
    v, f = GENERATORS[name]()
    vol = sum(np.dot(v[a], np.cross(v[b], v[c])) for a, b, c in f) / 6
    assert vol > 0


def test_damaged_meshes_against_oracle(rng):
    v, f = locus.icosphere(1.0, 1)
    f = f.tolist()
    for trial in range(12):
        g = [list(x) for x in f]
        k = int(rng.integers(1, 6))
        for i in sorted(rng.choice(len(g), size=k, replace=False), reverse=True):
            del g[i]                                # holes: boundary edges, maybe bow-ties
        if trial % 3 == 0:
            g.append(list(g[0][::-1]))              # a third face on three edges
        if trial % 4 == 1:
            i = int(rng.integers(len(g)))
            g[i] = g[i][::-1]                       # an orientation flip (still orientable)
        assert_matches_oracle(v, g)
    # two cubes sharing one vertex only: a non-manifold vertex, two components
    cv, cf = locus.hexahedron()
    v2 = np.vstack([cv, cv + (cv[7] - cv[0])])
    f2 = cf.tolist() + (cf + 8).tolist()
    # glue vertex 8 + 0 onto vertex 7
    f2 = [[7 if i == 8 else i for i in x] for x in f2]
    r = assert_matches_oracle(v2, f2, 1e-12)
    assert r.non_manifold_vertices.tolist() == [7] and r.components == 2
    assert r.isolated_vertices.tolist() == [8] and r.kind == "not_a_mesh"


def test_mobius_strip_is_not_orientable():
    n = 7
    v = []
    for i in range(n):
        a = 2 * np.pi * i / n
        for s in (-0.3, 0.3):
            w = s * np.cos(a / 2)
            v.append([(1 + w) * np.cos(a), (1 + w) * np.sin(a), s * np.sin(a / 2)])
    f = []
    for i in range(n):
        a0, a1 = 2 * i, 2 * i + 1
        if i + 1 < n:
            b0, b1 = 2 * i + 2, 2 * i + 3
        else:
            b0, b1 = 1, 0                           # the half twist
        f.append([a0, b0, b1, a1])
    r = assert_matches_oracle(np.array(v), f, 1e9)
    assert not r.orientable
    o = locus.orient_consistently(f)
    assert not o.orientable and o.non_orientable_components.tolist() == [0]


def test_orient_consistently_restores(rng):
    v, f = locus.icosphere(1.0, 2)
    flip = rng.random(len(f)) < 0.4
    flip[0] = False                                 # face 0 keeps its order: the reference
    g = np.where(flip[:, None], f[:, ::-1], f)
    o = locus.orient_consistently(g)
    assert o.status == "ok" and o.orientable
    assert np.array_equal(o.flipped, flip)
    assert np.array_equal(o.faces, f)
    assert o.faces.dtype == np.uint32 and o.face_component.tolist() == [0] * len(f)
    # every edge used once in each direction
    directed = {(a, b) for x in o.faces.tolist() for a, b in zip(x, x[1:] + x[:1])}
    assert len(directed) == 3 * len(f) and all((b, a) in directed for a, b in directed)
    # polygon faces (a list in, a list out)
    cv, cf = locus.cylinder(1.0, 1.0, 5)
    cf2 = [x[::-1] if i % 2 else x for i, x in enumerate(cf)]
    o = locus.orient_consistently(cf2, len(cv))
    assert isinstance(o.faces, list) and o.orientable
    assert all(np.array_equal(a, b) for a, b in zip(o.faces, cf))


def test_self_intersections_exact_oracle(rng):
    a_v, a_f = locus.icosphere(1.0, 1)
    rot = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    b_v = (a_v * 0.8) @ rot.T + rng.normal(size=3) * 0.3 + [1.1, 0, 0]
    v = np.vstack([a_v, b_v])
    f = np.vstack([a_f, a_f + len(a_v)])
    got = {tuple(p) for p in locus.self_intersections(v, f).tolist()}
    want = set()
    lo, hi = v[f].min(axis=1), v[f].max(axis=1)
    for i in range(len(a_f)):
        for j in range(len(a_f), len(f)):
            if np.any(lo[i] > hi[j]) or np.any(lo[j] > hi[i]):
                continue
            if tris_cross(v[f[i]], v[f[j]]):
                want.add((i, j))
    assert want and got == want
    r = locus.check_mesh(v, f)
    assert {tuple(p) for p in r.self_intersections.tolist()} == want
    assert r.kind == "not_a_mesh" and r.components == 2
    # each sphere alone is clean
    assert len(locus.self_intersections(a_v, a_f)) == 0


def test_self_intersections_touching_counts():
    # two triangles meeting at one point with different vertex ids: contact counts
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 0], [0, 0, 1], [-1, 0, 1.0]])
    assert locus.self_intersections(v, [[0, 1, 2], [3, 4, 5]]).tolist() == [[0, 1]]
    # the same with a shared vertex id: nothing beyond the shared vertex
    assert locus.self_intersections(v, [[0, 1, 2], [0, 4, 5]]).shape == (0, 2)


def test_float32_and_scale_covariance(rng):
    v, f = locus.torus(1.0, 0.4, 12, 8)
    r64 = locus.check_mesh(v, f)
    r32 = locus.check_mesh(v.astype(np.float32), f)
    assert r32.kind == r64.kind and r32.euler_characteristic == r64.euler_characteristic
    for s in (2.0**-20, 2.0**30):
        assert locus.check_mesh(v * s, f) == r64


def test_read_write_round_trip(tmp_path):
    v, f = locus.cylinder(1.0, 2.0, 6)
    for ext in ("obj", "off", "ply"):
        p = str(tmp_path / f"m.{ext}")
        locus.write_mesh(p, v, f)
        v2, f2 = locus.read_mesh(p)
        assert np.array_equal(v2, v)                # round trips are bit-exact
        assert all(np.array_equal(a, b) for a, b in zip(f2, f))
    tv, tf = locus.icosahedron()
    p = str(tmp_path / "m.stl")
    locus.write_mesh(p, tv, tf, "stl_ascii")
    v2, f2 = locus.read_mesh(p)
    assert f2.shape == (20, 3) and len(v2) == 12
    assert np.array_equal(v2[f2], tv[tf])           # corners merged, same triangles
    p = tmp_path / "bad.off"
    p.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(ValueError, match="parse_error"):
        locus.read_mesh(str(p))
    with pytest.raises(ValueError, match="io_error"):
        locus.read_mesh(str(tmp_path / "missing.obj"))
    with pytest.raises(ValueError, match="unknown format"):
        locus.read_mesh(str(p), "xyz")
    with pytest.raises(ValueError, match="non_finite"):
        locus.write_mesh(str(tmp_path / "n.obj"), np.array([[np.nan, 0, 0], [1, 0, 0], [0, 1, 0]]),
                         [[0, 1, 2]])


def test_bad_input():
    v, f = locus.tetrahedron()
    bad = v.copy()
    bad[2, 1] = np.nan
    for fn in (locus.check_mesh, locus.self_intersections):
        with pytest.raises(ValueError, match="non_finite_input"):
            fn(bad, f)
        with pytest.raises(ValueError, match="not an index below"):
            fn(v, f + 1)
        with pytest.raises(ValueError, match="columns"):
            fn(v[:, :2], f)
        with pytest.raises(ValueError, match="at least 3"):
            fn(v, f[:, :2])
        with pytest.raises(ValueError, match="repeats a vertex"):
            fn(v, [[0, 1, 2], [0, 0, 3]])
        with pytest.raises(ValueError, match="integers"):
            fn(v, f.astype(float))
        with pytest.raises(ValueError):
            fn(v, None)
        with pytest.raises(ValueError):
            fn(None, f)
    with pytest.raises(ValueError, match="empty_input"):
        locus.check_mesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=int))
    with pytest.raises(ValueError, match="coplanarity_tolerance"):
        locus.check_mesh(v, f, -1.0)
    with pytest.raises(ValueError, match="not an index below"):
        locus.orient_consistently([[0, 1, -2]])


def test_stub_fields_of_new_results():
    stub = pathlib.Path(__file__).resolve().parent.parent / "locus.pyi"
    tree = ast.parse(stub.read_text())
    fields = {n.name: {a.target.id for a in n.body if isinstance(a, ast.AnnAssign)}
              for n in tree.body if isinstance(n, ast.ClassDef)}
    v, f = locus.tetrahedron()
    for r in (locus.check_mesh(v, f), locus.orient_consistently(f),
              locus.ray_triangle_hits(np.zeros((1, 3)), np.ones((1, 3)), v[f]),
              locus.circle_circle([[0, 0]], [1], [[1, 0]], [1]),
              locus.ray_box_hits(np.zeros((1, 3)), np.ones((1, 3)), np.ones((1, 2, 3)))):
        assert set(vars(r)) == fields[type(r).__name__] | {"status"}


def test_all_pairs_touch_in_a_fan():
    # a closed fan (no self-intersection) of 8 triangles around a vertex, all ids shared
    k = 8
    ring = [[np.cos(2 * np.pi * i / k), np.sin(2 * np.pi * i / k), 0.0] for i in range(k)]
    v = np.array([[0, 0, 0.5]] + ring)
    f = [[0, 1 + i, 1 + (i + 1) % k] for i in range(k)]
    r = assert_matches_oracle(v, f)
    assert len(r.self_intersections) == 0 and r.boundary_edges.shape == (k, 2)
    assert not r.closed and r.manifold and r.kind == "mesh"


def test_read_points(tmp_path, rng):
    p = rng.random((20, 3)) * 2.0**rng.integers(-30, 30, size=(20, 1))
    csv = tmp_path / "p.csv"
    csv.write_text("x,y,z\n" + "".join(f"{a!r},{b!r},{c!r}\n" for a, b, c in p))
    q = locus.read_points(str(csv))
    assert q.shape == (20, 3) and np.array_equal(q, p)   # repr round-trips exactly
    two = tmp_path / "p.txt"
    two.write_text("".join(f"{a!r},{b!r}\n" for a, b, _ in p))
    assert np.array_equal(locus.read_points(str(two)), p[:, :2])
    xyz = tmp_path / "p.xyz"
    xyz.write_text("".join(f"{a!r} {b!r} {c!r}\n" for a, b, c in p))
    assert np.array_equal(locus.read_points(str(xyz)), p)
    bad = tmp_path / "bad.csv"
    bad.write_text("1,2\n3,x\n")
    with pytest.raises(ValueError, match="parse_error"):
        locus.read_points(str(bad))
    with pytest.raises(ValueError, match="io_error"):
        locus.read_points(str(tmp_path / "missing.csv"))
    with pytest.raises(ValueError, match="invalid_input"):
        locus.read_points(str(csv), 4)
    with pytest.raises(ValueError, match="unknown format"):
        locus.read_points(str(csv), 0, "wkt")
