"""Live-bus fixtures for these tests (see tests/livebus.py)."""

from livebus import bus

__all__ = ["bus"]
