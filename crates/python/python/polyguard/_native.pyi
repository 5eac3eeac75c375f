"""Type stubs of polyguard's native module (the functions are re-exported by ``polyguard``).

Paper A: A. Narkawicz and G. Hagen, Algorithms for Collision Detection Between a Point and
a Moving Polygon, with Applications to Aircraft Weather Avoidance, AIAA Aviation 2016.
Paper B: A. Bienkowski, D. Sidoti and K. R. Pattipati, Interference Identification for
Time-Varying Polyhedra, IEEE Access 9 (2021).
"""

from typing import (
    Any,
    Iterator,
    Literal,
    Mapping,
    Optional,
    Sequence,
    Tuple,
    TypedDict,
    Union,
    final,
    overload,
)

import numpy as np
import numpy.typing as npt

__all__ = [
    "CaseError",
    "Detection",
    "EntryTime",
    "Error",
    "KIND_CONSERVATIVE",
    "KIND_EXACT",
    "ScenarioError",
    "Truth",
    "__version__",
    "_encounters_columns",
    "_encounters_json",
    "conflicts",
    "course_bands",
    "detect",
    "detect_batch",
    "detect_case",
    "detect_exit",
    "detect_time",
    "detect_time_case",
    "inset",
    "intervals",
    "offset",
    "recover",
    "speed_bands",
    "truth",
    "truth_case",
    "vertical_speed_bands",
]

__version__: str

KIND_EXACT: int
"""Kind code of a batch hit whose every comparison was certified (0)."""
KIND_CONSERVATIVE: int
"""Kind code of a batch hit taken on a comparison f64 could not decide (1)."""

_Number = Union[float, int, np.floating[Any], np.integer[Any]]
_Vector = Union[Sequence[_Number], npt.NDArray[np.floating[Any]]]
_Points = Union[Sequence[Sequence[_Number]], npt.NDArray[np.floating[Any]]]
_Array = Union[npt.ArrayLike, npt.NDArray[Any]]
_Case = Union[Mapping[str, Any], str]

class _Span(TypedDict):
    """One span of ``intervals``: where the relation starts and stops, each enclosed."""

    start: Tuple[float, float]
    end: Tuple[float, float]
    certain: bool

class _Intervals(TypedDict):
    """``intervals(case, relation=None)``: the CLI's ``intervals`` object."""

    sep: float
    sep_v: float
    inside: list[_Span]
    near: list[_Span]
    breach: list[_Span]
    loss_of_separation: Optional[Tuple[float, float]]

class _Exit(TypedDict):
    """``detect_exit``'s answer: the CLI's ``exits`` and ``exit_kind``."""

    exits: bool
    kind: Literal["exact", "conservative"]

class Error(ValueError):
    """Bad input to polyguard: ``field`` names what is wrong, the message says why."""

    field: str

class CaseError(Error):
    """A detection case that breaks a rule of docs/cases.md (paper A's inputs).

    ``field`` is the case format's path: ``lookahead``, ``buff``, ``point.pos``,
    ``polygon.vertices[2][1]``, ``polygon.top``; in a batch the item is named,
    ``points[3].pos`` or ``polygons[7].vertices``, or the array, ``poly_offsets``.
    """

    field: str

class ScenarioError(Error):
    """A scenario GeoJSON (paper B) that cannot be read at all, or a bad option."""

    field: str
    line: Optional[int]

@final
class Detection:
    """The answer of ``detect`` (the fields of a ``polyguard detect`` answer line)."""

    detected: bool
    """Within BUFF (or F's slack) within [0, T], or undecided in f64 (then conservative)."""
    kind: Literal["exact", "conservative"]
    """"exact": paper A without rounding answers the same; "conservative": a yes taken
    on a comparison f64 could not decide (never a no)."""
    decided_by: Literal["detect_same_2d", "detect_diff_2d", "detect_3d"]
    """Which paper function decided (§II.H, §II.I, §III)."""
    well_formed: bool
    """Paper A §II.J at t = 0, for information only."""
    well_formed_reason: Optional[str]
    """Which §II.J rule fails when ``well_formed`` is False."""
    def to_dict(self) -> dict[str, Any]:
        """The answer as ``polyguard detect`` writes it after ``id``."""
    def __bool__(self) -> bool: ...

