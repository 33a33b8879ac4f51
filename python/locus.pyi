# Type stubs of the locus extension module (python/src/*.cpp). Installed next to the module.
# Points are (n, 2) or (n, 3) float64/float32 arrays (anything numpy converts to them); results
# are Result objects (status 'ok' or 'limit_exceeded' plus the fields listed) or numpy arrays.
from typing import Any

import numpy as np
import numpy.typing as npt

__version__: str
KIND_NAMES: tuple[str, ...]

_Points = npt.ArrayLike
_Floats = npt.NDArray[np.floating[Any]]
_Indices = npt.NDArray[np.uint32]
# Mesh faces: an (m, k) integer array, or a list of index sequences (polygons of mixed sizes).
_Faces = npt.NDArray[np.uint32] | list[npt.NDArray[np.uint32]]
_Mesh = tuple[_Floats, _Faces]

class Result:
    status: str

class Hull2Result(Result):
    dimension: int
    indices: _Indices

class Hull3Result(Result):
    dimension: int
    triangles: _Indices
    vertices: _Indices
    polygon: _Indices

class Delaunay2Result(Result):
    dimension: int
    triangles: _Indices
    adjacency: _Indices
    hull: _Indices
    duplicate_of: _Indices

class Delaunay3Result(Result):
    dimension: int
    tetrahedra: _Indices
    adjacency: _Indices
    hull: _Indices
    duplicate_of: _Indices
    triangles: _Indices
    chain: _Indices

class ConstrainedDelaunayResult(Result):
    dimension: int
    triangles: _Indices
    adjacency: _Indices
    hull: _Indices
    duplicate_of: _Indices
    constrained: npt.NDArray[np.uint8]
    rejected: _Indices

class TriangulationResult(Result):
    triangles: _Indices

class TrapezoidMapResult(Result):
    trapezoids: npt.NDArray[np.int64]
    located: npt.NDArray[np.int64]

class MinCircleResult(Result):
    center: _Floats
    radius: float
    support: _Indices

class MinSphereResult(Result):
    center: _Floats
    radius: float
    support: _Indices

class MinRectResult(Result):
    center: _Floats
    axes: _Floats
    extents: _Floats
    area: float
    perimeter: float
    edge: _Indices

class MinBoxResult(Result):
    center: _Floats
    axes: _Floats
    extents: _Floats
    volume: float
    certified: bool

class LineFitResult(Result):
    origin: _Floats
    direction: _Floats
    rms: float

class PlaneFitResult(Result):
    normal: _Floats
    constant: float
    rms: float

class SphereFitResult(Result):
    center: _Floats
    radius: float
    rms: float
    iterations: int

class GaussianFitResult(Result):
    mean: _Floats
    covariance: _Floats
    axes: _Floats
    extents: _Floats
    rms: float

class RootsResult(Result):
    roots: _Floats
    multiplicities: npt.NDArray[np.int32]

class GjkResult(Result):
    contact: str
    distance: float
    closest: _Floats
    normal: _Floats
    iterations: int

class PenetrationResult(Result):
    contact: str
    depth: float
    normal: _Floats
    closest: _Floats
    iterations: int

class SegmentIntersections(Result):
    kind: npt.NDArray[np.uint8]
    count: npt.NDArray[np.int8]
    points: _Floats
    param_a: _Floats
    param_b: _Floats

class MeshCheck(Result):
    kind: str
    closed: bool
    manifold: bool
    orientable: bool
    convex: bool
    euler_characteristic: int
    vertex_count: int
    edge_count: int
    face_count: int
    boundary_edges: _Indices
    non_manifold_edges: _Indices
    non_manifold_vertices: _Indices
    isolated_vertices: _Indices
    components: int
    face_component: _Indices
    self_intersections: _Indices
    degenerate_faces: _Indices
    non_planar_faces: _Indices

class MeshSlice(Result):
    polylines: list[_Floats]
    closed: npt.NDArray[np.bool_]

class OrientationResult(Result):
    faces: _Faces
    flipped: npt.NDArray[np.bool_]
    orientable: bool
    face_component: _Indices
    non_orientable_components: _Indices

class RayHits(Result):
    hit: npt.NDArray[np.bool_]
    t: _Floats
    triangle: npt.NDArray[np.int64]
    barycentric: _Floats
    point: _Floats
    front: npt.NDArray[np.bool_]

