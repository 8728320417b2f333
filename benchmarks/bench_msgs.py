"""Message encode/decode: robotmodel.msgs (fast TFMessage codec, generic path) next to rosbags alone.

Run: ``python benchmarks/bench_msgs.py``. "rosbags" starts from rosbags' own objects (no
conversion), which is the floor our generic path (convert + rosbags) builds on; the fast
TFMessage path replaces rosbags altogether.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from functools import partial
from typing import Any

from robotmodel.msgs import (
    JointState,
    TFMessage,
    decode_tf_records,
    deserialize,
    make_transform,
    serialize,
    to_rosbags,
    typestore,
)


def per_second(fn: Callable[[], Any], seconds: float = 0.05) -> float:
    fn()
    n, start = 0, time.perf_counter()
    while (elapsed := time.perf_counter() - start) < seconds:
        for _ in range(20):
            fn()
        n += 20
    return n / elapsed


def best_pair(ours: Callable[[], Any], theirs: Callable[[], Any], rounds: int = 7) -> tuple[float, float]:
    """Best rate of each over short alternating windows: both see the same machine load."""
    a = b = 0.0
    for _ in range(rounds):
        a = max(a, per_second(ours))
        b = max(b, per_second(theirs))
    return a, b


def row(name: str, ours: Callable[[], Any], theirs: Callable[[], Any]) -> None:
    a, b = best_pair(ours, theirs)
    print(f"{name:<44} {a:>12,.0f} {b:>12,.0f}   x{a / b:5.2f}")


def main() -> None:
    store = typestore()
    tf_type = TFMessage.__msgtype__
    print(f"{'case (messages/s)':<44} {'robotmodel':>12} {'rosbags':>12}   ratio")
    for n in (1, 2, 10, 50):
        msg = TFMessage([make_transform("odom", f"link_{k}", (k, 0.5, 0.25), (0.0, 0.0, 0.6, 0.8), 10**9 + k)
                         for k in range(n)])
        obj = to_rosbags(msg)
        raw = serialize(msg)
        rosbags_ser = partial(store.serialize_cdr, obj, tf_type)
        rosbags_de = partial(store.deserialize_cdr, raw, tf_type)
        row(f"TFMessage({n}) serialize", partial(serialize, msg), rosbags_ser)
        row(f"TFMessage({n}) deserialize", partial(deserialize, raw, TFMessage), rosbags_de)
        row(f"TFMessage({n}) decode_tf_records", partial(decode_tf_records, raw), rosbags_de)
        row(f"TFMessage({n}) serialize, generic path", partial(serialize, msg, store), rosbags_ser)
        row(f"TFMessage({n}) deserialize, generic path", partial(deserialize, raw, TFMessage, store), rosbags_de)
    js = JointState(name=[f"joint_{k}" for k in range(7)], position=[0.1 * k for k in range(7)],
                    velocity=[0.0] * 7, effort=[])
    js_type = JointState.__msgtype__
    obj = to_rosbags(js)
    raw = serialize(js)
    row("JointState(7) serialize", partial(serialize, js), partial(store.serialize_cdr, obj, js_type))
    row("JointState(7) deserialize", partial(deserialize, raw, JointState),
        partial(store.deserialize_cdr, raw, js_type))


if __name__ == "__main__":
    main()
