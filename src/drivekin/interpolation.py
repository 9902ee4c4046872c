"""TimeInterpolatableBuffer: a bounded history of timestamped samples that can be read
at any time between them (WPILib 2027 Java's ``TimeInterpolatableBuffer``).

Times and the history size are seconds on one clock. Deliberate departures from
WPILib: times must be finite and the history size finite and positive (ValueError
otherwise), where WPILib stores NaN keys or keeps nothing; 0.0 and -0.0 are one time.
"""
from __future__ import annotations

import bisect
import math
import threading
from typing import TYPE_CHECKING, Any, Callable, Generic, List, Optional, Tuple, TypeVar

from drivekin._core.errors import type_name
from drivekin._core.numbers import as_double

__all__ = ["TimeInterpolatableBuffer"]

T = TypeVar("T")


def _seconds(value: object, what: str) -> float:
    v = as_double(value, f"{what} must be a number of seconds")
    if not math.isfinite(v):
        raise ValueError(f"{what} must be a finite number of seconds, got {v!r}")
    return v


def _interpolate_method(start: Any, end: Any, t: float) -> Any:
    return start.interpolate(end, t)


def _lerp(start: float, end: float, t: float) -> float:
    return start + (end - start) * t


def _time(entry: Tuple[float, Any]) -> float:
    return entry[0]