class BoxHits(Result):
    hit: npt.NDArray[np.bool_]
    t_enter: _Floats
    t_exit: _Floats

class PlanarPieces(Result):
    kind: npt.NDArray[np.int8]
    t: _Floats
    points: _Floats
    st: _Floats

class ConvexIntersection(Result):
    kind: str
    vertices: _Floats

class Contact(Result):
    kind: str
    time: float | None
    points: _Floats

class Contact3(Result):
    kind: str
    time: float | None
    points: _Floats

class CurveIntersections(Result):
    kind: npt.NDArray[np.uint8]
    count: npt.NDArray[np.int8]
    points: _Floats
    multiplicity: npt.NDArray[np.int8]

def _input_address(points: _Points) -> tuple[int, bool]: ...
def convex_hull(
    points: _Points, keep_collinear: bool = False, method: str | None = None
) -> Hull2Result | Hull3Result: ...
def delaunay(points: _Points) -> Delaunay2Result | Delaunay3Result: ...
def constrained_delaunay(points: _Points, constraints: npt.ArrayLike) -> ConstrainedDelaunayResult: ...
def triangulate_polygon(
    points: _Points, ring_ends: npt.ArrayLike | None = None, method: str = "cdt"
) -> TriangulationResult: ...
def trapezoid_map(
    points: _Points, segments: npt.ArrayLike, queries: _Points | None = None
) -> TrapezoidMapResult: ...
def min_circle(points: _Points) -> MinCircleResult: ...
def min_sphere(points: _Points) -> MinSphereResult: ...
def min_rect(points: _Points, perimeter: bool = False) -> MinRectResult: ...
def min_box(points: _Points) -> MinBoxResult: ...
def fit_line(points: _Points) -> LineFitResult: ...
def fit_plane(points: _Points) -> PlaneFitResult: ...
def fit_circle(points: _Points, algebraic: bool = False) -> SphereFitResult: ...
def fit_sphere(points: _Points, algebraic: bool = False) -> SphereFitResult: ...
def fit_gaussian(points: _Points) -> GaussianFitResult: ...
def polynomial_roots(
    coefficients: npt.ArrayLike, lo: float = ..., hi: float = ..., exact: bool = True
) -> RootsResult: ...
def point_in_polygon(
    points: _Points, polygon: _Points, ring_ends: npt.ArrayLike | None = None
) -> npt.NDArray[np.int8]: ...
def point_in_polyhedron(
    points: _Points, vertices: _Points, triangles: npt.ArrayLike
) -> npt.NDArray[np.int8]: ...
def point_triangle_sqr_distances(points: _Points, triangles: npt.ArrayLike) -> _Floats: ...
def segment_segment_sqr_distances(a: npt.ArrayLike, b: npt.ArrayLike) -> _Floats: ...
def segment_triangle_sqr_distances(segments: npt.ArrayLike, triangles: npt.ArrayLike) -> _Floats: ...
def point_box_sqr_distances(points: _Points, boxes: npt.ArrayLike) -> _Floats: ...
def point_oriented_box_sqr_distances(points: _Points, boxes: npt.ArrayLike) -> _Floats: ...
def gjk_distance(a: _Points, b: _Points) -> GjkResult: ...
def penetration(a: _Points, b: _Points) -> PenetrationResult: ...
def segment_intersections(a: npt.ArrayLike, b: npt.ArrayLike) -> SegmentIntersections: ...
def check_mesh(
    vertices: _Points, faces: npt.ArrayLike, coplanarity_tolerance: float = 0.0
) -> MeshCheck: ...
def self_intersections(vertices: _Points, faces: npt.ArrayLike) -> _Indices: ...
def slice_mesh(
    vertices: _Points, faces: npt.ArrayLike, normal: npt.ArrayLike, constant: float
) -> MeshSlice: ...
def orient_consistently(
    faces: npt.ArrayLike, vertex_count: int | None = None
) -> OrientationResult: ...
def tetrahedron() -> _Mesh: ...
def hexahedron() -> _Mesh: ...
def octahedron() -> _Mesh: ...
def dodecahedron(triangulate: bool = False) -> _Mesh: ...
def icosahedron() -> _Mesh: ...
def uv_sphere(radius: float = 1.0, slices: int = 16, stacks: int = 8) -> _Mesh: ...
def icosphere(radius: float = 1.0, levels: int = 2) -> _Mesh: ...
def torus(
    major_radius: float = 1.0,
    minor_radius: float = 0.25,
    major_segments: int = 32,
    minor_segments: int = 16,
) -> _Mesh: ...
def cylinder(radius: float = 1.0, height: float = 2.0, slices: int = 16) -> _Mesh: ...
def cone(radius: float = 1.0, height: float = 2.0, slices: int = 16) -> _Mesh: ...
def read_mesh(path: str, format: str = "") -> _Mesh: ...
def write_mesh(path: str, vertices: _Points, faces: npt.ArrayLike, format: str = "") -> None: ...
def read_points(path: str, dimension: int = 0, format: str = "") -> _Floats: ...

