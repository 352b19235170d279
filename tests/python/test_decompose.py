"""madd.decompose, madd.triangulate and madd.partition."""
import itertools

import numpy as np
import pytest

import madd
from mesh_checks import check_decomposition, domain_area, edge_counts, signed_areas


def test_decompose_square_with_hole(square_with_hole):
    dec = madd.decompose(square_with_hole, 4)
    check_decomposition(dec, 0.75, 4, 60.0)
    # the input's points are kept, in order
    assert np.array_equal(dec.points[:8], square_with_hole.points)
    # boundary pieces keep their input segment's marker
    origin = np.asarray(dec.segment_origin)
    kept = origin >= 0
    assert np.array_equal(dec.markers[kept], square_with_hole.markers[origin[kept]])


@pytest.mark.parametrize("name,n,phi", [("key.poly", 2, 60), ("key.poly", 8, 60), ("key.poly", 17, 75),
                                        ("pipe.poly", 12, 60), ("spiral.poly", 9, 60), ("comb.poly", 7, 45)])
def test_decompose_files(data, name, n, phi):
    d = madd.read_domain(str(data / name))
    dec = madd.decompose(d, n, separator_angle_deg=phi, threads=2)
    smallest = check_decomposition(dec, domain_area(d), n, phi)
    assert dec.metrics()["angle_min"] == pytest.approx(smallest, abs=1e-6)
    assert dec.metrics()["subdomains"] == n
    assert dec.separator_angle_deg == phi


def test_decompose_threads_and_seed(data):
    d = madd.read_domain(str(data / "pipe.poly"))
    a = madd.decompose(d, 16, threads=1)
    b = madd.decompose(d, 16, threads=2)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.segments, b.segments)
    assert [list(map(list, s["rings"])) for s in a.subdomains] == [list(map(list, s["rings"])) for s in b.subdomains]


def test_decompose_with_max_area_splits_segments(square_with_hole):
    plain = madd.decompose(square_with_hole, 4)
    split = madd.decompose(square_with_hole, 4, max_area=0.001)
    check_decomposition(split, 0.75, 4)
    assert len(split.segments) > len(plain.segments)
    # every piece is short enough for a triangle of that area: an equilateral
    # triangle of area 0.001 has sides sqrt(4 * 0.001 / sqrt(3))
    p = split.points
    lengths = np.linalg.norm(p[split.segments[:, 0]] - p[split.segments[:, 1]], axis=1)
    assert lengths.max() <= 2 * np.sqrt(4 * 0.001 / np.sqrt(3))


def test_shapely_round_trip():
    from shapely.geometry import Polygon
    from shapely.ops import unary_union
    poly = Polygon([(0, 0), (5, 0), (5, 3), (2, 4), (0, 3)], [[(1, 1), (1, 2), (2, 2), (2, 1)],
                                                               [(3, 1), (4, 1.5), (3, 2)]])
    d = madd.Domain.from_shapely(poly)
    dec = madd.decompose(d, 4)
    check_decomposition(dec, poly.area, 4)
    pieces = dec.to_shapely()
    assert len(pieces) == 4
    assert all(p.is_valid and p.area > 0 for p in pieces)
    assert sum(p.area for p in pieces) == pytest.approx(poly.area, rel=1e-12)
    assert unary_union(pieces).symmetric_difference(poly).area < 1e-9 * poly.area
    for a, b in itertools.combinations(pieces, 2):
        assert a.intersection(b).area < 1e-12 * poly.area


def test_multipolygon_touching_at_a_vertex_is_bad_input():
    # Two squares sharing the corner (1, 1): madd takes them for two parts
    # (madd check: "the domain has 2 disconnected parts"), so decompose must
    # refuse them as bad input, naming the ids.
    from shapely.geometry import MultiPolygon, box
    mp = MultiPolygon([box(0, 0, 1, 1), box(1, 1, 2, 2)])
    assert mp.is_valid
    with pytest.raises(madd.BadInput) as e:
        madd.decompose(madd.Domain.from_shapely(mp), 4)
    assert e.value.ids


def test_multipolygon_of_disjoint_parts_refused_by_decompose_only():
    from shapely.geometry import MultiPolygon, box
    mp = MultiPolygon([box(0, 0, 1, 1), box(2, 0, 3, 1)])
    d = madd.Domain.from_shapely(mp)  # a valid PSLG
    assert d.summary()["parts"] == 2
    tri = madd.triangulate(d)  # any PSLG triangulates
    assert signed_areas(tri.points, tri.triangles).sum() == pytest.approx(2.0)
    with pytest.raises(madd.BadInput) as e:
        madd.decompose(d, 2)
    assert e.value.problem == "disconnected domain"


