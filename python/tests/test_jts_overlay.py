# Polygon booleans (locus.boolean, boolean/polygon_boolean.hpp) on the JTS XML overlay suites in
# tests/data/corpus/jts-testxml (EDL-1.0): the general area-overlay cases and the robustness
# failures reported against GEOS, PostGIS, QGIS, Shapely, R-sf and OSM data. For every case
# whose two operands are valid polygons or multipolygons (shapely decides, independently of
# locus), all four operations run and:
#  - every output is valid by shapely's checker (simple rings, holes inside, disjoint parts);
#  - the exact rational areas (shoelace on the output doubles, in fractions) satisfy the
#    identities |A u B| + |A n B| = |A| + |B|, |A \ B| + |A n B| = |A|, |A xor B| = |A u B| -
#    |A n B| within the snap-rounding bound;
#  - where the case gives JTS's expected result for the operation, the areas agree within the
#    same bound (the failure file's expected geometries are not for its cases: not compared).
# Bound: locus snaps to a grid of 2^-40 of the largest coordinate, so each output vertex moves
# at most 2^-40 * scale and an area by at most that times the perimeters; 2^-38 allows for
# JTS's own floating-point result and for the identities' four terms.
import glob
import pathlib
import re
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np
import pytest

shapely = pytest.importorskip("shapely")
import shapely.wkb  # noqa: E402
import shapely.wkt  # noqa: E402
from shapely.geometry import MultiPolygon, Polygon  # noqa: E402

import locus  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "corpus" / "jts-testxml"
FILES = sorted(
    [ROOT / "general" / "TestOverlayAA.xml", ROOT / "general" / "TestNGOverlayA.xml",
     ROOT / "failure" / "TestOverlayNGFailure.xml"]
    + [pathlib.Path(p) for p in glob.glob(str(ROOT / "robust" / "overlay" / "*.xml"))])
OPS = {"intersection": "intersection", "union": "union", "difference": "difference",
       "symdifference": "xor"}


def load(text):
    text = text.strip()
    if re.fullmatch(r"[0-9A-Fa-f]+", text):
        return shapely.wkb.loads(text, hex=True)
    return shapely.wkt.loads(text)


def rings(geom):
    """The rings of a polygon or multipolygon as (n, 2) arrays (even-odd fill: exact for valid
    input, whose parts are disjoint and whose holes lie inside their shells)."""
    out = []
    for p in [geom] if geom.geom_type == "Polygon" else list(geom.geoms):
        for ring in [p.exterior, *p.interiors]:
            if ring.is_empty:
                continue
            c = np.asarray(ring.coords, dtype=np.float64)[:-1, :2]
            if len(c) >= 3:
                out.append(c)
    return out


def exact_area(ring_list):
    """Signed area of rings, exactly (fractions of the doubles)."""
    total = Fraction(0)
    for r in ring_list:
        x = [Fraction(float(v)) for v in r[:, 0]]
        y = [Fraction(float(v)) for v in r[:, 1]]
        n = len(x)
        total += sum(x[i] * y[(i + 1) % n] - x[(i + 1) % n] * y[i] for i in range(n)) / 2
    return total


def polygonal_area(geom):
    """Exact area of a valid polygon or multipolygon: each shell minus its holes."""
    total = Fraction(0)
    for p in [geom] if geom.geom_type == "Polygon" else list(geom.geoms):
        if p.is_empty:
            continue
        total += abs(exact_area(rings(p)[:1])) - sum(abs(exact_area([h])) for h in rings(p)[1:])
    return total


def cases():
    out = []
    for path in FILES:
        root = ET.parse(path).getroot()
        pm = root.find("precisionModel")
        if pm is not None and (pm.get("type", "FLOATING") != "FLOATING" or pm.get("scale")):
            continue  # fixed-precision suites round their expected results to a grid
        for k, case in enumerate(root.iter("case")):
            if case.find("a") is None or case.find("b") is None:
                continue
            expected = {}
            if path.parent.name != "failure":
                for op in case.iter("op"):
                    name = op.get("name", "").removesuffix("NG")
                    if name in OPS and op.get("arg1", "A").upper() == "A" and op.text:
                        expected[OPS[name]] = op.text
            out.append(pytest.param(case.find("a").text, case.find("b").text, expected,
                                    id=f"{path.stem}-{k}"))
    return out


@pytest.mark.parametrize("wkt_a, wkt_b, expected", cases())
def test_jts_overlay_case(wkt_a, wkt_b, expected):
    try:
        a, b = load(wkt_a), load(wkt_b)
    except shapely.errors.ShapelyError:
        pytest.skip("operand not readable by shapely")
    if not all(g.geom_type in ("Polygon", "MultiPolygon") for g in (a, b)):
        pytest.skip("not a polygonal pair")
    if not (a.is_valid and b.is_valid) or a.is_empty or b.is_empty:
        pytest.skip("invalid or empty operand (JTS semantics differ)")
    ra, rb = rings(a), rings(b)
    scale = max(float(np.max(np.abs(r))) for r in ra + rb)
    bound = Fraction(2.0**-38) * Fraction(a.length + b.length) * Fraction(scale)
    area = {}
    for op in OPS.values():
        res = locus.boolean(op, ra, rb)
        assert res.status == "ok"
        parts = [Polygon(p[0], p[1:]) for p in res.polygons]
        assert all(p.is_valid for p in parts), op
        assert MultiPolygon(parts).is_valid, op
        for p in res.polygons:  # outer rings counter-clockwise, holes clockwise
            assert exact_area([p[0]]) > 0 and all(exact_area([h]) < 0 for h in p[1:])
        area[op] = exact_area([r for p in res.polygons for r in p])
        if op in expected:
            try:
                e = load(expected[op])
            except shapely.errors.ShapelyError:
                e = None
            if e is not None:
                assert abs(float(area[op]) - e.area) <= float(bound), (op, float(area[op]), e.area)
    area_a, area_b = polygonal_area(a), polygonal_area(b)
    assert abs(area["union"] + area["intersection"] - area_a - area_b) <= 2 * bound
    assert abs(area["difference"] + area["intersection"] - area_a) <= 2 * bound
    assert abs(area["xor"] - (area["union"] - area["intersection"])) <= 2 * bound
