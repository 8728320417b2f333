"""Words the ROS-shaped TF programs take besides ROS's own: ``--connect ENDPOINT`` and the recording options.

tf2_echo and static_transform_publisher parse their own words (ROS's exact texts), so these
options are taken out before the ROS parser sees them.
"""

from __future__ import annotations

from collections.abc import Sequence

from robotmodel.errors import EchoArgsError

__all__ = ["parse_seconds_ns", "split_bag_words", "split_connect"]

_VALUED = ("--bag", "--time", "--every", "--urdf")


def split_connect(words: Sequence[str]) -> tuple[list[str], list[str]]:
    """Take ``--connect ENDPOINT`` / ``--connect=ENDPOINT`` out of raw words: (other words, endpoints).

    A trailing ``--connect`` without a value is left in place for the command to reject.
    """
    rest: list[str] = []
    endpoints: list[str] = []
    i = 0
    while i < len(words):
        word = words[i]
        if word.startswith("--connect="):
            endpoints.append(word.split("=", 1)[1])
        elif word == "--connect" and i + 1 < len(words):
            endpoints.append(words[i + 1])
            i += 1
        else:
            rest.append(word)
        i += 1
    return rest, endpoints


def _bad(text: str) -> EchoArgsError:
    return EchoArgsError(f"robotmodel tf2-echo: error: {text}", 2)


def split_bag_words(words: Sequence[str]) -> tuple[list[str], dict[str, str | bool]]:
    """Take ``--bag``, ``--time``, ``--every``, ``--urdf`` and ``--no-progress`` out of raw words.

    A valued option without its value raises :class:`robotmodel.errors.EchoArgsError` (exit 2).
    """
    rest: list[str] = []
    found: dict[str, str | bool] = {}
    it = iter(words)
    for word in it:
        name, eq, value = word.partition("=")
        if name in _VALUED:
            if not eq:
                value = next(it, "")
                if not value:
                    raise _bad(f"{name} needs a value")
            found[name[2:]] = value
        elif word == "--no-progress":
            found["no_progress"] = True
        else:
            rest.append(word)
    return rest, found


def parse_seconds_ns(text: str, what: str, *, signed: bool = False) -> int:
    """Seconds as text (``12.5``, ``1700000000.123456789``) to integer ns, exactly, within tf2's time range.

    EchoArgsError if not a number, not finite, or out of range (negative too unless ``signed``).
    """
    from robotmodel.time import parse_seconds

    try:
        return parse_seconds(text, signed=signed)
    except ValueError as exc:
        raise _bad(f"{what}: {exc}") from None
