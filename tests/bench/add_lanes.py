#!/usr/bin/python3
"""Draws interior constraints across a domain, for checking the decomposition
on real coastlines with lanes (docs/algorithm.md, "Interior segments").

usage: add_lanes.py IN.poly OUT.poly [--lanes K] [--points M] [--seed S]

Adds K shipping lanes (open polylines of three to six vertices, each kept a
margin inside the water, so they cross no shore and no island), K/2 lanes
from a shore vertex straight out into the water, and M isolated survey
points. Needs python3-shapely. Deterministic for a given seed.
"""
import argparse
import math
import random

from shapely.geometry import LineString, Point, Polygon
from shapely.ops import unary_union


def read_poly(path):
    rows = [l.split('#')[0].split() for l in open(path)]
    rows = [r for r in rows if r]
    n, dim, attrs, bm = map(int, rows[0][:4])
    pts = [(float(r[1]), float(r[2])) for r in rows[1:1 + n]]
    base = int(rows[1][0])
    m = int(rows[1 + n][0])
    segs = [(int(r[1]) - base, int(r[2]) - base) for r in rows[2 + n:2 + n + m]]
    h = int(rows[2 + n + m][0])
    holes = [(float(r[1]), float(r[2])) for r in rows[3 + n + m:3 + n + m + h]]
    return pts, segs, holes


def rings(pts, segs):
    nxt = {}
    for a, b in segs:
        nxt.setdefault(a, []).append(b)
        nxt.setdefault(b, []).append(a)
    seen, out = set(), []
    for start in nxt:
        if start in seen:
            continue
        ring, prev, v = [start], None, start
        seen.add(start)
        while True:
            cand = [w for w in nxt[v] if w != prev and (w not in seen or w == start)]
            if not cand:
                break
            w = cand[0]
            if w == start:
                break
            ring.append(w)
            seen.add(w)
            prev, v = v, w
        out.append(ring)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('inp')
    ap.add_argument('out')
    ap.add_argument('--lanes', type=int, default=8)
    ap.add_argument('--points', type=int, default=20)
    ap.add_argument('--seed', type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    pts, segs, holes = read_poly(a.inp)
    polys = [Polygon([pts[i] for i in r]) for r in rings(pts, segs) if len(r) >= 3]
    polys.sort(key=lambda p: -p.area)
    water = polys[0]
    for island in polys[1:]:
        water = water.difference(island)
    minx, miny, maxx, maxy = water.bounds
    size = math.sqrt(water.area)
    margin = size * 2e-3
    inner = water.buffer(-margin)
    new_pts, new_segs = list(pts), list(segs)
    drawn = []

    def clear(line):
        return inner.contains(line) and all(line.distance(d) > margin for d in drawn)

    def add_chain(coords, start=None):
        ids = [] if start is None else [start]
        for c in coords:
            new_pts.append(c)
            ids.append(len(new_pts) - 1)
        for u, v in zip(ids, ids[1:]):
            new_segs.append((u, v))

    tries = 0
    while len([d for d in drawn if d.length > 0]) < a.lanes and tries < 20000:
        tries += 1
        x, y = rng.uniform(minx, maxx), rng.uniform(miny, maxy)
        k = rng.randint(3, 6)
        step = size * rng.uniform(0.02, 0.08)
        heading = rng.uniform(0, 2 * math.pi)
        coords = [(x, y)]
        for _ in range(k - 1):
            heading += rng.uniform(-0.6, 0.6)
            coords.append((coords[-1][0] + step * math.cos(heading), coords[-1][1] + step * math.sin(heading)))
        line = LineString(coords)
        if clear(line):
            drawn.append(line)
            add_chain(coords)
    shore = [i for i in range(len(pts))]
    rng.shuffle(shore)
    made = 0
    for v in shore:
        if made >= a.lanes // 2:
            break
        p = pts[v]
        for _ in range(8):
            heading = rng.uniform(0, 2 * math.pi)
            length = size * rng.uniform(0.01, 0.04)
            end = (p[0] + length * math.cos(heading), p[1] + length * math.sin(heading))
            line = LineString([p, end])
            # Out into the water from the shore vertex only: the rest inside the margin.
            away = LineString([(p[0] + 0.2 * (end[0] - p[0]), p[1] + 0.2 * (end[1] - p[1])), end])
            if water.contains(line.interpolate(0.5, normalized=True)) and clear(away) and \
                    line.intersection(water.boundary).equals(Point(p)):
                drawn.append(line)
                add_chain([end], start=v)
                made += 1
                break
    placed = 0
    while placed < a.points and tries < 40000:
        tries += 1
        q = (rng.uniform(minx, maxx), rng.uniform(miny, maxy))
        if inner.contains(Point(q)) and all(Point(q).distance(d) > margin for d in drawn):
            new_pts.append(q)
            placed += 1
    with open(a.out, 'w') as f:
        f.write(f"# {a.inp.split('/')[-1]} with {len(drawn)} lanes and {placed} survey points (tests/bench/add_lanes.py)\n")
        f.write(f"{len(new_pts)} 2 0 0\n")
        for i, (x, y) in enumerate(new_pts):
            f.write(f"{i + 1} {x!r} {y!r}\n")
        f.write(f"{len(new_segs)} 0\n")
        for i, (u, v) in enumerate(new_segs):
            f.write(f"{i + 1} {u + 1} {v + 1}\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i + 1} {x!r} {y!r}\n")
    print(f"{a.out}: {len(drawn)} lanes, {placed} points")


if __name__ == '__main__':
    main()
