#!/usr/bin/env python3
"""Draws a madd mesh as SVG: triangles filled by subdomain, thin edges.

    draw_mesh.py PREFIX OUT.svg [--box X0 Y0 X1 Y1] [--width PX] [--edge W]

Reads PREFIX.node ("id x y [attrs] [marker]") and PREFIX.ele
("id a b c k": the one attribute k is the subdomain), as `madd mesh -o PREFIX`
writes them. Each subdomain gets a colour of a fixed palette that no
subdomain touching it has (greedy, in index order; --by-index:
PALETTE[k % len]), so a separator shows as a change of colour. --box crops to a rectangle in mesh
coordinates (the triangles meeting it are drawn, clipped to it). Coordinates
are scaled to a picture --width pixels wide and rounded to 0.1 px (4-5
significant digits), which keeps a picture of 40,000 triangles near 2 MB.
--edge is the stroke width in pixels (default: from the mean triangle size).
Python 3 standard library only.
"""

import argparse
import math
import sys

# Twenty fills, light enough for dark edges to show, neighbours in the list
# far apart in hue.
PALETTE = [
    "#8dd3c7", "#fdb462", "#bebada", "#fb8072", "#80b1d3", "#b3de69",
    "#fccde5", "#ffed6f", "#bc80bd", "#d9b38c", "#66c2a5", "#e5e5e5",
]


def colour_subdomains(triangles, count):
    """Colour index of each subdomain: the least used so far of the colours
    not taken by a subdomain met earlier (in index order) that shares a vertex
    with it, so two subdomains that touch never share a colour while the
    palette lasts, and the palette is spread over the picture."""
    at_vertex = {}
    for a, b, c, k in triangles:
        for v in (a, b, c):
            at_vertex.setdefault(v, set()).add(k)
    touching = {}
    for ks in at_vertex.values():
        for k in ks:
            touching.setdefault(k, set()).update(ks - {k})
    colour, uses = {}, [0] * count
    for k in sorted({t[3] for t in triangles}):
        taken = {colour[j] for j in touching.get(k, ()) if j in colour}
        free = [i for i in range(count) if i not in taken]
        colour[k] = min(free, key=lambda i: (uses[i], i)) if free else k % count
        uses[colour[k]] += 1
    return colour


def data_lines(path):
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                yield line


def read_node(path):
    lines = data_lines(path)
    count = int(next(lines)[0])
    first = None
    points = {}
    for _ in range(count):
        row = next(lines)
        i = int(row[0])
        if first is None:
            first = i
        points[i] = (float(row[1]), float(row[2]))
    return points


def read_ele(path):
    lines = data_lines(path)
    header = next(lines)
    count, per, attrs = int(header[0]), int(header[1]), int(header[2]) if len(header) > 2 else 0
    triangles = []
    for _ in range(count):
        row = next(lines)
        a, b, c = int(row[1]), int(row[2]), int(row[3])
        k = int(float(row[1 + per])) if attrs > 0 else 0
        triangles.append((a, b, c, k))
    return triangles


def fmt(v):
    s = "%.1f" % v
    if s.endswith(".0"):
        s = s[:-2]
    return "0" if s == "-0" else s


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("prefix")
    ap.add_argument("out")
    ap.add_argument("--box", nargs=4, type=float, metavar=("X0", "Y0", "X1", "Y1"))
    ap.add_argument("--width", type=float, default=1000.0)
    ap.add_argument("--edge", type=float, default=None)
    ap.add_argument("--by-index", action="store_true")
    args = ap.parse_args(argv)

    points = read_node(args.prefix + ".node")
    triangles = read_ele(args.prefix + ".ele")
    # Coloured on the whole mesh, so a crop has the colours of the full picture.
    if args.by_index:
        colour = {k: k % len(PALETTE) for k in {t[3] for t in triangles}}
    else:
        colour = colour_subdomains(triangles, len(PALETTE))

    if args.box:
        x0, y0, x1, y1 = args.box
        x0, x1 = min(x0, x1), max(x0, x1)
        y0, y1 = min(y0, y1), max(y0, y1)

        def meets(t):
            xs = [points[v][0] for v in t[:3]]
            ys = [points[v][1] for v in t[:3]]
            return max(xs) >= x0 and min(xs) <= x1 and max(ys) >= y0 and min(ys) <= y1

        triangles = [t for t in triangles if meets(t)]
    else:
        used = {v for t in triangles for v in t[:3]}
        xs = [points[v][0] for v in used]
        ys = [points[v][1] for v in used]
        x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    if not triangles:
        sys.exit("no triangles to draw")

    scale = args.width / (x1 - x0)
    width = args.width
    height = (y1 - y0) * scale
    margin = 2.0

    def xy(v):
        x, y = points[v]
        return fmt((x - x0) * scale + margin) + " " + fmt((y1 - y) * scale + margin)

    if args.edge is None:
        area = 0.0
        for a, b, c, _ in triangles:
            (ax, ay), (bx, by), (cx, cy) = points[a], points[b], points[c]
            area += abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2
        mean_side = math.sqrt(area / len(triangles)) * scale
        edge = max(0.05, min(1.0, 0.06 * mean_side))
    else:
        edge = args.edge

    by_subdomain = {}
    for a, b, c, k in triangles:
        by_subdomain.setdefault(k, []).append("M" + xy(a) + "L" + xy(b) + "L" + xy(c) + "Z")

    out = []
    w, h = width + 2 * margin, height + 2 * margin
    out.append('<svg xmlns="http://www.w3.org/2000/svg" width="%s" height="%s" viewBox="0 0 %s %s">'
               % (fmt(w), fmt(h), fmt(w), fmt(h)))
    out.append('<rect width="100%" height="100%" fill="#ffffff"/>')
    if args.box:
        out.append('<clipPath id="box"><rect x="%s" y="%s" width="%s" height="%s"/></clipPath>'
                   % (fmt(margin), fmt(margin), fmt(width), fmt(height)))
        out.append('<g clip-path="url(#box)" stroke="#333333" stroke-width="%s" stroke-linejoin="round">'
                   % ("%.3g" % edge))
    else:
        out.append('<g stroke="#333333" stroke-width="%s" stroke-linejoin="round">' % ("%.3g" % edge))
    for k in sorted(by_subdomain):
        out.append('<path fill="%s" d="%s"/>' % (PALETTE[colour[k]], "".join(by_subdomain[k])))
    out.append("</g>")
    out.append("</svg>")
    with open(args.out, "w") as f:
        f.write("\n".join(out) + "\n")
    print("%s: %d triangles, %d subdomains, edge %.3g px" % (args.out, len(triangles), len(by_subdomain), edge))


if __name__ == "__main__":
    main(sys.argv[1:])
