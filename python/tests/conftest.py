# Shared fixtures of the locus Python tests. Run with the built module on PYTHONPATH:
#   PYTHONPATH=build/python/python /usr/bin/python3 -m pytest python/tests
import os
import zlib

import numpy as np
import pytest

import locus  # noqa: F401  (fails early, with the import error, when the module is not found)


@pytest.fixture
def rng(request):
    """A seeded generator; the seed is printed so that a failure can be replayed
    (LOCUS_SEED=<seed> pytest ...)."""
    seed = int(os.environ.get("LOCUS_SEED", "0")) or zlib.crc32(request.node.name.encode())
    print(f"seed {seed} (replay with LOCUS_SEED={seed})")
    return np.random.default_rng(seed)
