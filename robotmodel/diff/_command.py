"""``diff`` as a program: two descriptions (or one and its git revision) in, the semantic diff printed."""

from __future__ import annotations

import sys
from collections.abc import Mapping, Sequence

from robotmodel.errors import RobotModelError

__all__ = ["run_diff"]


def run_diff(old_file: str, new_file: str | None = None, mappings: Mapping[str, str] | None = None, *,
             git: str | None = None, format: str = "text", tolerance: float = 1e-9,
             package_paths: Sequence[str] = (), untrusted: bool = False, command: str = "diff") -> int:
    """Print the diff of ``old_file`` and ``new_file`` ('-': stdin), or with ``git`` of ``old_file`` at that revision.

    Returns 0 when equal, 1 when different, 2 (with one ``robotmodel COMMAND: error:`` line on
    stderr) when the words are wrong or a description cannot be read, as diff does.
    """
    from robotmodel.diff._diff import diff_descriptions
    from robotmodel.diff._git import load_revision
    from robotmodel.diff._json import render_json
    from robotmodel.diff._text import render_text
    from robotmodel.model import load_source

    def _fail(message: str) -> int:
        print(f"robotmodel {command}: error: {' '.join(message.splitlines())}", file=sys.stderr)
        return 2

    if git is None and new_file is None:
        return _fail("two files to compare, OLD and NEW (or one FILE with --git REV)")
    if git is not None and new_file is not None:
        return _fail("--git REV compares one FILE with its revision REV; got two files")
    if not tolerance >= 0.0 or tolerance == float("inf"):
        return _fail(f"--tolerance must be a finite number >= 0, not {tolerance}")
    if old_file == "-" and new_file == "-":
        return _fail("only one of OLD and NEW can be '-' (stdin)")
    try:
        if git is not None:
            old, old_label = load_revision(old_file, git, mappings, package_paths=package_paths,
                                           untrusted=untrusted)
            new_file = old_file
        else:
            old, _ = load_source(old_file, mappings, package_paths=package_paths, untrusted=untrusted)
            old_label = old_file
        assert new_file is not None
        new, _ = load_source(new_file, mappings, package_paths=package_paths, untrusted=untrusted)
        diff = diff_descriptions(old, new, tolerance=tolerance, old_label=old_label, new_label=new_file)
    except RobotModelError as exc:
        return _fail(str(exc))
    sys.stdout.write(render_json(diff) if format == "json" else render_text(diff))
    sys.stdout.flush()
    return 0 if diff.equal else 1
