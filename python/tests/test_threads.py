# The GIL is released during heavy calls: while two threads are inside locus.delaunay, the main
# thread keeps running Python code (a progress counter), and both threads' results equal the
# single-threaded one. Progress is counted, not timed: with the GIL held, the counter could not
# advance at all while both workers are inside the call.
import sys
import threading

import numpy as np

import locus


def test_heavy_calls_release_the_gil(rng):
    p = rng.random((300000, 2))
    ref = locus.delaunay(p).triangles
    inside = [threading.Event(), threading.Event()]
    done = [threading.Event(), threading.Event()]
    results = [None, None]

    def work(k):
        inside[k].set()
        results[k] = locus.delaunay(p).triangles
        done[k].set()

    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # hand the GIL over at once when a worker asks for it
    try:
        threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
        for t in threads:
            t.start()
        for e in inside:
            e.wait()
        progress = 0
        while not (done[0].is_set() or done[1].is_set()):
            progress += 1
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(old)
    assert all(np.array_equal(r, ref) for r in results)
    # a Delaunay of 3e5 points takes > 50 ms; the main thread loops ~10^6 times per 100 ms when
    # it has the GIL. Holding the GIL would freeze it after a handful of iterations.
    assert progress > 1000, progress
