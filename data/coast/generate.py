#!/usr/bin/env python3
"""Writes data/coast/bay.geojson: a synthetic raw coastal file, water
polygons in WGS84 longitude/latitude, the kind a user cuts a box from.

The box to clip for a domain: -70.0,43.5,-69.5,43.9 (lon0, lat0, lon1, lat1).

Feature 0, the sea: one Polygon. Its outer ring (counter-clockwise) runs
along the bottom and the sides of lon [-70.2, -69.3] x lat [43.3, coast],
then along the mainland coast lat = coast(lon) from east to west, sampled
every 0.0005 degrees of longitude, with three narrow fjords cut into the
land. Its holes are about 300 islands (seeded pseudo-random): star-shaped
polygons of 6-20 vertices, 30 m to 1.5 km across in radius, that neither
overlap nor cross each other or the coast, except on purpose:
  - 5 specks of 2-5 m radius;
  - 3 pairs of islands touching at exactly one shared vertex;
  - 1 island touching the coast at exactly one shared vertex (a vertex of
    the coast ring);
  - 1 island with a vertex repeated (consecutive duplicates);
  - the islands' rings are clockwise, except a few counter-clockwise (real
    files get the direction wrong).
Feature 1: a lake north of the coast, on land, with "properties":
{"marker": 3}. Feature 2: a LineString (a ferry route, to be skipped).
Feature 3: "geometry": null.

Coordinates are written with 7 decimals (about 1 cm). Scales: 1 degree of
latitude = 111 km, 1 degree of longitude = 80.5 km (at 43.6 N).

Run from anywhere: python3 data/coast/generate.py (pure python3, no
packages). The output is deterministic; it prints what it wrote.
data/coast/check_bay.py checks the geometry with shapely."""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
M_PER_LON = 80500.0
M_PER_LAT = 111000.0
WEST, EAST, SOUTH = -70.2, -69.3, 43.3
STEP = 0.0005
BOX = (-70.0, 43.5, -69.5, 43.9)
GAP = 25.0  # metres kept between islands, and between islands and the coast


def coast(lon):
    t = lon + 70.0
    return (43.80 + 0.030 * math.sin(2 * math.pi * t / 0.21)
            + 0.012 * math.sin(2 * math.pi * t / 0.053 + 1.0))


def rnd(v):
    return round(v, 7)


def vertex(lon, lat):
    return (rnd(lon), rnd(lat))


def metres(p):
    """Local plane coordinates in metres (x east, y north)."""
    return ((p[0] + 70.0) * M_PER_LON, (p[1] - 43.6) * M_PER_LAT)


def degrees(x, y):
    return vertex(x / M_PER_LON - 70.0, y / M_PER_LAT + 43.6)


def signed_area(ring):
    s = 0.0
    for k in range(len(ring)):
        (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % len(ring)]
        s += x0 * y1 - x1 * y0
    return 0.5 * s


# --- the mainland coast, with fjords -----------------------------------------

# (mouth centre lon, mouth width in samples, length km, meander m)
FJORDS = [(-69.905, 8, 3.0, 120.0), (-69.7615, 6, 4.0, -150.0), (-69.5825, 10, 5.0, 200.0)]


def fjord(east_corner, west_corner, length_km, meander_m):
    """The fjord's banks from the east mouth corner up and round the head
    back down to the west one (both corners excluded): the coast runs east
    to west, so the water goes up the east bank first."""
    (xe, ye), (xw, yw) = metres(east_corner), metres(west_corner)
    half = 0.5 * (xe - xw)
    length = 1000.0 * length_km
    n = int(length / 100.0)
    top = max(ye, yw) + length  # both banks end there, so the head is a half circle
    east, west = [], []
    for k in range(1, n + 1):
        t = k / n
        shift = meander_m * math.sin(math.pi * t) ** 2
        east.append(degrees(xe + shift, ye + t * (top - ye)))
        west.append(degrees(xw + shift, yw + t * (top - yw)))
    # A round head: a half ellipse from the east bank's end to the west one's.
    (xa, ya), (xb, yb) = metres(east[-1]), metres(west[-1])
    cx, cy = 0.5 * (xa + xb), 0.5 * (ya + yb)
    head = [degrees(cx + half * math.cos(math.pi * j / 6), cy + half * math.sin(math.pi * j / 6)) for j in range(1, 6)]
    return east + head + west[::-1]


