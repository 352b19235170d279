"""Independent checks of madd's results, computed here with numpy (and
shapely for areas), then compared with what the module reports."""
import numpy as np


def signed_areas(points, triangles):
    """The signed area of every triangle (positive: counter-clockwise)."""
    p = np.asarray(points, dtype=float)
    t = np.asarray(triangles)
    a, b, c = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def angles_deg(points, triangles):
    """(M, 3) interior angles in degrees, at corners 0, 1, 2."""
    p = np.asarray(points, dtype=float)
    t = np.asarray(triangles)
    out = np.empty(t.shape, dtype=float)
    for k in range(3):
        o = p[t[:, k]]
        u = p[t[:, (k + 1) % 3]] - o
        v = p[t[:, (k + 2) % 3]] - o
        cross = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
        out[:, k] = np.degrees(np.arctan2(cross, (u * v).sum(axis=1)))
    return out


def edge_counts(triangles):
    """The undirected edges of the triangles (sorted pairs) and how many
    triangles hold each."""
    t = np.asarray(triangles, dtype=np.int64)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    e.sort(axis=1)
    return np.unique(e, axis=0, return_counts=True)


def sorted_rows(edges):
    e = np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1)
    return e[np.lexsort((e[:, 1], e[:, 0]))]


def wedge_angles(points, segments):
    """Per vertex, the angles (degrees) between angularly consecutive
    segments around it: every wedge, inside or outside the domain, as
    {vertex: [(angle, segment_a, segment_b), ...]}."""
    p = np.asarray(points, dtype=float)
    s = np.asarray(segments, dtype=np.int64)
    around = {}
    for i, (a, b) in enumerate(s):
        around.setdefault(int(a), []).append((int(b), i))
        around.setdefault(int(b), []).append((int(a), i))
    out = {}
    for v, ends in around.items():
        if len(ends) < 2:
            continue
        d = p[[e for e, _ in ends]] - p[v]
        theta = np.arctan2(d[:, 1], d[:, 0])
        order = np.argsort(theta)
        th = theta[order]
        gaps = np.degrees(np.diff(np.concatenate([th, th[:1] + 2 * np.pi])))
        ids = [ends[k][1] for k in order]
        out[v] = [(gaps[k], ids[k], ids[(k + 1) % len(ids)]) for k in range(len(ids))]
    return out


def small_angle_vertices(points, segments, bound_deg):
    """Input vertices where some wedge between two segments is below bound."""
    return {v for v, wedges in wedge_angles(points, segments).items() if min(w[0] for w in wedges) < bound_deg}


def domain_area(domain):
    """The domain's area from its segments and hole points, by shapely:
    the faces the segments bound, minus those holding a hole point."""
    from shapely.geometry import LineString, Point
    from shapely.ops import polygonize, unary_union
    p = np.asarray(domain.points)
    lines = [LineString([p[a], p[b]]) for a, b in np.asarray(domain.segments)]
    faces = list(polygonize(unary_union(lines)))
    holes = [Point(h) for h in np.asarray(domain.holes)]
    return sum(f.area for f in faces if not any(f.contains(h) for h in holes))


