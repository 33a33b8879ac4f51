# ray_surface_hits and plane_surface_curves: hits of rays through known surface points of random
# Bézier patches (residual checks against a numpy evaluation of the patch), a NURBS sphere
# against the analytic sphere, and plane sections of a bowl (known circle, topology), plus bad
# input.
import math

import numpy as np
import pytest

import locus


def bernstein(n, t):
    return np.array([math.comb(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)])


def patch_point(control, u, v):
    bu = bernstein(control.shape[0] - 1, u)
    bv = bernstein(control.shape[1] - 1, v)
    return np.einsum("i,j,ijk->k", bu, bv, control)


def test_rays_through_known_points_of_random_patches():
    rng = np.random.default_rng(20261204)
    found = 0
    for _ in range(30):
        control = rng.uniform(-1, 1, (4, 4, 3))
        u, v = rng.uniform(0.1, 0.9, 2)
        q = patch_point(control, u, v)
        d = rng.normal(size=3)
        d /= np.linalg.norm(d)
        r = locus.ray_surface_hits((q - 2 * d)[None, :], d[None, :], control)
        assert r.status == "ok"
        assert np.all(r.ray == 0)
        for t, uv, p in zip(r.t, r.uv, r.points):
            assert np.allclose(q - 2 * d + t * d, p, atol=1e-9)
            assert np.allclose(patch_point(control, *uv), p, atol=1e-9)
        if len(r.t) and np.min(np.linalg.norm(r.points - q, axis=1)) < 1e-9:
            found += 1
    assert found >= 25  # the rest are near-tangent draws


def nurbs_sphere():
    h = math.sqrt(0.5)
    m = [(0, 1), (1, 1), (1, 0), (1, -1), (0, -1)]
    wm = [1, h, 1, h, 1]
    c = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    wc = [1, h, 1, h, 1, h, 1, h, 1]
    control = np.array([[(mi[0] * cj[0], mi[0] * cj[1], mi[1]) for cj in c] for mi in m], float)
    weights = np.outer(wm, wc)
    ku = [0, 0, 0, 0.5, 0.5, 1, 1, 1]
    kv = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    return control, ku, kv, weights


def test_nurbs_sphere_matches_the_analytic_sphere():
    control, ku, kv, w = nurbs_sphere()
    rng = np.random.default_rng(5)
    o = rng.uniform(-3, 3, (40, 3))
    d = rng.uniform(-1.2, 1.2, (40, 3)) - o
    r = locus.ray_surface_hits(o, d, control, ku, kv, w)
    for i in range(40):
        # t^2 |d|^2 + 2 t o.d + |o|^2 - 1 = 0, t >= 0
        a, b, c = d[i] @ d[i], 2 * o[i] @ d[i], o[i] @ o[i] - 1
        disc = b * b - 4 * a * c
        want = [] if disc < 0 else [t for t in ((-b - disc**0.5) / (2 * a), (-b + disc**0.5) / (2 * a)) if t >= 0]
        got = r.t[r.ray == i]
        assert len(got) == len(want)
        assert np.allclose(got, want, atol=1e-9)
    assert np.allclose(np.linalg.norm(r.points, axis=1), 1.0, atol=1e-9)


def bowl():
    a = [1, -1, 1]
    return np.array([[(i - 1, j - 1, a[i] + a[j]) for j in range(3)] for i in range(3)], float)


def test_plane_cuts_the_bowl():
    r = locus.plane_surface_curves([0, 0, 1], 0.5, bowl())
    assert list(r.closed) == [True]
    p = r.points[0]
    assert np.allclose(p[:, 2], 0.5, atol=1e-12)
    assert np.allclose(p[:, 0] ** 2 + p[:, 1] ** 2, 0.5, atol=1e-12)
    assert r.uv[0].shape == (len(p), 2)
    four = locus.plane_surface_curves([0, 0, 1], 1.5, bowl(), grid=8)
    assert len(four.points) == 4 and not any(four.closed)
    assert len(locus.plane_surface_curves([0, 0, 1], -1.0, bowl()).points) == 0


def test_bad_input():
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.ray_surface_hits([[0, 0, np.nan]], [[0, 0, 1]], bowl())
    with pytest.raises(ValueError):
        locus.ray_surface_hits([[0, 0, 0]], [[0, 0, 1]], np.zeros((3, 3)))
    with pytest.raises(ValueError):
        locus.plane_surface_curves([0, 0, 1], 0.5, bowl(), knots_u=[0, 0, 0, 1, 1, 1])
    with pytest.raises(ValueError):
        locus.plane_surface_curves([0, 0, 0], 0.5, bowl())
    control, ku, kv, w = nurbs_sphere()
    with pytest.raises(ValueError):
        locus.ray_surface_hits([[0, 0, 3]], [[0, 0, -1]], control, ku, kv, -w)



def patch_partials(control, u, v, step=1e-6):
    su = (patch_point(control, u + step, v) - patch_point(control, u - step, v)) / (2 * step)
    sv = (patch_point(control, u, v + step) - patch_point(control, u, v - step)) / (2 * step)
    return su, sv


