"""madd.mesh: arrays in, arrays out, and the properties of the mesh."""
import gc
import math

import numpy as np
import pytest

import madd
from mesh_checks import (angles_deg, check_mesh, domain_area, edge_counts, perimeter, signed_areas,
                       small_angle_vertices)


def test_arrays_in_arrays_out(square_with_hole):
    m = madd.mesh(square_with_hole, 4, q=30, max_area=0.01, threads=1)
    assert m.subdomain_count == 4
    check_mesh(m, area=0.75, q=30, max_area=0.01, holes=1, perimeter=6.0)
    assert m.domain is square_with_hole or np.array_equal(m.domain.points, square_with_hole.points)

    p = m.points
    # point markers: 1 on the outer square, 2 on the hole's, 0 inside
    outer = np.isclose(p, 0).any(axis=1) | np.isclose(p, 1).any(axis=1)
    inner = ((np.isclose(p, 0.25) | np.isclose(p, 0.75)).any(axis=1)
             & (p >= 0.25 - 1e-12).all(axis=1) & (p <= 0.75 + 1e-12).all(axis=1))
    expected = np.where(outer, 1, np.where(inner, 2, 0))
    assert np.array_equal(m.point_markers, expected)
    # boundary edges carry their segment's marker
    be = m.boundary_edges
    assert np.array_equal(m.boundary_markers, expected[be[:, 0]])
    assert np.array_equal(m.boundary_markers, expected[be[:, 1]])
    # the constrained edges: the boundary ones and the separators (marker 0),
    # which are interior edges of the mesh
    edges, counts = edge_counts(m.triangles)
    held = dict(zip(map(tuple, edges.tolist()), counts.tolist()))
    for (a, b), marker in zip(np.sort(m.edges, axis=1).tolist(), m.edge_markers.tolist()):
        assert held[(a, b)] == (2 if marker == 0 else 1)
    assert (m.edge_markers == 0).sum() > 0  # 4 subdomains: separators exist
    assert m.attributes is None


@pytest.mark.parametrize("name", ["points", "triangles", "subdomain", "neighbours", "point_markers",
                                  "subdomain_first_triangle", "edges"])
def test_mesh_arrays_are_read_only(square_with_hole, name):
    m = madd.mesh(square_with_hole, 2, max_area=0.05, threads=1)
    a = getattr(m, name)
    assert not a.flags.writeable
    with pytest.raises(ValueError):
        a[0] = 0
    b = a.copy()
    b[0] = 0  # a copy is the caller's


def test_arrays_keep_the_mesh_alive(square_with_hole):
    m = madd.mesh(square_with_hole, 4, max_area=0.001, threads=1)
    t, p, s = m.triangles, m.points, m.subdomain
    expected = (int(np.asarray(t, dtype=np.int64).sum()), float(p.sum()), int(s.sum()), len(t))
    del m
    gc.collect()
    # allocate over the freed memory, were it freed
    junk = [madd.mesh(square_with_hole, 4, max_area=0.002, threads=1) for _ in range(3)]
    del junk
    gc.collect()
    assert (int(np.asarray(t, dtype=np.int64).sum()), float(p.sum()), int(s.sum()), len(t)) == expected
    assert (signed_areas(p, t) > 0).all()


def test_mesh_from_path_domain_and_shapely_agree(data, tmp_path):
    from shapely.geometry import Polygon
    a = madd.mesh(str(data / "key.poly"), 4, q=28, max_area=0.02, threads=1)
    b = madd.mesh(madd.read_domain(str(data / "key.poly")), 4, q=28, max_area=0.02, threads=1)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.triangles, b.triangles)
    poly = Polygon([(0, 0), (2, 0), (2, 1), (0, 1)], [[(0.5, 0.25), (0.5, 0.75), (1.5, 0.75), (1.5, 0.25)]])
    c = madd.mesh(poly, 3, max_area=0.01, threads=1)
    d = madd.mesh(madd.Domain.from_shapely(poly), 3, max_area=0.01, threads=1)
    assert np.array_equal(c.points, d.points) and np.array_equal(c.triangles, d.triangles)
    check_mesh(c, area=poly.area, q=30, max_area=0.01, holes=1, perimeter=poly.length)


