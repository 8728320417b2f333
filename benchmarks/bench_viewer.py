"""Viewer speed: Talos (all visual meshes) to its first complete frame in headless Chromium,
robotmodel.viewer against Pinocchio's MeshcatVisualizer measured in the same run.

- Start to first complete frame: from "load the URDF" to the browser having drawn every
  visual mesh (the page's mesh count reaches the robot's, then two animation frames).
  Chromium is already running on about:blank for both, and Python imports are done.
  - robotmodel: load + Viewer (meshes converted or read from the cache, server on
    127.0.0.1) + page load. Cold = empty mesh cache; warm = the later starts.
  - Pinocchio: buildModelsFromUrdf (coal/assimp meshes) + meshcat's server process (bound
    to 127.0.0.1 by a small launcher) + initViewer + loadViewerModel + display + page load.
    It has no cache; its "warm" is its later starts in the same process.
  Warm starts alternate between the two (best and median of --rounds each).
  Goal: robotmodel warm <= 0.5x Pinocchio warm.
- Slider-to-redraw latency: a slider input event in the page until the page has drawn the
  state containing it (the server's "synced" answer, then render()). Single moves spaced
  out, and a 60 Hz drag (coalesced to 30 Hz redraws). Goal p50 <= 50 ms.

Run: python benchmarks/bench_viewer.py [--rounds N]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from pathlib import Path
from typing import Any

import meshcat
import pinocchio as pin
from pinocchio.visualize import MeshcatVisualizer

from robotmodel.model import load
from robotmodel.viewer import Browser, Viewer

SHARE = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix" / "share"
TALOS = SHARE / "example-robot-data" / "robots" / "talos_data" / "robots" / "talos_reduced.urdf"
MESH_COUNT = "(() => { let n = 0; viewer.scene.traverse(o => { if (o.isMesh) n++; }); return n; })()"
TWO_FRAMES = "new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))"

# meshcat's server binds every interface; this launcher binds it to 127.0.0.1 only.
_MESHCAT_LAUNCHER = """
import sys, tornado.web
from meshcat.servers import zmqserver
_listen = tornado.web.Application.listen
def _loopback(self, port, address="127.0.0.1", **kw):
    return _listen(self, port, address=address, **kw)
tornado.web.Application.listen = _loopback
bridge = zmqserver.ZMQWebSocketBridge(host="127.0.0.1")
print(f"zmq_url={bridge.zmq_url}", flush=True)
print(f"web_url={bridge.web_url}", flush=True)
bridge.run()
"""


def _wait_drawn(browser: Browser, url: str, meshes: int) -> None:
    browser.navigate(url)
    browser.wait_for(f"typeof viewer !== 'undefined' && {MESH_COUNT} >= {meshes}", timeout=120, poll=0.01)
    browser.evaluate(TWO_FRAMES)


def ours(browser: Browser, cache: Path, meshes: int) -> float:
    start = time.perf_counter()
    viewer = Viewer(load(TALOS), port=0, cache_dir=cache)
    try:
        _wait_drawn(browser, viewer.url or "", meshes)
        return time.perf_counter() - start
    finally:
        viewer.close()
        browser.navigate("about:blank")


def pinocchio(browser: Browser) -> float:
    start = time.perf_counter()
    model, collision, visual = pin.buildModelsFromUrdf(str(TALOS), package_dirs=[str(SHARE)])
    server = subprocess.Popen([sys.executable, "-u", "-c", _MESHCAT_LAUNCHER], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, text=True)
    try:
        assert server.stdout is not None
        zmq_url = server.stdout.readline().strip().split("=", 1)[1]
        web_url = server.stdout.readline().strip().split("=", 1)[1]
        viz = MeshcatVisualizer(model, collision, visual)
        with contextlib.redirect_stdout(io.StringIO()):  # meshcat prints its URL
            viz.initViewer(viewer=meshcat.Visualizer(zmq_url=zmq_url))
        viz.loadViewerModel()
        viz.display(pin.neutral(model))
        _wait_drawn(browser, web_url, len(visual.geometryObjects))
        return time.perf_counter() - start
    finally:
        server.kill()
        server.wait()
        browser.navigate("about:blank")


def latencies(browser: Browser, viewer: Viewer, joint: str) -> tuple[list[float], list[float]]:
    browser.navigate(viewer.url or "")
    browser.wait_for("window.robotmodel && window.robotmodel.renders > 0", timeout=60)
    move = f"""(step) => {{ const s = document.getElementById("joint-{joint}");
        s.value = step; s.dispatchEvent(new Event("input")); }}"""
    single = []
    for i in range(40):
        browser.evaluate(f"window.robotmodel.latencies = []; ({move})({2000 + i * 150})")
        browser.wait_for("window.robotmodel.latencies.length >= 1", timeout=10, poll=0.005)
        single.append(browser.evaluate("window.robotmodel.latencies[0]"))
        time.sleep(0.05)  # spaced out: each move is drawn on its own
    drag = browser.evaluate(f"""new Promise(done => {{
        window.robotmodel.latencies = []; let i = 0;
        const timer = setInterval(() => {{
            ({move})(1000 + (i * 37) % 8000); i += 1;
            if (i === 120) {{ clearInterval(timer); setTimeout(() => done(window.robotmodel.latencies), 500); }}
        }}, 1000 / 60); }})""")
    return single, drag


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--rounds", type=int, default=3, help="warm starts measured per viewer (best kept)")
    args = parser.parse_args()
    desc = load(TALOS)
    meshes = sum(len(link.visuals) for link in desc.links)
    print(f"Talos (talos_reduced.urdf): {meshes} visuals, {len(desc.movable_joints)} movable joints")
    with Browser(width=1280, height=800, timeout=120) as browser, tempfile.TemporaryDirectory() as tmp:
        cache = Path(tmp)
        ours_cold = ours(browser, cache, meshes)
        pin_cold = pinocchio(browser)
        # Interleaved, so a change in the machine's load hits both alike.
        ours_runs, pin_runs = [], []
        for _ in range(args.rounds):
            ours_runs.append(ours(browser, cache, meshes))
            pin_runs.append(pinocchio(browser))
        ours_warm, pin_warm = min(ours_runs), min(pin_runs)
        ours_med, pin_med = statistics.median(ours_runs), statistics.median(pin_runs)
        print("start to first complete frame (s)      cold     warm best   warm median")
        print(f"  robotmodel.viewer                    {ours_cold:6.2f}   {ours_warm:6.2f}      {ours_med:6.2f}")
        print(f"  pinocchio MeshcatVisualizer          {pin_cold:6.2f}   {pin_warm:6.2f}      {pin_med:6.2f}")
        print(f"  ratio robotmodel / pinocchio         {ours_cold / pin_cold:6.2f}x  {ours_warm / pin_warm:6.2f}x"
              f"     {ours_med / pin_med:6.2f}x   (goal warm <= 0.5x)")
        viewer = Viewer(desc, port=0, cache_dir=cache)
        try:
            single, drag = latencies(browser, viewer, "arm_left_4_joint")
        finally:
            viewer.close()

    def summary(values: list[Any]) -> str:
        ordered = sorted(float(v) for v in values)
        p90 = ordered[int(0.9 * (len(ordered) - 1))]
        return f"p50 {statistics.median(ordered):5.1f} ms   p90 {p90:5.1f} ms   (n={len(ordered)})"

    print("slider-to-redraw latency (goal p50 <= 50 ms)")
    print(f"  single moves                         {summary(single)}")
    print(f"  60 Hz drag, redraws <= 30 Hz         {summary(drag)}")


if __name__ == "__main__":
    main()
