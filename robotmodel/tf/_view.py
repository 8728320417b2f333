"""view_frames from a buffer: the frame tree as graphviz text in tf2_tools' layout, and a PDF."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from robotmodel.errors import RobotModelError
from robotmodel.tf._names import dot_quoted

if TYPE_CHECKING:
    from robotmodel.tf._core import BufferCore

__all__ = ["view_frames_gv", "write_view_frames"]


def view_frames_gv(frames_yaml: str, recorded_at_ns: int) -> str:
    """Graphviz text of tf2_tools' view_frames for ``all_frames_as_yaml()`` output.

    Names are escaped for dot (quotes, backslashes, unprintable characters), so any frame
    name a publisher sends gives a graph that dot draws.
    """
    data: Any = yaml.safe_load(frames_yaml) if frames_yaml.strip() else None
    if not data:
        return 'digraph G { "No tf data received" }'
    data = {str(child): {**info, "parent": str(info["parent"])} for child, info in data.items()}
    lines = ["digraph G {\n"]
    for child, info in data.items():
        lines.append(
            f'"{dot_quoted(info["parent"])}" -> "{dot_quoted(child)}"'
            f'[label=" Broadcaster: {dot_quoted(str(info["broadcaster"]))}\\n'
            f'Average rate: {info["rate"]}\\nBuffer length: {info["buffer_length"]}\\n'
            f'Most recent transform: {info["most_recent_transform"]}\\n'
            f'Oldest transform: {info["oldest_transform"]}\\n"];\n'
        )
    # As view_frames: the legend hangs off the last parent (in YAML order) that is no child.
    roots = [info["parent"] for info in data.values() if info["parent"] not in data]
    if not roots:
        raise RobotModelError("view_frames: the frame tree has no root (it contains a loop)")
    seconds = recorded_at_ns // 1_000_000_000 + (recorded_at_ns % 1_000_000_000) / 1e9
    lines.append("edge [style=invis];\n")
    lines.append(' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";\n')
    lines.append(f'"Recorded at time: {seconds}"[ shape=plaintext ] ;\n')
    lines.append(f'}}->"{dot_quoted(roots[-1])}";\n}}')
    return "".join(lines)


def write_view_frames(
    buffer: BufferCore, name: str | os.PathLike[str], recorded_at_ns: int
) -> tuple[Path, Path | None]:
    """Write ``name.gv`` and, when graphviz's ``dot`` exists, ``name.pdf``; returns both paths.

    The PDF path is None when ``dot`` is not installed (nothing is claimed then).
    """
    base = Path(name)
    gv = base.with_name(base.name + ".gv")
    text = view_frames_gv(buffer.all_frames_as_yaml(), recorded_at_ns)
    gv.parent.mkdir(parents=True, exist_ok=True)
    tmp = gv.with_name(f".{gv.name}.tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(gv)
    dot = shutil.which("dot")
    if dot is None:
        return gv, None
    pdf = base.with_name(base.name + ".pdf")
    with tempfile.TemporaryDirectory(dir=pdf.resolve().parent) as scratch:
        out = Path(scratch) / pdf.name
        result = subprocess.run([dot, "-Tpdf", str(gv), "-o", str(out)], capture_output=True, text=True,
                                check=False)
        if result.returncode != 0:
            raise RobotModelError(f"dot failed on {gv}: {result.stderr.strip()}")
        out.replace(pdf)
    return gv, pdf
