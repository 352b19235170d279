"""madd: Medial Axis Domain Decomposition and parallel quality meshing in 2D.

Three lines from a shapely polygon to a mesh in numpy arrays::

    import madd
    m = madd.mesh(madd.Domain.from_shapely(polygon), 16, q=30, max_area=0.01)
    m.points, m.triangles, m.subdomain        # (N, 2) float64, (M, 3) int32, (M,) int32

The compiled core (madd._madd) does the work with the GIL released; this
module adds the conversions from and to shapely and meshio, which are
imported only when used. docs/python.md has the whole API.
"""
import numpy as _np

from . import _madd
from ._madd import (  # noqa: F401
    BadInput,
    Decomposition,
    DecompositionError,
    Domain,
    Error,
    InternalError,
    LimitError,
    Mesh,
    OptionError,
    OutputError,
    Partition,
    Projection,
    Triangulation,
    __version__,
    read_domain,
)

__all__ = [
    "BadInput", "Decomposition", "DecompositionError", "Domain", "Error", "InternalError", "LimitError", "Mesh",
    "OptionError", "OutputError", "Partition", "Projection", "Triangulation", "coast_domain", "decompose", "mesh",
    "partition", "read_domain", "triangulate",
]


# ---- shapely in ----

def _polygons_of(geometry):
    """The polygons of a shapely Polygon or MultiPolygon (or anything with
    __geo_interface__ holding them), as (outer, [holes]) coordinate arrays."""
    if hasattr(geometry, "geoms"):
        parts = list(geometry.geoms)
    elif hasattr(geometry, "exterior"):
        parts = [geometry]
    else:
        raise TypeError(f"expected a shapely Polygon or MultiPolygon, got {type(geometry).__name__}")
    out = []
    for p in parts:
        if not hasattr(p, "exterior"):
            raise TypeError(f"expected polygons only, got a {type(p).__name__}")
        if p.is_empty:
            continue
        rings = [_np.asarray(p.exterior.coords, dtype=float)[:, :2]]
        rings += [_np.asarray(r.coords, dtype=float)[:, :2] for r in p.interiors]
        out.append(rings)
    return out


def _hole_point(ring, polygon_parts):
    """A point strictly inside the hole bounded by `ring` and in none of the
    polygons (islands) inside that hole."""
    from shapely.geometry import Polygon
    hole = Polygon(ring)
    for part in polygon_parts:
        if hole.contains(part):
            hole = hole.difference(part)
    p = hole.representative_point()
    return p.x, p.y


def _from_shapely(geometry, marker=1):
    points, segments, holes = [], [], []
    index = {}  # a point shared by two rings (they touch there) is one vertex

    def vertex(xy):
        key = (float(xy[0]), float(xy[1]))
        if key not in index:
            index[key] = len(points)
            points.append(key)
        return index[key]

    parts = _polygons_of(geometry)
    from shapely.geometry import Polygon
    shapes = [Polygon(rings[0], rings[1:]) for rings in parts]
    for rings in parts:
        for k, ring in enumerate(rings):
            ring = ring[:-1] if len(ring) > 1 and (ring[0] == ring[-1]).all() else ring
            ids = [vertex(p) for p in ring]
            segments.extend((ids[i], ids[(i + 1) % len(ids)]) for i in range(len(ids)))
            if k > 0:
                holes.append(_hole_point(rings[k], shapes))
    count = len(segments)
    return Domain(_np.asarray(points, dtype=float).reshape(-1, 2), _np.asarray(segments, dtype=_np.int64).reshape(-1, 2),
                  holes=_np.asarray(holes, dtype=float).reshape(-1, 2), markers=_np.full(count, marker))


def _domain_from_shapely(geometry, marker=1):
    """Domain.from_shapely(geometry, marker=1) -> Domain

    A shapely Polygon or MultiPolygon as it is: every ring a closed chain of
    segments with `marker`, a hole point inside every interior ring (outside
    any polygon nested in it), a point where rings touch one vertex.
    Coordinates are used as given (no projection, no cleaning: see
    madd.coast_domain for real coastlines, which also keeps one water body
    of several). decompose and mesh need one connected domain: a
    MultiPolygon whose parts touch at a vertex only is refused
    (madd.BadInput names the ids)."""
    return _from_shapely(geometry, marker)


Domain.from_shapely = staticmethod(_domain_from_shapely)