def check_hermite(control, normal, constant, grid, t, rate):
    # Tangents against the patch (numpy, central differences) and the interpolants against
    # a numpy evaluation of the patch. rate: the bound c in |R(t) - S(p(t))| <= c h^4 and
    # |N.S(p(t)) - k| <= c h^4 per segment of length h (None: no bound). Returns the largest
    # deviation / h^4 over the segments longer than 1e-3 (shorter ones: rounding dominates).
    r = locus.plane_surface_hermite(normal, constant, control, grid=grid, t=t)
    assert r.status == "ok"
    unit = np.asarray(normal, float) / np.linalg.norm(normal)
    level = constant / np.linalg.norm(normal)
    worst_rate = 0.0
    for pts, uv, tan, cp, cq, closed in zip(r.points, r.uv, r.tangents, r.curve_points,
                                            r.curve_uv, r.closed):
        segs = len(pts) if closed else len(pts) - 1
        assert cp.shape == (segs, len(t), 3) and cq.shape == (segs, len(t), 2)
        # traced points on the plane and the surface; tangents unit, in the plane, in the
        # surface's tangent plane (and along the point order on a gently curved branch)
        assert np.allclose(pts @ unit, level, atol=1e-12)
        assert np.allclose(np.linalg.norm(tan, axis=1), 1.0, atol=1e-12)
        assert np.allclose(tan @ unit, 0.0, atol=1e-12)
        for p, q, d in zip(pts, uv, tan):
            assert np.allclose(patch_point(control, *q), p, atol=1e-12)
            n = np.cross(*patch_partials(control, *q))
            assert abs(d @ n) <= 1e-6 * np.linalg.norm(n)
        chords = np.roll(pts, -1, axis=0) - pts
        if rate is not None:
            assert np.all(np.einsum("ij,ij->i", tan[:segs], chords[:segs]) > 0)
        for i in range(segs):
            j = (i + 1) % len(pts)
            assert np.allclose(cp[i, 0], pts[i], atol=1e-14)
            assert np.allclose(cp[i, -1], pts[j], atol=1e-14)
            assert np.allclose(cq[i, 0], uv[i], atol=1e-14)
            assert np.allclose(cp[i] @ unit, level, atol=1e-12)  # R(t) lies in the plane
            h4 = np.linalg.norm(pts[j] - pts[i]) ** 4
            for rp, q in zip(cp[i], cq[i]):
                s = patch_point(control, *q)
                e = max(np.linalg.norm(rp - s), abs(s @ unit - level))
                if h4 > 1e-12:
                    worst_rate = max(worst_rate, e / h4)
                if rate is not None:
                    assert e <= rate * h4 + 1e-13, (e, h4)
    return worst_rate, len(r.points)


def test_hermite_tangents_on_random_patches():
    rng = np.random.default_rng(20261205)
    for _ in range(8):
        control = rng.uniform(-1, 1, (4, 4, 3))
        normal = rng.normal(size=3)
        constant = normal @ patch_point(control, *rng.uniform(0.3, 0.7, 2))
        assert check_hermite(control, normal, constant, 8, np.linspace(0, 1, 3), None)[1] > 0


def test_hermite_interpolants_are_fourth_order():
    # gently curved graph patches cut by steep planes (one smooth branch, no near-tangency):
    # the deviation is O(h^4) per segment, so deviation / h^4 stays bounded as the grid is
    # refined 4 times (within a factor 6 for local variation; a chord's O(h^2) would make it
    # grow about 16 times)
    rng = np.random.default_rng(20261206)
    t = np.linspace(0, 1, 7)
    g = np.linspace(-1, 1, 4)
    for _ in range(8):
        z = rng.uniform(-0.4, 0.4, (4, 4))
        control = np.stack(np.meshgrid(g, g, indexing="ij") + [z], axis=-1)
        angle = rng.uniform(0, 2 * np.pi)
        normal = np.array([np.cos(angle), np.sin(angle), rng.uniform(-0.5, 0.5)])
        constant = normal @ patch_point(control, *rng.uniform(0.3, 0.7, 2))
        coarse, n = check_hermite(control, normal, constant, 8, t, 1.0)
        fine, _ = check_hermite(control, normal, constant, 32, t, 1.0)
        assert n == 1
        assert 0 < coarse and fine < 6 * coarse, (coarse, fine)


def test_hermite_of_the_bowl_and_bad_input():
    r = locus.plane_surface_hermite([0, 0, 1], 0.5, bowl(), t=[0.0, 0.5, 1.0])
    assert len(r.points) == 1 and r.closed[0]
    assert r.curve_points[0].shape == (len(r.points[0]), 3, 3)
    # the section is the circle x^2 + y^2 = 1/2 at z = 0.5
    mid = r.curve_points[0][:, 1]
    assert np.allclose(mid[:, 2], 0.5, atol=1e-12)
    assert np.allclose(np.hypot(mid[:, 0], mid[:, 1]), np.sqrt(0.5), atol=1e-5)
    empty = locus.plane_surface_hermite([0, 0, 1], 0.5, bowl())
    assert empty.curve_points[0].shape == (len(empty.points[0]), 0, 3)
    with pytest.raises(ValueError, match="t must"):
        locus.plane_surface_hermite([0, 0, 1], 0.5, bowl(), t=[1.5])
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.plane_surface_hermite([0, 0, 1], 0.5, bowl(), t=[np.nan])
    with pytest.raises(ValueError, match="degenerate_input"):
        locus.plane_surface_hermite([0, 0, 0], 0.5, bowl())
