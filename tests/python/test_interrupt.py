"""Ctrl-C stops a long run: SIGINT to a process inside madd.mesh raises
KeyboardInterrupt there (at the run's next step), with nothing returned."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

LONG_RUN = """
import madd
print("started", flush=True)
try:
    madd.mesh("data/pipe.poly", 64, max_area=0.000005, threads=1)  # minutes: ~10^8 triangles
    print("finished", flush=True)
except KeyboardInterrupt:
    print("interrupted", flush=True)
"""


def test_sigint_stops_a_long_mesh_with_keyboard_interrupt():
    run = subprocess.Popen([sys.executable, "-c", LONG_RUN], cwd=ROOT, env=dict(os.environ), stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
    try:
        assert run.stdout.readline().strip() == "started"
        time.sleep(1.0)  # well inside the run
        run.send_signal(signal.SIGINT)
        out, err = run.communicate(timeout=60)  # a run's step is under a second; a minute is a hang
    finally:
        if run.poll() is None:
            run.kill()
    assert out.strip() == "interrupted", out + err
    assert run.returncode == 0