# WKT and GeoJSON geometries (io/wkt.hpp, io/geojson.hpp)
class Geometry(Result):
    type: str
    points: _Floats
    lines: list[_Floats]
    polygons: list[list[_Floats]]

def read_wkt(text: str, orient: bool = False) -> list[Geometry]: ...
def read_geojson(text: str, orient: bool = False) -> list[Geometry]: ...
def triangles_intersect(a: npt.ArrayLike, b: npt.ArrayLike) -> npt.NDArray[np.bool_]: ...
def ray_triangle_hits(
    origins: _Points,
    directions: _Points,
    triangles: npt.ArrayLike,
    faces: npt.ArrayLike | None = None,
) -> RayHits: ...
def ray_box_hits(origins: _Points, directions: _Points, boxes: npt.ArrayLike) -> BoxHits: ...
def segment_box_hits(segments: npt.ArrayLike, boxes: npt.ArrayLike) -> BoxHits: ...
def planar_polygon_pieces(
    polygon: _Points,
    p: npt.ArrayLike,
    q: npt.ArrayLike,
    kind: str = "segment",
    frame: npt.ArrayLike | None = None,
) -> PlanarPieces: ...
def circle_circle(
    c0: npt.ArrayLike, r0: npt.ArrayLike, c1: npt.ArrayLike, r1: npt.ArrayLike
) -> CurveIntersections: ...
def segment_circle(
    segments: npt.ArrayLike, centers: npt.ArrayLike, radii: npt.ArrayLike
) -> CurveIntersections: ...
def circle_ellipse(
    centers: npt.ArrayLike,
    radii: npt.ArrayLike,
    c1: npt.ArrayLike,
    angle1: npt.ArrayLike,
    e1: npt.ArrayLike,
) -> CurveIntersections: ...
def ellipse_ellipse(
    c0: npt.ArrayLike,
    angle0: npt.ArrayLike,
    e0: npt.ArrayLike,
    c1: npt.ArrayLike,
    angle1: npt.ArrayLike,
    e1: npt.ArrayLike,
) -> CurveIntersections: ...
def quadratic_curves(q0: npt.ArrayLike, q1: npt.ArrayLike) -> CurveIntersections: ...
def circle_arc(
    centers: npt.ArrayLike,
    radii: npt.ArrayLike,
    c1: npt.ArrayLike,
    r1: npt.ArrayLike,
    start1: npt.ArrayLike,
    sweep1: npt.ArrayLike,
) -> CurveIntersections: ...
def arc_arc(
    c0: npt.ArrayLike,
    r0: npt.ArrayLike,
    start0: npt.ArrayLike,
    sweep0: npt.ArrayLike,
    c1: npt.ArrayLike,
    r1: npt.ArrayLike,
    start1: npt.ArrayLike,
    sweep1: npt.ArrayLike,
) -> CurveIntersections: ...
def convex_polygons_intersect(a: npt.ArrayLike, b: npt.ArrayLike) -> bool: ...
def convex_polygon_intersection(a: npt.ArrayLike, b: npt.ArrayLike) -> ConvexIntersection: ...
def first_contact(
    a: npt.ArrayLike, va: npt.ArrayLike, b: npt.ArrayLike, vb: npt.ArrayLike, tmax: float
) -> Contact: ...
def sat3_test(a: npt.ArrayLike, b: npt.ArrayLike) -> bool: ...
def sat3_first_contact(
    a: npt.ArrayLike, va: npt.ArrayLike, b: npt.ArrayLike, vb: npt.ArrayLike, tmax: float
) -> Contact3: ...
def ellipsoid_relation(
    center_a: npt.ArrayLike,
    axes_a: npt.ArrayLike,
    extents_a: npt.ArrayLike,
    center_b: npt.ArrayLike,
    axes_b: npt.ArrayLike,
    extents_b: npt.ArrayLike,
) -> str: ...