class TimeInterpolatableBuffer(Generic[T]):
    """TimeInterpolatableBuffer(func, history_size)

    Samples keyed by time (s), keeping ``history_size`` seconds of history measured back
    from each newly added time. Build one with :meth:`createBuffer` or
    :meth:`createDoubleBuffer` (the constructor is the two-argument ``createBuffer``).
    """

    _ready = False     # set last by __init__: a __new__'d or failed object refuses work

    def __init__(self, func: Callable[[T, T, float], T], history_size: float) -> None:
        if self._ready:
            raise TypeError("TimeInterpolatableBuffer is already initialised: __init__ "
                            "cannot be called again (use clear)")
        if not callable(func):
            raise TypeError(f"func must be a callable f(start, end, t), got {type_name(func)}")
        history = _seconds(history_size, "history_size")
        if history <= 0.0:
            raise ValueError(f"history_size must be positive (s), got {history!r}")
        self._f = func
        self._history = history
        # An immutable snapshot, replaced whole: readers need no lock, and a writer
        # whose snapshot changed while it worked (another thread, or a finalizer that
        # re-entered) starts again instead of overwriting that change.
        self._entries: Tuple[Tuple[float, T], ...] = ()
        # Re-entrant: CPython 3.14 (seen there) may run a finalizer (and so a nested addSample on
        # this buffer) at the eval-breaker check right after the lock is taken, which
        # deadlocked with a plain Lock. The nested call commits first; this one's
        # identity test then fails and it starts again.
        self._commit = threading.RLock()
        self._ready = True

    @staticmethod
    def createBuffer(*args: Any) -> "TimeInterpolatableBuffer[Any]":
        """createBuffer(history_size) or createBuffer(func, history_size).

        With one argument the samples must have an ``interpolate(end, t)`` method
        (Pose2d, Rotation2d, Translation2d, …); with two, ``func(start, end, t)``
        blends two samples (t in [0, 1]). ``history_size`` in s."""
        if len(args) == 1:
            return TimeInterpolatableBuffer(_interpolate_method, args[0])
        if len(args) == 2:
            return TimeInterpolatableBuffer(args[0], args[1])
        raise TypeError("createBuffer takes (history_size) or (func, history_size), "
                        f"got {len(args)} arguments")

    @staticmethod
    def createDoubleBuffer(history_size: float) -> "TimeInterpolatableBuffer[float]":
        """A buffer of floats, interpolated linearly; ``history_size`` in s."""
        return TimeInterpolatableBuffer(_lerp, history_size)

    def _check(self) -> None:
        if not self._ready:
            raise RuntimeError("TimeInterpolatableBuffer.__init__ has not completed")

    def addSample(self, time: float, sample: T) -> None:
        """Add ``sample`` taken at ``time`` (s). First every sample at least
        ``history_size`` older than ``time`` is dropped (so an old sample drops nothing);
        a sample already stored at ``time`` is replaced."""
        self._check()
        t = _seconds(time, "time")
        if self._f is _lerp:
            sample = _float_sample(sample)   # type: ignore[assignment]
        entry = (t, sample)
        while True:
            old = self._entries
            first = 0
            while first < len(old) and t - old[first][0] >= self._history:
                first += 1
            i = bisect.bisect_left(old, t, lo=first, key=_time)
            after = i + 1 if i < len(old) and old[i][0] == t else i
            new = old[first:i] + (entry,) + old[after:]
            with self._commit:
                done = self._entries is old
                if done:
                    self._entries = new
            if done:
                return   # ``old`` dies here, outside the lock (its samples' finalizers)

    def getSample(self, time: float) -> Optional[T]:
        """The sample at ``time`` (s): the stored one on an exact hit, the oldest/newest
        one outside the stored range, else the interpolation between the two
        neighbours; None when the buffer is empty."""
        self._check()
        t = _seconds(time, "time")
        entries = self._entries
        if not entries:
            return None
        i = bisect.bisect_left(entries, t, key=_time)
        if i < len(entries) and entries[i][0] == t:
            return entries[i][1]
        if i == 0:
            return entries[0][1]
        if i == len(entries):
            return entries[-1][1]
        (t0, a), (t1, b) = entries[i - 1], entries[i]
        d = t1 - t0
        if math.isinf(d) and math.isfinite(t0) and math.isfinite(t1):
            # Two finite times whose span overflows (1e308 and -1e308): the same ratio of
            # halves (exact scalings, so the same value where the plain form is finite)
            # instead of inf/inf. (The estimators' history spans at most 1.5 s.)
            return self._f(a, b, (0.5 * t - 0.5 * t0) / (0.5 * t1 - 0.5 * t0))
        return self._f(a, b, (t - t0) / d)

    def clear(self) -> None:
        """Remove every sample."""
        self._check()
        self._entries = ()

    def getInternalBuffer(self) -> List[Tuple[float, T]]:
        """A snapshot of the stored ``(time s, sample)`` pairs, oldest first."""
        self._check()
        return list(self._entries)

    def __reduce__(self) -> Tuple[Any, ...]:
        # Copies and pickles get their own history (the lock is not state).
        self._check()
        return (_rebuild, (self._f, self._history, self._entries))

    # robotpy 2027's spellings (drivekin._core.pynames; scripts/stub_aliases.py)
    if TYPE_CHECKING:
        add_sample = addSample
        create_buffer = createBuffer
        create_double_buffer = createDoubleBuffer
        get_internal_buffer = getInternalBuffer
        sample = getSample


def _rebuild(f: Callable[[Any, Any, float], Any], history: float,
             entries: Tuple[Tuple[float, Any], ...]) -> TimeInterpolatableBuffer[Any]:
    buf: TimeInterpolatableBuffer[Any] = TimeInterpolatableBuffer(f, history)
    times = [t for t, _ in entries]
    if (not isinstance(entries, tuple) or
            any(type(e) is not tuple or len(e) != 2 or type(e[0]) is not float
                or not math.isfinite(e[0]) for e in entries) or
            any(a >= b for a, b in zip(times, times[1:]))):
        raise ValueError("TimeInterpolatableBuffer state must be (time, sample) pairs "
                         "with finite, strictly increasing float times")
    if f is _lerp and any(type(s) is not float for _, s in entries):
        raise ValueError("a double buffer's samples must be floats")
    buf._entries = entries
    return buf


def _float_sample(sample: object) -> float:
    # A double buffer stores floats (Java's Double): refuse anything else now rather
    # than fail inside a later getSample.
    return as_double(sample, "sample must be a float")