def in_circle(points, triangles, others):
    """For each triangle, whether any of `others` lies strictly inside its circumcircle."""
    p = np.asarray(points, float)
    a, b, c = (p[triangles[:, k]][:, None, :] for k in range(3))
    d = np.asarray(others, float)[None, :, :]
    m = np.stack([a - d, b - d, c - d], axis=2)  # (M, N, 3, 2)
    lift = (m ** 2).sum(axis=3)
    det = (m[..., 0, 0] * (m[..., 1, 1] * lift[..., 2] - lift[..., 1] * m[..., 2, 1])
           - m[..., 0, 1] * (m[..., 1, 0] * lift[..., 2] - lift[..., 1] * m[..., 2, 0])
           + lift[..., 0] * (m[..., 1, 0] * m[..., 2, 1] - m[..., 1, 1] * m[..., 2, 0]))
    scale = np.abs(m).max() ** 4
    return det > 1e-12 * scale


def test_triangulate_random_points_is_delaunay_over_the_hull():
    from shapely.geometry import MultiPoint
    rng = np.random.default_rng(20240607)
    pts = rng.random((400, 2))
    tri = madd.triangulate(pts)
    t = np.asarray(tri.triangles)
    assert tri.verify() == []
    assert np.array_equal(tri.points, pts)
    a = signed_areas(pts, t)
    assert (a > 0).all()
    hull = MultiPoint([tuple(x) for x in pts]).convex_hull
    assert a.sum() == pytest.approx(hull.area, rel=1e-12)
    h = len(hull.exterior.coords) - 1
    assert len(t) == 2 * len(pts) - 2 - h  # every point used, general position
    assert not in_circle(pts, t, pts).any()
    edges, counts = edge_counts(t)
    assert counts.max() == 2 and (counts == 1).sum() == h


def test_triangulate_pslg_keeps_the_segments(data):
    d = madd.read_domain(str(data / "key.poly"))
    tri = madd.triangulate(d)
    assert tri.verify() == []
    assert len(tri.points) == len(d.points)
    t = np.asarray(tri.triangles)
    assert signed_areas(tri.points, t).sum() == pytest.approx(domain_area(d), rel=1e-9)
    edges = set(map(tuple, np.sort(np.concatenate([t[:, [1, 2]], t[:, [2, 0]], t[:, [0, 1]]]), axis=1).tolist()))
    for a, b in np.sort(d.segments, axis=1).tolist():
        assert (a, b) in edges
    # segment_of names, for each triangle edge, the input segment it lies on
    so = np.asarray(tri.segment_of)
    for i, k in zip(*np.nonzero(so >= 0)):
        ends = sorted((int(t[i, (k + 1) % 3]), int(t[i, (k + 2) % 3])))
        assert ends == sorted(d.segments[so[i, k]].tolist())
    assert (so >= 0).sum() == len(d.segments)  # each boundary segment, seen from its one triangle
    # convex_hull: the whole hull but the holes
    from shapely.geometry import LineString, MultiPoint, Point
    from shapely.ops import polygonize, unary_union
    p = d.points
    faces = list(polygonize(unary_union([LineString([p[a], p[b]]) for a, b in d.segments])))
    hole_area = sum(f.area for f in faces if any(f.contains(Point(h)) for h in d.holes))
    assert hole_area > 0
    hull = madd.triangulate(d, convex_hull=True)
    assert hull.verify() == []
    assert signed_areas(hull.points, hull.triangles).sum() == pytest.approx(
        MultiPoint([tuple(x) for x in p]).convex_hull.area - hole_area, rel=1e-9)


def test_triangulate_region_attributes():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0], [0.5, 1]], float)
    d = madd.Domain(pts, [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]],
                    regions=[[0.25, 0.5, 7, 0], [0.75, 0.5, 9, 0]])
    tri = madd.triangulate(d, region_attributes=True)
    c = tri.points[tri.triangles].mean(axis=1)
    assert np.array_equal(np.asarray(tri.attributes).ravel() == 7, c[:, 0] < 0.5)


CROSS = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 3\n6 2 4\n0\n"


def test_crossing_segments_are_refused_without_resolve_crossings(tmp_path):
    path = tmp_path / "cross.poly"  # the unit square and both its diagonals
    path.write_text(CROSS)
    with pytest.raises(madd.BadInput) as e:
        madd.triangulate(str(path))
    assert e.value.problem == "segments intersect" and e.value.line > 0


