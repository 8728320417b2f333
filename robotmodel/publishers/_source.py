"""What the publishers accept as a robot: a description, URDF text, or a file (xacro expanded)."""

from __future__ import annotations

import os

from robotmodel.model import RobotDescription, load, parse_urdf, to_urdf

__all__ = ["RobotSource", "resolve"]

#: A :class:`RobotDescription`, URDF text (a str starting with ``<``), or a .urdf/.xacro path.
RobotSource = RobotDescription | str | os.PathLike[str]


def resolve(source: RobotSource) -> tuple[RobotDescription, str]:
    """The description and the exact text to publish as /robot_description.

    Text is kept byte for byte, as robot_state_publisher publishes its parameter; a file
    goes through xacro (``robotmodel xacro``'s output); a description uses the text it
    was parsed from, or its URDF when built in code.
    """
    if isinstance(source, RobotDescription):
        return source, source.source_text or to_urdf(source)
    if isinstance(source, str) and source.lstrip("\ufeff \t\r\n").startswith("<"):
        return parse_urdf(source), source
    desc = load(source)
    return desc, desc.source_text or to_urdf(desc)
