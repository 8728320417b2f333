"""Which checks ``check-urdf FILE...`` runs: globs expanded, config entries applied, fragments redirected.

For each FILE, in order:

- a file some config entry names is checked once per such entry, with its args;
- a macro-only xacro file (see :func:`robotmodel.check.is_macro_only`) is checked through
  the config entries whose expansion includes it; with none, it is reported as not checked;
- any other file is checked with the command line's ``name:=value`` args.

Command-line args override an entry's args of the same name. A check that would repeat
(same file and args) runs once. Without FILE, every config entry is checked.
"""

from __future__ import annotations

import glob
import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robotmodel.check._project import Entry, ProjectConfig
    from robotmodel.check._run import CheckJob

__all__ = ["expand_files", "plan_checks"]

_GLOB_CHARS = frozenset("*?[")


def expand_files(patterns: Iterable[str]) -> list[str]:
    """FILE words with glob patterns (``**`` recursive) expanded, sorted, each file once.

    A pattern that matches nothing stays as written, so it is reported as a missing file,
    as a shell would have passed it.
    """
    files: list[str] = []
    for pattern in patterns:
        if _GLOB_CHARS.isdisjoint(pattern):
            files.append(pattern)
            continue
        # glob.glob, not Path.glob: patterns may be absolute, as the shell takes them.
        matches = sorted(p for p in glob.glob(pattern, recursive=True) if Path(p).is_file())  # noqa: PTH207
        files.extend(matches or [pattern])
    return list(dict.fromkeys(files))


def _entry_label(entry: Entry) -> str:
    from robotmodel.check._locations import display_path

    return display_path(entry.file)


def plan_checks(
    files: Sequence[str],
    base: CheckJob,
    cli_args: Mapping[str, str],
    config: ProjectConfig | None,
    includes: Callable[[Sequence[CheckJob]], list[list[str] | None]],
) -> tuple[list[CheckJob], list[str]]:
    """The checks to run, and the macro-only files no entry includes.

    ``base`` holds the options every check shares; ``includes`` maps entry checks to the
    files each includes, None for one that does not expand (run in parallel by the caller,
    and only when a fragment needs it).
    """
    from robotmodel.check._project import is_macro_only
    from robotmodel.check._run import job_args

    def with_args(file: str, args: Iterable[tuple[str, str]], via: str | None = None) -> CheckJob:
        merged = dict(args)
        merged.update(cli_args)
        return replace(base, file=file, args=job_args(merged), via=via)

    entries = config.entries if config is not None else ()
    entry_jobs = [with_args(_entry_label(e), e.args) for e in entries]
    if not files:
        return list(dict.fromkeys(entry_jobs)), []
    jobs: list[CheckJob] = []
    orphans: list[str] = []
    included: list[set[str] | None] | None = None
    for file in files:
        own = config.entries_for(file) if config is not None else []
        if own:
            jobs.extend(with_args(file, e.args) for e in own)
        elif entries and is_macro_only(file):
            if included is None:
                included = [None if deps is None else {os.path.realpath(p) for p in deps}
                            for deps in includes(entry_jobs)]
            real = os.path.realpath(file)
            # An entry that does not expand may be broken by this very file: it is checked too.
            users = [replace(job, via=file) for job, deps in zip(entry_jobs, included, strict=True)
                     if deps is None or real in deps]
            if users:
                jobs.extend(users)
            else:
                orphans.append(file)
        elif is_macro_only(file):
            orphans.append(file)
        else:
            jobs.append(with_args(file, ()))
    unique: dict[tuple[str, tuple[tuple[str, str], ...]], CheckJob] = {}
    for job in jobs:
        unique.setdefault((os.path.realpath(job.file), job.args), job)
    return list(unique.values()), orphans
