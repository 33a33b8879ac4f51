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