class SvgWriter:
    def __init__(
        self,
        max_width: float = 480.0,
        max_height: float = 480.0,
        margin: float = 24.0,
        background: str = "white",
        title: str = "",
    ) -> None: ...
    def set_view(self, lo: npt.ArrayLike, hi: npt.ArrayLike) -> None: ...
    def point(self, p: npt.ArrayLike, **style: Any) -> None: ...
    def points(self, points: _Points, **style: Any) -> None: ...
    def segment(self, a: npt.ArrayLike, b: npt.ArrayLike, **style: Any) -> None: ...
    def polyline(self, points: _Points, closed: bool = False, **style: Any) -> None: ...
    def polygon(self, points: _Points, **style: Any) -> None: ...
    def triangles(self, points: _Points, triangles: npt.ArrayLike, **style: Any) -> None: ...
    def circle(self, center: npt.ArrayLike, radius: float, **style: Any) -> None: ...
    def text(self, p: npt.ArrayLike, text: str, **style: Any) -> None: ...
    def __len__(self) -> int: ...
    def to_string(self) -> str: ...
    def write(self, path: str) -> None: ...

# Chapter 12 (construct/misc3.hpp)
def line_plane_angles(
    directions: _Points, normals: _Points, acute: bool = False
) -> npt.NDArray[np.float64]: ...
def line_line_angles(d0: _Points, d1: _Points, acute: bool = False) -> npt.NDArray[np.float64]: ...
def plane_plane_angles(
    n0: _Points, n1: _Points, acute: bool = False
) -> npt.NDArray[np.float64]: ...
def project_points_to_plane(
    points: _Points, normal: npt.ArrayLike, constant: float
) -> npt.NDArray[np.float64]: ...
class Construction(Result):
    circles: _Floats
    lines: _Floats
    infinite: bool
    circle_signs: npt.NDArray[np.int32]
    line_signs: npt.NDArray[np.int32]

def construct(kind: str, args: list[float]) -> Construction: ...
class SurfaceHits(Result):
    count: npt.NDArray[np.int32]
    t: _Floats
    points: _Floats
    normals: _Floats
    uv: _Floats
    multiplicity: npt.NDArray[np.int32]
    on_surface: npt.NDArray[np.bool_]

def ray_quadric_hits(
    origins: _Points, directions: _Points, a: npt.ArrayLike, b: npt.ArrayLike, c: float
) -> SurfaceHits: ...
def ray_torus_hits(
    origins: _Points,
    directions: _Points,
    center: npt.ArrayLike,
    normal: npt.ArrayLike,
    major_radius: float,
    minor_radius: float,
) -> SurfaceHits: ...

# Rays and planes against parametric surfaces (intersection/ray_surface.hpp, plane_surface.hpp)
class PatchHits(Result):
    ray: npt.NDArray[np.int64]
    t: _Floats
    uv: _Floats
    points: _Floats
    normals: _Floats
    tangent: npt.NDArray[np.bool_]
    on_surface: npt.NDArray[np.bool_]

class PatchCurves(Result):
    points: list[_Floats]
    uv: list[_Floats]
    closed: npt.NDArray[np.bool_]

class PatchHermite(Result):
    points: list[_Floats]
    uv: list[_Floats]
    tangents: list[_Floats]
    uv_tangents: list[_Floats]
    closed: npt.NDArray[np.bool_]
    curve_points: list[_Floats]
    curve_uv: list[_Floats]

