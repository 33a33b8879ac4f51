# Inputs are read in place (no copy) when they are C-contiguous float32/float64; results own
# their memory; nothing leaks over many calls (reference counts of the inputs unchanged,
# traced Python allocations and the resident set bounded over 10^4 calls).
import gc
import sys
import tracemalloc

import numpy as np
import pytest

import locus


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
@pytest.mark.parametrize("dim", [2, 3])
def test_contiguous_input_is_not_copied(rng, dtype, dim):
    p = rng.random((100, dim)).astype(dtype)
    address, copied = locus._input_address(p)
    assert address == p.ctypes.data and not copied
    view = p[10:20]  # a contiguous slice is read in place too
    address, copied = locus._input_address(view)
    assert address == view.ctypes.data and not copied


def test_other_layouts_are_copied(rng):
    p = rng.random((100, 4))[:, :2]
    address, copied = locus._input_address(p)
    assert copied and address != p.ctypes.data
    assert locus._input_address(p.astype(np.int32))[1]
    assert locus._input_address(p.astype(">f8"))[1]  # non-native byte order


def test_results_own_their_memory(rng):
    r = locus.delaunay(rng.random((1000, 2)))
    t = r.triangles
    assert t.base is not None and not t.flags["OWNDATA"]  # a view of the C++ vector's storage
    del r
    gc.collect()
    assert t.sum() > 0  # still valid: the array keeps the storage alive


def rss_kb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def test_no_leak_over_many_calls(rng):
    p2 = rng.random((64, 2))
    p3 = rng.random((64, 3))
    poly = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])
    tris = rng.random((64, 3, 3))
    seg = rng.random((64, 2, 2))
    before = [sys.getrefcount(x) for x in (p2, p3, poly, tris, seg)]

    def calls():
        locus.convex_hull(p2)
        locus.convex_hull(p3)
        locus.delaunay(p2)
        locus.delaunay(p3)
        locus.min_circle(p2)
        locus.fit_sphere(p3)
        locus.point_in_polygon(p2, poly)
        locus.point_triangle_sqr_distances(p3, tris)
        locus.segment_intersections(seg, seg[::-1])
        locus.gjk_distance(p3, p3 + 3)
        try:
            locus.delaunay(p2[:0])
        except ValueError:
            pass

    for _ in range(200):  # warm up caches and allocator pools
        calls()
    gc.collect()
    tracemalloc.start()
    rss0 = rss_kb()
    snap0 = tracemalloc.take_snapshot()
    for _ in range(10000):
        calls()
    gc.collect()
    snap1 = tracemalloc.take_snapshot()
    rss1 = rss_kb()
    tracemalloc.stop()
    grown = sum(s.size_diff for s in snap1.compare_to(snap0, "filename"))
    assert grown < 256 * 1024, grown  # 10^5 calls: a leak of even 1 object per call shows
    assert rss1 - rss0 < 16 * 1024, (rss0, rss1)  # KiB; a leaked result would be > 100 MB
    assert [sys.getrefcount(x) for x in (p2, p3, poly, tris, seg)] == before