def coast_domain(geometry, lonlat=True, **options):
    """coast_domain(geometry, lonlat=True, **options) -> Domain

    Water polygons (a shapely Polygon/MultiPolygon, e.g. read with geopandas)
    as a coastal domain, as `madd mesh` makes one of a GeoJSON file: cut to
    `clip` (x0, y0, x1, y1; its sides become open boundary, marker 2),
    cleaned (duplicate vertices, spikes, crossings, touching rings, islands
    below min_island_area square metres), the water body holding `water_at`
    (else the largest) kept, and with lonlat=True projected to metres about
    its centre (the Domain's `projection` maps back). Keywords as
    `madd check`: clip, water_at, min_island_area, min_edge_length (hmin:
    islands below 4 hmin^2 are removed unless min_island_area is given)."""
    polygons = [(rings[0], rings[1:], 1) for rings in _polygons_of(geometry)]
    return _madd._coast_from_polygons(polygons, lonlat, **options)


def _domain_argument(domain):
    if hasattr(domain, "exterior") or hasattr(domain, "geoms"):
        return _from_shapely(domain)
    return domain


# ---- the runs ----

def mesh(domain, n, q=None, max_area=None, threads=0, progress=None, **options):
    return _madd.mesh(_domain_argument(domain), n, q, max_area, threads, progress, **options)


def decompose(domain, n, progress=None, **options):
    return _madd.decompose(_domain_argument(domain), n, progress, **options)


def triangulate(domain_or_points, **options):
    return _madd.triangulate(_domain_argument(domain_or_points), **options)


def partition(graph, k, vertex_weights=None, edge_weights=None, **options):
    """partition(graph, k, vertex_weights=None, edge_weights=None, *, seed=1,
    connected=False, balance_tolerance=0.03) -> Partition

    graph: a scipy.sparse matrix (its pattern; its values as edge weights
    unless edge_weights is given) or an (indptr, indices) pair, each edge
    listed from both ends. A k-way partition by recursive multilevel
    bisection, as `madd partition` (gpmetis -ptype=rb)."""
    if hasattr(graph, "tocsr"):
        csr = graph.tocsr()
        indptr, indices = csr.indptr, csr.indices
        if edge_weights is None and csr.data is not None and len(csr.data) == len(indices):
            edge_weights = _np.asarray(csr.data, dtype=float)
    else:
        indptr, indices = graph
    return _madd.partition(indptr, indices, k, vertex_weights, edge_weights, **options)


mesh.__doc__ = _madd.mesh.__doc__
decompose.__doc__ = _madd.decompose.__doc__
triangulate.__doc__ = _madd.triangulate.__doc__


# ---- meshio and shapely out ----

def _mesh_to_meshio(self):
    """Mesh.to_meshio() -> meshio.Mesh

    The mesh as a meshio.Mesh (points with z = 0 dropped to 2D as meshio
    keeps them, one "triangle" cell block, cell data "subdomain" and, with
    regions, "attribute"; point data "marker"), for every format meshio
    writes (.xdmf for FEniCS, .msh, .vtu, .med...)."""
    import meshio
    cell_data = {"subdomain": [_np.asarray(self.subdomain)]}
    if self.attributes is not None:
        cell_data["attribute"] = [_np.asarray(self.attributes)]
    return meshio.Mesh(_np.asarray(self.points), [("triangle", _np.asarray(self.triangles))],
                       point_data={"marker": _np.asarray(self.point_markers)}, cell_data=cell_data)


def _decomposition_to_shapely(self):
    """Decomposition.to_shapely() -> list of shapely Polygons, one per subdomain."""
    from shapely.geometry import Polygon
    points = _np.asarray(self.points)
    out = []
    for s in self.subdomains:
        rings = [points[r] for r in s["rings"]]
        out.append(Polygon(rings[0], rings[1:]))
    return out


def _mesh_plot(self, ax=None, **kwargs):
    """Mesh.plot(ax=None, **tripcolor_options): the triangles coloured by
    subdomain with matplotlib (imported only here); returns the axes."""
    import matplotlib.pyplot as plt
    if ax is None:
        ax = plt.gca()
    p = _np.asarray(self.points)
    kwargs.setdefault("cmap", "tab20")
    kwargs.setdefault("edgecolors", "k")
    kwargs.setdefault("linewidth", 0.1)
    ax.tripcolor(p[:, 0], p[:, 1], _np.asarray(self.triangles), facecolors=_np.asarray(self.subdomain) % 20, **kwargs)
    ax.set_aspect("equal")
    return ax


Mesh.to_meshio = _mesh_to_meshio
Mesh.plot = _mesh_plot
Decomposition.to_shapely = _decomposition_to_shapely
