"""Live-bus fixtures for the viewer tests (see tests/livebus.py)."""

from livebus import bus

__all__ = ["bus"]
