"""Bus options the TF tools share: ``--connect ENDPOINT`` (repeatable), and clean stops on signals."""

from __future__ import annotations

from collections.abc import Sequence

from robotmodel.signals import stop_on_signals

__all__ = ["split_connect", "stop_on_signals", "strip_ros_args"]


def split_connect(words: Sequence[str]) -> tuple[list[str], list[str]]:
    """Take ``--connect ENDPOINT`` / ``--connect=ENDPOINT`` out of raw words: (other words, endpoints).

    The ROS-shaped commands parse their own words (ROS's exact texts), so the bus option
    is removed before they see them. A trailing ``--connect`` without a value is left in
    place for the command to reject.
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


def strip_ros_args(words: Sequence[str]) -> list[str]:
    """The words without ROS's own arguments, as ``rclcpp::init_and_remove_ros_arguments`` leaves them.

    Each ``--ros-args`` block runs to a ``--`` (dropped too) or to the end. The blocks are
    dropped unread: the node commands read them with :mod:`robotmodel.cli._ros_args`
    (remaps, parameters, namespace), which refuses what rcl refuses.
    """
    rest: list[str] = []
    inside = False
    for word in words:
        if inside:
            inside = word != "--"
        elif word == "--ros-args":
            inside = True
        else:
            rest.append(word)
    return rest
