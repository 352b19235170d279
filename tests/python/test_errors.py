"""Every error kind: its class, its attributes, its message."""
import pathlib
import re

import numpy as np
import pytest

import madd

BAD = pathlib.Path(__file__).resolve().parents[2] / "data" / "bad"


def test_error_classes():
    assert issubclass(madd.BadInput, madd.Error) and issubclass(madd.BadInput, ValueError)
    assert issubclass(madd.OptionError, madd.Error) and issubclass(madd.OptionError, ValueError)
    assert issubclass(madd.OutputError, madd.Error) and issubclass(madd.OutputError, OSError)
    for cls in (madd.DecompositionError, madd.LimitError, madd.InternalError):
        assert issubclass(cls, madd.Error) and issubclass(cls, RuntimeError)
    assert issubclass(madd.Error, Exception)
    assert not issubclass(madd.Error, ValueError)
    assert len({madd.BadInput, madd.OptionError, madd.OutputError, madd.DecompositionError, madd.LimitError,
                madd.InternalError}) == 6


def expected_outcomes():
    """(file, domain problem, domain line, pslg problem, pslg line) from data/bad/*.expected:
    line 1 what decompose/mesh report, line 2 ('pslg ...') what reading it as any PSLG reports."""
    out = []
    for f in sorted(BAD.glob("*.poly")):
        first, second = f.with_suffix(".expected").read_text().split("\n")[:2]
        kind, line = first.split()
        pslg = second.split()[1:]
        out.append((f, kind, int(line), pslg[0], int(pslg[1]) if len(pslg) > 1 else None))
    return out


def _normal(problem):
    return re.sub(r"[ _-]+", "_", problem)


def _params():
    for f, kind, line, pslg, pslg_line in expected_outcomes():
        yield pytest.param(f, kind, line, pslg, pslg_line, id=f.stem)


@pytest.mark.parametrize("path,kind,line,pslg,pslg_line", list(_params()))
def test_bad_files(path, kind, line, pslg, pslg_line):
    if pslg == "ok":
        d = madd.read_domain(str(path))  # any PSLG reads...
        assert d.path == str(path)
        with pytest.raises(madd.BadInput) as e:
            d.check()  # ... but is no domain
        with pytest.raises(madd.BadInput):
            madd.mesh(str(path), 2, max_area=0.1)
    else:
        with pytest.raises(madd.BadInput) as e:
            madd.read_domain(str(path))  # not even a PSLG: what reading it reports
        kind, line = pslg, pslg_line
    err = e.value
    assert isinstance(err, ValueError) and isinstance(err, madd.Error)
    assert err.path == str(path)
    if kind == "parse":
        assert err.line == line and err.column >= 1
        assert str(err).startswith(f"{path}:{line}:{err.column}: ")
    else:
        assert _normal(err.problem) == _normal(kind)
        if line:
            assert err.line == line
            assert f":{line}:" in str(err)


def test_parse_error_names_the_place():
    path = BAD / "non_numeric.poly"
    with pytest.raises(madd.BadInput) as e:
        madd.read_domain(str(path))
    text = path.read_text().splitlines()
    assert "zero" in text[e.value.line - 1]  # the line it names holds the bad field
    assert text[e.value.line - 1][e.value.column - 1:].startswith("zero")
    assert "zero" in str(e.value)


def test_missing_file():
    with pytest.raises((madd.BadInput, OSError)) as e:
        madd.read_domain("/nonexistent/no.poly")
    assert "/nonexistent/no.poly" in str(e.value)


SQUARE = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)


def test_segment_index_out_of_range():
    with pytest.raises(madd.BadInput) as e:
        madd.Domain(SQUARE, [[0, 1], [1, 2], [2, 3], [3, 7]])
    assert e.value.path is None
    assert "7" in str(e.value) and "row 3" in str(e.value)


def test_duplicate_points_are_named_by_ids():
    pts = np.vstack([SQUARE, [[1, 0]]])  # point 4 repeats point 1
    with pytest.raises(madd.BadInput) as e:
        madd.Domain(pts, [[0, 4], [4, 2], [2, 3], [3, 0]])
    assert _normal(e.value.problem) == "duplicate_vertex"
    assert {1, 4} <= set(e.value.ids)
    assert e.value.path is None


def test_crossing_segments_are_named_by_ids():
    with pytest.raises(madd.BadInput) as e:
        madd.Domain(SQUARE, [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [1, 3]])
    assert _normal(e.value.problem) == "segments_intersect"
    assert {4, 5} <= set(e.value.ids)  # the two diagonals, 0-based segment ids
    assert any(np.allclose(p, [0.5, 0.5]) for p in e.value.points)


@pytest.mark.parametrize("points", [np.array([[0, 0], [1, np.nan], [0, 1]]), np.zeros((3, 3))])
def test_bad_point_arrays(points):
    with pytest.raises(madd.BadInput):
        madd.Domain(points, [[0, 1], [1, 2], [2, 0]])


