"""The progress bar: drawn on its stream only when enabled and only after its delay; closed with a newline."""

from __future__ import annotations

import io

from robotmodel.recording._progress import Progress


def test_bar_when_enabled():
    out = io.StringIO()
    bar = Progress("run.mcap", 200, enabled=True, stream=out, delay_s=0.0)
    bar.update(50)
    bar.close()
    assert out.getvalue() == "\rrun.mcap [#######                       ]  25%  50 messages\n"


def test_nothing_before_the_delay_nor_when_disabled_or_not_a_terminal():
    for bar in (Progress("x", 10, enabled=True, stream=io.StringIO(), delay_s=60.0),
                Progress("x", 10, enabled=False, stream=io.StringIO(), delay_s=0.0),
                Progress("x", 10, stream=io.StringIO(), delay_s=0.0)):  # StringIO is not a tty
        bar.update(5)
        bar.close()
        assert bar.stream.getvalue() == ""
