"""Meshing and checking release the GIL: a pure-Python loop on the main thread
keeps running while another thread is inside the library.

The main thread samples the clock in a loop while the worker runs; the largest
gap between samples taken during the library call is compared with the call's
duration. Holding the GIL for the call would leave one gap as long as the call
itself; with the GIL released the gaps are scheduler slices (milliseconds).
The jobs are sized to take over 0.3 s, and the bound is half their duration,
so scheduling noise on a loaded machine does not make the test fail.
"""

import threading
import time

import pytest

import pqmesh
from conftest import CUBE_FACETS, CUBE_POINTS, assert_valid

MIN_SECONDS = 0.3


def largest_gap_during(call):
    """Run call() on a worker thread; return (its duration, the largest gap between
    the main thread's clock samples within it, its result)."""
    span = {}

    def work():
        span["start"] = time.perf_counter()
        span["result"] = call()
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    samples = []
    worker.start()
    while worker.is_alive():
        samples.append(time.perf_counter())
    worker.join()
    start, end = span["start"], span["end"]
    inside = [start] + [t for t in samples if start < t < end] + [end]
    return end - start, max(b - a for a, b in zip(inside, inside[1:])), span["result"]


@pytest.fixture(scope="module")
def fine_cube():
    """The construction alone on a 2 x 1 x 1 bar, about 4.8 million tetrahedra: some 10 s to make
    and 0.6 s to check on an idle machine."""
    bar = [(2 * x, y, z) for x, y, z in CUBE_POINTS]
    duration, gap, mesh = largest_gap_during(
        lambda: pqmesh.tetrahedralize(bar, CUBE_FACETS, max_size=0.025, improve=False))
    return mesh, duration, gap


def test_gil_released_while_meshing(fine_cube):
    mesh, duration, gap = fine_cube
    print(f"meshing: {duration:.3f} s, largest gap {gap:.4f} s")
    assert duration > MIN_SECONDS, "the job is too short to tell; make the mesh finer"
    assert gap < duration / 2, (gap, duration)
    assert_valid(mesh)


def test_gil_released_while_checking(fine_cube):
    mesh = fine_cube[0]
    duration, gap, report = largest_gap_during(lambda: pqmesh.check(mesh, mesh.domain))
    print(f"checking: {duration:.3f} s, largest gap {gap:.4f} s")
    assert report.valid, report.text
    assert duration > MIN_SECONDS, "the check is too short to tell; make the mesh finer"
    assert gap < duration / 2, (gap, duration)
