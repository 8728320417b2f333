"""Reused chain walks: a lookup's links, found once per (target, source) pair and kept while the tree keeps its shape.

A plan lists the caches BufferCore._walk visits and the order it composes them in, valid
while every cache on the way has one parent for all its samples (so the walk is the same at
every time); BufferCore keeps it with the topology version it was made at. ``chain_pose`` is
the hot path of every lookup: the links sampled and composed inline, with the same operations
as the kernels in robotmodel.spatial (the same results to the bit, which tests/tf/test_plans.py
checks against the full walk), and None wherever a link has no data (the full walk then gives
tf2's error).
"""

from __future__ import annotations

from bisect import bisect_right
from math import acos as _acos
from math import copysign as _copysign
from math import sin as _sin
from math import sqrt as _sqrt

from robotmodel.spatial import Pose7, pose_compose, pose_inverse, quat_canonical
from robotmodel.tf._cache import _ROW, StaticCache, TimeCache, _unpack, _unpack_pair
from robotmodel.tf._graph import MAX_GRAPH_DEPTH

__all__ = ["BOTH", "DOWN", "NONE", "UP", "Plan", "build_plan", "chain_pose", "latest_common", "run_plan"]

UP, DOWN, BOTH, NONE = 0, 1, 2, 3
# (topology version, kind, source-side links, target-side links, the dynamic links whose newest
# stamps give the latest common time); links in walking order, each with one parent.
Plan = tuple[int, int, tuple["TimeCache | StaticCache", ...], tuple["TimeCache | StaticCache", ...],
              tuple[TimeCache, ...]]


def _dynamic(links: list[TimeCache | StaticCache]) -> tuple[TimeCache, ...]:
    return tuple(c for c in links if isinstance(c, TimeCache))


def latest_common(links: tuple[TimeCache, ...]) -> int:
    """BufferCore._latest_common_time over a plan's links: the oldest of their newest stamps (0 when none)."""
    common = 0
    for cache in links:
        stamp = cache._newest
        if stamp and (stamp < common or not common):
            common = stamp
    return common


def chain_pose(links: tuple[TimeCache | StaticCache, ...], t: int, final: bool) -> Pose7 | None:
    """The links' poses at ``t`` composed as BufferCore._walk does; None where a link has no data.

    ``final``: with the quaternion in tf2's canonical form (the lookup's result).

    The hot path of every lookup: TimeCache.sample's interpolation and ``pose_compose`` inlined, with
    the same operations in the same order (the same results to the bit), and no tuple per step.
    """
    first = True
    ax = ay = az = qx = qy = qz = qw = 0.0
    t0 = t1 = i = start = -1
    r = u = 0.0
    for cache in links:
        if cache.__class__ is TimeCache:
            oldest, newest = cache._oldest, cache._newest
            if oldest < t < newest:
                smv = cache._smv
                # Links published together hold the same stamps: the previous link's bracket
                # [t0, t1) around t, if this cache has it at the same place, is this one's too.
                i += cache._start - start
                start = cache._start
                if not (0 <= i < cache._end - 1 and smv[i] == t0 and smv[i + 1] == t1):
                    end = cache._end
                    i = start + (t - oldest) * (end - 1 - start) // (newest - oldest)
                    t0 = smv[i]
                    if t0 <= t:
                        t1 = smv[i + 1]
                        if t1 <= t:
                            i = bisect_right(smv, t, i + 1, end) - 1
                            t0, t1 = smv[i], smv[i + 1]
                    else:
                        i = bisect_right(smv, t, start, i) - 1
                        t0, t1 = smv[i], smv[i + 1]
                    r = (t - t0) / (t1 - t0)
                    u = 1.0 - r
                if r == 0.0:  # t is the stamp of sample i: its pose is the interpolation's (as in TimeCache.sample)
                    bx, by, bz, px, py, pz, pw = _unpack(smv, cache._pbase + i * _ROW)
                else:
                    bx, by, bz, px, py, pz, pw, cx, cy, cz, rx, ry, rz, rw = _unpack_pair(
                        smv, cache._pbase + i * _ROW)
                    dot = px * rx + py * ry + pz * rz + pw * rw
                    theta = _acos(dot if 0.0 <= dot <= 1.0 else min(1.0, abs(dot)))
                    bx, by, bz = bx * u + cx * r, by * u + cy * r, bz * u + cz * r
                    if theta != 0.0:
                        sn = _sin(theta)
                        wa = _sin(u * theta) / sn
                        wb = _sin(r * theta) / sn
                        if dot < 0.0:
                            wb = -wb
                        px, py, pz, pw = px * wa + rx * wb, py * wa + ry * wb, pz * wa + rz * wb, pw * wa + rw * wb
            elif t == newest and cache._end > cache._start:
                bx, by, bz, px, py, pz, pw = _unpack(cache._smv, cache._pbase + (cache._end - 1) * _ROW)
            else:
                return None
        else:
            bx, by, bz, px, py, pz, pw = cache.pose  # type: ignore[union-attr]
        if first:
            ax, ay, az, qx, qy, qz, qw = bx, by, bz, px, py, pz, pw
            first = False
            continue
        # (b, p) ∘ (a, q): pose_compose(link, accumulated).
        cx = py * az - pz * ay
        cy = pz * ax - px * az
        cz = px * ay - py * ax
        ax, ay, az, qx, qy, qz, qw = (
            bx + ax + 2.0 * (pw * cx + py * cz - pz * cy),
            by + ay + 2.0 * (pw * cy + pz * cx - px * cz),
            bz + az + 2.0 * (pw * cz + px * cy - py * cx),
            pw * qx + px * qw + py * qz - pz * qy,
            pw * qy - px * qz + py * qw + pz * qx,
            pw * qz + px * qy - py * qx + pz * qw,
            pw * qw - px * qx - py * qy - pz * qz,
        )
    if first:
        return None
    if not final:
        return ax, ay, az, qx, qy, qz, qw
    # quat_canonical inlined where its branch is certain: w dominant (a clearly positive
    # matrix trace: 4w^2 > |q|^2, with a margin far above rounding) and |q|^2 well inside the range.
    n2 = qx * qx + qy * qy + qz * qz + qw * qw
    if qw * qw > 0.2501 * n2 and 1e-300 < n2 < 1e300:
        inv = _copysign(1.0 / _sqrt(n2), qw)
        return ax, ay, az, qx * inv, qy * inv, qz * inv, qw * inv
    qx, qy, qz, qw = quat_canonical((qx, qy, qz, qw))
    return ax, ay, az, qx, qy, qz, qw


