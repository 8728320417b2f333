"""The README and docs/ stay navigable and true.

- README.md: under 250 lines, the two Quick start commands exactly, a task index linking
  every page of docs/tasks/.
- Every command of ``robotmodel --help`` has its page in docs/commands/, listed in the
  command index, naming every option its parser has.
- Every relative link in README.md and docs/ resolves (file, and heading anchor).
- Every environment variable the code reads is in docs/environment.md.
- The Python blocks marked ``<!-- runs in tests/test_docs.py -->`` run, each in a fresh
  interpreter on a private bus (after starting what the marker's ``with:`` names), and
  print what the page shows in the plain block after them.
"""

from __future__ import annotations

import argparse
import ast
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from conftest import REPO
from livebus import Bus, Proc

README = REPO / "README.md"
DOCS = REPO / "docs"
PAGES = sorted([README, *DOCS.rglob("*.md")])
QUICK_START = ("pip install . && robotmodel demo", "bash .ci/run")
MARK = re.compile(r"^<!-- runs in tests/test_docs\.py(?: with: (?P<with>.*?))? -->\n```python\n(?P<code>.*?)^```\n",
                  re.M | re.S)
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^```.*?^```\n", re.M | re.S)


def _section(text: str, title: str) -> str:
    match = re.search(rf"^## {re.escape(title)}\n(.*?)(?=^## |\Z)", text, re.M | re.S)
    assert match is not None, f"README has no '## {title}' section"
    return match.group(1)


def test_readme_is_short_and_starts_with_the_quick_start() -> None:
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) < 250
    blocks = re.findall(r"^```bash\n(.*?)\n```$", _section(text, "Quick start"), re.M | re.S)
    assert tuple(blocks) == QUICK_START


def test_readme_task_index_links_every_task_page() -> None:
    index = _section(README.read_text(encoding="utf-8"), "What do you want to do?")
    linked = {(REPO / target).resolve() for target in LINK.findall(index)}
    pages = {p.resolve() for p in (DOCS / "tasks").glob("*.md")}
    assert len(pages) >= 9
    assert pages <= linked, sorted(str(p) for p in pages - linked)


def _commands() -> Iterator[tuple[str, list[argparse.ArgumentParser]]]:
    """(name, its parser and its verbs' parsers) for each command of ``robotmodel --help``."""
    from robotmodel.cli.main import build_parser

    def walk(parser: argparse.ArgumentParser) -> list[argparse.ArgumentParser]:
        found = [parser]
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for child in dict.fromkeys(action.choices.values()):
                    found += walk(child)
        return found

    top = build_parser()
    [sub] = [a for a in top._actions if isinstance(a, argparse._SubParsersAction)]
    seen: set[int] = set()
    for name, parser in sub.choices.items():
        if id(parser) not in seen:
            seen.add(id(parser))
            yield name, walk(parser)


COMMANDS = list(_commands())
# Commands that read their own words (ROS's parsers): what their page must name.
OWN_WORDS = {
    "tf2-echo": ("--bag", "--time", "--every", "--urdf", "--no-progress", "--connect", "--namespace", "--ros-args"),
    "static-transform-publisher": ("--x", "--y", "--z", "--qx", "--qy", "--qz", "--qw", "--roll", "--pitch", "--yaw",
                                   "--frame-id", "--child-frame-id", "period_ms", "--connect", "--namespace",
                                   "--ros-args"),
}


@pytest.mark.parametrize(("name", "parsers"), COMMANDS, ids=[name for name, _ in COMMANDS])
def test_every_command_has_a_page_naming_every_option(name: str, parsers: list[argparse.ArgumentParser]) -> None:
    page = DOCS / "commands" / f"{name}.md"
    assert page.is_file(), f"no {page.relative_to(REPO)} for 'robotmodel {name}'"
    assert f"]({name}.md)" in (DOCS / "commands" / "README.md").read_text(encoding="utf-8")
    text = page.read_text(encoding="utf-8")
    options = {o for p in parsers for a in p._actions for o in a.option_strings if o not in ("-h", "--help")}
    options |= set(OWN_WORDS.get(name, ()))
    if any(getattr(p, "takes_ros_args", False) for p in parsers):
        options.add("--ros-args")
    missing = sorted(o for o in options if not re.search(rf"(?<![\w-]){re.escape(o)}(?![\w-])", text))
    assert not missing, f"{page.relative_to(REPO)} does not name {missing}"


