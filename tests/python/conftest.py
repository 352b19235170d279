"""Fixtures of the madd Python suite (run by ctest as
`python3 -m pytest -q tests/python` with PYTHONPATH=BUILD/python and
MADD_CLI=BUILD/madd)."""
import os
import pathlib

import numpy as np
import pytest

import madd


def pytest_configure(config):
    config.addinivalue_line(
        "markers",
        "gil: the GIL-release test (two meshes in two Python threads against one after the other); "
        "timing-sensitive, wants a free second core")


@pytest.fixture(scope="session")
def data():
    """The repository's data/ directory, found from this file."""
    d = pathlib.Path(__file__).resolve().parents[2] / "data"
    assert (d / "key.poly").is_file(), f"no data/ beside tests/: {d}"
    return d


@pytest.fixture(scope="session")
def cli():
    """The madd command line tool (MADD_CLI); tests needing it are skipped without it."""
    path = os.environ.get("MADD_CLI")
    if not path:
        pytest.skip("MADD_CLI is not set")
    path = os.path.abspath(path)  # the tests run it in their own directories
    if not os.access(path, os.X_OK):
        pytest.fail(f"MADD_CLI={path} is not an executable")
    return path


SQUARE = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
HOLE = np.array([[0.25, 0.25], [0.75, 0.25], [0.75, 0.75], [0.25, 0.75]], dtype=float)


@pytest.fixture
def square_with_hole():
    """The unit square with a centred square hole of side 0.5 (area 0.75),
    from arrays, ids 0-based; outer segments marker 1, hole segments 2."""
    points = np.vstack([SQUARE, HOLE])
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]])
    markers = np.array([1, 1, 1, 1, 2, 2, 2, 2])
    return madd.Domain(points, segments, holes=[[0.5, 0.5]], markers=markers)


@pytest.fixture
def unit_square():
    return madd.Domain(SQUARE, np.array([[0, 1], [1, 2], [2, 3], [3, 0]]))
