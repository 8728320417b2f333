"""Every option a command takes is in its ``--help``.

The options are derived from the parsers ``robotmodel`` builds (every action of every
subcommand, and of a subcommand's own verbs, such as ``topic list``/``topic echo``), and
from what the command parser reads before argparse (``--ros-args`` blocks, ``name:=value``
words). The help text is what ``robotmodel CMD --help`` prints, through the console
script's ``main``, so the test holds wherever the command modules live.

tf2-echo and static-transform-publisher read their own words, as ROS's programs do (their
argparse parser holds one catch-all positional): their forms are listed here by hand.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Iterator

import pytest
from robotmodel.cli.main import build_parser, main

# Commands that parse their own words: what their --help must name beyond ROS's own usage text.
OWN_WORDS: dict[str, tuple[str, ...]] = {
    "tf2-echo": (
        "source_frame target_frame [echo_rate]",
        "--bag FILE", "--time T", "--every DT", "--urdf FILE", "--no-progress",
        "--connect ENDPOINT", "--namespace NS", "--ros-args", "-r __ns:=/NS", "-r __node:=NAME",
    ),
    "static-transform-publisher": (
        "--x X", "--y Y", "--z Z", "--qx QX", "--qy QY", "--qz QZ", "--qw QW",
        "--roll ROLL", "--pitch PITCH", "--yaw YAW", "--frame-id FRAME_ID", "--child-frame-id CHILD_FRAME_ID",
        # ROS 2's deprecated positional forms, then ROS 1 tf's with the period.
        "x y z yaw pitch roll frame_id child_frame_id\n",
        "x y z qx qy qz qw frame_id child_frame_id\n",
        "x y z yaw pitch roll frame_id child_frame_id period_in_ms",
        "x y z qx qy qz qw frame_id child_frame_id period_in_ms",
        "--connect ENDPOINT", "--namespace NS", "--ros-args", "-r __ns:=/NS", "-r __node:=NAME",
    ),
}


def _subparsers(parser: argparse.ArgumentParser) -> argparse._SubParsersAction | None:  # type: ignore[type-arg]
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return action
    return None


def _commands(parser: argparse.ArgumentParser, path: tuple[str, ...] = ()) -> Iterator[
        tuple[tuple[str, ...], argparse.ArgumentParser]]:
    """(words, parser) for every command and verb, each once (aliases share their parser)."""
    sub = _subparsers(parser)
    if sub is None:
        yield path, parser
        return
    seen: set[int] = set()
    for name, child in sub.choices.items():
        if id(child) in seen:
            continue
        seen.add(id(child))
        yield from _commands(child, (*path, name))


COMMANDS = list(_commands(build_parser()))


def help_text(capsys: pytest.CaptureFixture[str], words: tuple[str, ...]) -> str:
    """What ``robotmodel WORDS --help`` prints on stdout (exit 0), unwrapped.

    A terminal as wide as the longest paragraph: argparse wraps at hyphens (``--params-``
    / ``file``), which would hide a word that is there.
    """
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("COLUMNS", "10000")
        return _help_text(capsys, words)


def _help_text(capsys: pytest.CaptureFixture[str], words: tuple[str, ...]) -> str:
    try:
        code = main([*words, "--help"])
    except SystemExit as exc:  # argparse's own help exits
        code = int(exc.code or 0)
    out, _ = capsys.readouterr()
    assert code == 0, out
    return out


def _named(text: str, word: str) -> bool:
    return re.search(rf"(?<![\w-]){re.escape(word)}(?![\w-])", text) is not None


def test_every_command_is_walked() -> None:
    names = {words[0] for words, _ in COMMANDS}
    assert {"tf2-echo", "static-transform-publisher", "view", "launch", "record"} <= names
    assert ("topic", "echo") in [words for words, _ in COMMANDS]
    assert set(OWN_WORDS) <= names


@pytest.mark.parametrize(("words", "parser"), COMMANDS, ids=[" ".join(w) for w, _ in COMMANDS])
def test_help_names_every_option(capsys: pytest.CaptureFixture[str], words: tuple[str, ...],
                                 parser: argparse.ArgumentParser) -> None:
    text = help_text(capsys, words)
    missing = []
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            continue
        if action.option_strings:
            missing += [o for o in action.option_strings if not _named(text, o)]
        elif words[0] not in OWN_WORDS:  # a positional: its metavar (or name) is in the usage
            shown = action.metavar if isinstance(action.metavar, str) else action.dest
            if shown not in text:
                missing.append(shown)
    if getattr(parser, "takes_ros_args", False):
        # Read before argparse (the CommandParser takes the blocks out first).
        missing += [w for w in ("--ros-args", "-r", "-p", "--params-file", "__ns", "__node") if w not in text]
    if getattr(parser, "takes_mappings", False):
        missing += [w for w in ("name:=value",) if w not in text]
    missing += [form for form in OWN_WORDS.get(words[0], ()) if form not in text]
    assert not missing, f"robotmodel {' '.join(words)} --help does not name: {missing}\n{text}"


def test_help_keeps_ros_usage_first(capsys: pytest.CaptureFixture[str]) -> None:
    """ROS's own usage text comes first, word for word; robotmodel's additions follow it."""
    assert help_text(capsys, ("tf2_echo",)).startswith(
        "Usage: tf2_echo source_frame target_frame [echo_rate]\n\nThis will echo the transform")
    assert help_text(capsys, ("static_transform_publisher",)).startswith(
        "usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] [--qz QZ] [--qw QW] "
        "[--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID --child-frame-id CHILD_FRAME_ID\n\n"
        "A command line utility for manually sending a static transform.")
