"""Raw CDR through cyclonedds-python: writers and readers that move serialized bytes, never samples.

cyclonedds-python's ``DataWriter.write`` serializes a Python sample and hands the bytes, in
a ``{pointer, size}`` container, to ``dds_write``, whose sertype copies them as they are;
its ``DataReader.take`` gets ``(bytes, SampleInfo)`` pairs from its C layer's ``ddspy_take``
and deserializes them. Calling ``dds_write`` with such a container and ``ddspy_take``
directly moves the payload the seam hands over (CDR with its 4-byte encapsulation header)
unchanged in both directions; Cyclone still checks each payload against the topic type (:mod:`._dds_types`).
As Cyclone's own serializer does, a payload is padded to a multiple of 4 bytes and the
padding is recorded in the low two bits of the encapsulation options (XTypes 1.3, 7.6.3.1.2);
the receiving side strips it again.

Listeners run on Cyclone's threads (for a local reader, in the writer's thread), so a
reader's listener only wakes a :class:`Pump`, whose own thread takes the samples and runs
the callbacks: a slow callback never stalls Cyclone, and a callback may publish or close.

Only the DDS wire uses this module (it is below the backend seam).
"""

from __future__ import annotations

import ctypes
import logging
import threading
from collections.abc import Callable
from typing import Any

from cyclonedds._clayer import ddspy_take
from cyclonedds.core import DDSException, Entity, Listener
from cyclonedds.internal import DDS

from robotmodel.errors import BusError

log = logging.getLogger("robotmodel.bus")

__all__ = ["ANY_STATE", "Pump", "destroy", "make_listener", "pad", "take_raw", "unpad", "write_raw"]

#: Every sample, view and instance state (DDS_ANY_STATE).
ANY_STATE = 0x7F
_BATCH = 256
_dds_write = DDS._dll_handle.dds_write
_dds_write.restype = ctypes.c_int32
_dds_write.argtypes = [ctypes.c_int32, ctypes.c_void_p]


class _Container(ctypes.Structure):
    # The binding's ddspy_sample_container_t: what its sertype copies a written sample from.
    _fields_ = [("usample", ctypes.c_char_p), ("usample_size", ctypes.c_size_t)]


def pad(payload: bytes) -> bytes:
    """The payload padded to 4 bytes, the padding count in the encapsulation options' low bits."""
    extra = -len(payload) % 4
    if not extra or len(payload) < 4:
        return payload
    return payload[:3] + bytes([(payload[3] & 0xFC) | extra]) + payload[4:] + b"\0" * extra


def unpad(data: bytes) -> bytes:
    """Undo :func:`pad`: drop the padding the encapsulation options record."""
    if len(data) < 4:
        return data
    extra = data[3] & 0x03
    if not extra:
        return data
    return data[:3] + bytes([data[3] & 0xFC]) + data[4:len(data) - extra]


def write_raw(writer: Any, payload: bytes, topic: str, typename: str) -> None:
    """Write one CDR payload on a cyclonedds DataWriter; BusError when Cyclone refuses it."""
    data = pad(payload)
    # dds_write through ctypes, which lets go of the GIL: a reliable writer may wait for
    # acknowledgements, which Cyclone's receive thread handles while Python threads run.
    container = _Container(data, len(data))  # held until dds_write returns
    ret = _dds_write(writer._ref, ctypes.byref(container))
    if ret < 0:
        raise BusError(f"DDS refused a sample on '{topic}' ({DDSException(ret, '')}): "
                       f"is it CDR of '{typename}'?")


def take_raw(reader: Any) -> list[tuple[bytes, Any]]:
    """Take up to a batch of (CDR payload, SampleInfo) from a cyclonedds DataReader ([] when none)."""
    ret = ddspy_take(reader._ref, ANY_STATE, _BATCH)
    if isinstance(ret, int):
        return []
    return [(unpad(data), info) for data, info in ret]


def destroy(entity: Any) -> None:
    """Delete a cyclonedds entity now (its children with it), not when Python collects it."""
    ref = getattr(entity, "_ref", None)
    known: Any = Entity._entities.get(ref) if ref is not None else None
    if known is not None and known is entity:
        del Entity._entities[ref]
        known._delete(ref)


def make_listener(**callbacks: Callable[..., None]) -> Any:
    """A Cyclone listener with these ``on_...`` callbacks (they run on Cyclone's threads)."""
    return Listener(**callbacks)  # type: ignore[no-untyped-call]


class Pump:
    """A thread that runs ``drain()`` after each :meth:`poke` (pokes while it runs coalesce)."""

    def __init__(self, name: str, drain: Callable[[], None]) -> None:
        self._drain = drain
        self._cond = threading.Condition()
        self._poked = False
        self._open = True
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

    def poke(self, *_args: Any) -> None:
        """Ask for a drain (safe from any thread, Cyclone's listeners included)."""
        with self._cond:
            self._poked = True
            self._cond.notify()

    def listener(self, **callbacks: Callable[..., None]) -> Any:
        """A Cyclone listener that pokes this pump when data arrives (plus ``callbacks``)."""
        return make_listener(on_data_available=self.poke, **callbacks)

    def _run(self) -> None:
        while True:
            with self._cond:
                self._cond.wait_for(lambda: self._poked or not self._open)
                if not self._open:
                    return
                self._poked = False
            try:
                self._drain()
            except Exception:  # a pump that died would leave its readers silent for good
                log.exception("%s: taking samples failed", self._thread.name)

    def close(self) -> None:
        """Stop the thread (waits for a drain in progress unless called from it)."""
        with self._cond:
            self._open = False
            self._cond.notify()
        if threading.current_thread() is not self._thread:
            self._thread.join(5.0)
