#!/usr/bin/python3
"""From a shapely coastline to a meshio file and a picture (docs/python.md).

Reads the bundled bay's water polygon (GeoJSON, lon/lat) with shapely, makes
it a coastal domain (cut to a box whose sides become open boundary,
cleaned, projected to metres), meshes it with a coastal size field on two
threads, writes the mesh with meshio and draws it coloured by subdomain:

    python3 docs/examples/coast_to_meshio.py [OUTPUT_DIR]
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import shapely.geometry

import madd

out = sys.argv[1] if len(sys.argv) > 1 else "."
with open(os.path.join(os.path.dirname(__file__), "..", "..", "data", "coast", "bay.geojson")) as f:
    water = shapely.geometry.shape(json.load(f)["features"][0]["geometry"])

# The box's sides become open boundary (marker 2); islands below 4 hmin^2 go.
domain = madd.coast_domain(water, clip=(-70.0, 43.5, -69.5, 43.9), min_edge_length=100)
mesh = madd.mesh(domain, 16, q=30, threads=2,
                 min_edge_length=100,     # h at the coast, metres (--hmin)
                 max_edge_length=3000,    # --hmax
                 distance_rate=0.15,      # h <= hmin + 0.15 d
                 cells_across=3,          # 3 triangles across every channel
                 size_gradation=0.2)      # neighbours differ by at most 0.2 per metre
assert not mesh.verify()
print(domain.coast_report["islands"], "islands;", mesh)

mesh.to_meshio().write(os.path.join(out, "bay.vtu"))  # or .xdmf, .msh, .med: any format meshio writes
mesh.write_fort14(os.path.join(out, "bay.14"))        # ADCIRC, in lon/lat (the domain's projection maps back)

fig, ax = plt.subplots(figsize=(7, 6))
mesh.plot(ax, linewidth=0.05)
ax.set_title(f"{len(mesh):,} triangles in {mesh.subdomain_count} subdomains")
ax.set_xlabel("x (m)")
ax.set_ylabel("y (m)")
fig.savefig(os.path.join(out, "bay.png"), dpi=80, bbox_inches="tight")