@pytest.mark.parametrize("q", [20, 30, 33])
def test_key_quality_and_size(data, q):
    d = madd.read_domain(str(data / "key.poly"))
    m = madd.mesh(d, 8, q=q, max_area=0.01, threads=2)
    small = small_angle_vertices(d.points, d.segments, q)
    check_mesh(m, area=domain_area(d), q=q, max_area=0.01, small_input_angles=small, holes=len(d.holes),
               perimeter=perimeter(d))
    ang = angles_deg(m.points, m.triangles).min(axis=1)
    assert m.metrics()["smallest_angle_deg"] == pytest.approx(ang.min(), abs=1e-9)
    assert m.metrics()["triangles"] == len(m)
    assert m.metrics()["below_bound"] == (ang < q - 1e-9).sum()


def test_small_input_angle_is_the_only_shortfall():
    # a 12 degree wedge: only triangles at its tip may stay below q
    tip = np.radians(12)
    pts = np.array([[0, 0], [2, 0], [2, 2 * np.tan(tip)]])
    d = madd.Domain(pts, [[0, 1], [1, 2], [2, 0]])
    q = 30
    m = madd.mesh(d, 4, q=q, max_area=0.001, threads=1)
    assert small_angle_vertices(d.points, d.segments, q) == {0}
    check_mesh(m, area=2 * np.tan(tip), q=q, max_area=0.001, small_input_angles={0}, holes=0)
    bad = angles_deg(m.points, m.triangles).min(axis=1) < q - 1e-6
    assert bad.sum() >= 1  # the tip's triangle keeps the 12 degree angle
    assert m.shortfall["input_angle"] == bad.sum()
    assert m.shortfall["separator"] == 0 and m.shortfall["precision"] == 0


def test_regions_give_attributes_and_local_max_area():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0], [0.5, 1]], float)
    seg = [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]]
    d = madd.Domain(pts, seg, markers=[1, 1, 2, 2, 2, 1, 3], regions=[[0.25, 0.5, 7, 0], [0.75, 0.5, 9, 0.001]])
    m = madd.mesh(d, 4, max_area=0.01, threads=1)
    check_mesh(m, area=1.0, q=30, max_area=0.01, holes=0)
    centre = m.points[m.triangles].mean(axis=1)
    attr = m.attributes
    assert attr.shape == (len(m),)
    assert np.array_equal(attr == 7, centre[:, 0] < 0.5)
    assert np.array_equal(attr == 9, centre[:, 0] > 0.5)
    assert signed_areas(m.points, m.triangles)[attr == 9].max() <= 0.001
    # the interior segment x = 0.5 is made of mesh edges with its marker 3
    on = np.isclose(m.points[m.edges][:, :, 0], 0.5).all(axis=1)
    assert set(m.edge_markers[on].tolist()) <= {0, 3} and 3 in m.edge_markers[on]


def area_bound_at_centroids(m, f):
    c = m.points[m.triangles].mean(axis=1)
    return signed_areas(m.points, m.triangles) / f(c[:, 0], c[:, 1])


def test_size_function_expression_and_callable(square_with_hole):
    def f(x, y):
        return 0.0005 + 0.005 * x

    a = madd.mesh(square_with_hole, 4, triangle_area_function="0.0005 + 0.005*x", threads=2)
    b = madd.mesh(square_with_hole, 4, triangle_area_function=f, threads=2)
    check_mesh(a, area=0.75, q=30, holes=1)
    assert area_bound_at_centroids(a, f).max() <= 1 + 1e-9
    assert np.array_equal(a.points, b.points) and np.array_equal(a.triangles, b.triangles)
    # graded: the small end holds smaller triangles
    ar = signed_areas(a.points, a.triangles)
    cx = a.points[a.triangles].mean(axis=1)[:, 0]
    assert ar[cx < 0.2].mean() < ar[cx > 0.8].mean()


def test_size_samples_array_and_file(square_with_hole, tmp_path):
    def f(x, y):
        return 0.0005 + 0.005 * x

    # samples of a linear function at the corners of a box around the
    # domain: their linear interpolation is the function itself
    s = np.array([[x, y, f(x, y)] for x in (-0.05, 1.1) for y in (-0.1, 1.1)])
    a = madd.mesh(square_with_hole, 4, triangle_area_samples=s, threads=1)
    check_mesh(a, area=0.75, q=30, holes=1)
    assert area_bound_at_centroids(a, f).max() <= 1 + 1e-9
    node = tmp_path / "sizes.node"
    node.write_text("4 2 1 0\n" + "".join(f"{i + 1} {x!r} {y!r} {v!r}\n" for i, (x, y, v) in enumerate(s)))
    b = madd.mesh(square_with_hole, 4, triangle_area_samples=str(node), threads=1)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.triangles, b.triangles)


