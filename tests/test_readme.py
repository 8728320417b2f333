"""The README's library example runs as written."""

from __future__ import annotations

import re

from conftest import REPO


def test_library_snippet_runs() -> None:
    text = (REPO / "README.md").read_text(encoding="utf-8")
    code = re.search(r"## Library\n\n```python\n(.*?)```", text, re.S)
    assert code is not None
    exec(compile(code.group(1), "README.md", "exec"), {})