def test_triangulate_resolve_crossings(tmp_path, cli):
    import subprocess
    path = tmp_path / "cross.poly"
    path.write_text(CROSS)
    subprocess.run([cli, "triangulate", str(path), "--resolve-crossings", "-o", str(tmp_path / "cli")], check=True,
                   capture_output=True)
    tri = madd.triangulate(str(path), resolve_crossings=True)
    assert tri.verify() == []
    assert len(tri.points) == 5 and np.allclose(tri.points[4], [0.5, 0.5])
    assert len(tri) == 4
    assert signed_areas(tri.points, tri.triangles).sum() == pytest.approx(1.0)
    tri.write(str(tmp_path / "py"))
    for ext in ("node", "ele", "neigh", "edge"):
        assert (tmp_path / f"py.{ext}").read_bytes() == (tmp_path / f"cli.{ext}").read_bytes()


def grid_graph(nx, ny):
    """CSR (indptr, indices) of an nx x ny grid graph, each edge from both ends."""
    idx = np.arange(nx * ny).reshape(ny, nx)
    e = np.concatenate([np.c_[idx[:, :-1].ravel(), idx[:, 1:].ravel()], np.c_[idx[:-1, :].ravel(), idx[1:, :].ravel()]])
    e = np.concatenate([e, e[:, ::-1]])
    e = e[np.lexsort((e[:, 1], e[:, 0]))]
    indptr = np.searchsorted(e[:, 0], np.arange(nx * ny + 1))
    return indptr, e[:, 1], e


def test_partition_grid_into_4():
    indptr, indices, e = grid_graph(24, 20)
    n = 24 * 20
    p = madd.partition((indptr, indices), 4, edge_weights=np.ones(len(indices)))
    part = np.asarray(p.part)
    assert part.shape == (n,) and part.min() == 0 and part.max() == 3
    sizes = np.bincount(part, minlength=4)
    assert (sizes > 0).all()
    assert sizes.max() <= 1.03 * n / 4 + 1 and sizes.min() >= 0.97 * n / 4 - 1
    assert np.array_equal(p.part_weights, sizes)
    cut = (part[e[:, 0]] != part[e[:, 1]]).sum() / 2
    assert p.cut == cut
    # a good partition of a grid: about 2 x 24 + 20 edges cut; far below a random one
    assert cut <= 2 * (24 + 20)


def test_partition_connected_and_seeded():
    indptr, indices, e = grid_graph(16, 16)
    w = np.ones(len(indices))
    a = madd.partition((indptr, indices), 4, edge_weights=w, seed=3, connected=True)
    b = madd.partition((indptr, indices), 4, edge_weights=w, seed=3, connected=True)
    assert np.array_equal(a.part, b.part)
    part = np.asarray(a.part)
    for k in range(4):  # each part connected: a flood fill inside it reaches all of it
        members = np.flatnonzero(part == k)
        seen = {members[0]}
        todo = [members[0]]
        while todo:
            v = todo.pop()
            for u in indices[indptr[v]:indptr[v + 1]]:
                if part[u] == k and u not in seen:
                    seen.add(u)
                    todo.append(u)
        assert len(seen) == len(members)


def test_partition_vertex_weights():
    indptr, indices, e = grid_graph(20, 10)
    vw = np.where(np.arange(200) % 20 < 10, 3.0, 1.0)  # left half 3 times heavier
    p = madd.partition((indptr, indices), 2, vertex_weights=vw, edge_weights=np.ones(len(indices)))
    weights = np.bincount(p.part, weights=vw, minlength=2)
    assert np.allclose(p.part_weights, weights)
    assert abs(weights[0] - weights[1]) <= 0.03 * vw.sum() + 3


def test_partition_scipy_matrix():
    sparse = pytest.importorskip("scipy.sparse")
    indptr, indices, e = grid_graph(12, 12)
    a = sparse.csr_matrix((np.ones(len(indices)), indices, indptr), shape=(144, 144))
    p = madd.partition(a, 4)
    part = np.asarray(p.part)
    assert (np.bincount(part, minlength=4) > 0).all()
    assert p.cut == (part[e[:, 0]] != part[e[:, 1]]).sum() / 2


def test_partition_default_edge_weights_are_one():
    # the path 0-1-2-3-4: any 2-way split cuts one edge of weight 1
    indptr = np.array([0, 1, 3, 5, 7, 8])
    indices = np.array([1, 0, 2, 1, 3, 2, 4, 3])
    p = madd.partition((indptr, indices), 2)
    assert p.cut == 1.0
    indptr, indices, e = grid_graph(20, 20)
    p = madd.partition((indptr, indices), 4)
    part = np.asarray(p.part)
    assert p.cut == (part[e[:, 0]] != part[e[:, 1]]).sum() / 2