def test_max_edge_length_bounds_every_triangle(square_with_hole):
    h = 0.05
    m = madd.mesh(square_with_hole, 4, max_edge_length=h, threads=1)
    check_mesh(m, area=0.75, q=30, max_area=math.sqrt(3) / 4 * h * h, holes=1)


def test_coastal_size_field(data):
    hmin, hmax = 200.0, 3000.0
    d = madd.read_domain(str(data / "coast" / "bay.geojson"), clip=(-70.0, 43.5, -69.5, 43.9), min_edge_length=hmin)
    m = madd.mesh(d, 8, min_edge_length=hmin, max_edge_length=hmax, distance_rate=0.15, cells_across=3,
                  size_gradation=0.2, threads=2)
    check_mesh(m, area=d.area, q=30, max_area=math.sqrt(3) / 4 * hmax * hmax,
               small_input_angles=small_angle_vertices(d.points, d.segments, 30), holes=len(d.holes),
               perimeter=perimeter(d))
    assert set(np.unique(m.boundary_markers)) == {1, 2}
    # finer at the coast than in open water: the triangles touching land are
    # smaller on average than the rest
    land = np.isin(m.triangles, np.unique(m.boundary_edges[m.boundary_markers == 1])).any(axis=1)
    ar = signed_areas(m.points, m.triangles)
    assert ar[land].mean() < 0.5 * ar[~land].mean()


@pytest.mark.parametrize("name,n", [("key.poly", 8), ("pipe.poly", 6)])
def test_thread_count_does_not_change_the_mesh(data, name, n):
    d = madd.read_domain(str(data / name))
    area = 2e-4 * d.area
    one = madd.mesh(d, n, max_area=area, threads=1)
    two = madd.mesh(d, n, max_area=area, threads=2)
    for field in ("points", "triangles", "subdomain", "neighbours", "point_markers", "edges", "edge_markers",
                  "boundary_edges", "boundary_markers", "subdomain_first_triangle"):
        assert np.array_equal(getattr(one, field), getattr(two, field)), field
    assert one.report["threads"] == 1 and two.report["threads"] == 2


def test_same_call_same_mesh_and_seed(data):
    d = madd.read_domain(str(data / "key.poly"))
    a = madd.mesh(d, 6, max_area=0.02, threads=2, seed=5)
    b = madd.mesh(d, 6, max_area=0.02, threads=2, seed=5)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.triangles, b.triangles)
    check_mesh(a, area=d.area, q=30, max_area=0.02, holes=len(d.holes))


@pytest.mark.parametrize("options", [dict(balance_by_work=False), dict(off_centres=False), dict(verify=False),
                                     dict(separator_angle_deg=75), dict(q=0)])
def test_options_keep_a_valid_mesh(square_with_hole, options):
    options = dict(options)
    q = options.pop("q", 30)
    m = madd.mesh(square_with_hole, 5, q=q, max_area=0.005, threads=1, **options)
    assert m.subdomain_count == 5
    check_mesh(m, area=0.75, q=q, max_area=0.005, holes=1, perimeter=6.0)


def test_off_centres_give_fewer_triangles(square_with_hole):
    a = madd.mesh(square_with_hole, 4, max_area=0.001, threads=1)
    b = madd.mesh(square_with_hole, 4, max_area=0.001, threads=1, off_centres=False)
    assert len(a) <= len(b)


def test_decomposition_of_the_mesh(square_with_hole):
    m = madd.mesh(square_with_hole, 4, max_area=0.01, threads=1)
    dec = m.decomposition
    assert len(dec) == 4
    assert sum(dec.areas) == pytest.approx(0.75, rel=1e-12)
    # each subdomain's triangles add up to its area
    ar = signed_areas(m.points, m.triangles)
    assert np.allclose(np.bincount(m.subdomain, weights=ar), dec.areas, rtol=1e-9)
    # the decomposition's points come first in the mesh
    assert np.array_equal(m.points[:len(dec.points)], dec.points)


def test_plot(square_with_hole):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    m = madd.mesh(square_with_hole, 3, max_area=0.01, threads=1)
    fig, ax = plt.subplots()
    try:
        assert m.plot(ax) is ax
        assert len(ax.collections) == 1
        assert len(ax.collections[0].get_array()) == len(m)
    finally:
        plt.close(fig)
