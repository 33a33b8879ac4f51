#!/usr/bin/env python3
"""locus vs scipy.spatial (Qhull) and shapely (GEOS) on 10^6 points, from Python.

    PYTHONPATH=build/python/python /usr/bin/python3 python/bench/bench_vs_scipy.py [--n 1000000]

Every time includes the cost of crossing from Python (argument conversion, result arrays).
Times are the best of --repeat runs (a single run for calls slower than 5 s). Prints a Markdown
table for bench/results/python.md. shapely 1.8 has no vectorised distance: its time is a Python
loop over prepared Point objects (their construction is not timed, which favours shapely).
"""
import argparse
import platform
import time

import numpy as np
import scipy
import shapely
import shapely.geometry as sg
import shapely.vectorized as sv
from scipy import spatial

import locus


def best(f, repeat):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
        if times[-1] > 5.0:
            break
    return min(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    n, rep = args.n, args.repeat
    rng = np.random.default_rng(42)
    rows = []

    def row(task, t_peer, t_locus, peer, check):
        rows.append((task, peer, t_peer, t_locus, t_peer / t_locus, check))
        print(f"{task}: {peer} {t_peer:.4f} s, locus {t_locus:.4f} s, "
              f"ratio {t_peer / t_locus:.1f}x ({check})", flush=True)

    p2 = rng.random((n, 2))
    p3 = rng.standard_normal((n, 3))

    # Delaunay 2D
    ours = locus.delaunay(p2)
    theirs = spatial.Delaunay(p2)
    check = f"{len(ours.triangles)} vs {len(theirs.simplices)} triangles"
    row(f"Delaunay 2D, {n} uniform points", best(lambda: spatial.Delaunay(p2), rep),
        best(lambda: locus.delaunay(p2), rep), "scipy.spatial.Delaunay", check)

    # Convex hulls
    same = set(locus.convex_hull(p2).indices.tolist()) == set(spatial.ConvexHull(p2).vertices.tolist())
    row(f"convex hull 2D, {n} uniform points", best(lambda: spatial.ConvexHull(p2), rep),
        best(lambda: locus.convex_hull(p2), rep), "scipy.spatial.ConvexHull",
        f"same vertex set: {same}")
    same = set(locus.convex_hull(p3).vertices.tolist()) == set(spatial.ConvexHull(p3).vertices.tolist())
    row(f"convex hull 3D, {n} Gaussian points", best(lambda: spatial.ConvexHull(p3), rep),
        best(lambda: locus.convex_hull(p3), rep), "scipy.spatial.ConvexHull",
        f"same vertex set: {same}")

    c3 = rng.random((n, 3))
    same = set(locus.convex_hull(c3).vertices.tolist()) == set(spatial.ConvexHull(c3).vertices.tolist())
    row(f"convex hull 3D, {n} points uniform in a cube", best(lambda: spatial.ConvexHull(c3), rep),
        best(lambda: locus.convex_hull(c3), rep), "scipy.spatial.ConvexHull",
        f"same vertex set: {same}")

    # Delaunay 3D (n / 10 points: Qhull's 3D Delaunay of 10^6 points takes minutes)
    m = n // 10
    q3 = rng.random((m, 3))
    ours3, theirs3 = locus.delaunay(q3), spatial.Delaunay(q3)
    row(f"Delaunay 3D, {m} uniform points", best(lambda: spatial.Delaunay(q3), rep),
        best(lambda: locus.delaunay(q3), rep), "scipy.spatial.Delaunay",
        f"{len(ours3.tetrahedra)} vs {len(theirs3.simplices)} tetrahedra")

    # Point in polygon: a 256-vertex star with a square hole
    ang = np.linspace(0, 2 * np.pi, 256, endpoint=False)
    rad = rng.uniform(0.6, 1.0, 256)
    outer = np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=1)
    hole = 0.25 * np.array([[1, 1], [1, -1], [-1, -1], [-1, 1.0]])
    rings = np.concatenate([outer, hole])
    ends = [256, 260]
    poly = sg.Polygon(outer, [hole])
    q = rng.uniform(-1.1, 1.1, (n, 2))
    x, y = q[:, 0].copy(), q[:, 1].copy()
    same = np.array_equal(locus.point_in_polygon(q, rings, ends) == 1, sv.contains(poly, x, y))
    row(f"point in polygon (260 vertices, 1 hole), {n} points",
        best(lambda: sv.contains(poly, x, y), rep),
        best(lambda: locus.point_in_polygon(q, rings, ends), rep),
        "shapely.vectorized.contains", f"same answers: {same}")

    # Point-triangle distance (triangle in z = 0; shapely: Polygon.distance(Point))
    tri2 = np.array([[-0.5, -0.4], [0.6, -0.3], [0.1, 0.7]])
    tri3 = np.zeros((3, 3))
    tri3[:, :2] = tri2
    shp_tri = sg.Polygon(tri2)
    d_pts = np.zeros((n, 3))
    d_pts[:, :2] = q
    pts = [sg.Point(a, b) for a, b in q]
    ref = np.array([shp_tri.distance(pt) for pt in pts[:1000]])
    ours_d = np.sqrt(locus.point_triangle_sqr_distances(d_pts[:1000], tri3))
    err = np.max(np.abs(ours_d**2 - ref**2))
    row(f"point-triangle distance, {n} points", best(lambda: [shp_tri.distance(pt) for pt in pts], 1),
        best(lambda: np.sqrt(locus.point_triangle_sqr_distances(d_pts, tri3)), rep),
        "shapely Polygon.distance (loop)", f"max |d^2 - d_ref^2| = {err:.1e}")

    print()
    print(f"Machine: {platform.processor() or platform.machine()}, Python {platform.python_version()}, "
          f"numpy {np.__version__}, scipy {scipy.__version__}, shapely {shapely.__version__}")
    print()
    print("| task | peer | peer (s) | locus (s) | peer / locus | check |")
    print("|---|---|---:|---:|---:|---|")
    for task, peer, tp, tl, ratio, check in rows:
        print(f"| {task} | {peer} | {tp:.4f} | {tl:.4f} | {ratio:.1f}x | {check} |")


if __name__ == "__main__":
    main()
