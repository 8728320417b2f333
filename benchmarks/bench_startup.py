"""Start-up of the command line and of loading a plain URDF, next to their peers in the same run.

Prints the best and median wall time and the best CPU time of each command (fresh
interpreter each time):
`robotmodel --help`, `robotmodel check-urdf` on a plain URDF (Panda), the xacro command's
own `--help` and its run on the same file (the peer: a Python command line of the same
family), urdfdom's check_urdf binary (C++), and a bare interpreter (the floor). Then, in one
process, `robotmodel.load` of the plain URDF against the old route through the xacro child
process. Goals: `--help` <= 0.15 s, check-urdf on a plain URDF <= 0.3 s.
"""

from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import sysconfig
import time
from pathlib import Path

RUNS = 15
PREFIX = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix"
PANDA = PREFIX / "share" / "example-robot-data" / "robots" / "panda_description" / "urdf" / "panda.urdf"
ENV = dict(os.environ, LD_LIBRARY_PATH=f"{PREFIX / 'lib'}:{os.environ.get('LD_LIBRARY_PATH', '')}")
XACRO_MAIN = "import sys; from xacro import main; sys.argv[0] = 'xacro'; main()"


def _wall(argv: list[str]) -> tuple[float, float, float]:
    """Best and median wall time, and best CPU time (user + system; steadier on a loaded host)."""
    times, cpus = [], []
    for _ in range(RUNS):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV, check=False)
        times.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return min(times), statistics.median(times), min(cpus)


def _in_process(fn: object, runs: int) -> float:
    assert callable(fn)
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return best


def main() -> None:
    py = sys.executable
    rows = [
        ("python -c pass (floor)", [py, "-c", "pass"]),
        ("robotmodel --help", [py, "-m", "robotmodel.cli.main", "--help"]),
        ("xacro --help (peer)", [py, "-c", XACRO_MAIN, "--help"]),
        ("robotmodel check-urdf panda.urdf", [py, "-m", "robotmodel.cli.main", "check-urdf", str(PANDA)]),
        ("xacro panda.urdf (peer)", [py, "-c", XACRO_MAIN, str(PANDA)]),
        ("check_urdf panda.urdf (urdfdom, C++)", [str(PREFIX / "bin" / "check_urdf"), str(PANDA)]),
    ]
    print(f"{'command (fresh process)':40s} {'wall best':>10s} {'median':>10s} {'CPU best':>10s}   ({RUNS} runs each)")
    for label, argv in rows:
        best, median, cpu = _wall(argv)
        print(f"{label:40s} {best * 1e3:7.1f} ms {median * 1e3:7.1f} ms {cpu * 1e3:7.1f} ms")

    import robotmodel
    from robotmodel.model import parse_urdf
    from robotmodel.xacro import expand

    direct = _in_process(lambda: robotmodel.load(PANDA), 50)
    through_xacro = _in_process(lambda: parse_urdf(expand(PANDA)), 5)
    print(f"\nrobotmodel.load(panda.urdf), plain URDF parsed directly: {direct * 1e3:8.2f} ms")
    print(f"the same through the xacro child process (old route):    {through_xacro * 1e3:8.2f} ms "
          f"({through_xacro / direct:.0f}x)")


if __name__ == "__main__":
    main()
