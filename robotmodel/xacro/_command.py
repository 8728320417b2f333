"""The ``xacro`` command as a program: expand, or list the dependencies, and print or write the result."""

from __future__ import annotations

import sys
from collections.abc import Mapping, Sequence

from robotmodel.errors import XacroError

__all__ = ["run_xacro"]


def run_xacro(file: str, mappings: Mapping[str, str] | None = None, *, output: str | None = None,
              just_deps: bool = False, in_order: bool = False, root_dir: str | None = None, verbosity: int = 1,
              package_paths: Sequence[str] = (), untrusted: bool = False) -> int:
    """The xacro command: expand ``file`` ('-': stdin) and print it, or write ``output`` whole; the exit code.

    ``just_deps`` prints the included files instead (not for stdin); ``in_order`` only prints
    xacro's notice that it is the default. Failures raise :class:`robotmodel.errors.XacroError`.
    """
    from robotmodel._atomic import write_atomic
    from robotmodel.xacro._expand import dependencies, expand, expand_string
    from robotmodel.xacro._stdin import read_stdin_document

    mappings = dict(mappings or {})
    if in_order:
        # xacro's own notice, word for word.
        print("xacro: in-order processing became default in ROS Melodic. You can drop the option.",
              file=sys.stderr)
    if file == "-":
        if just_deps:
            raise XacroError("--deps needs an input file, not stdin")
        text = expand_string(read_stdin_document(), mappings, base_dir=root_dir, name="-", package_paths=package_paths,
                             untrusted=untrusted, verbosity=verbosity)
    elif just_deps:
        text = " ".join(dependencies(file, mappings, root_dir=root_dir, package_paths=package_paths,
                                     untrusted=untrusted, verbosity=verbosity))
    else:
        text = expand(file, mappings, root_dir=root_dir, package_paths=package_paths, untrusted=untrusted,
                      verbosity=verbosity)
    if output:
        write_atomic(output, text)
    else:
        sys.stdout.write(text)
    return 0
