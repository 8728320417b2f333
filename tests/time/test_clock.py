"""Clocks: system, set by hand, recording playback; Rate on any of them."""

from __future__ import annotations

import threading
import time

import pytest

from robotmodel.time import Clock, Duration, PlaybackClock, Rate, SimClock, SystemClock, Time

SEC = 1_000_000_000


def test_every_clock_is_a_clock() -> None:
    for clock in (SystemClock(), SimClock(), PlaybackClock(Time(seconds=5))):
        assert isinstance(clock, Clock)
        assert isinstance(clock.now(), Time)


def test_system_clock_is_wall_time() -> None:
    before = time.time_ns()
    now = SystemClock().now().nanoseconds
    after = time.time_ns()
    assert before <= now <= after


def test_system_clock_sleep_until() -> None:
    clock = SystemClock()
    target = clock.now() + Duration(seconds=0.02)
    assert clock.sleep_until(target)
    assert clock.now() >= target
    far = clock.now() + Duration(seconds=60)
    start = time.monotonic()
    assert clock.sleep_until(far, timeout=Duration(seconds=0.02)) is False
    assert time.monotonic() - start < 5


def test_sim_clock_moves_only_when_told() -> None:
    clock = SimClock(Time(seconds=100))
    assert clock.now() == Time(seconds=100) == clock.now()
    assert clock.advance(Duration(seconds=0.5)) == Time(seconds=100.5) == clock.now()
    clock.set(Time(seconds=3))  # may jump back, as ROS time on a looping replay
    assert clock.now() == Time(seconds=3)
    with pytest.raises(ValueError, match="negative"):
        clock.advance(Duration(seconds=-4))
    assert clock.now() == Time(seconds=3)


def test_sim_clock_wakes_sleepers_when_set() -> None:
    clock = SimClock()
    woke = threading.Event()
    results: list[bool] = []

    def sleeper() -> None:
        results.append(clock.sleep_until(Time(seconds=10)))
        woke.set()

    thread = threading.Thread(target=sleeper)
    thread.start()
    clock.set(Time(seconds=9))
    assert not woke.wait(0.05)  # not yet: the clock is before the target
    clock.advance(Duration(seconds=1))
    assert woke.wait(5.0)
    thread.join(5.0)
    assert results == [True]
    assert clock.sleep_until(Time(seconds=11), timeout=Duration(seconds=0.01)) is False


def test_playback_clock_runs_at_its_rate() -> None:
    clock = PlaybackClock(Time(seconds=1000), rate=10.0)
    # now() reads the monotonic clock between w0 and w1, then between w2 and w3.
    w0 = time.monotonic_ns()
    c0 = clock.now().nanoseconds
    w1 = time.monotonic_ns()
    time.sleep(0.02)
    w2 = time.monotonic_ns()
    c1 = clock.now().nanoseconds
    w3 = time.monotonic_ns()
    assert 10 * (w2 - w1) - 1 <= c1 - c0 <= 10 * (w3 - w0) + 1
    assert 1000 * SEC <= c0 <= 1000 * SEC + 10 * (w1 - w0) + 10 * SEC


def test_playback_clock_pause_seek_rate() -> None:
    clock = PlaybackClock(Time(seconds=50), rate=1.0, paused=True)
    assert clock.paused and clock.now() == Time(seconds=50)
    clock.seek(Time(seconds=70))
    assert clock.now() == Time(seconds=70)
    clock.resume()
    assert clock.now() >= Time(seconds=70) and not clock.paused
    clock.pause()
    frozen = clock.now()
    assert clock.now() == frozen
    clock.set_rate(4.0)
    assert clock.rate == 4.0 and clock.now() == frozen
    with pytest.raises(ValueError, match="positive"):
        PlaybackClock(Time(), rate=0.0)
    with pytest.raises(ValueError, match="positive"):
        clock.set_rate(-1.0)


def test_playback_clock_sleep_until_at_rate() -> None:
    clock = PlaybackClock(Time(seconds=10), rate=50.0)
    start = time.monotonic()
    assert clock.sleep_until(Time(seconds=11))  # 1 s of recording = 20 ms of wall time
    assert clock.now() >= Time(seconds=11)
    assert time.monotonic() - start < 5
    paused = PlaybackClock(Time(seconds=10), paused=True)
    assert paused.sleep_until(Time(seconds=11), timeout=Duration(seconds=0.03)) is False


def test_rate_on_a_sim_clock() -> None:
    clock = SimClock(Time(seconds=1))
    rate = Rate(10.0, clock)  # wake-ups at 1.1, 1.2, 1.3 s
    assert rate.period == Duration(seconds=0.1)
    wakes: list[Time] = []
    woke = threading.Semaphore(0)

    def loop() -> None:
        for _ in range(3):
            rate.sleep()
            wakes.append(clock.now())
            woke.release()

    thread = threading.Thread(target=loop)
    thread.start()
    for _ in range(3):
        for _ in range(10):  # ten 10 ms steps: the sleeper must wake on the tenth only
            clock.advance(Duration(seconds=0.01))
        assert woke.acquire(timeout=5.0)
    thread.join(5.0)
    assert wakes == [Time(seconds=1.1), Time(seconds=1.2), Time(seconds=1.3)]


def test_rate_restarts_after_falling_behind() -> None:
    clock = SimClock(Time(seconds=1))
    rate = Rate(10.0, clock)
    clock.set(Time(seconds=5))  # the loop did 4 s of work: no burst of 39 immediate wake-ups
    done = threading.Event()
    thread = threading.Thread(target=lambda: (rate.sleep(), done.set()))
    thread.start()
    clock.set(Time(seconds=5.05))
    assert not done.wait(0.05)
    clock.set(Time(seconds=5.1))
    assert done.wait(5.0)
    thread.join(5.0)


def test_rate_on_the_system_clock() -> None:
    rate = Rate(200.0)
    start = time.monotonic()
    for _ in range(4):
        rate.sleep()
    assert time.monotonic() - start >= 0.015  # four 5 ms periods, the first from the first call
    with pytest.raises(ValueError, match="positive"):
        Rate(0.0)
