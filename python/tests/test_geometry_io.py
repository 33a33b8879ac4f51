# read_wkt and read_geojson: random polygons and multipolygons with holes made and written by
# shapely (WKT, and GeoJSON through json.dumps of shapely's mapping), read back by locus and
# compared with shapely's own parsing of the same text (coordinates, ring counts, areas,
# orientation), plus the other geometry types and malformed text.
import json

import numpy as np
import pytest
import shapely.wkt
from shapely.geometry import MultiPolygon, Point, mapping, shape
from shapely.geometry.polygon import orient
from shapely.ops import unary_union

import locus


def signed_area(ring):
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def same_cycle(a, b):
    # the same closed ring, possibly starting at another vertex (orienting may rotate it)
    if a.shape != b.shape:
        return False
    starts = np.flatnonzero(np.all(a == b[0], axis=1))
    return any(np.array_equal(np.roll(a, -k, axis=0), b) for k in starts)


def random_shape(rng):
    # a union of discs and a ring-shaped piece: often several parts, some with holes
    parts = [Point(*rng.uniform(-5, 5, 2)).buffer(rng.uniform(0.5, 2), resolution=4)
             for _ in range(rng.integers(1, 6))]
    c = rng.uniform(-5, 5, 2)
    parts.append(Point(*c).buffer(2.5, resolution=5).difference(Point(*c).buffer(1.2)))
    return unary_union(parts)


def polygons_of(geom):
    return list(geom.geoms) if isinstance(geom, MultiPolygon) else [geom]


def compare(got, expected, oriented):
    polys = polygons_of(expected)
    assert got.type == ("MULTIPOLYGON" if isinstance(expected, MultiPolygon) else "POLYGON")
    assert len(got.polygons) == len(polys)
    total = 0.0
    for rings, p in zip(got.polygons, polys):
        if oriented:
            p = orient(p, 1.0)  # shapely: exterior counter-clockwise, holes clockwise
        ref = [p.exterior, *p.interiors]
        assert len(rings) == len(ref) == 1 + len(p.interiors)
        for ring, r in zip(rings, ref):
            coords = np.asarray(r.coords)[:-1, :2]  # shapely repeats the closing point
            assert same_cycle(ring, coords) if oriented else np.array_equal(ring, coords)
            assert signed_area(ring) == pytest.approx(signed_area(coords), rel=1e-12)
        area = abs(signed_area(rings[0])) - sum(abs(signed_area(h)) for h in rings[1:])
        assert area == pytest.approx(p.area, rel=1e-12)
        if oriented:
            assert signed_area(rings[0]) > 0 and all(signed_area(h) < 0 for h in rings[1:])
        total += area
    assert total == pytest.approx(expected.area, rel=1e-12)


def test_random_polygons_match_shapely(rng):
    holes = 0
    for _ in range(30):
        geom = random_shape(rng)
        wkt = geom.wkt
        for oriented in (False, True):
            (w,) = locus.read_wkt(wkt, orient=oriented)
            compare(w, shapely.wkt.loads(wkt), oriented)
            text = json.dumps(mapping(geom))
            (g,) = locus.read_geojson(text, orient=oriented)
            compare(g, shape(json.loads(text)), oriented)
        holes += sum(len(p.interiors) for p in polygons_of(geom))
    assert holes >= 30


def test_other_types_and_collections():
    text = ("GEOMETRYCOLLECTION (POINT (1 2), LINESTRING (0 0, 1 1, 2 0), "
            "MULTIPOINT ((3 4), (5 6))) POLYGON EMPTY")
    got = locus.read_wkt(text)
    assert [g.type for g in got] == ["POINT", "LINESTRING", "MULTIPOINT", "POLYGON"]
    assert np.array_equal(got[0].points, [[1, 2]])
    assert np.array_equal(got[1].lines[0], [[0, 0], [1, 1], [2, 0]])
    assert np.array_equal(got[2].points, [[3, 4], [5, 6]])
    assert got[3].polygons == []
    fc = {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"a": 1},
         "geometry": {"type": "LineString", "coordinates": [[0, 0, 9], [1, 2, 9]]}},
        {"type": "Feature", "properties": None, "geometry": None},
        {"type": "Feature", "properties": None,
         "geometry": {"type": "Point", "coordinates": [0.1, 0.2]}}]}
    got = locus.read_geojson(json.dumps(fc))
    assert [g.type for g in got] == ["LINESTRING", "POINT"]
    assert np.array_equal(got[0].lines[0], [[0, 0], [1, 2]])
    assert np.array_equal(got[1].points, [[0.1, 0.2]])


@pytest.mark.parametrize("text", [
    "POLYGON ((0 0, 1 0, 1 1))",             # too few points
    "POLYGON ((0 0, 1 0, 1 1, 0 1))",        # not closed
    "POLYGON ((0 0, 1 0, 1 1, 0 0)",         # truncated
    "POLYGON ((0 0, 1 x, 1 1, 0 0))",        # not a number
])
def test_malformed_wkt_raises(text):
    with pytest.raises(Exception):
        shapely.wkt.loads(text)  # shapely rejects it too
    with pytest.raises(ValueError, match="parse_error"):
        locus.read_wkt(text)


@pytest.mark.parametrize("text", [
    '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1]]]}',
    '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}',
    '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0]]]',
    '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 0],]]}',
    '{"type": "Triangle", "coordinates": []}',
])
def test_malformed_geojson_raises(text):
    with pytest.raises(ValueError, match="parse_error"):
        locus.read_geojson(text)


def test_empty_and_non_finite():
    with pytest.raises(ValueError, match="empty_input"):
        locus.read_wkt("   ")
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.read_wkt("POINT (1e400 0)")
    with pytest.raises(ValueError, match="non_finite_input"):
        locus.read_geojson('{"type": "Point", "coordinates": [1e400, 0]}')
