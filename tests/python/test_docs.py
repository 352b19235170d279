"""docs/python.md's examples: shown on the page as the files hold them, and
they run (the dolfinx one when FEniCSx is installed, as CI installs it)."""
import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def example_blocks():
    """(path, text) of every `<!-- example: PATH -->` block of docs/python.md."""
    page = (ROOT / "docs" / "python.md").read_text()
    return re.findall(r"<!-- example: (\S+) -->\n```python\n(.*?)```\n", page, re.S)


def test_the_page_shows_each_example_as_its_file_holds_it():
    blocks = example_blocks()
    assert sorted(path for path, _ in blocks) == ["docs/examples/coast_to_meshio.py", "docs/examples/poisson_dolfinx.py"]
    for path, text in blocks:
        assert text == (ROOT / path).read_text(), f"docs/python.md shows another {path}"


def run_example(name, *args):
    env = dict(os.environ)
    return subprocess.run([sys.executable, str(ROOT / "docs" / "examples" / name), *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=600)


@pytest.mark.skipif(any(importlib.util.find_spec(m) is None for m in ("shapely", "meshio", "matplotlib")),
                    reason="needs shapely, meshio and matplotlib")
def test_the_coast_example_writes_a_mesh_meshio_reads_back(tmp_path):
    run = run_example("coast_to_meshio.py", str(tmp_path))
    assert run.returncode == 0, run.stderr
    import meshio
    import numpy as np
    back = meshio.read(tmp_path / "bay.vtu")
    triangles = back.cells_dict["triangle"]
    count = int(re.search(r"<madd.Mesh: (\d+) triangles", run.stdout).group(1))
    assert len(triangles) == count
    p = back.points[:, :2]
    a, b, c = p[triangles[:, 0]], p[triangles[:, 1]], p[triangles[:, 2]]
    assert (np.cross(b - a, c - a) > 0).all()  # counter-clockwise, none degenerate
    assert (tmp_path / "bay.png").stat().st_size > 10000
    first = (tmp_path / "bay.14").read_text().splitlines()[1].split()
    assert int(first[0]) == count  # NE of the fort.14


@pytest.mark.skipif(importlib.util.find_spec("dolfinx") is None, reason="needs FEniCSx (python3-dolfinx)")
def test_the_dolfinx_example_converges_at_second_order():
    run = run_example("poisson_dolfinx.py", "data/key.poly")
    assert run.returncode == 0, run.stdout + run.stderr  # it asserts its L2 rates lie in [1.8, 2.3]
    rates = [float(line.split()[3]) for line in run.stdout.splitlines()[3:5]]
    assert len(rates) == 2 and all(1.8 <= r <= 2.3 for r in rates)
