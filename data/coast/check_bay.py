#!/usr/bin/env python3
"""Checks data/coast/bay.geojson (made by generate.py) with shapely: the
islands lie in the sea and neither overlap nor cross each other or the
coast, except the intended single-vertex touches; the sea with its islands
is a valid polygon (OGC: rings may touch at single points); the lake lies
on land. Needs shapely (python3 -m pip install shapely, or Debian's
python3-shapely); not run by the tests. Prints what it found; exits 1 on a
failed check."""
import json
import os
import sys
from itertools import combinations

from shapely.geometry import LineString, Polygon

HERE = os.path.dirname(os.path.abspath(__file__))


def fail(message):
    print("FAILED:", message)
    sys.exit(1)


def main():
    with open(os.path.join(HERE, "bay.geojson"), encoding="utf-8") as f:
        doc = json.load(f)
    features = doc["features"]
    kinds = [f["geometry"]["type"] if f["geometry"] else None for f in features]
    if kinds != ["Polygon", "Polygon", "LineString", None]:
        fail(f"feature geometry types {kinds}")
    rings = features[0]["geometry"]["coordinates"]
    outer = Polygon(rings[0])
    if not outer.exterior.is_ccw:
        fail("the sea's outer ring is not counter-clockwise")
    islands = [Polygon(r) for r in rings[1:]]
    for k, island in enumerate(islands):
        if not island.is_valid:
            fail(f"island {k} is not a valid polygon")
        if not outer.covers(island):
            fail(f"island {k} is not in the sea")
    # Pairs that meet: exactly the intended touching pairs, at one shared vertex.
    touching = []
    for i, j in combinations(range(len(islands)), 2):
        if islands[i].intersects(islands[j]):
            meet = islands[i].intersection(islands[j])
            if meet.geom_type != "Point" or tuple(meet.coords[0]) not in set(map(tuple, rings[1 + i])):
                fail(f"islands {i} and {j} meet in {meet.geom_type}")
            touching.append((i, j))
    if len(touching) != 3:
        fail(f"{len(touching)} touching pairs, expected 3: {touching}")
    boundary = LineString(rings[0])
    on_coast = [k for k, island in enumerate(islands) if island.intersects(boundary)]
    if len(on_coast) != 1:
        fail(f"islands meeting the coast: {on_coast}, expected one")
    meet = islands[on_coast[0]].intersection(boundary)
    if meet.geom_type != "Point" or list(meet.coords[0]) not in rings[0]:
        fail(f"the coast-touching island meets the coast in {meet.geom_type}")
    sea = Polygon(rings[0], rings[1:])
    if not sea.is_valid:
        from shapely.validation import explain_validity
        fail("the sea is not a valid polygon: " + explain_validity(sea))
    lake = Polygon(features[1]["geometry"]["coordinates"][0])
    if lake.intersects(sea) or features[1]["properties"].get("marker") != 3:
        fail("the lake meets the sea, or has no marker 3")
    clockwise = sum(1 for r in rings[1:] if not Polygon(r).exterior.is_ccw)
    duplicates = sum(1 for r in rings[1:] if any(r[k] == r[k + 1] for k in range(len(r) - 1)))
    specks = sum(1 for island in islands if island.area * 111000 * 80500 < 100)
    print(f"ok: {len(islands)} islands ({clockwise} clockwise, {len(islands) - clockwise} counter-clockwise), "
          f"{specks} specks under 100 m2, {duplicates} with consecutive duplicates, touching pairs {touching}, "
          f"island {on_coast[0]} touches the coast at {meet.coords[0]}; sea area {sea.area:.6f} deg2")


if __name__ == "__main__":
    main()