@final
class EntryTime:
    """The answer of ``detect_time``: where the exact first-entry time t* lies."""

    kind: Literal["never", "enters", "possible"]
    """"never" and "enters" are certified; "possible": undecided in f64."""
    lo: Optional[float]
    """No entry before lo (None for "never")."""
    hi: Optional[float]
    """"enters": in the polygon at some time <= hi; "possible": T (None for "never")."""
    def __iter__(self) -> Iterator[Any]:
        """``kind, lo, hi = detect_time(...)``."""

@final
class Truth:
    """The exact first-entry time from the oracle (rational arithmetic)."""

    entry_time: float
    """The float nearest to the exact time."""
    entry_time_exact: str
    """The exact time: ``p/q`` or ``a + (b)·√(d)``."""

def detect(
    lookahead: _Number,
    pos: _Vector,
    vel: _Vector,
    vertices: _Points,
    velocities: Optional[_Points] = None,
    *,
    buff: _Number,
    fac: _Number = 0.0001,
    kappa_deg: _Number = 5.0,
    bottom: Optional[_Number] = None,
    top: Optional[_Number] = None,
    vz: Optional[_Number] = None,
) -> Detection:
    """Does the point pos + t·vel come within ``buff`` of the polygon vertices +
    t·velocities for some t in [0, lookahead]?

    Paper A: detect_same_2D (§II.H) when all vertex velocities are equal (or none are
    given: at rest), detect_diff_2D (§II.I) otherwise, detect_3D (§III) when ``pos`` and
    ``vel`` have a height and the polygon a slab (``bottom``, ``top``, ``vz``). Vertices
    counterclockwise. ``fac`` is F (§II.I), ``kappa_deg`` the corner angle of §II.J.
    Polygons of 64 vertices or more are answered without the GIL.

    Raises CaseError naming the field.
    """

def detect_case(case: Union[Mapping[str, Any], str]) -> Detection:
    """``detect`` on a case object of docs/cases.md (a dict, or a JSON line).

    A dict is written by ``json.dumps`` and read by the case format's own reader: its
    values must be JSON-serialisable (lists, not numpy arrays); unknown or repeated keys
    and NaN are errors naming the field.
    """

def detect_time(
    lookahead: _Number,
    pos: _Vector,
    vel: _Vector,
    vertices: _Points,
    velocities: Optional[_Points] = None,
    *,
    buff: _Number,
    fac: _Number = 0.0001,
    kappa_deg: _Number = 5.0,
    bottom: Optional[_Number] = None,
    top: Optional[_Number] = None,
    vz: Optional[_Number] = None,
) -> EntryTime:
    """When the point first enters the closed polygon (and slab), enclosed in f64.

    No BUFF: the time the exact truth computes, which paper A's detection (§II–III) is
    guaranteed to flag. ``buff``, ``fac``, ``kappa_deg`` are validated as for ``detect``.
    """

def detect_time_case(case: Union[Mapping[str, Any], str]) -> EntryTime:
    """``detect_time`` on a case object of docs/cases.md."""

@overload
def intervals(
    case: _Case,
    relation: Literal["inside", "near", "breach"] = "near",
    sep: _Number = 0.0,
    sep_v: _Number = 0.0,
) -> list[_Span]:
    """Every time during [0, lookahead] that the relation holds, as certified spans
    (docs/cases.md, "Separation and fences"): "inside" the closed polygon (and slab),
    "near" (within ``sep`` of it, and ``sep_v`` of the slab: the first start is the loss
    of separation), or "breach" (not deeper than ``sep`` inside a keep-in fence, or than
    ``sep_v`` inside its slab). The same numbers as ``polyguard detect --intervals``.

    ``case`` is a case object of docs/cases.md; its own ``sep`` and ``sep_v`` win over
    the arguments, as a line's do over the CLI's ``--sep`` and ``--sep-v``. Spans are
    sorted; nothing is missed; every end of the set lies in a span's ``start`` or
    ``end``; a ``certain`` span holds throughout [start[1], end[0]].

    Raises CaseError naming the field (``sep``), or Error naming ``relation``.
    """

@overload
def intervals(
    case: _Case,
    relation: None,
    sep: _Number = 0.0,
    sep_v: _Number = 0.0,
) -> _Intervals:
    """The three relations at once: the CLI's ``intervals`` object (see above)."""