def ray_surface_hits(
    origins: _Points,
    directions: _Points,
    control: npt.ArrayLike,
    knots_u: npt.ArrayLike | None = None,
    knots_v: npt.ArrayLike | None = None,
    weights: npt.ArrayLike | None = None,
) -> PatchHits: ...
def plane_surface_curves(
    normal: npt.ArrayLike,
    constant: float,
    control: npt.ArrayLike,
    knots_u: npt.ArrayLike | None = None,
    knots_v: npt.ArrayLike | None = None,
    weights: npt.ArrayLike | None = None,
    grid: int = 16,
) -> PatchCurves: ...
def plane_surface_hermite(
    normal: npt.ArrayLike,
    constant: float,
    control: npt.ArrayLike,
    knots_u: npt.ArrayLike | None = None,
    knots_v: npt.ArrayLike | None = None,
    weights: npt.ArrayLike | None = None,
    grid: int = 16,
    t: npt.ArrayLike | None = None,
) -> PatchHermite: ...

# Convex partition and the BSP tree of a polygon (triangulate/convex_partition.hpp, bsp/bsp2.hpp,
# bsp/bsp2_boolean.hpp)
class ConvexPartitionResult(Result):
    points: _Floats
    vertices: _Indices
    piece_ends: _Indices
    diagonals: _Indices
    @property
    def pieces(self) -> list[_Indices]: ...

class BspPartition(Result):
    pieces: _Floats
    location: npt.NDArray[np.int8]
    segment: _Indices

class BspBoolean(Result):
    edges: _Floats
    operand: npt.NDArray[np.uint8]
    loops: list[_Floats]
    closed: bool
    segments: _Floats
    points: _Floats

def convex_partition(
    outer: _Points, holes: list[_Points] | None = None, method: str = "hertel_mehlhorn"
) -> ConvexPartitionResult: ...
def bsp_classify(
    polygon_rings: _Points | list[_Points], points: _Points
) -> npt.NDArray[np.int8]: ...
def bsp_partition(
    polygon_rings: _Points | list[_Points], segments: npt.ArrayLike
) -> BspPartition: ...
def bsp_boolean(
    op: str, a: _Points | list[_Points], b: _Points | list[_Points]
) -> BspBoolean: ...
# Polygon booleans (boolean/polygon_boolean.hpp)
class BooleanResult(Result):
    polygons: list[list[_Floats]]
    grid: float

def boolean(
    op: str,
    a: _Points | list[_Points],
    b: _Points | list[_Points],
    fill_rule: str = "even_odd",
    grid_bits: int = 0,
) -> BooleanResult: ...
# Polygon offsetting (boolean/polygon_offset.hpp)
def offset(
    region: _Points | list[_Points] | list[list[_Points]],
    delta: float,
    join: str = "round",
    miter_limit: float = 2.0,
    arc_tolerance: float = 0.0,
    grid_bits: int = 0,
) -> BooleanResult: ...
def offset_polyline(
    paths: _Points | list[_Points],
    delta: float,
    join: str = "round",
    end: str = "round",
    closed: bool = False,
    miter_limit: float = 2.0,
    arc_tolerance: float = 0.0,
    grid_bits: int = 0,
) -> BooleanResult: ...
class MeshBooleanResult(Result):
    vertices: _Floats
    triangles: _Indices

def mesh_boolean(
    op: str, a: tuple[_Points, npt.ArrayLike], b: tuple[_Points, npt.ArrayLike]
) -> MeshBooleanResult: ...
def bspline_surface_insert_knot(
    control: npt.ArrayLike,
    knots_u: npt.ArrayLike,
    knots_v: npt.ArrayLike,
    degree_u: int,
    degree_v: int,
    t: float,
    direction: str = "u",
    times: int = 1,
) -> tuple[_Floats, _Floats, _Floats]: ...

class CurveHits(Result):
    kind: str
    points: _Floats
    param_a: _Floats
    param_b: _Floats
    multiplicity: npt.NDArray[np.int32]

_Curve = _Points | dict[str, Any]

def line_curve_hits(
    a: npt.ArrayLike,
    b: npt.ArrayLike,
    curve: _Curve,
    component: str = "line",
    method: str = "algebraic",
    tolerance: float = ...,
    raster_cells: int = 256,
) -> CurveHits: ...
def curve_intersections(
    a: _Curve,
    b: _Curve,
    method: str = "algebraic",
    tolerance: float = ...,
    raster_cells: int = 256,
) -> CurveHits: ...
def curve_self_intersections(
    curve: _Curve,
    method: str = "algebraic",
    tolerance: float = ...,
    raster_cells: int = 256,
) -> CurveHits: ...