def coast_line():
    """The coast from east to west: samples of coast(lon), fjords cut in."""
    count = int(round((EAST - WEST) / STEP))
    samples = [vertex(WEST + i * STEP, coast(WEST + i * STEP)) for i in range(count + 1)]
    cuts = {}
    for lon, width, length_km, meander in FJORDS:
        i = int(round((lon - WEST) / STEP))
        lo, hi = i - width // 2, i + width // 2
        cuts[hi] = (lo, fjord(samples[hi], samples[lo], length_km, meander))
    line, i = [], count
    while i >= 0:
        line.append(samples[i])
        if i in cuts:
            lo, banks = cuts[i]
            for p in banks:
                assert p[1] > coast(p[0]) + 1e-4, "a fjord bank dips below the coast"
            line.extend(banks)
            i = lo
        else:
            i -= 1
    return line, samples


# --- distances in metres -----------------------------------------------------

def point_segment(p, a, b):
    (px, py), (ax, ay), (bx, by) = p, a, b
    dx, dy = bx - ax, by - ay
    t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)
    t = max(0.0, min(1.0, t))
    return math.hypot(px - ax - t * dx, py - ay - t * dy)


class Coast:
    """The coast as segments in metres, bucketed by x for quick distances."""

    def __init__(self, line):
        self.segments = [(metres(line[k]), metres(line[k + 1])) for k in range(len(line) - 1)]
        self.bucket = 500.0
        self.buckets = {}
        for s in self.segments:
            lo, hi = sorted((s[0][0], s[1][0]))
            for b in range(int(lo // self.bucket), int(hi // self.bucket) + 1):
                self.buckets.setdefault(b, []).append(s)

    def distance(self, p, reach):
        """Distance from p to the coast, exact when below reach."""
        best = math.inf
        for b in range(int((p[0] - reach) // self.bucket), int((p[0] + reach) // self.bucket) + 1):
            for a, c in self.buckets.get(b, ()):
                best = min(best, point_segment(p, a, c))
        return best


# --- islands -----------------------------------------------------------------

class Islands:
    def __init__(self, rng, coast_metres):
        self.rng = rng
        self.coast = coast_metres
        self.discs = []  # (x, y, r) in metres: every island lies in its disc
        self.rings = []  # clockwise unless made otherwise, open

    def star(self, x, y, r, n, touch_angle=None):
        """n vertices round (x, y) within radius r, angles increasing, so the
        polygon is star-shaped about its centre (hence simple). With
        touch_angle, the vertex there lies on the circle and all others
        within 0.9 r, so the island touches its disc at that vertex only."""
        rng = self.rng
        start = rng.random() * 2 * math.pi if touch_angle is None else touch_angle
        pts = []
        for k in range(n):
            a = start + 2 * math.pi * (k + (0.0 if k == 0 else 0.35 * (rng.random() - 0.5))) / n
            rad = r if (touch_angle is not None and k == 0) else r * (0.55 + 0.35 * rng.random())
            pts.append((x + rad * math.cos(a), y + rad * math.sin(a)))
        return pts  # counter-clockwise

    def free(self, x, y, r):
        """Whether a disc keeps GAP from the box's sides, the coast and every island."""
        lon, lat = x / M_PER_LON - 70.0, y / M_PER_LAT + 43.6
        if (lon - WEST) * M_PER_LON < r + GAP or (EAST - lon) * M_PER_LON < r + GAP:
            return False
        if (lat - SOUTH) * M_PER_LAT < r + GAP or lat > coast(lon):
            return False
        if self.coast.distance((x, y), r + GAP + 1.0) < r + GAP:
            return False
        return all(math.hypot(x - a, y - b) >= r + c + GAP for a, b, c in self.discs)

    def add(self, pts_metres, disc, clockwise=True):
        ring = [degrees(px, py) for px, py in pts_metres]
        if clockwise:
            ring = ring[::-1]
        self.discs.append(disc)
        self.rings.append(ring)
        return ring

    def place(self, r, n, lon_range, lat_depth, tries=2000):
        """A free island of radius r somewhere in lon_range, at most lat_depth
        degrees south of the coast (biased towards the coast)."""
        rng = self.rng
        for _ in range(tries):
            lon = lon_range[0] + (lon_range[1] - lon_range[0]) * rng.random()
            depth = lat_depth * rng.random() ** 2
            x, y = metres((lon, coast(lon) - depth))
            if self.free(x, y, r):
                return self.add(self.star(x, y, r, n), (x, y, r))
        return None


def random_count(rng, lo, hi):
    return lo + int((hi - lo + 1) * rng.random())


def touching_pair(isl, box_lon):
    """Two islands whose discs touch at one point, which is a vertex of both."""
    rng = isl.rng
    for _ in range(2000):
        ra, rb = 80 + 400 * rng.random(), 80 + 400 * rng.random()
        lon = box_lon[0] + (box_lon[1] - box_lon[0]) * rng.random()
        xa, ya = metres((lon, coast(lon) - 0.02 - 0.15 * rng.random()))
        angle = 2 * math.pi * rng.random()
        xb, yb = xa + (ra + rb) * math.cos(angle), ya + (ra + rb) * math.sin(angle)
        # The pair must be free as one disc holding both.
        cx, cy = 0.5 * (xa + xb), 0.5 * (ya + yb)
        if not isl.free(cx, cy, 0.5 * (ra + rb) + max(ra, rb)):
            continue
        a = isl.star(xa, ya, ra, random_count(rng, 6, 20), touch_angle=angle)
        b = isl.star(xb, yb, rb, random_count(rng, 6, 20), touch_angle=angle + math.pi)
        b[0] = a[0]  # the same vertex, bit for bit
        ring_a = isl.add(a, (cx, cy, 0.5 * (ra + rb) + max(ra, rb)))
        ring_b = isl.add(b, (cx, cy, 0.0))
        assert ring_a[-1] == ring_b[-1]  # vertex 0, last after reversing to clockwise
        return
    raise RuntimeError("no room for a touching pair")


def coast_touching(isl, line, samples, box_lon):
    """An island hanging from a coast vertex at a trough of the coast (where
    the coast curves away from the water), touching it there only."""
    i0, i1 = (int(round((lon - WEST) / STEP)) for lon in box_lon)
    for i in range(i0 + 1, i1):
        if not samples[i - 1][1] > samples[i][1] < samples[i + 1][1] or samples[i] not in line:
            continue
        r = 120.0
        px, py = metres(samples[i])
        x, y = px, py - r
        pts = isl.star(x, y, r, 9, touch_angle=math.pi / 2)
        pts[0] = (px, py)
        ring = [degrees(qx, qy) for qx, qy in pts]
        ring[0] = samples[i]
        # Every other vertex keeps GAP from the coast.
        if all(isl.coast.distance(metres(p), GAP + 1.0) >= GAP for p in ring[1:]) and all(
                math.hypot(x - a, y - b) >= r + c + GAP for a, b, c in isl.discs):
            isl.discs.append((x, y, r))
            isl.rings.append(ring[::-1])
            return samples[i]
    raise RuntimeError("no trough for the coast-touching island")


def islands(line, samples):
    rng = random.Random(20240)
    isl = Islands(rng, Coast(line))
    box_lon = (BOX[0] + 0.02, BOX[2] - 0.02)
    touch = coast_touching(isl, line, samples, box_lon)
    for _ in range(3):
        touching_pair(isl, box_lon)
    specks = 0
    while specks < 5:
        if isl.place(2.0 + 3.0 * rng.random(), random_count(rng, 6, 8), box_lon, 0.3):
            specks += 1
    duplicate = isl.place(300.0, 12, box_lon, 0.2)
    k = 4
    duplicate.insert(k, duplicate[k])  # a vertex repeated, as sloppy digitising leaves it
    while len(isl.rings) < 300:
        r = 30.0 * 50.0 ** (rng.random() ** 1.6)  # 30 m .. 1.5 km, mostly small
        lon_range = box_lon if rng.random() < 0.5 else (WEST, EAST)
        isl.place(r, random_count(rng, 6, 20), lon_range, 0.45, tries=50)
    # A few counter-clockwise, as real files have them.
    ccw = [17, 58, 101, 150, 222, 271]
    for k in ccw:
        isl.rings[k] = isl.rings[k][::-1]
    return isl.rings, touch, ccw


# --- the file ----------------------------------------------------------------

def lake():
    cx, cy = metres((-69.68, 43.872))
    ring = [degrees(cx + 900 * math.cos(2 * math.pi * k / 40) * (1 + 0.15 * math.sin(3 * 2 * math.pi * k / 40)),
                    cy + 500 * math.sin(2 * math.pi * k / 40)) for k in range(40)]
    for p in ring:
        assert p[1] > coast(p[0]) + 0.01, "the lake must lie on land"
    return ring


def number(v):
    text = repr(v)
    return text[:-2] if text.endswith(".0") else text


def ring_text(ring):
    closed = ring + [ring[0]]
    return "[" + ",".join(f"[{number(x)},{number(y)}]" for x, y in closed) + "]"


def polygon_text(rings):
    return "[\n" + ",\n".join(ring_text(r) for r in rings) + "\n]"


def main():
    line, samples = coast_line()
    sea = [vertex(WEST, SOUTH), vertex(EAST, SOUTH)] + line
    assert sea[-1] == vertex(WEST, coast(WEST))
    assert signed_area(sea) > 0, "the sea's outer ring must be counter-clockwise"
    holes, touch, ccw = islands(line, samples)
    assert touch in sea
    ferry = [(-69.95, 43.55), (-69.8, 43.62), (-69.62, 43.70)]
    crs = '"crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:OGC:1.3:CRS84"}}'
    features = [
        '{"type":"Feature","properties":{"name":"Baie synth\u00e9tique (synthetic)","kind":"sea"},'
        '"geometry":{"type":"Polygon","coordinates":' + polygon_text([sea] + holes) + '}}',
        '{"type":"Feature","properties":{"name":"lake","marker":3},'
        '"geometry":{"type":"Polygon","coordinates":' + polygon_text([lake()]) + '}}',
        '{"type":"Feature","properties":{"name":"ferry"},'
        '"geometry":{"type":"LineString","coordinates":[' + ",".join(f"[{x!r},{y!r}]" for x, y in ferry) + ']}}',
        '{"type":"Feature","properties":{"name":"unsurveyed"},"geometry":null}',
    ]
    text = ('{"type":"FeatureCollection","name":"bay",' + crs + ',"features":[\n' + ",\n".join(features) + "\n]}\n")
    path = os.path.join(HERE, "bay.geojson")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    n_vertices = len(sea) + sum(len(h) for h in holes)
    print(f"bay.geojson: {len(text.encode())} bytes, 4 features (2 polygons), sea: {len(sea)} outer vertices, "
          f"{len(holes)} holes, {n_vertices} vertices; counter-clockwise holes {ccw}; "
          f"coast-touching vertex {touch}; lake {len(lake())} vertices")


if __name__ == "__main__":
    main()
