"""A frame pair's pose over time from a loaded buffer, written as CSV (or Parquet with pyarrow).

Rows are ``stamp_ns, time_s, x, y, z, qx, qy, qz, qw``: the pose of ``child`` in
``parent`` (as ``lookup_transform(parent, child, t)``). Without a rate the stamps are the
recorded ones of every dynamic frame between the two (all samples, merged); with a rate
they are evenly spaced. Either way only the span where the whole chain has data is used,
and a stamp the buffer cannot answer (a gap across a parent change) is left out.
"""

from __future__ import annotations

import importlib
import io
import os
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
import numpy.typing as npt

from robotmodel.errors import RecordingError, TransformException

if TYPE_CHECKING:
    from robotmodel.tf import Buffer

__all__ = ["COLUMNS", "MAX_ROWS", "MAX_STEPS", "PoseSeries", "pose_series", "sample_times", "write_poses"]

COLUMNS = ("stamp_ns", "time_s", "x", "y", "z", "qx", "qy", "qz", "qw")
#: Most instants :func:`sample_times` gives by default (tf2-echo --every prints a block for each).
MAX_STEPS = 100_000
#: Most rows :func:`pose_series` samples at a rate (7 doubles and a stamp each: 640 MB).
MAX_ROWS = 10_000_000


class PoseSeries(NamedTuple):
    """Stamps (N,) int64 ns, translations (N, 3), quaternions (N, 4) x y z w."""

    stamps: npt.NDArray[np.int64]
    translations: npt.NDArray[np.float64]
    rotations: npt.NDArray[np.float64]


def _chain(buffer: Buffer, frame: str) -> list[str]:
    parents = buffer.frames()
    out, seen = [], set()
    while frame in parents and frame not in seen:
        seen.add(frame)
        out.append(frame)
        frame = parents[frame]
    return out


def _recorded_stamps(buffer: Buffer, frames: list[str]) -> list[npt.NDArray[np.int64]]:
    # The buffer's own per-frame arrays (read-only views); robotmodel.tf has no public
    # accessor for a frame's stamps, and copying them at load time would double the memory.
    from robotmodel.tf._cache import TimeCache

    out = []
    with buffer._lock:
        for name in frames:
            cache = buffer._caches[buffer._ids[name]]
            if isinstance(cache, TimeCache) and len(cache):
                out.append(cache.arrays()[0].copy())
    return out


def sample_times(start_ns: int, end_ns: int, step_ns: int, *, limit: int = MAX_STEPS, where: str = "") -> range:
    """``start_ns``, ``start_ns + step_ns``, ... up to ``end_ns`` (included), as a range.

    Raises :class:`RecordingError` when that is more than ``limit`` instants: over a span
    that long a damaged stamp (one flipped bit in the seconds moves it days away) is far
    likelier than the wish, and the answer would be millions of lookups. ``where`` (a
    file name) starts the message.
    """
    if step_ns <= 0:
        raise ValueError(f"the step must be positive, got {step_ns} ns")
    count = (end_ns - start_ns) // step_ns + 1 if end_ns >= start_ns else 0
    if count > limit:
        prefix = f"{where}: " if where else ""
        raise RecordingError(
            f"{prefix}the transforms span {(end_ns - start_ns) / 1e9:.9g} s (t={start_ns / 1e9:.9f} to "
            f"t={end_ns / 1e9:.9f}): every {step_ns / 1e9:.9g} s is {count:,} instants, more than {limit:,} "
            "(is a stamp damaged? ask for fewer: a longer step, or one time)")
    return range(start_ns, end_ns + 1, step_ns)


def pose_series(buffer: Buffer, parent: str, child: str, rate_hz: float | None = None) -> PoseSeries:
    """The pose of ``child`` in ``parent`` at the recorded stamps (or every 1/``rate_hz`` s).

    Raises :class:`~robotmodel.errors.TransformException` (tf2's text) when the frames
    are unknown or never connected, and :class:`RecordingError` when a rate would sample
    more than :data:`MAX_ROWS` rows (see :func:`sample_times`).
    """
    chain = sorted(set(_chain(buffer, parent)) ^ set(_chain(buffer, child)))
    stamps_per_frame = _recorded_stamps(buffer, chain)
    buffer.lookup_ns(parent, child, 0)  # raises tf2's error for unknown or unconnected frames
    if not stamps_per_frame:  # all static: one pose, valid at any time
        pose, _ = buffer.lookup_ns(parent, child, 0)
        return PoseSeries(np.zeros(1, dtype=np.int64), np.array([pose[:3]]), np.array([pose[3:]]))
    start = max(int(s[0]) for s in stamps_per_frame)
    end = min(int(s[-1]) for s in stamps_per_frame)
    if rate_hz is None:
        merged = np.unique(np.concatenate(stamps_per_frame))
        stamps = merged[(merged >= start) & (merged <= end)]
    else:
        times = sample_times(start, end, max(round(1e9 / rate_hz), 1), limit=MAX_ROWS)
        stamps = np.arange(times.start, times.stop, times.step, dtype=np.int64)
    return _lookup_all(buffer, parent, child, stamps)


def _lookup_all(buffer: Buffer, parent: str, child: str, stamps: npt.NDArray[np.int64]) -> PoseSeries:
    stamps = stamps[stamps > 0]
    if not len(stamps):
        return PoseSeries(stamps, np.zeros((0, 3)), np.zeros((0, 4)))
    try:
        trans, quats = buffer.lookup_transforms(parent, child, stamps)
        return PoseSeries(stamps, trans, quats)
    except TransformException:
        pass
    kept, rows = [], []
    for t in stamps.tolist():
        try:
            pose, _ = buffer.lookup_ns(parent, child, t)
        except TransformException:
            continue
        kept.append(t)
        rows.append(pose)
    poses = np.asarray(rows, dtype=np.float64).reshape(-1, 7)
    return PoseSeries(np.asarray(kept, dtype=np.int64), poses[:, :3], poses[:, 3:])


def _csv_text(series: PoseSeries) -> str:
    buf = io.StringIO()
    buf.write(",".join(COLUMNS) + "\n")
    for s, t, q in zip(series.stamps.tolist(), series.translations.tolist(), series.rotations.tolist(),
                       strict=True):
        values = ",".join(repr(v) for v in (*t, *q))
        buf.write(f"{s},{s // 1_000_000_000}.{s % 1_000_000_000:09d},{values}\n")
    return buf.getvalue()


def write_poses(series: PoseSeries, path: str | os.PathLike[str]) -> Path:
    """Write ``series`` as CSV, or as Parquet when ``path`` ends in ``.parquet`` (needs pyarrow).

    The file appears whole or not at all (written beside it, then renamed).
    """
    out = Path(path)
    tmp = out.with_name(f".{out.name}.tmp")
    try:
        if out.suffix == ".parquet":
            try:
                # Optional (the "parquet" extra): imported by name so that the package works without it.
                pa = importlib.import_module("pyarrow")
                pq = importlib.import_module("pyarrow.parquet")
            except ImportError:
                raise RecordingError(f"{out}: writing Parquet needs pyarrow (pip install pyarrow); "
                                     "use a .csv name") from None
            columns = [series.stamps, series.stamps / 1e9, *series.translations.T, *series.rotations.T]
            pq.write_table(pa.table(dict(zip(COLUMNS, columns, strict=True))), tmp)
        else:
            tmp.write_text(_csv_text(series))
        tmp.replace(out)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise RecordingError(f"{out}: cannot write: {exc.strerror or exc}") from None
    return out
