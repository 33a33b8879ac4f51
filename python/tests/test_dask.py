# The Dask example (python/examples/dask_batch.py) on a LocalCluster of 2 worker processes
# gives exactly the single-process answer.
import importlib
import os
import pathlib
import sys

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

EXAMPLE = pathlib.Path(__file__).resolve().parent.parent / "examples" / "dask_batch.py"


def load_example():
    """Imports the example by name; the worker processes find it (and locus) through
    PYTHONPATH, which they inherit."""
    import locus

    module_dir = str(pathlib.Path(locus.__file__).resolve().parent)
    extra = [str(EXAMPLE.parent), module_dir]
    old = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    os.environ["PYTHONPATH"] = os.pathsep.join(extra + old)
    sys.path.insert(0, str(EXAMPLE.parent))
    return importlib.import_module("dask_batch")


# distributed 2022.12 on tornado 6.2 warns about its own event-loop set-up
@pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
def test_dask_local_cluster_equals_single_process():
    mod = load_example()
    polygon, ends = mod.make_polygon()
    n, chunks = 200_000, 8
    ref = mod.run_local(n, chunks, polygon, ends)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        out = mod.run_dask(client, n, chunks, polygon, ends)
        assert len(client.scheduler_info()["workers"]) == 2
    assert out.dtype == np.int8 and len(out) == n
    assert np.array_equal(out, ref)
    assert (out == 1).any() and (out == -1).any()