@pytest.mark.parametrize("keywords,option,word", [
    (dict(q=70), "min_triangle_angle_deg", "q"),
    (dict(max_area=-1), "max_triangle_area", "max_area"),
    (dict(separator_angle_deg=95), "separator_angle_deg", "separator_angle_deg"),
    (dict(max_edge_length=-2.0), "max_edge_length", "max_edge_length"),
    (dict(triangle_area_function="0.01 + zz"), "triangle_area_function", "triangle_area_function"),
])
def test_option_errors(unit_square, keywords, option, word):
    with pytest.raises(madd.OptionError) as e:
        madd.mesh(unit_square, 2, **keywords)
    assert isinstance(e.value, ValueError) and isinstance(e.value, madd.Error)
    assert e.value.option == option
    assert re.search(rf"\b{word}\b", str(e.value)), str(e.value)
    assert e.value.requirement


def test_option_errors_of_decompose_and_n(unit_square):
    with pytest.raises(madd.OptionError) as e:
        madd.decompose(unit_square, 2, separator_angle_deg=95)
    assert e.value.option == "separator_angle_deg" and "separator_angle_deg" in str(e.value)
    with pytest.raises(madd.OptionError) as e:
        madd.mesh(unit_square, 0)
    assert e.value.option == "subdomains"


def test_unknown_keyword_is_a_type_error(unit_square):
    with pytest.raises(TypeError, match="bogus"):
        madd.mesh(unit_square, 2, bogus=1)
    with pytest.raises(TypeError, match="max_areaa"):
        madd.decompose(unit_square, 2, max_areaa=1)
    with pytest.raises(TypeError):
        madd.triangulate(unit_square, quality=3)


def test_decomposition_error():
    # a needle triangle 1 x 0.001: no separator meets both long sides at 89.9 degrees
    needle = madd.Domain(np.array([[0, 0], [1, 0], [0.5, 0.001]]), [[0, 1], [1, 2], [2, 0]])
    with pytest.raises(madd.DecompositionError) as e:
        madd.decompose(needle, 2, separator_angle_deg=89.9)
    assert isinstance(e.value, RuntimeError) and isinstance(e.value, madd.Error)
    assert e.value.separator_angle_deg == 89.9
    assert e.value.subdomain == 0
    assert e.value.area == pytest.approx(0.0005, rel=1e-9)  # the whole needle
    assert "89.9" in str(e.value)
    with pytest.raises(madd.DecompositionError):
        madd.mesh(needle, 2, separator_angle_deg=89.9, max_area=0.01)
    # a wide enough angle bound splits it
    assert len(madd.decompose(needle, 2, separator_angle_deg=60)) == 2


def test_output_error(unit_square, tmp_path):
    m = madd.mesh(unit_square, 2, max_area=0.05, threads=1)
    missing = tmp_path / "no" / "such" / "dir" / "p"
    with pytest.raises(madd.OutputError) as e:
        m.write(str(missing))
    assert isinstance(e.value, OSError) and isinstance(e.value, madd.Error)
    assert str(missing) in str(e.value)
    assert not (tmp_path / "no").exists()
    with pytest.raises(madd.OutputError):
        m.write_vtu(str(missing) + ".vtu")
    with pytest.raises(madd.OutputError):
        madd.decompose(unit_square, 2).write_poly(str(missing) + ".poly")


def test_output_is_all_or_nothing(unit_square, tmp_path):
    m = madd.mesh(unit_square, 2, max_area=0.05, threads=1)
    (tmp_path / "p.ele").mkdir()  # .ele cannot be written: nothing is
    with pytest.raises(madd.OutputError):
        m.write(str(tmp_path / "p"), msh=True)
    assert sorted(x.name for x in tmp_path.iterdir()) == ["p.ele"]
    assert not any((tmp_path / "p.ele").iterdir())


def test_limit_errors(data):
    with pytest.raises(madd.LimitError) as e:
        madd.mesh(str(data / "pipe.poly"), 8, max_area=0.001, threads=1, time_limit_seconds=1e-9)
    assert isinstance(e.value, RuntimeError) and isinstance(e.value, madd.Error)
    assert "time limit" in str(e.value)
    with pytest.raises(madd.LimitError) as e:
        madd.mesh(str(data / "key.poly"), 4, max_area=0.01, threads=1, max_memory_bytes=1)
    assert "memory" in str(e.value)
    with pytest.raises(madd.LimitError):
        madd.decompose(str(data / "pipe.poly"), 64, time_limit_seconds=1e-9)


def test_error_kind_and_message(unit_square):
    with pytest.raises(madd.OptionError) as e:
        madd.mesh(unit_square, 2, q=70)
    assert e.value.kind and e.value.message and e.value.message in str(e.value)


def test_errors_leave_the_module_usable(unit_square):
    for _ in range(3):
        with pytest.raises(madd.OptionError):
            madd.mesh(unit_square, 2, q=70)
        with pytest.raises(madd.BadInput):
            madd.read_domain(str(BAD / "nan.poly"))
    m = madd.mesh(unit_square, 2, max_area=0.05, threads=1)
    assert m.verify() == []