def run_plan(plan: Plan, t: int) -> Pose7 | None:
    """A plan's result at ``t`` (the lookup's pose); None: ask BufferCore._walk."""
    kind = plan[1]
    if kind == UP:
        return chain_pose(plan[2], t, True)
    if kind == NONE:
        return None
    target_acc = chain_pose(plan[3], t, False)
    if target_acc is None:
        return None
    if kind == DOWN:
        pose = pose_inverse(target_acc)
    else:
        source_acc = chain_pose(plan[2], t, False)
        if source_acc is None:
            return None
        pose = pose_compose(pose_inverse(target_acc), source_acc)
    qx, qy, qz, qw = quat_canonical(pose[3:])
    return pose[0], pose[1], pose[2], qx, qy, qz, qw



def build_plan(caches: list[TimeCache | StaticCache | None], target_id: int, source_id: int, topology: int) -> Plan:
    """The links BufferCore._walk and _latest_common_time would visit, when that is the same at every time.

    Walks the tree as BufferCore._walk does, by each cache's one parent (``parent`` > 0); a
    NONE plan when a cache on the way has none (empty, or more than one parent over time), or
    when the walk would raise. A miss at lookup time still goes to _walk, for its error.
    """
    none: Plan = (topology, NONE, (), (), ())
    up: list[TimeCache | StaticCache] = []
    frame, top, depth = source_id, 0, 0
    while frame:
        cache = caches[frame]
        top = frame
        if cache is None or frame == target_id:
            break
        parent = cache.parent
        if parent <= 0:
            return none
        up.append(cache)
        frame = parent
        depth += 1
        if depth > MAX_GRAPH_DEPTH:
            return none
    if frame == target_id:
        return topology, UP, tuple(up), (), _dynamic(up)
    down: list[TimeCache | StaticCache] = []
    frame, depth = target_id, 0
    while frame != top:
        cache = caches[frame]
        if cache is None:
            return none
        parent = cache.parent
        if parent <= 0:
            return none
        if frame == source_id:
            return topology, DOWN, (), tuple(down), _dynamic(down)
        down.append(cache)
        frame = parent
        depth += 1
        if depth > MAX_GRAPH_DEPTH:
            return none
    if not down:
        return none
    if frame == source_id:
        return topology, DOWN, (), tuple(down), _dynamic(down)
    # The latest common time reads the links below the common ancestor on both sides.
    parents = [c.parent for c in up]
    below: list[TimeCache | StaticCache] = []
    for cache in down:
        below.append(cache)
        if cache.parent in parents:
            below.extend(up[:parents.index(cache.parent) + 1])
            break
    else:
        return none
    return topology, BOTH, tuple(up), tuple(down), _dynamic(below)

