"""The ``--bag FILE`` options shared by the commands that read a recording instead of the bus."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotmodel.recording import Loaded

__all__ = ["BagWordsError", "add_bag_arguments", "load_bag", "parse_seconds_ns", "split_bag_words"]


def add_bag_arguments(parser: argparse.ArgumentParser, *, required: bool = False) -> None:
    """``--bag FILE``, ``--urdf FILE`` (the robot for joint states) and ``--no-progress``."""
    parser.add_argument("--bag", required=required, metavar="FILE",
                        help="read TF from this recording (ROS 1 .bag, ROS 2 bag folder, .db3 or .mcap)")
    parser.add_argument("--urdf", metavar="FILE",
                        help="with --bag: the robot whose /joint_states to turn into TF when there is no /tf "
                             "(default: the recorded /robot_description)")
    parser.add_argument("--no-progress", action="store_true", help="with --bag: no progress bar on stderr")


def load_bag(args: argparse.Namespace) -> Loaded:
    """Load ``args.bag`` into an unbounded buffer (skipped transforms are logged as one warning)."""
    from robotmodel.recording import load_recording

    return load_recording(args.bag, robot=args.urdf, progress=False if args.no_progress else None)


class BagWordsError(Exception):
    """A bad ``--bag``/``--time``/``--every`` word (the text to print on stderr)."""


_VALUED = ("--bag", "--time", "--every", "--urdf")


def split_bag_words(words: Sequence[str]) -> tuple[list[str], dict[str, str | bool]]:
    """Take the recording options out of raw words (for commands that parse their own words)."""
    rest: list[str] = []
    found: dict[str, str | bool] = {}
    it = iter(words)
    for word in it:
        name, eq, value = word.partition("=")
        if name in _VALUED:
            if not eq:
                value = next(it, "")
                if not value:
                    raise BagWordsError(f"{name} needs a value")
            found[name[2:]] = value
        elif word == "--no-progress":
            found["no_progress"] = True
        else:
            rest.append(word)
    return rest, found


def parse_seconds_ns(text: str, what: str, *, signed: bool = False) -> int:
    """Seconds as text (``12.5``, ``1700000000.123456789``) to integer ns, exactly, within tf2's time range."""
    from robotmodel.time import parse_seconds

    try:
        return parse_seconds(text, signed=signed)
    except ValueError as exc:
        raise BagWordsError(f"{what}: {exc}") from None