def detect_exit(case: _Case, sep: _Number = 0.0, sep_v: _Number = 0.0) -> _Exit:
    """Does the point leave the polygon taken as a keep-in fence (come within ``sep`` of
    its boundary or outside it, or within ``sep_v`` of the slab's floor or ceiling)
    during [0, lookahead]? Never False when it does: ``polyguard detect --fence
    keep-in``'s ``exits`` and ``exit_kind``. The case's own ``sep``, ``sep_v`` win.
    """

def truth(
    lookahead: _Number,
    pos: _Vector,
    vel: _Vector,
    vertices: _Points,
    velocities: Optional[_Points] = None,
    *,
    buff: _Number,
    fac: _Number = 0.0001,
    kappa_deg: _Number = 5.0,
    bottom: Optional[_Number] = None,
    top: Optional[_Number] = None,
    vz: Optional[_Number] = None,
) -> Optional[Truth]:
    """The exact first-entry time (the oracle, rational arithmetic), or None when the
    point never enters the closed polygon (and slab) within [0, lookahead]: the ground
    truth paper A's theorem (§II–III) says detection must flag. Releases the GIL.
    """

def truth_case(case: Union[Mapping[str, Any], str]) -> Optional[Truth]:
    """``truth`` on a case object of docs/cases.md."""

def detect_batch(
    lookahead: _Number,
    points_pos: _Array,
    points_vel: _Array,
    poly_vertices: _Array,
    poly_offsets: Optional[_Array] = None,
    poly_velocities: Optional[_Array] = None,
    *,
    buff: _Number,
    fac: _Number = 0.0001,
    poly_slabs: Optional[_Array] = None,
    parallel: bool = True,
) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.int64], npt.NDArray[np.uint8]]:
    """Paper A (§II.H, §II.I, §III) for every point against every polygon.

    Returns (point index, polygon index, kind code) arrays of the detected pairs, sorted
    by (point, polygon): exactly the pairs ``detect`` answers detected. Kind codes:
    KIND_EXACT, KIND_CONSERVATIVE.

    - points_pos, points_vel: (N, 2), or (N, 3) with the height.
    - poly_vertices: (M, n, 2), or (V, 2) with poly_offsets (M + 1 integers, 0 to V).
    - poly_velocities: None (at rest), poly_vertices' shape, or (M, 2) (one drift each).
    - poly_slabs: (M, 3) of bottom, top, vz for a 3-D batch.

    float64 arrays are read in place (any strides); other inputs are converted to
    float64 first (one copy). Releases the GIL. Raises CaseError naming the array or
    the item (``polygons[7].vertices``).
    """

def conflicts(
    geojson: str,
    geodesy: Literal["sphere", "wgs84"] = "sphere",
    *,
    tolerance_s: float = 1.0,
    regions: bool = True,
) -> dict[str, Any]:
    """Paper B's four stages (§IV) on a scenario GeoJSON text (docs/scenario.md).

    Returns the answer object of ``polyguard conflicts``: ``conflicts``, ``stats``,
    ``errors`` (rejected features; the others are still answered), ``warnings``.
    Raises ScenarioError when the text cannot be read at all.
    """

_Encountered = Tuple[dict[str, Any], list[str], list[str]]

def _encounters_json(
    movers: str,
    areas: str,
    *,
    sep: float = 0.0,
    sep_v: float = 0.0,
    max_gap: float = 60.0,
    geodesy: str = "sphere",
) -> _Encountered:
    """The encounters of MF-JSON movers with GeoJSON / MF-JSON areas
    (docs/moving-features.md): (columns, errors, warnings), one entry per span in the
    columns; ``polyguard.encounters`` makes the DataFrame. Raises Error when nothing can
    be read or an option is bad. Releases the GIL.
    """

def _encounters_columns(
    t_ns: npt.NDArray[np.int64],
    lon: npt.NDArray[np.float64],
    lat: npt.NDArray[np.float64],
    alt: Optional[npt.NDArray[np.float64]],
    icao24: Sequence[Optional[str]],
    callsign: Optional[Sequence[Optional[str]]],
    flight_id: Optional[Sequence[Optional[str]]],
    areas: str,
    *,
    sep: float = 0.0,
    sep_v: float = 0.0,
    max_gap: float = 60.0,
    geodesy: str = "sphere",
) -> _Encountered:
    """``_encounters_json`` for movers given as the columns of a table of fixes
    (int64 nanoseconds, NaT as missing; NaN altitude: none), grouped as the CSV of fixes.
    """

