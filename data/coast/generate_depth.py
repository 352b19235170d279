#!/usr/bin/env python3
"""Writes the synthetic bay's bathymetry: depth.asc (an Esri ASCII grid) and
depth.xyz (a scatter of the same function). Deterministic, pure python3:

    python3 data/coast/generate_depth.py   # from the repository root

Depth in metres, positive below the datum. The mainland coast is
coast(lon) (the coast of bay.geojson); water lies south of it, where the depth
rises from 2 m at the coast towards 62 m offshore over a scale of 0.08
degrees, with a shoal, a smaller shoal and a trench. On land (north of the
coast) the value is -2 (2 m above the datum) within 0.02 degrees of the coast
and NODATA (-9999) beyond.
"""
import math
import os

LON0, LAT0 = -70.2, 43.3  # the grid's lower left corner
CELL = 0.005  # degrees
COLS, ROWS = 180, 140  # lon [-70.2, -69.3], lat [43.3, 44.0]
NODATA = -9999
SCATTER_POINTS = 300


def coast(lon):
    return (43.80 + 0.030 * math.sin(2 * math.pi * (lon + 70) / 0.21)
            + 0.012 * math.sin(2 * math.pi * (lon + 70) / 0.053 + 1.0))


def bump(lon, lat, lon0, lat0, radius):
    return math.exp(-((lon - lon0) ** 2 + (lat - lat0) ** 2) / (2 * radius * radius))


def trench(lon, lat):
    # 20 m deeper along the line from (-70.15, 43.35) to (-69.35, 43.50),
    # 0.02 degrees wide, fading out towards its ends.
    ax, ay, bx, by = -70.15, 43.35, -69.35, 43.50
    ux, uy = bx - ax, by - ay
    t = ((lon - ax) * ux + (lat - ay) * uy) / (ux * ux + uy * uy)
    if t < 0 or t > 1:
        return 0.0
    d = abs((lon - ax) * uy - (lat - ay) * ux) / math.hypot(ux, uy)
    return 20.0 * math.sin(math.pi * t) * math.exp(-((d / 0.02) ** 2))


def depth(lon, lat):
    """The depth at (lon, lat), or None where there is no data."""
    c = coast(lon)
    if lat < c:
        base = 2 + 60 * (1 - math.exp(-(c - lat) / 0.08))
        return (base - 25 * bump(lon, lat, -69.85, 43.55, 0.04) - 12 * bump(lon, lat, -69.55, 43.65, 0.025)
                + trench(lon, lat))
    if lat - c <= 0.02:
        return -2.0
    return None


def write_grid(path):
    lines = ["ncols %d" % COLS, "nrows %d" % ROWS, "xllcorner %.3f" % LON0, "yllcorner %.3f" % LAT0,
             "cellsize %.3f" % CELL, "NODATA_value %d" % NODATA]
    for i in range(ROWS):  # the north row first
        lat = LAT0 + (ROWS - 1 - i + 0.5) * CELL
        row = []
        for j in range(COLS):
            lon = LON0 + (j + 0.5) * CELL
            d = depth(lon, lat)
            row.append(str(NODATA) if d is None else "%.3f" % d)
        lines.append(" ".join(row))
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def write_scatter(path):
    state = 20240524  # a linear congruential generator (Numerical Recipes' constants)

    def uniform():
        nonlocal state
        state = (1664525 * state + 1013904223) % 2**32
        return state / 2**32

    seen = set()
    lines = ["# Synthetic bay: depth in metres (positive down) at scattered points,",
             "# the function of generate_depth.py (the same as depth.asc).", "lon lat depth"]
    while len(seen) < SCATTER_POINTS:
        lon = round(LON0 + 0.9 * uniform(), 6)
        lat = round(LAT0 + 0.7 * uniform(), 6)
        d = depth(lon, lat)
        if d is None or (lon, lat) in seen:
            continue
        seen.add((lon, lat))
        lines.append("%.6f %.6f %.3f" % (lon, lat, d))
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    write_grid(os.path.join(here, "depth.asc"))
    write_scatter(os.path.join(here, "depth.xyz"))
