"""Files: what the module writes is what the CLI writes, byte for byte, and
says what the arrays say; meshio round trips."""
import json
import subprocess

import numpy as np
import pytest

import madd
from mesh_checks import domain_area, signed_areas


def run_cli(cli, *args, cwd):
    run = subprocess.run([cli, *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    return run


def same_bytes(a, b, names):
    for name in names:
        assert (a / name).read_bytes() == (b / name).read_bytes(), f"{name} differs from the CLI's"


def read_table(path):
    """A Triangle file's rows after the header, as floats; and the header."""
    lines = [ln.split("#")[0].split() for ln in path.read_text().splitlines()]
    lines = [ln for ln in lines if ln]
    return [int(x) for x in lines[0]], np.array(lines[1:], dtype=float)


@pytest.fixture
def dirs(tmp_path):
    a, b = tmp_path / "cli", tmp_path / "py"
    a.mkdir()
    b.mkdir()
    return a, b


def test_key_mesh_is_the_cli_mesh(cli, data, dirs):
    a, b = dirs
    run_cli(cli, "mesh", data / "key.poly", "-n", 8, "-q", 30, "-a", 0.01, "-j", 2, "-o", "P", "--msh", "--vtu",
            "--neigh", "--edge", cwd=a)
    m = madd.mesh(madd.read_domain(str(data / "key.poly")), 8, q=30, max_area=0.01, threads=2)
    m.write(str(b / "P"), msh=True, vtu=True, neigh=True, edge=True)
    same_bytes(a, b, ["P.node", "P.ele", "P.msh", "P.vtu", "P.neigh", "P.edge"])
    # from a path too
    m2 = madd.mesh(str(data / "key.poly"), 8, q=30, max_area=0.01, threads=1)
    m2.write(str(b / "Q"), msh=True, vtu=True)
    for ext in ("node", "ele", "msh", "vtu"):
        assert (a / f"P.{ext}").read_bytes() == (b / f"Q.{ext}").read_bytes()

    # and the files hold the arrays (1-based ids)
    head, node = read_table(b / "P.node")
    assert head[:2] == [len(m.points), 2]
    assert np.array_equal(node[:, 0], np.arange(1, len(m.points) + 1))
    assert np.array_equal(node[:, 1:3], m.points)  # written to round trip
    assert np.array_equal(node[:, -1], m.point_markers)
    head, ele = read_table(b / "P.ele")
    assert head[:2] == [len(m), 3]
    assert np.array_equal(ele[:, 1:4], m.triangles + 1)
    assert np.array_equal(ele[:, 4], m.subdomain)
    head, neigh = read_table(b / "P.neigh")
    assert np.array_equal(neigh[:, 1:4], np.where(m.neighbours < 0, -1, m.neighbours + 1))
    head, edge = read_table(b / "P.edge")
    t = m.triangles
    all_edges = np.unique(np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1), axis=0)
    assert head[0] == len(all_edges)
    written = np.unique(np.sort(edge[:, 1:3].astype(np.int64) - 1, axis=1), axis=0)
    assert np.array_equal(written, all_edges)


def test_first_index_zero(data, tmp_path):
    m = madd.mesh(str(data / "l_shape.poly"), 2, max_area=0.1, threads=1)
    m.write(str(tmp_path / "z"), first_index=0)
    _, node = read_table(tmp_path / "z.node")
    _, ele = read_table(tmp_path / "z.ele")
    assert node[0, 0] == 0 and np.array_equal(ele[:, 1:4], m.triangles)


BAY_CLIP = "-70.0,43.5,-69.5,43.9"


def test_coastal_mesh_is_the_cli_mesh(cli, data, dirs):
    a, b = dirs
    coast = data / "coast"
    run_cli(cli, "mesh", coast / "bay.geojson", "--clip", BAY_CLIP, "--hmin", 50, "--hmax", 3000,
            "--distance-rate", 0.15, "--cells-across", 3, "--gradation", 0.2, "--depth", coast / "depth.asc",
            "--wavelength-cells", 50, "-n", 16, "-j", 2, "-o", "P", "--fort14", "P.14", cwd=a)
    m = madd.mesh(str(coast / "bay.geojson"), 16, clip=(-70.0, 43.5, -69.5, 43.9), min_edge_length=50,
                  max_edge_length=3000, distance_rate=0.15, cells_across=3, size_gradation=0.2,
                  depth=str(coast / "depth.asc"), wavelength_cells=50, threads=2)
    m.write(str(b / "P"), fort14=str(b / "P.14"))
    same_bytes(a, b, ["P.node", "P.ele", "P.14"])
    # fort.14: NE NP, then the nodes in lon/lat with a depth
    lines = (b / "P.14").read_text().splitlines()
    ne, np_ = map(int, lines[1].split()[:2])
    assert (ne, np_) == (len(m), len(m.points))
    nodes = np.array([ln.split()[:4] for ln in lines[2:2 + np_]], dtype=float)
    assert np.allclose(nodes[:, 1:3], m.domain.projection.to_lonlat(m.points), atol=1e-6)
    assert np.isfinite(nodes[:, 3]).all()
    elements = np.array([ln.split()[:5] for ln in lines[2 + np_:2 + np_ + ne]], dtype=np.int64)
    assert np.array_equal(elements[:, 1], np.full(ne, 3))
    assert np.array_equal(elements[:, 2:5], m.triangles + 1)


def test_gr3_2dm_and_split_are_the_cli_files(cli, data, dirs):
    a, b = dirs
    run_cli(cli, "mesh", data / "l_shape.poly", "-n", 3, "-a", 0.05, "-j", 1, "-o", "L", "--gr3", "L.gr3", "--2dm",
            "L.2dm", "--split-mesh", "S", cwd=a)
    m = madd.mesh(str(data / "l_shape.poly"), 3, max_area=0.05, threads=1)
    m.write(str(b / "L"), gr3=str(b / "L.gr3"), sms2dm=str(b / "L.2dm"), split_mesh=str(b / "S"))
    same_bytes(a, b, ["L.node", "L.ele", "L.gr3", "L.2dm"])
    split = sorted(p.name for p in (a / "S").iterdir())
    assert split == sorted(p.name for p in (b / "S").iterdir())
    same_bytes(a / "S", b / "S", split)
    # the pieces' triangles are the mesh's, once each: each piece's .node
    # holds its points with their global id as attribute
    tris = []
    stems = sorted(name[:-5] for name in split if name.endswith(".node"))
    assert len(stems) == 3 and stems == sorted(name[:-4] for name in split if name.endswith(".ele"))
    assert [s.rsplit("-", 1)[1] for s in stems] == ["0", "1", "2"]
    for k, stem in enumerate(stems):
        _, node = read_table(b / "S" / f"{stem}.node")
        _, ele = read_table(b / "S" / f"{stem}.ele")
        global_id = node[:, 3].astype(np.int64) - 1
        assert np.array_equal(node[:, 1:3], m.points[global_id])
        local = ele[:, 1:4].astype(np.int64) - 1
        tris.append(global_id[local])
        assert (ele[:, 4] == k).all() or (ele[:, 4] == 0).all()
        assert len(ele) == (m.subdomain == k).sum()
    rows = np.sort(np.concatenate(tris), axis=1)
    assert np.array_equal(np.unique(rows, axis=0), np.unique(np.sort(m.triangles, axis=1), axis=0))
    assert len(rows) == len(m)


def test_single_writers_are_write_s_files(data, tmp_path):
    m = madd.mesh(str(data / "l_shape.poly"), 2, max_area=0.05, threads=1)
    m.write(str(tmp_path / "all"), neigh=True, edge=True, msh=True, vtu=True)
    m.write_node(str(tmp_path / "one.node"))
    m.write_ele(str(tmp_path / "one.ele"))
    m.write_neigh(str(tmp_path / "one.neigh"))
    m.write_edge(str(tmp_path / "one.edge"))
    m.write_msh(str(tmp_path / "one.msh"))
    m.write_vtu(str(tmp_path / "one.vtu"))
    for ext in ("node", "ele", "neigh", "edge", "vtu"):
        assert (tmp_path / f"all.{ext}").read_bytes() == (tmp_path / f"one.{ext}").read_bytes(), ext
    assert (tmp_path / "one.msh").read_text().startswith("$MeshFormat\n4.1")


def test_decomposition_files_are_the_cli_files(cli, data, dirs):
    a, b = dirs
    run_cli(cli, "decompose", data / "key.poly", "-n", 8, "-o", "K.poly", "--svg", "K.svg", "--geojson", "K.geojson",
            "--vtk", "K.vtk", "--geo", "K.geo", "--subdomains-file", "K.sub", "--split", "S", "-q", cwd=a)
    dec = madd.decompose(str(data / "key.poly"), 8)
    dec.write_poly(str(b / "K.poly"))
    dec.write_svg(str(b / "K.svg"))
    dec.write_geojson(str(b / "K.geojson"))
    dec.write_vtk(str(b / "K.vtk"))
    dec.write_geo(str(b / "K.geo"))
    dec.write_subdomains(str(b / "K.sub"))
    dec.write_split(str(b / "S"), "key")
    same_bytes(a, b, ["K.poly", "K.svg", "K.geojson", "K.vtk", "K.geo", "K.sub"])
    assert dec.to_svg() == (b / "K.svg").read_text()
    names = sorted(p.name for p in (a / "S").iterdir())
    assert names == [f"key-{k}.poly" for k in range(8)]
    same_bytes(a / "S", b / "S", names)

    # what they hold: the pieces, adding up to the domain
    area = domain_area(madd.read_domain(str(data / "key.poly")))
    pieces = [madd.read_domain(str(b / "S" / name)) for name in names]
    assert sum(domain_area(p) for p in pieces) == pytest.approx(area, rel=1e-9)
    from shapely.geometry import shape
    features = [f for f in json.loads((b / "K.geojson").read_text())["features"]
                if f["geometry"]["type"] == "Polygon"]
    assert len(features) == 8
    assert sum(shape(f["geometry"]).area for f in features) == pytest.approx(area, rel=1e-9)
    whole = madd.read_domain(str(b / "K.poly"))
    assert len(whole.regions) == 8
    assert domain_area(whole) == pytest.approx(area, rel=1e-9)


def test_triangulation_files_are_the_cli_files(cli, data, dirs):
    a, b = dirs
    run_cli(cli, "triangulate", data / "key.poly", "-o", "T", cwd=a)
    madd.triangulate(str(data / "key.poly")).write(str(b / "T"))
    same_bytes(a, b, ["T.node", "T.ele", "T.neigh", "T.edge"])


def test_to_meshio(square_with_hole, tmp_path):
    meshio = pytest.importorskip("meshio")
    m = madd.mesh(square_with_hole, 4, max_area=0.005, threads=1)
    mm = m.to_meshio()
    assert np.array_equal(mm.points[:, :2], m.points)
    assert len(mm.cells) == 1 and mm.cells[0].type == "triangle"
    assert np.array_equal(mm.cells[0].data, m.triangles)
    assert np.array_equal(mm.cell_data["subdomain"][0], m.subdomain)
    assert np.array_equal(mm.point_data["marker"], m.point_markers)
    path = tmp_path / "m.vtu"
    mm.write(str(path))
    back = meshio.read(str(path))
    assert np.array_equal(back.cells_dict["triangle"], m.triangles)
    assert np.allclose(back.points[:, :2], m.points, rtol=0, atol=0)
    assert np.array_equal(back.cell_data["subdomain"][0], m.subdomain)
    assert (signed_areas(back.points[:, :2], back.cells_dict["triangle"]) > 0).all()


def test_meshio_reads_madd_files(square_with_hole, tmp_path):
    meshio = pytest.importorskip("meshio")
    m = madd.mesh(square_with_hole, 3, max_area=0.01, threads=1)
    m.write(str(tmp_path / "p"), vtu=True, msh=True)
    index = {tuple(p): i for i, p in enumerate(m.points.tolist())}
    for ext in ("vtu", "msh"):
        back = meshio.read(str(tmp_path / f"p.{ext}"))
        assert len(back.points) == len(m.points)
        # gmsh lists the nodes by entity: match them to madd's by coordinates
        to_madd = np.array([index[tuple(p)] for p in back.points[:, :2].tolist()])
        assert len(set(to_madd.tolist())) == len(m.points)
        tri = to_madd[np.concatenate([c.data for c in back.cells if c.type == "triangle"])]
        assert np.array_equal(np.unique(np.sort(tri, axis=1), axis=0), np.unique(np.sort(m.triangles, axis=1), axis=0))
        assert len(tri) == len(m)
    # the .msh has a physical surface per subdomain
    back = meshio.read(str(tmp_path / "p.msh"))
    blocks = [c for c in back.cells if c.type == "triangle"]
    assert sorted(len(c.data) for c in blocks) == sorted(np.bincount(m.subdomain).tolist())


def test_to_meshio_attributes():
    pytest.importorskip("meshio")
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0], [0.5, 1]], float)
    d = madd.Domain(pts, [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]],
                    regions=[[0.25, 0.5, 7, 0], [0.75, 0.5, 9, 0]])
    m = madd.mesh(d, 2, max_area=0.02, threads=1)
    assert np.array_equal(m.to_meshio().cell_data["attribute"][0], m.attributes)