def _slug(heading: str) -> str:
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def _anchors(page: Path) -> set[str]:
    text = FENCE.sub("", page.read_text(encoding="utf-8"))
    return {_slug(m) for m in re.findall(r"^#+ (.*)$", text, re.M)}


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(REPO)) for p in PAGES])
def test_every_link_resolves(page: Path) -> None:
    text = FENCE.sub("", page.read_text(encoding="utf-8"))
    broken = []
    for target in LINK.findall(text):
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        resolved = (page.parent / path).resolve() if path else page
        if not resolved.exists() or (anchor and (resolved.suffix != ".md" or anchor not in _anchors(resolved))):
            broken.append(target)
    assert not broken, f"{page.relative_to(REPO)}: broken links {broken}"


def _environment_variables() -> set[str]:
    """Names the code reads from the environment, found in the source.

    A constant string passed to an environment read (``os.environ.get``, ``os.getenv``,
    ``os.environ[...]``, ``env.pop``, the zenoh config's ``_from_file(VARIABLE)``).
    """
    reads = re.compile(r"(environ|getenv|\benv\b|_from_file)")
    names: set[str] = set()
    for path in [*(REPO / "robotmodel").rglob("*.py"), *(REPO / "cli").rglob("*.py")]:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and node.args:
                target, key = node.func, node.args[0]
            elif isinstance(node, ast.Subscript) and isinstance(node.ctx, ast.Load):
                target, key = node.value, node.slice
            else:
                continue
            if isinstance(key, ast.Constant) and isinstance(key.value, str) and reads.search(ast.unparse(target)):
                names.add(key.value)
    return names


def test_every_environment_variable_is_documented() -> None:
    names = _environment_variables()
    assert {"ROBOTMODEL_ZENOH_PORT", "ROS_DOMAIN_ID", "ZENOH_CONFIG_OVERRIDE", "ZENOH_ROUTER_CONFIG_URI",
            "ROBOTMODEL_CACHE_DIR", "AMENT_PREFIX_PATH"} <= names
    text = (DOCS / "environment.md").read_text(encoding="utf-8")
    missing = sorted(n for n in names if f"`{n}`" not in text)
    assert not missing, f"docs/environment.md does not document {missing}"


def _marked_blocks() -> Iterator[tuple[str, str, str, str | None]]:
    """(page:line, code, the printed output the page shows or None, the 'with:' commands) per marked block."""
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        for match in MARK.finditer(text):
            rest = text[match.end():]
            shown = re.match(r"(?:[^`\n][^\n]*\n|\n)*?```\n(.*?)^```\n", rest, re.M | re.S)
            next_code = re.search(r"^```\w", rest, re.M)
            output = shown.group(1) if shown and (next_code is None or next_code.start() > shown.start(1)) else None
            where = f"{page.relative_to(REPO)}:{text[:match.start()].count(chr(10)) + 2}"
            yield where, match.group("code"), output, match.group("with") or ""


BLOCKS = list(_marked_blocks())


def test_the_marked_blocks_are_found() -> None:
    pages = {where.split(":")[0] for where, *_ in BLOCKS}
    assert "docs/library.md" in pages and len(BLOCKS) >= 6


@pytest.mark.parametrize(("where", "code", "output", "needs"), BLOCKS, ids=[b[0] for b in BLOCKS])
def test_marked_python_block_runs_and_prints_what_the_page_shows(tmp_path: Path, where: str, code: str,
                                                                 output: str | None, needs: str) -> None:
    bus = Bus(tmp_path, "zenoh")
    try:
        for command in filter(None, (c.strip() for c in needs.split(";"))):
            words = command.split()
            assert words[0] == "robotmodel", f"{where}: 'with:' names robotmodel commands only"
            proc = Proc([sys.executable, "-m", "robotmodel.cli.main", *words[1:]], bus.env, REPO)
            bus.procs.append(proc)
        done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=bus.env, capture_output=True,
                              text=True, timeout=300, check=False)
    finally:
        bus.reap()
    assert done.returncode == 0, f"{where}:\n{done.stderr}"
    if output is not None:
        assert done.stdout == output, f"{where} prints:\n{done.stdout}"
