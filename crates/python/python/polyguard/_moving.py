"""``encounters``: whole flights against areas, with the certified spans of inside and
near (docs/moving-features.md), as a pandas DataFrame: the answer of ``polyguard
encounters`` one span a row.

The inputs are turned into what the native module reads: MF-JSON / GeoJSON text, or the
columns of a table of fixes (numpy arrays) that Rust groups into trajectories as the CSV
of fixes is grouped (flight_id, else icao24 and callsign).
"""

import json
import warnings
from typing import Any, Dict, List, Optional

import numpy as np

from ._native import _encounters_columns, _encounters_json

COLUMNS = ["mover", "callsign", "area", "relation", "start_lo", "start_hi", "end_lo",
           "end_hi", "certain", "start", "end"]
TEXT = ("mover", "callsign", "area", "relation")


def _pandas() -> Any:
    """pandas, imported when first needed (the rest of the package does not need it)."""
    try:
        import pandas
    except ImportError as e:
        raise ImportError("polyguard.encounters returns a pandas DataFrame: "
                          "install pandas (pip install pandas)") from e
    return pandas


def _is_frame(obj: Any) -> bool:
    """Whether obj is a pandas DataFrame (GeoDataFrame included), without importing pandas."""
    return any(c.__module__.split(".")[0] in ("pandas", "geopandas")
               and c.__name__ in ("DataFrame", "GeoDataFrame") for c in type(obj).__mro__)


def _jsonable(x: Any) -> Any:
    """numpy scalars and arrays as JSON values (dicts built from frames hold them)."""
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, np.ndarray):
        return x.tolist()
    raise TypeError(f"{type(x).__name__} is not JSON")


def _json_text(obj: Any) -> str:
    """MF-JSON / GeoJSON as text: a string as it is, a list of Features as a
    FeatureCollection, any other dict as JSON."""
    if isinstance(obj, (str, bytes)):
        return obj.decode() if isinstance(obj, bytes) else obj
    if isinstance(obj, (list, tuple)):
        obj = {"type": "FeatureCollection", "features": list(obj)}
    return json.dumps(obj, default=_jsonable, allow_nan=True)


def _areas_text(areas: Any) -> str:
    """Areas as GeoJSON text; a GeoDataFrame through its ``__geo_interface__``, each
    feature's id its ``id`` column (else its index), its ``floor_ft`` / ``ceiling_ft``
    (when not missing) its only properties."""
    if not _is_frame(areas):
        return _json_text(areas)
    ids = areas["id"].tolist() if "id" in areas.columns else list(areas.index)
    features = []
    for k, f in enumerate(areas.__geo_interface__["features"]):
        props = {}
        for name in ("floor_ft", "ceiling_ft"):
            v = f["properties"].get(name)
            if v is not None and not (isinstance(v, float) and np.isnan(v)):
                props[name] = float(v)
        features.append({"type": "Feature", "id": str(ids[k]), "geometry": f["geometry"],
                         "properties": props})
    return _json_text(features)


def _texts(frame: Any, name: str) -> Optional[List[Optional[str]]]:
    """A text column as a list (missing cells None), or None without that column."""
    if name not in frame.columns:
        return None
    col = frame[name]
    return [None if m else str(v) for v, m in zip(col.tolist(), col.isna().tolist())]


