"""polyguard: does a moving point enter a moving polygon, and which moving areas conflict?

- Paper A (A. Narkawicz and G. Hagen, NASA, AIAA Aviation 2016): ``detect`` answers whether
  a linearly moving point comes within BUFF of a moving, possibly warping polygon within a
  lookahead time (detect_same_2D §II.H, detect_diff_2D §II.I, detect_3D §III). Every
  comparison is certified: a "no" is always paper A's exact "no". ``detect_time`` encloses
  the first entry time; ``truth`` computes it exactly (rational arithmetic);
  ``detect_batch`` checks N points against M polygons from numpy arrays.
- Beyond paper A (docs/cases.md, "Separation and fences"): ``intervals`` encloses every
  time the point is inside, within a separation of (loss of separation) or breaching a
  keep-in polygon; ``detect_exit`` says whether it leaves a keep-in fence.
- Moving features (docs/moving-features.md): ``encounters`` answers whole flights (MF-JSON,
  or pandas frames of fixes as traffic and MovingPandas hold them) against static and
  moving areas with the certified spans of inside and near, as a pandas DataFrame.
- The way out (docs/python.md, "The way out"): ``course_bands``, ``speed_bands`` and
  ``vertical_speed_bands`` give certified conflict-free bands among moving polygons,
  ``recover`` the nearest point out of (or into) a polygon's separation, ``offset`` and
  ``inset`` certified grown and shrunk polygons.
- Paper B (A. Bienkowski, D. Sidoti and K. R. Pattipati, IEEE Access 9, 2021):
  ``conflicts`` runs the four-stage interference identification (§IV) on a scenario
  GeoJSON.

Bad input raises ``CaseError`` / ``ScenarioError`` (both ``ValueError``), whose ``field``
names the field as the case format spells it (``polygon.vertices[2][1]``).
"""

from ._native import (
    KIND_CONSERVATIVE,
    KIND_EXACT,
    CaseError,
    Detection,
    EntryTime,
    Error,
    ScenarioError,
    Truth,
    __version__,
    conflicts,
    course_bands,
    detect,
    detect_batch,
    detect_case,
    detect_exit,
    detect_time,
    detect_time_case,
    inset,
    intervals,
    offset,
    recover,
    speed_bands,
    truth,
    truth_case,
    vertical_speed_bands,
)
from ._moving import encounters

__all__ = [
    "KIND_CONSERVATIVE",
    "KIND_EXACT",
    "CaseError",
    "Detection",
    "EntryTime",
    "Error",
    "ScenarioError",
    "Truth",
    "__version__",
    "conflicts",
    "course_bands",
    "detect",
    "detect_batch",
    "detect_case",
    "detect_exit",
    "detect_time",
    "detect_time_case",
    "encounters",
    "inset",
    "intervals",
    "offset",
    "recover",
    "speed_bands",
    "truth",
    "truth_case",
    "vertical_speed_bands",
]
