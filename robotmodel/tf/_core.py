"""tf2's BufferCore: frame registry, per-frame caches, validated inserts, lookups along the tree.

Semantics follow ROS 2 (Jazzy) tf2: time 0 means the latest common time of the chain,
static transforms are valid at all times, no extrapolation, interpolation per link,
walk to the common ancestor, loop detection at MAX_GRAPH_DEPTH, and tf2's texts in
errors and logs. All state is guarded by one lock; a thread waiting for a transform
registers the frames its lookup depends on and is woken only by inserts into those
frames. Nothing outside the buffer (log handlers included) runs under the lock.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from robotmodel.errors import (
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TransformException,
)
from robotmodel.msgs.geometry_msgs import TransformStamped
from robotmodel.spatial import IDENTITY_POSE as IDENTITY
from robotmodel.spatial import Pose7, pose_compose, pose_inverse, quat_canonical
from robotmodel.tf._cache import CacheMiss, StaticCache, TimeCache, format_time
from robotmodel.tf._checks import (
    STAMP_LIMIT,
    canonical_pose,
    canonical_poses,
    checked_stamps,
    frame_ids_ok,
    int_time_ns,
    log,
    time_arg_ns,
)
from robotmodel.tf._checks import stamp_ns as check_stamp
from robotmodel.tf._graph import MAX_GRAPH_DEPTH, FrameGraph
from robotmodel.tf._plan import NONE, UP, Plan, build_plan, chain_pose, latest_common, run_plan

__all__ = ["MAX_GRAPH_DEPTH", "BufferCore"]

_DEFAULT_CACHE_NS = 10_000_000_000
_MAX_PLANS = 10_000


def _log_old_data(child: str, stamp: int, authority: str) -> None:
    log.warning("TF_OLD_DATA ignoring data from the past for frame %s at time %s according to "
                "authority %s\nPossible reasons are listed at "
                "http://wiki.ros.org/tf/Errors%%20explained", child, format_time(stamp), authority)


class BufferCore(FrameGraph):
    """Transform storage and lookup with tf2's BufferCore semantics (times in integer ns).

    ``cache_time_ns`` is the window of each dynamic frame (tf2's cache_time);
    ``None`` keeps every sample (unbounded, for offline use: nothing is pruned or
    rejected as too old).
    """

    def __init__(self, cache_time_ns: int | None = _DEFAULT_CACHE_NS) -> None:
        if cache_time_ns is not None and cache_time_ns < 0:
            raise InvalidArgumentException(f"Invalid cache time {cache_time_ns} ns: it cannot be negative")
        self.cache_time_ns = cache_time_ns
        self._ids: dict[str, int] = {"NO_PARENT": 0}
        self._names: list[str] = ["NO_PARENT"]
        self._caches: list[TimeCache | StaticCache | None] = [None]
        self._lock = threading.RLock()
        # The chain walk of a (target, source) pair, kept while no insert changes the shape of the
        # tree (a cache created or replaced, a frame's parent changed, a cache cleared): see _plan.py.
        self._topology = 0
        self._plans: dict[tuple[str, str], Plan] = {}
        # Waiting lookups by the frame names they depend on (tf2's transformable requests).
        # A waiter is a sleeping thread's Condition or an asynchronous request's retry callable,
        # which runs after the inserting thread has released the lock.
        self._waiters: dict[str, list[threading.Condition | Callable[[], None]]] = {}

    # ----------------------------------------------------------------- insert
    def set_transform(self, transform: TransformStamped, authority: str, is_static: bool = False) -> bool:
        """Insert a TransformStamped (an adapter over :meth:`insert`); False when tf2 would drop it."""
        try:
            header, tf = transform.header, transform.transform
            tr, rot, stamp = tf.translation, tf.rotation, header.stamp
            x, y, z, rx, ry, rz, rw = tr.x, tr.y, tr.z, rot.x, rot.y, rot.z, rot.w
        except AttributeError as exc:
            raise InvalidArgumentException(f"Invalid argument passed to setTransform - not a TransformStamped "
                                           f"({exc})") from None
        try:
            ns = stamp.sec * 1_000_000_000 + stamp.nanosec  # a stamp message (checked by insert)
        except (AttributeError, TypeError):
            ns = time_arg_ns(stamp, f'setTransform argument stamp of child_frame_id "{transform.child_frame_id}"')
        parent, child = header.frame_id, transform.child_frame_id
        # The common case checked here as insert checks it (a unit quaternion with |w| > 0.5 needs
        # no canonical form but its sign); anything else goes through insert's full checks.
        if (type(x) is float and type(rw) is float and type(ns) is int and 0 <= ns < STAMP_LIMIT
                and type(parent) is str and type(child) is str and parent and child and parent != child
                and parent[0] != "/" and child[0] != "/"):
            n2 = rx * rx + ry * ry + rz * rz + rw * rw
            total = x + y + z + n2
            if total - total == 0.0 and abs(n2 - 1.0) < 1e-12:
                if rw > 0.5:
                    pose = (x, y, z, rx, ry, rz, rw)
                elif rw < -0.5:
                    pose = (x, y, z, -rx, -ry, -rz, -rw)
                else:
                    return self.insert(parent, child, ns, (x, y, z, rx, ry, rz, rw), authority, is_static)
                # _store, inline (one call less on every message).
                with self._lock:
                    done = self._put(parent, child, ns, pose, authority, is_static)
                if done is True:
                    return True
                return self._after_put(done, child, ns, authority)
        return self.insert(parent, child, ns, (x, y, z, rx, ry, rz, rw), authority, is_static)

    def insert(self, parent: str, child: str, stamp_ns: int, pose: Iterable[float], authority: str,
               is_static: bool = False) -> bool:
        """Insert ``child``'s pose in ``parent`` (x, y, z, qx, qy, qz, qw) at ``stamp_ns``, as setTransform.

        Returns False (after logging tf2's text) for what tf2 drops: equal or empty frame ids,
        NaN, a zero quaternion, data older than the window (TF_OLD_DATA). A stamp outside
        [0, 2**63) ns or a pose that is not 7 numbers raises InvalidArgumentException.
        """
        checked = self._checked(parent, child, stamp_ns, pose, authority)
        return checked is not None and self._store(*checked, authority, is_static)

    def _checked(self, parent: str, child: str, stamp_ns: int, pose: Iterable[float],
                 authority: str) -> tuple[str, str, int, Pose7] | None:
        """The checks of :meth:`insert`: the sample to store, or None (logged) for what tf2 drops."""
        if type(parent) is not str or type(child) is not str:
            raise InvalidArgumentException(f"Invalid argument passed to setTransform - frame ids must be strings, "
                                           f"got {parent!r} and {child!r}")
        if parent[:1] == "/":
            parent = parent[1:]
        if child[:1] == "/":
            child = child[1:]
        if type(stamp_ns) is not int or not 0 <= stamp_ns < STAMP_LIMIT:
            stamp_ns = check_stamp(stamp_ns, child, authority)
        values: Pose7 | None = None
        if type(pose) is tuple and len(pose) == 7 and child and parent and child != parent:
            x, y, z, rx, ry, rz, rw = pose
            if type(rw) is float and type(x) is float:
                n2 = rx * rx + ry * ry + rz * rz + rw * rw
                total = x + y + z + n2
                if total - total == 0.0:  # finite
                    if rw > 0.5 and abs(n2 - 1.0) < 1e-12:
                        # Already a unit quaternion in tf2's sign (w > 0.5: positive matrix trace),
                        # which tf2's matrix round trip returns as is.
                        values = pose
                    elif rw < -0.5 and abs(n2 - 1.0) < 1e-12:
                        values = (x, y, z, -rx, -ry, -rz, -rw)  # the same rotation in tf2's sign
                    elif n2 > 0.0:
                        values = (x, y, z, *quat_canonical((rx, ry, rz, rw)))
        if values is None:
            ids_ok = frame_ids_ok(parent, child, authority)
            values = canonical_pose(pose, child, authority)
            if values is None or not ids_ok:
                return None
        return parent, child, stamp_ns, values

    def insert_records(self, records: Iterable[Sequence[Any]], authority: str,
                       is_static: bool = False) -> list[tuple[Any, TransformException]]:
        """Insert ``(parent, child, stamp_ns, pose)`` records (a decoded TFMessage), each as :meth:`insert` would.

        The same checks, logs and results as one insert per record, with the lock taken once
        (so within one call the checks' texts come before TF_OLD_DATA's); waiting lookups are
        retried once all are in. Returns the records that raised, with the
        exception (the others still go in, as tf2_ros's listener has it).
        """
        failures: list[tuple[Any, TransformException]] = []
        items: list[Sequence[Any]] = []
        checked = self._checked
        for rec in records:
            parent, child, stamp, pose = rec
            # The common record checked here as insert checks it (see set_transform).
            if (type(parent) is str and type(child) is str and parent and child and parent != child
                    and parent[0] != "/" and child[0] != "/" and type(stamp) is int and 0 <= stamp < STAMP_LIMIT
                    and type(pose) is tuple and len(pose) == 7):
                x, y, z, rx, ry, rz, rw = pose
                if type(x) is float and type(rw) is float:
                    n2 = rx * rx + ry * ry + rz * rz + rw * rw
                    total = x + y + z + n2
                    if total - total == 0.0 and abs(n2 - 1.0) < 1e-12:
                        if rw > 0.5:
                            items.append(rec)
                            continue
                        if rw < -0.5:
                            items.append((parent, child, stamp, (x, y, z, -rx, -ry, -rz, -rw)))
                            continue
            try:
                item = checked(parent, child, stamp, pose, authority)
            except TransformException as exc:
                failures.append((rec, exc))
                continue
            if item is not None:
                items.append(item)
        rejected = []
        retries: list[Callable[[], None]] = []
        with self._lock:
            put = self._put
            for parent, child, stamp_ns, values in items:
                done = put(parent, child, stamp_ns, values, authority, is_static)
                if done is False:
                    rejected.append((child, stamp_ns))
                elif done is not True:
                    retries.extend(done)
        for child, stamp_ns in rejected:
            _log_old_data(child, stamp_ns, authority)
        for request in dict.fromkeys(retries):
            request()
        return failures

    def _store(self, parent: str, child: str, stamp_ns: int, values: Pose7, authority: str, is_static: bool) -> bool:
        """Insert a checked sample (valid names without '/', stamp in range, canonical pose)."""
        with self._lock:
            done = self._put(parent, child, stamp_ns, values, authority, is_static)
        return done is True or self._after_put(done, child, stamp_ns, authority)

    @staticmethod
    def _after_put(done: bool | list[Callable[[], None]], child: str, stamp_ns: int, authority: str) -> bool:
        """What :meth:`_put` left to do outside the lock (log TF_OLD_DATA, retry waiting requests)."""
        if done is False:
            _log_old_data(child, stamp_ns, authority)
            return False
        if done is not True:
            for request in done:
                request()
        return True

    def _put(self, parent: str, child: str, stamp_ns: int, values: Pose7, authority: str,
             is_static: bool) -> bool | list[Callable[[], None]]:
        """Store a checked sample (the lock held).

        False: rejected (too old); True: accepted; a non-empty list: accepted, and these waiting
        requests are to be retried once the lock is released.
        """
        ids = self._ids
        child_id = ids.get(child) or self._intern(child)
        cache = self._caches[child_id]
        # ROS 2 switches a frame between static and dynamic, dropping its history.
        if is_static:
            if cache.__class__ is not StaticCache:
                cache = self._caches[child_id] = StaticCache(values, 0)
                self._topology += 1
        elif cache.__class__ is not TimeCache:
            cache = self._caches[child_id] = TimeCache(self.cache_time_ns)
            self._topology += 1
        parent_id = ids.get(parent) or self._intern(parent)
        if cache.parent != parent_id and cache.parent > 0:
            self._topology += 1  # a new parent: chains through this frame change
        if not cache.insert(stamp_ns, values, parent_id):
            return False
        cache.authority = authority
        if self._waiters:
            return self._wake(child) or True
        return True

    def insert_many(self, parent: str, child: str, stamps: npt.ArrayLike, poses: npt.ArrayLike,
                    authority: str) -> int:
        """Insert N dynamic samples of one link at once; returns how many were accepted.

        ``stamps`` are N integer ns, ``poses`` an (N, 7) array (x, y, z, qx, qy, qz, qw).
        The result is exactly that of N :meth:`insert` calls in the given order (same
        validation, logs, canonical quaternions, pruning, TF_OLD_DATA and duplicates);
        strictly increasing stamps newer than the frame's data are stored in one step.
        """
        if type(parent) is not str or type(child) is not str:
            raise InvalidArgumentException(f"Invalid argument passed to insert_many - frame ids must be strings, "
                                           f"got {parent!r} and {child!r}")
        if parent[:1] == "/":
            parent = parent[1:]
        if child[:1] == "/":
            child = child[1:]
        where = f'insert_many argument stamps for child_frame_id "{child}"'
        stamp_arr = checked_stamps(stamps, where)
        try:
            pose_arr = np.asarray(poses, dtype=np.float64)
        except (TypeError, ValueError):
            pose_arr = np.empty((0, 0))
        if pose_arr.ndim != 2 or pose_arr.shape[1] != 7 or pose_arr.shape[0] != stamp_arr.shape[0]:
            raise InvalidArgumentException(
                f'Invalid argument passed to insert_many for child_frame_id "{child}" - poses must be an '
                f"(N, 7) array with one row per stamp ({stamp_arr.shape[0]} stamps, poses of shape "
                f"{getattr(pose_arr, 'shape', None)})")
        if not frame_ids_ok(parent, child, authority):
            return 0
        values, good = canonical_poses(pose_arr, child, authority)
        if not good.all():
            values, stamp_arr = values[good], stamp_arr[good]
        if stamp_arr.shape[0] == 0:
            return 0
        with self._lock:
            child_id = self._ids.get(child) or self._intern(child)
            cache = self._caches[child_id]
            if not isinstance(cache, TimeCache):
                cache = self._caches[child_id] = TimeCache(self.cache_time_ns)
                self._topology += 1
            parent_id = self._ids.get(parent) or self._intern(parent)
            if cache.parent != parent_id and cache.parent > 0:
                self._topology += 1
            rejected = cache.insert_many(stamp_arr, values, parent_id)
            accepted = int(stamp_arr.shape[0]) - len(rejected)
            retry = None
            if accepted:
                cache.authority = authority
                if self._waiters:
                    retry = self._wake(child)
        for k in rejected:
            _log_old_data(child, int(stamp_arr[k]), authority)
        for request in retry or ():
            request()
        return accepted

    def _intern(self, name: str) -> int:
        found = self._ids.get(name)
        if found is None:
            # The buffer keeps its own copy of a new name, made now: the caller's string was
            # typically decoded along with a whole message's throw-away objects, and kept, it
            # would pin the allocator's memory they used (a 100k-frame message: ~50 MiB for good).
            name = "".join((name, ""))
            found = self._ids[name] = len(self._names)
            self._names.append(name)
            self._caches.append(None)
        return found

    def _wake(self, frame: str) -> list[Callable[[], None]]:
        """Notify the threads waiting on ``frame``; return the requests to retry once unlocked."""
        retry = []
        for waiter in self._waiters.get(frame, ()):
            if isinstance(waiter, threading.Condition):
                waiter.notify()
            else:
                retry.append(waiter)
        return retry

    # ----------------------------------------------------------------- lookup
    def _validate(self, name: str, arg: str) -> int:
        if not isinstance(name, str):
            raise InvalidArgumentException(f"Invalid argument {name!r} passed to {arg} - a frame_id is a string")
        if not name:
            raise InvalidArgumentException(
                f'Invalid argument "" passed to {arg} - in tf2 frame_ids cannot be empty')
        if name.startswith("/"):
            raise InvalidArgumentException(
                f'Invalid argument "{name}" passed to {arg} - in tf2 frame_ids cannot start with a \'/\'')
        found = self._ids.get(name)
        if not found:
            raise LookupException(f'"{name}" passed to {arg} does not exist. ')
        return found

    def lookup_ns(self, target: str, source: str, time_ns: int) -> tuple[Pose7, int]:
        """T_target_source at ``time_ns`` (0 = latest common); returns (pose, stamp used)."""
        if type(time_ns) is not int or not 0 <= time_ns < STAMP_LIMIT:
            time_ns = int_time_ns(time_ns, "lookupTransform argument time")
        with self._lock:
            try:
                plan = self._plans.get((target, source))
            except TypeError:  # unhashable: not a frame name (the checks below say so)
                plan = None
            current = plan is not None and plan[0] == self._topology
            if current:
                t = time_ns or latest_common(plan[4])  # type: ignore[index]
                pose = chain_pose(plan[2], t, True) if plan[1] == UP else run_plan(plan, t)  # type: ignore[index,arg-type]
                if pose is not None:
                    return pose, t
            if target == source:
                stamp = time_ns
                if stamp == 0 and (fid := self._ids.get(target)):
                    cache = self._caches[fid]
                    stamp = cache.latest()[0] if cache is not None else 0
                return IDENTITY, stamp
            ids = self._ids
            try:
                target_id, source_id = ids.get(target), ids.get(source)
            except TypeError:  # unhashable: not a frame name (the checks below say so)
                target_id = source_id = None
            # Known names are valid unless they start with '/' (a "//x" inserted as "/x"): check only then.
            if not target_id or target[0] == "/":
                target_id = self._validate(target, "lookupTransform argument target_frame")
            if not source_id or source[0] == "/":
                source_id = self._validate(source, "lookupTransform argument source_frame")
            if not current:
                plan = build_plan(self._caches, target_id, source_id, self._topology)
                if len(self._plans) >= _MAX_PLANS:  # a bound for buffers asked about very many pairs
                    self._plans.clear()
                self._plans[target, source] = plan
                if plan[1] != NONE:
                    if time_ns == 0:
                        time_ns = latest_common(plan[4])
                    pose = run_plan(plan, time_ns)
                    if pose is not None:
                        return pose, time_ns
            if time_ns == 0:
                time_ns = self._latest_common_time(target_id, source_id, target, source)
            pose = self._walk(time_ns, target_id, source_id, target, source)
            qx, qy, qz, qw = quat_canonical(pose[3:])
            return (pose[0], pose[1], pose[2], qx, qy, qz, qw), time_ns

    def _lookup_ids(self, target_id: int, source_id: int, time_ns: int, target: str,
                    source: str) -> tuple[Pose7, int]:
        if time_ns == 0:
            time_ns = self._latest_common_time(target_id, source_id, target, source)
        pose = self._walk(time_ns, target_id, source_id, target, source)
        qx, qy, qz, qw = quat_canonical(pose[3:])
        return (pose[0], pose[1], pose[2], qx, qy, qz, qw), time_ns

    def lookup_full_ns(self, target: str, target_ns: int, source: str, source_ns: int,
                       fixed: str) -> tuple[Pose7, int]:
        """T_target_source with the source at ``source_ns`` and the target at ``target_ns`` via ``fixed``."""
        for value, arg in ((target_ns, "target_time"), (source_ns, "source_time")):
            if type(value) is not int or not 0 <= value < STAMP_LIMIT:
                int_time_ns(value, f"lookupTransform argument {arg}")
        with self._lock:
            self._validate(target, "lookupTransform argument target_frame")
            self._validate(source, "lookupTransform argument source_frame")
            self._validate(fixed, "lookupTransform argument fixed_frame")
            fixed_source, _ = self.lookup_ns(fixed, source, source_ns)
            target_fixed, stamp = self.lookup_ns(target, fixed, target_ns)
            pose = pose_compose(target_fixed, fixed_source)
            qx, qy, qz, qw = quat_canonical(pose[3:])
            return (pose[0], pose[1], pose[2], qx, qy, qz, qw), stamp

    def _walk(self, time_ns: int, target_id: int, source_id: int, target: str, source: str) -> Pose7:
        caches = self._caches
        source_acc: Pose7 | None = None
        frame = source_id
        top = 0
        miss: CacheMiss | None = None
        depth = 0
        compose, limit = pose_compose, MAX_GRAPH_DEPTH  # locals: this loop runs on every lookup
        while frame:
            cache = caches[frame]
            top = frame
            if cache is None:
                break
            got = cache.sample(time_ns)
            if got.__class__ is CacheMiss:  # final class: cheaper than isinstance in the hot loop
                miss = got
                break
            if frame == target_id:
                break
            pose, parent = got  # type: ignore[misc]
            source_acc = pose if source_acc is None else compose(pose, source_acc)
            frame = parent
            depth += 1
            if depth > limit:
                raise self._loop_error(target, source)
        if source_acc is None:
            source_acc = IDENTITY
        if frame == target_id and miss is None:
            return source_acc
        target_acc: Pose7 | None = None
        frame = target_id
        depth = 0
        while frame != top:
            cache = caches[frame]
            if cache is None:
                break
            got = cache.sample(time_ns)
            if isinstance(got, CacheMiss):
                raise self._extrapolation(got, time_ns, target, source)
            pose, parent = got
            if frame == source_id:
                return pose_inverse(target_acc or IDENTITY)
            target_acc = pose if target_acc is None else pose_compose(pose, target_acc)
            frame = parent
            depth += 1
            if depth > MAX_GRAPH_DEPTH:
                raise self._loop_error(target, source)
        if frame != top:
            if miss is not None:
                raise self._extrapolation(miss, time_ns, target, source)
            raise self._connectivity(target, source)
        if target_acc is None:
            return IDENTITY if frame == source_id else source_acc
        if frame == source_id:
            return pose_inverse(target_acc)
        return pose_compose(pose_inverse(target_acc), source_acc)

    def _extrapolation(self, miss: CacheMiss, time_ns: int, target: str, source: str) -> ExtrapolationException:
        return ExtrapolationException(
            f"{miss.message}, when looking up transform from frame [{source}] to frame [{target}]",
            direction=miss.direction, target_frame=target, source_frame=source, time_ns=time_ns,
            earliest_ns=miss.earliest_ns, latest_ns=miss.latest_ns)

    def can_transform_ns(self, target: str, source: str, time_ns: int) -> tuple[bool, str]:
        """(True, '') when ``lookup_ns`` would succeed, else (False, its error text)."""
        try:
            self.lookup_ns(target, source, time_ns)
        except TransformException as exc:
            return False, str(exc)
        return True, ""

    def clear(self) -> None:
        """Empty every dynamic cache; static transforms and frame names stay."""
        with self._lock:
            self._topology += 1
            self._plans.clear()
            for cache in self._caches:
                if cache is not None:
                    cache.clear()
