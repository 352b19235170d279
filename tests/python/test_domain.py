"""Domains: from arrays, files, shapely and coastlines; read-only views."""
import json

import numpy as np
import pytest

import madd
from mesh_checks import domain_area, perimeter


def test_domain_from_arrays(square_with_hole):
    d = square_with_hole
    assert d.points.shape == (8, 2) and d.points.dtype == np.float64
    assert d.segments.shape == (8, 2) and d.segments.dtype == np.int32
    assert np.array_equal(d.points[:4], [[0, 0], [1, 0], [1, 1], [0, 1]])
    assert np.array_equal(d.segments[4], [4, 5])  # 0-based, as given
    assert np.array_equal(d.markers, [1, 1, 1, 1, 2, 2, 2, 2])
    assert np.array_equal(d.holes, [[0.5, 0.5]])
    assert d.regions.shape[0] == 0
    assert d.path is None and d.coast_report is None
    assert not d.projection.geographic
    d.check()
    assert d.area == pytest.approx(1 - 0.5 ** 2, rel=1e-12)
    assert d.area == pytest.approx(domain_area(d), rel=1e-12)
    s = d.summary()
    assert s["boundary_segments"] == 8 and s["interior_segments"] == 0
    assert s["parts"] == 1 and s["isolated_vertices"] == 0
    assert s["area"] == pytest.approx(0.75)


@pytest.mark.parametrize("name", ["points", "segments", "markers", "holes"])
def test_domain_arrays_are_read_only(square_with_hole, name):
    a = getattr(square_with_hole, name)
    assert not a.flags.writeable
    with pytest.raises(ValueError):
        a[0] = 0


def test_domain_copies_its_inputs():
    points = np.array([[0, 0], [2, 0], [0, 2]], dtype=float)
    segments = np.array([[0, 1], [1, 2], [2, 0]])
    d = madd.Domain(points, segments)
    points[1, 0] = 5.0
    segments[0, 1] = 2
    assert d.points[1, 0] == 2.0 and d.segments[0, 1] == 1
    assert d.area == pytest.approx(2.0)


def test_domain_from_lists_and_other_dtypes():
    pts = [[0, 0], [3, 0], [3, 1], [0, 1]]
    a = madd.Domain(pts, [[0, 1], [1, 2], [2, 3], [3, 0]])
    b = madd.Domain(np.array(pts, dtype=np.float32), np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.uint16))
    assert np.array_equal(a.points, b.points) and np.array_equal(a.segments, b.segments)
    assert a.area == pytest.approx(3.0)


def test_domain_regions_and_point_markers():
    pts = np.array([[0, 0], [2, 0], [2, 1], [0, 1], [1, 0], [1, 1]], float)
    seg = [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]]
    d = madd.Domain(pts, seg, regions=[[0.5, 0.5, 3, 0], [1.5, 0.5, 4, 0.01]], point_markers=[1, 2, 3, 4, 5, 6])
    assert d.regions.shape == (2, 4)
    assert np.array_equal(d.regions[:, 2], [3, 4])
    assert np.array_equal(d.point_markers, [1, 2, 3, 4, 5, 6])
    assert d.summary()["interior_segments"] == 1
    assert d.area == pytest.approx(2.0)


def test_write_poly_round_trip(square_with_hole, tmp_path):
    path = tmp_path / "sq.poly"
    square_with_hole.write_poly(str(path))
    back = madd.read_domain(str(path))
    assert back.path == str(path)
    assert np.array_equal(back.points, square_with_hole.points)
    assert np.array_equal(back.segments, square_with_hole.segments)
    assert np.array_equal(back.markers, square_with_hole.markers)
    assert np.array_equal(back.holes, square_with_hole.holes)
    assert back.area == square_with_hole.area


@pytest.mark.parametrize("name", ["key.poly", "pipe.poly", "l_shape.poly", "spiral.poly"])
def test_read_poly_area(data, name):
    d = madd.read_domain(str(data / name))
    assert d.path == str(data / name)
    d.check()
    assert d.area == pytest.approx(domain_area(d), rel=1e-9)


def test_read_node_file(data):
    d = madd.read_domain(str(data / "l_shape.node"))
    assert len(d.points) > 0 and len(d.segments) == 0


CLIP = (-70.0, 43.5, -69.5, 43.9)


def _water_polygons(path):
    from shapely.geometry import MultiPolygon, shape
    features = json.loads(path.read_text())["features"]
    polys = []
    for f in features:
        g = f["geometry"]
        if g and g["type"] in ("Polygon", "MultiPolygon"):
            s = shape(g)
            polys.extend(getattr(s, "geoms", [s]))
    return MultiPolygon(polys)


def test_geojson_shapefile_and_shapely_give_one_coast(data):
    a = madd.read_domain(str(data / "coast" / "bay.geojson"), clip=CLIP)
    b = madd.read_domain(str(data / "coast" / "bay.shp"), clip=CLIP)
    c = madd.coast_domain(_water_polygons(data / "coast" / "bay.geojson"), clip=CLIP)
    for other in (b, c):
        assert np.array_equal(a.points, other.points)
        assert np.array_equal(a.segments, other.segments)
        assert np.array_equal(a.markers, other.markers)
    assert a.projection.geographic
    # the box's sides are open boundary (marker 2), the rest land (1)
    assert set(np.unique(a.markers)) == {1, 2}
    rep = a.coast_report
    assert rep["open_segments"] == (a.markers == 2).sum()
    assert rep["land_segments"] == (a.markers == 1).sum()
    assert a.area == pytest.approx(domain_area(a), rel=1e-9)
    assert rep["area_m2"] == pytest.approx(a.area, rel=1e-9)
    # back in lon/lat, everything lies in the clip box; open segments on its sides
    ll = a.projection.to_lonlat(a.points)
    assert (ll[:, 0] >= CLIP[0] - 1e-9).all() and (ll[:, 0] <= CLIP[2] + 1e-9).all()
    assert (ll[:, 1] >= CLIP[1] - 1e-9).all() and (ll[:, 1] <= CLIP[3] + 1e-9).all()
    ends = ll[a.segments[a.markers == 2]]  # (k, 2, 2)
    on_side = np.zeros(len(ends), bool)
    for axis, value in ((0, CLIP[0]), (1, CLIP[1]), (0, CLIP[2]), (1, CLIP[3])):
        on_side |= np.isclose(ends[:, :, axis], value, atol=1e-9).all(axis=1)
    assert on_side.all()
    assert np.allclose(a.projection.to_metres(ll), a.points, atol=1e-6)


def test_coast_small_islands_removed(data):
    geometry = _water_polygons(data / "coast" / "bay.geojson")
    full = madd.coast_domain(geometry, clip=CLIP)
    cut = madd.coast_domain(geometry, clip=CLIP, min_island_area=1e6)
    assert len(cut.holes) < len(full.holes)
    assert cut.coast_report["small_islands_removed"] == len(full.holes) - len(cut.holes)
    assert cut.area > full.area  # islands are holes: removing them adds water


def test_from_shapely_polygon_with_hole():
    from shapely.geometry import Point, Polygon
    p = Polygon([(0, 0), (4, 0), (4, 3), (0, 3)], [[(1, 1), (1, 2), (2, 2), (2, 1)]])
    d = madd.Domain.from_shapely(p, marker=7)
    assert len(d.points) == 8 and len(d.segments) == 8
    assert (d.markers == 7).all()
    assert len(d.holes) == 1 and Polygon(p.interiors[0]).contains(Point(d.holes[0]))
    assert d.area == pytest.approx(p.area)
    assert perimeter(d) == pytest.approx(p.length)
