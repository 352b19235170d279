"""The Python module's overhead (issue 25's target: within 5% of the C++ call).

Alternates, RUNS times each, the C++ call (madd_bench mesh: mesh_with_report
on a domain read before the clock starts) and the same call from Python
(madd.mesh on a madd.Domain read before the clock starts, the result's
points, triangles and subdomain arrays taken), with the same options, and
prints both medians and their ratio. Run on a quiet machine:

  PYTHONPATH=build/python /usr/bin/python3 tests/bench/python_overhead.py build/tests/madd_bench data/pipe.poly \
      -n 64 -q 30 -a 0.00025 -j 2 --runs 7
"""
import argparse
import re
import statistics
import subprocess
import time

import madd


def cxx_seconds(bench, path, args):
    out = subprocess.run([bench, "mesh", path, "-n", str(args.n), "-q", str(args.q), "-a", str(args.a),
                          "-j", str(args.j), "--runs", "1"], check=True, capture_output=True, text=True).stdout
    row = [line for line in out.splitlines() if re.match(r"^\S+\s+\d+\s+\d+\s+[\d.]+", line)][0].split()
    return int(row[2]), float(row[3])


def python_seconds(domain, args):
    start = time.perf_counter()
    m = madd.mesh(domain, args.n, q=args.q, max_area=args.a, threads=args.j)
    arrays = (m.points, m.triangles, m.subdomain)
    seconds = time.perf_counter() - start
    count = len(arrays[1])
    del arrays, m  # freed outside the clock, as the C++ side frees its mesh
    return count, seconds


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("bench")
    p.add_argument("domain")
    p.add_argument("-n", type=int, default=64)
    p.add_argument("-q", type=float, default=30)
    p.add_argument("-a", type=float, default=0.00025)
    p.add_argument("-j", type=int, default=2)
    p.add_argument("--runs", type=int, default=7)
    args = p.parse_args()
    domain = madd.read_domain(args.domain)
    cxx, py = [], []
    for _ in range(args.runs):
        n_cxx, t = cxx_seconds(args.bench, args.domain, args)
        cxx.append(t)
        n_py, t = python_seconds(domain, args)
        py.append(t)
        if n_cxx != n_py:
            raise SystemExit(f"the two calls made different meshes: {n_cxx} and {n_py} triangles")
    c, q = statistics.median(cxx), statistics.median(py)
    print(f"{args.domain}: {n_py} triangles, -n {args.n} -q {args.q} -a {args.a} -j {args.j}, {args.runs} alternating runs")
    print(f"C++ mesh_with_report  median {c:.3f} s  (runs {', '.join(f'{x:.3f}' for x in cxx)})")
    print(f"Python madd.mesh      median {q:.3f} s  (runs {', '.join(f'{x:.3f}' for x in py)})")
    print(f"Python / C++          {q / c:.3f}")


if __name__ == "__main__":
    main()
