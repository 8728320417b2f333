"""One self-contained HTML page of a scene: meshcat's viewer script and the scene inlined.

Like meshcat's static export, but the commands are decoded and run synchronously in
order, so the page is complete the moment its script has run (``window.robotmodel.synced``
becomes 1), which makes it usable for screenshots and offline bug reports.
"""

from __future__ import annotations

import base64
import json
from collections.abc import Iterable, Sequence
from html import escape

from robotmodel.viewer._server import meshcat_dist

__all__ = ["static_page"]

_TEMPLATE = """<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><title>{title}</title>
<style>body {{ margin: 0; }} #meshcat-pane {{ width: 100vw; height: 100vh; overflow: hidden; }}</style>
</head>
<body>
<div id="meshcat-pane"></div>
<script>{script}</script>
<script>
(function () {{
  var viewer = new MeshCat.Viewer(document.getElementById("meshcat-pane"));
  window.viewer = viewer;
  var commands = {commands};
  for (var i = 0; i < commands.length; i++) {{
    var text = atob(commands[i]);
    var bytes = new Uint8Array(text.length);
    for (var j = 0; j < text.length; j++) bytes[j] = text.charCodeAt(j);
    viewer.handle_command_bytearray(bytes);
  }}
  viewer.controls.target.fromArray({target});  // what the camera looks at (see _camera.py)
  viewer.render();
  window.robotmodel = {{synced: 1, renders: 1, static: true}};
}})();
</script>
</body>
</html>
"""


def static_page(title: str, commands: Iterable[bytes], *, target: Sequence[float] = (0.0, 0.0, 0.0)) -> str:
    """The HTML text of a page that draws ``commands`` with no server and no network.

    ``target`` is the point (three.js coordinates) the camera looks at.
    """
    script = (meshcat_dist() / "main.min.js").read_text(encoding="utf-8")
    # A literal "</script" inside the inlined code would end the element early.
    script = script.replace("</script", "<\\/script")
    encoded = json.dumps([base64.b64encode(c).decode("ascii") for c in commands], separators=(",", "\n"))
    return _TEMPLATE.format(title=escape(title), script=script, commands=encoded,
                            target=json.dumps([float(v) for v in target]))