def check_mesh(m, area, q=None, max_area=None, small_input_angles=(), holes=None, perimeter=None):
    """Every property a conforming quality mesh has, asserted.

    area: the domain's area, computed independently; q: the angle bound
    (every triangle not touching one of `small_input_angles` has all angles
    >= q - 1e-6); max_area: the area bound; holes: the number of holes, for
    Euler's formula (V - E + F = 1 - holes on one connected domain);
    perimeter: the length of the domain's boundary (without interior
    segments), which the mesh's boundary edges must add up to."""
    p = np.asarray(m.points)
    t = np.asarray(m.triangles)
    n = len(p)
    assert p.ndim == 2 and p.shape[1] == 2 and np.isfinite(p).all()
    assert t.ndim == 2 and t.shape[1] == 3 and t.dtype == np.int32
    assert len(m) == m.triangle_count == len(t) > 0
    assert t.min() >= 0 and t.max() < n
    assert (t[:, 0] != t[:, 1]).all() and (t[:, 1] != t[:, 2]).all() and (t[:, 0] != t[:, 2]).all()
    # every point is a corner of some triangle
    assert len(np.unique(t)) == n

    a = signed_areas(p, t)
    assert (a > 0).all(), "a triangle is not counter-clockwise"
    assert abs(a.sum() - area) <= 1e-9 * area
    if max_area is not None:
        assert a.max() <= max_area * (1 + 1e-12)

    if q is not None:
        ang = angles_deg(p, t)
        assert np.allclose(ang.sum(axis=1), 180.0)
        bad = ang.min(axis=1) < q - 1e-6
        if bad.any():
            near = np.isin(t[bad], list(small_input_angles)).any(axis=1)
            assert near.all(), f"{(~near).sum()} triangles below {q} degrees away from small input angles"

    # conformity: every edge is held by one or two triangles; the ones held
    # by one are exactly the boundary edges
    edges, counts = edge_counts(t)
    assert counts.max() <= 2
    boundary = edges[counts == 1]
    assert np.array_equal(sorted_rows(boundary), sorted_rows(m.boundary_edges))
    assert len(m.boundary_markers) == len(m.boundary_edges)
    if holes is not None:
        assert n - len(edges) + len(t) == 1 - holes
    if perimeter is not None:
        length = np.linalg.norm(p[boundary[:, 0]] - p[boundary[:, 1]], axis=1).sum()
        assert abs(length - perimeter) <= 1e-9 * perimeter

    # neighbours: across the edge opposite corner k; symmetric; -1 on the boundary
    nb = np.asarray(m.neighbours)
    assert nb.shape == t.shape
    rows = np.arange(len(t))[:, None]
    ends0 = t[:, [1, 2, 0]]
    ends1 = t[:, [2, 0, 1]]
    outside = nb < 0
    assert (nb[outside] == -1).all() and nb.max() < len(t)
    open_edges = np.stack([ends0[outside], ends1[outside]], axis=1)
    assert np.array_equal(sorted_rows(open_edges), sorted_rows(boundary))
    j = np.where(outside, 0, nb)
    across = t[j]
    holds = (across == ends0[..., None]).any(-1) & (across == ends1[..., None]).any(-1)
    back = (nb[j] == rows[..., None]).any(-1)
    assert (holds | outside).all() and (back | outside).all()
    assert ((j != rows) | outside).all()

    # subdomains: grouped, counted, each triangle in one
    sub = np.asarray(m.subdomain)
    first = np.asarray(m.subdomain_first_triangle)
    assert len(sub) == len(t)
    assert len(first) == m.subdomain_count + 1 and first[0] == 0 and first[-1] == len(t)
    assert (np.diff(first) > 0).all()
    for k in range(m.subdomain_count):
        assert (sub[first[k]:first[k + 1]] == k).all()
    assert m.verify() == []


def ring_area(points, ring):
    """Shoelace area of a closed ring of point indices (signed)."""
    r = np.asarray(points, dtype=float)[np.asarray(ring)]
    x, y = r[:, 0], r[:, 1]
    return 0.5 * (x * np.roll(y, -1) - np.roll(x, -1) * y).sum()


def perimeter(domain):
    p = np.asarray(domain.points)
    s = np.asarray(domain.segments)
    return np.linalg.norm(p[s[:, 0]] - p[s[:, 1]], axis=1).sum()


def check_decomposition(dec, area, n, phi=60.0):
    """A conforming subdivision into n subdomains: areas add up, separators
    (marker 0) bound two subdomains and boundary pieces one, every angle a
    separator makes is >= phi."""
    p = np.asarray(dec.points)
    s = np.asarray(dec.segments)
    markers = np.asarray(dec.markers)
    assert len(dec) == dec.subdomain_count == n == len(dec.subdomains) == len(dec.areas)
    seps = np.flatnonzero(markers == 0)
    assert np.array_equal(seps, np.sort(np.asarray(dec.separators)))
    assert np.array_equal(np.flatnonzero(np.asarray(dec.segment_origin) == -1), seps)
    areas = []
    uses = {}
    for sd in dec.subdomains:
        rings = sd["rings"]
        outer = ring_area(p, rings[0])
        assert outer > 0, "outer ring not counter-clockwise"
        inner = [ring_area(p, r) for r in rings[1:]]
        assert all(x < 0 for x in inner), "hole ring not clockwise"
        areas.append(outer + sum(inner))
        assert abs(sd["area"] - areas[-1]) <= 1e-9 * area
        for r in rings:
            r = np.asarray(r)
            for a, b in zip(r, np.roll(r, -1)):
                key = (min(a, b), max(a, b))
                uses[key] = uses.get(key, 0) + 1
    areas = np.array(areas)
    assert (areas > 0).all()
    assert abs(areas.sum() - area) <= 1e-9 * area
    assert np.allclose(np.asarray(dec.areas), areas, rtol=1e-9, atol=0)
    for i, (a, b) in enumerate(s):
        expected = 2 if markers[i] == 0 else 1
        assert uses.get((min(a, b), max(a, b)), 0) == expected, f"segment {i}"
    assert sum(uses.values()) == 2 * len(seps) + (len(s) - len(seps))
    is_sep = markers == 0
    smallest = 180.0
    for wedges in wedge_angles(p, s).values():
        for angle, sa, sb in wedges:
            if is_sep[sa] or is_sep[sb]:
                smallest = min(smallest, angle)
    if len(seps):
        assert smallest >= phi - 1e-6
    assert dec.verify() == []
    return smallest
