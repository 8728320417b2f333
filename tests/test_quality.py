"""The tree stays lint-clean and type-clean (ruff, mypy strict on the library), as CI checks."""

from __future__ import annotations

import shutil
import subprocess
import sys

import pytest
from conftest import REPO


@pytest.mark.parametrize(
    "command",
    [
        pytest.param([sys.executable, "-m", "ruff", "check", "."], id="ruff"),
        pytest.param([sys.executable, "-m", "mypy"], id="mypy"),
    ],
)
def test_tool_is_clean(command: list[str]) -> None:
    if shutil.which(command[2]) is None:
        pytest.fail(f"{command[2]} is not installed; install the test extras")
    result = subprocess.run(command, cwd=REPO, capture_output=True, text=True, timeout=600, check=False)
    assert result.returncode == 0, result.stdout[-4000:] + result.stderr[-2000:]