_Kind = Literal["clear", "conflict", "unknown"]

class _CourseBands(TypedDict):
    """``course_bands``' answer: the bands in degrees, tiling [0, 360]."""

    bands: list[Tuple[float, float, _Kind]]
    unknown_total_deg: float
    met: bool

class _Bands(TypedDict):
    """``speed_bands`` / ``vertical_speed_bands``' answer: the bands tiling [min, max]."""

    bands: list[Tuple[float, float, _Kind]]
    unknown_total: float
    met: bool

class _Recovery(TypedDict, total=False):
    """``recover``'s answer: ``point``, ``distance``, ``min_lo``, ``moved``; or
    ``impossible`` alone."""

    point: Tuple[float, float]
    distance: float
    min_lo: float
    moved: bool
    impossible: str

class _Region(TypedDict):
    """One region of ``offset`` / ``inset``: its outer ring (counterclockwise) and its
    holes (clockwise)."""

    outer: list[Tuple[float, float]]
    holes: list[list[Tuple[float, float]]]

def course_bands(
    pos: _Vector,
    vel: _Vector,
    obstacles: Sequence[Mapping[str, Any]],
    *,
    lookahead: _Number,
    sep: _Number,
    sep_v: _Number = 0.0,
    speed: Optional[_Number] = None,
    unknown_max_deg: _Number = 0.1,
) -> _CourseBands:
    """Course bands over [0°, 360°] (clockwise from +y) for the point at ``pos`` (3
    numbers in 3D, ``vel``'s third the vertical speed) moving at ``speed`` (default: the
    horizontal |vel|) among the moving ``obstacles`` over [0, lookahead], separation
    ``sep`` (and ``sep_v`` in 3D). A clear band is certified free of loss of separation
    for every course in it, a conflict band certified in conflict for every course; the
    Unknown total is refined towards ``unknown_max_deg``. Raises Error naming the field.
    """

def speed_bands(
    pos: _Vector,
    vel: _Vector,
    obstacles: Sequence[Mapping[str, Any]],
    *,
    lookahead: _Number,
    sep: _Number,
    min: _Number,
    max: _Number,
    sep_v: _Number = 0.0,
    course_deg: Optional[_Number] = None,
    unknown_max: Optional[_Number] = None,
) -> _Bands:
    """Speed bands over [min, max] at ``course_deg`` (default: ``vel``'s course), as
    ``course_bands``; ``unknown_max`` defaults to (max - min) / 1000."""

def vertical_speed_bands(
    pos: _Vector,
    vel: _Vector,
    obstacles: Sequence[Mapping[str, Any]],
    *,
    lookahead: _Number,
    sep: _Number,
    sep_v: _Number,
    min: _Number,
    max: _Number,
    unknown_max: Optional[_Number] = None,
) -> _Bands:
    """Vertical speed bands over [min, max] with ``vel``'s horizontal part fixed (3D:
    ``pos`` and ``vel`` of 3 numbers), as ``speed_bands``."""

def recover(
    vertices: _Points,
    s: _Vector,
    sep: _Number,
    *,
    fence: Literal["keep_out", "keep_in"] = "keep_out",
    velocities: Optional[_Points] = None,
    t: _Number = 0.0,
) -> _Recovery:
    """The nearest point to ``s`` at least ``sep`` from the polygon (``keep_out``), or
    inside it at least ``sep`` from its boundary (``keep_in``), at time ``t``: certified
    to meet its condition, the exact minimum distance in [min_lo, distance]; or
    ``{"impossible": reason}``. Raises Error naming the field."""

def offset(
    vertices: _Points,
    d: _Number,
    eps: _Number = 0.01,
    *,
    velocities: Optional[_Points] = None,
    t: _Number = 0.0,
) -> list[_Region]:
    """The certified offset by ``d``: regions Q with P + disc(d) inside Q inside
    P + disc(d (1 + eps)). Raises Error naming the field."""

def inset(
    vertices: _Points,
    d: _Number,
    eps: _Number = 0.01,
    *,
    velocities: Optional[_Points] = None,
    t: _Number = 0.0,
) -> list[_Region]:
    """The certified inset by ``d``: pieces inside {x in P : dist(x, boundary) >= d}
    containing {x in P : dist(x, boundary) >= d (1 + eps)}; maybe none."""