def _columns(frame: Any) -> Dict[str, Any]:
    """The arrays of a frame of fixes: ``timestamp`` (a column of datetimes, texts or
    epoch seconds, else a DatetimeIndex; tz-naive is UTC) as int64 nanoseconds,
    coordinates and altitude as float64."""
    pd = _pandas()
    if "timestamp" in frame.columns:
        col = frame["timestamp"]
        # numbers are epoch seconds, as in the CSV of fixes (not pandas' nanoseconds)
        numeric = pd.api.types.is_numeric_dtype(col) and not pd.api.types.is_bool_dtype(col)
        times = pd.to_datetime(col, utc=True, unit="s" if numeric else None)
    elif isinstance(frame.index, pd.DatetimeIndex):
        times = pd.Series(frame.index, index=frame.index)
        times = times.dt.tz_localize("UTC") if times.dt.tz is None else times
    else:
        raise ValueError("movers: a frame of fixes needs a 'timestamp' column or a "
                         "DatetimeIndex")
    missing = [c for c in ("icao24", "latitude", "longitude") if c not in frame.columns]
    if missing:
        raise ValueError(f"movers: the frame has no column {', '.join(missing)} "
                         "(required: timestamp, icao24, latitude, longitude)")
    t_ns = times.dt.tz_convert("UTC").dt.tz_localize(None).to_numpy(dtype="datetime64[ns]")

    def floats(name: str) -> Any:
        return frame[name].to_numpy(dtype=np.float64, na_value=np.nan)

    return {
        "t_ns": t_ns.view(np.int64),
        "lon": floats("longitude"),
        "lat": floats("latitude"),
        "alt": floats("altitude") if "altitude" in frame.columns else None,
        "icao24": _texts(frame, "icao24"),
        "callsign": _texts(frame, "callsign"),
        "flight_id": _texts(frame, "flight_id"),
    }


def encounters(movers: Any, areas: Any, *, sep: float = 0.0, sep_v: float = 0.0,
               max_gap: float = 60.0, geodesy: str = "sphere") -> Any:
    """Whole flights against areas (docs/moving-features.md): one row per certified span
    of ``inside`` or ``near`` (within ``sep`` nm and ``sep_v`` ft), the answer of
    ``polyguard encounters`` (same movers, areas, order and values).

    - movers: MF-JSON trajectories / MovingPoints (a dict, a list of Feature dicts or a
      JSON string), or a pandas DataFrame of fixes as traffic or MovingPandas hold them
      (``timestamp`` or a DatetimeIndex, ``icao24``, ``latitude``, ``longitude``, optional
      ``callsign``, ``altitude`` in feet, ``flight_id``), grouped as the CSV of fixes.
    - areas: GeoJSON Polygons / MultiPolygons or MF-JSON MovingPolygons (dict, list or
      string), or a GeoDataFrame (``floor_ft``, ``ceiling_ft`` columns; ids from an
      ``id`` column, else the index).

    Columns: mover, callsign, area, relation ('inside' | 'near'), start_lo, start_hi,
    end_lo, end_hi (epoch seconds), certain, start (start_lo as a UTC Timestamp), end
    (end_hi). Features or rows that cannot be read are named in one ``warnings.warn``;
    ``polyguard.Error`` is raised when nothing can be read or an option is bad.
    """
    pd = _pandas()
    opts = {"sep": float(sep), "sep_v": float(sep_v), "max_gap": float(max_gap),
            "geodesy": geodesy}
    areas_text = _areas_text(areas)
    if _is_frame(movers):
        cols, errors, remarks = _encounters_columns(areas=areas_text, **_columns(movers),
                                                    **opts)
    else:
        cols, errors, remarks = _encounters_json(_json_text(movers), areas_text, **opts)
    if errors:
        warnings.warn("polyguard.encounters: some input was not answered:\n"
                      + "\n".join(errors), stacklevel=2)
    if remarks:
        warnings.warn("polyguard.encounters: " + "\n".join(remarks), stacklevel=2)
    # The dtypes do not depend on the rows: an empty answer (a Dask `meta`) has the
    # dtypes of a full one. Text takes the dtype pandas gives a list of str.
    text = pd.Series(["x"]).dtype
    frame = pd.DataFrame({k: pd.Series(cols[k], dtype=text if k in TEXT else None)
                          for k in COLUMNS[:-2]})
    for name, seconds in (("start", "start_lo"), ("end", "end_hi")):
        frame[name] = pd.to_datetime(frame[seconds], unit="s", utc=True).astype(
            "datetime64[ns, UTC]")
    return frame
