"""Message encode/decode: robotmodel.msgs (fast TFMessage codec, generic path) next to rosbags alone.

Run: ``python benchmarks/bench_msgs.py``. "rosbags alone" starts from rosbags' own objects
(no conversion), which is the floor our generic path (convert + rosbags) builds on.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from robotmodel.msgs import (
    JointState,
    TFMessage,
    deserialize,
    from_rosbags,
    make_transform,
    serialize,
    to_rosbags,
    typestore,
)


def per_second(fn: Callable[[], Any], seconds: float = 0.4) -> float:
    fn()
    n, start = 0, time.perf_counter()
    while (elapsed := time.perf_counter() - start) < seconds:
        for _ in range(100):
            fn()
        n += 100
    return n / elapsed


def row(name: str, ours: float, floor: float, unit: str) -> None:
    print(f"{name:<44} {ours:>12,.0f} {floor:>12,.0f}   x{ours / floor:5.2f}  {unit}")


def main() -> None:
    store = typestore()
    tf_type = TFMessage.__msgtype__
    print(f"{'case':<44} {'robotmodel':>12} {'rosbags':>12}   ratio  unit")
    for n in (1, 2, 10, 50):
        msg = TFMessage([make_transform("odom", f"link_{k}", (k, 0.5, 0.25), (0.0, 0.0, 0.6, 0.8), 10**9 + k)
                         for k in range(n)])
        obj = to_rosbags(msg)
        raw = serialize(msg)
        row(f"TFMessage({n}) serialize", per_second(lambda m=msg: serialize(m)),
            per_second(lambda o=obj: store.serialize_cdr(o, tf_type)), "msgs/s")
        row(f"TFMessage({n}) deserialize", per_second(lambda r=raw: deserialize(r, TFMessage)),
            per_second(lambda r=raw: store.deserialize_cdr(r, tf_type)), "msgs/s")
        row(f"TFMessage({n}) serialize, generic path", per_second(lambda m=msg: serialize(m, store)),
            per_second(lambda o=obj: store.serialize_cdr(o, tf_type)), "msgs/s")
        row(f"TFMessage({n}) deserialize, generic path",
            per_second(lambda r=raw: from_rosbags(store.deserialize_cdr(r, tf_type))),
            per_second(lambda r=raw: store.deserialize_cdr(r, tf_type)), "msgs/s")
    js = JointState(name=[f"joint_{k}" for k in range(7)], position=[0.1 * k for k in range(7)],
                    velocity=[0.0] * 7, effort=[])
    js_type = JointState.__msgtype__
    obj = to_rosbags(js)
    raw = serialize(js)
    row("JointState(7) serialize", per_second(lambda: serialize(js)),
        per_second(lambda: store.serialize_cdr(obj, js_type)), "msgs/s")
    row("JointState(7) deserialize", per_second(lambda: deserialize(raw, JointState)),
        per_second(lambda: store.deserialize_cdr(raw, js_type)), "msgs/s")


if __name__ == "__main__":
    main()
