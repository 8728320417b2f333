"""``tf2-echo --bag FILE SOURCE TARGET [--time T | --every DT]``: tf2_echo's output over a recording.

``--time T`` prints the transform at T (seconds; absolute, or relative to the first
recorded transform with a leading ``+``); ``--every DT`` prints it every DT seconds of
recording time from the first to the last recorded transform (default: 1/RATE, tf2_echo's
rate argument, so once per recorded second). A lookup that fails prints tf2_echo's
failure block at that time; with ``--time`` the exit code is then 1.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from robotmodel.errors import EchoArgsError
from robotmodel.recording import sample_times
from robotmodel.tf_ros._echo_args import EchoArgs, failure_text, format_echo
from robotmodel.tf_ros._words import parse_seconds_ns

__all__ = ["run_bag_echo"]

_NS = 1_000_000_000


def _times(start: int, end: int, options: dict[str, str | bool], rate_hz: float) -> tuple[Sequence[int], bool]:
    if "time" in options and "every" in options:
        raise EchoArgsError("robotmodel tf2-echo: error: give --time or --every, not both", 2)
    text = options.get("time")
    if isinstance(text, str):
        if text.startswith("+"):
            t = start + parse_seconds_ns(text[1:], "--time", signed=True)
            if t >= 2**63:
                raise EchoArgsError(f"robotmodel tf2-echo: error: --time {text}: beyond tf2's time range from the "
                                    "first transform", 2)
            return [t], True
        return [parse_seconds_ns(text, "--time")], True
    every = options.get("every")
    step = parse_seconds_ns(every, "--every") if isinstance(every, str) else round(_NS / rate_hz)
    if step <= 0:
        raise EchoArgsError("robotmodel tf2-echo: error: --every must be greater than 0", 2)
    if end == 0:  # static transforms only: one answer, valid at any time
        return [0], False
    return sample_times(start, end, step, where=str(options["bag"])), False


def _text(value: str | bool | None) -> str | None:
    return value if isinstance(value, str) else None


def run_bag_echo(echo: EchoArgs, options: dict[str, str | bool]) -> int:
    """Load the recording, then print the transform at each requested time."""
    from robotmodel.errors import TransformException
    from robotmodel.recording import load_recording

    try:
        _times(0, 0, options, echo.rate_hz)  # check the words before a long load
        loaded = load_recording(str(options["bag"]), robot=_text(options.get("urdf")),
                                progress=False if options.get("no_progress") else None)
        times, single = _times(loaded.start_ns, loaded.end_ns, options, echo.rate_hz)
    except EchoArgsError as exc:
        print(exc, file=sys.stderr)
        return exc.code
    buffer = loaded.buffer
    printed = False
    failed = False
    out = []
    for t in times:
        try:
            pose, stamp = buffer.lookup_ns(echo.source_frame, echo.target_frame, t)
        except TransformException as exc:
            out.append(failure_text(t / 1e9, str(exc), buffer.all_frames_as_string(), printed))
            failed = True
        else:
            sec, nanosec = divmod(stamp, _NS)
            out.append(format_echo(sec, nanosec, pose[:3], pose[3:]))
            printed = True
        if len(out) >= 256:
            sys.stdout.write("".join(out))
            out.clear()
    sys.stdout.write("".join(out))
    sys.stdout.flush()
    return 1 if single and failed else 0
