#!/usr/bin/env python3
"""Scale a batch of point-in-polygon queries out over a Dask cluster.

The job: classify N points (uniform in a square, generated chunk by chunk from per-chunk seeds,
as a real job would read tiles from storage) against one polygon with a hole. Each Dask task
builds locus's slab locator once and classifies its chunk with the GIL released; the results
come back as int8 arrays (1 inside, 0 boundary, -1 outside) and are checked against the same
computation in this process.

    PYTHONPATH=build/python/python /usr/bin/python3 python/examples/dask_batch.py \
        --n 10000000 --workers 2 --chunks 20

Without --scheduler a distributed.LocalCluster with --workers worker processes (one thread
each) is started on this machine. With --scheduler tcp://host:8786 the same code runs on an
existing multi-node cluster (every worker needs the locus module importable; see
docs/python.md).
"""
import argparse
import time

import numpy as np

import locus


def make_polygon(seed=7, n=256):
    """A star-shaped outer ring (counter-clockwise) and a square hole; (vertices, ring_ends)."""
    rng = np.random.default_rng(seed)
    ang = np.linspace(0, 2 * np.pi, n, endpoint=False)
    rad = rng.uniform(0.6, 1.0, n)
    outer = np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=1)
    hole = 0.25 * np.array([[1, 1], [1, -1], [-1, -1], [-1, 1.0]])
    return np.concatenate([outer, hole]), np.array([n, n + 4])


def chunk_points(seed, size):
    """The points of one chunk (deterministic from its seed)."""
    return np.random.default_rng(seed).uniform(-1.1, 1.1, (size, 2))


def classify_chunk(seed, size, polygon, ring_ends):
    """One task: generate the chunk and classify it."""
    return locus.point_in_polygon(chunk_points(seed, size), polygon, ring_ends)


def chunk_sizes(n, chunks):
    base, extra = divmod(n, chunks)
    return [base + (1 if k < extra else 0) for k in range(chunks)]


def run_local(n, chunks, polygon, ring_ends, seed=1000):
    """The single-process reference: the same chunks, one after the other."""
    return np.concatenate([classify_chunk(seed + k, s, polygon, ring_ends)
                           for k, s in enumerate(chunk_sizes(n, chunks))])


def run_dask(client, n, chunks, polygon, ring_ends, seed=1000):
    """The same job as Dask tasks: the polygon is scattered once to every worker."""
    poly_f = client.scatter(polygon, broadcast=True, hash=False)
    ends_f = client.scatter(ring_ends, broadcast=True, hash=False)
    sizes = chunk_sizes(n, chunks)
    futures = client.map(classify_chunk, [seed + k for k in range(chunks)], sizes,
                         polygon=poly_f, ring_ends=ends_f, pure=False)
    return np.concatenate(client.gather(futures))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=10_000_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--chunks", type=int, default=20)
    ap.add_argument("--scheduler", default=None, help="address of an existing scheduler")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()

    from distributed import Client, LocalCluster

    polygon, ring_ends = make_polygon()
    best_local = float("inf")
    for _ in range(args.repeat):
        t = time.perf_counter()
        ref = run_local(args.n, args.chunks, polygon, ring_ends)
        best_local = min(best_local, time.perf_counter() - t)
    print(f"single process: {args.n} points in {best_local:.3f} s "
          f"({args.n / best_local / 1e6:.1f} M points/s)")

    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    try:
        run_dask(client, args.n // 100, args.chunks, polygon, ring_ends)  # warm up workers
        best = float("inf")
        for _ in range(args.repeat):
            t = time.perf_counter()
            out = run_dask(client, args.n, args.chunks, polygon, ring_ends)
            best = min(best, time.perf_counter() - t)
        equal = np.array_equal(out, ref)
        nworkers = len(client.scheduler_info()["workers"])
        print(f"dask, {nworkers} workers: {best:.3f} s ({args.n / best / 1e6:.1f} M points/s); "
              f"speed-up {best_local / best:.2f}x; equal to single process: {equal}")
        print(f"inside {int((out == 1).sum())}, boundary {int((out == 0).sum())}, "
              f"outside {int((out == -1).sum())}")
        if not equal:
            raise SystemExit("results differ")
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


if __name__ == "__main__":
    main()
