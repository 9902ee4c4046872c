"""The demo's driver: a scripted joystick, and the control period."""
from __future__ import annotations

import math

from drivekin import ChassisVelocities

DT = 0.02                   # control period, s (50 Hz)
BUDGET_NS = 20_000_000      # the same period in ns, for the budget columns

_cos = math.cos


class JoystickScript:
    """A deterministic driver: field-relative stick values, repeated every 30 s.

    Segments (stick values in [-1, 1]; translation scaled by ``max_speed`` m/s, rotation
    by ``max_omega`` rad/s):

    ========  ====  ====================================================================
    forward    3 s  +x at 0.5
    strafe     3 s  +y (left) at 0.5
    spin       3 s  rotate counter-clockwise at 0.5, no translation
    figure-8  16 s  one lemniscate-like loop (x ~ sin ωt, y ~ sin 2ωt, returns to its
                    start) while rotating at 0.35
    return     3 s  -x and -y at 0.5, back towards the start
    stop       2 s  sticks released
    ========  ====  ====================================================================
    """

    SEGMENTS = (
        ("forward", 3.0),
        ("strafe", 3.0),
        ("spin", 3.0),
        ("figure-8", 16.0),
        ("return", 3.0),
        ("stop", 2.0),
    )
    CYCLE = sum(d for _, d in SEGMENTS)

    __slots__ = ("_max_speed", "_max_omega", "_writers", "_durations", "_count", "_index",
                 "_t", "_fig8_w")

    def __init__(self, max_speed: float, max_omega: float) -> None:
        self._max_speed = float(max_speed)
        self._max_omega = float(max_omega)
        # Plain functions, not bound methods: bound methods stored on self would form a
        # reference cycle, leaving discarded simulations to the cyclic GC.
        cls = type(self)
        writers = {
            "forward": cls._forward, "strafe": cls._strafe, "spin": cls._spin,
            "figure-8": cls._figure8, "return": cls._return, "stop": cls._stop,
        }
        self._writers = tuple(writers[name] for name, _ in self.SEGMENTS)
        self._durations = tuple(d for _, d in self.SEGMENTS)
        self._count = len(self.SEGMENTS)
        self._fig8_w = 2.0 * math.pi / dict(self.SEGMENTS)["figure-8"]
        self._index = 0          # current segment (small int: no allocation)
        self._t = 0.0            # time inside the segment, s

    def write(self, cv: ChassisVelocities) -> None:
        """Write this step's field-relative command (m/s, rad/s) into ``cv`` and advance
        the script by one period."""
        t = self._t
        if t >= self._durations[self._index] - 1e-9:
            self._index = (self._index + 1) % self._count
            t = 0.0
        self._writers[self._index](self, t, cv)
        self._t = t + DT

    def _set(self, cv, jx, jy, jr):
        cv.vx = jx * self._max_speed
        cv.vy = jy * self._max_speed
        cv.omega = jr * self._max_omega

    def _forward(self, t, cv):
        self._set(cv, 0.5, 0.0, 0.0)

    def _strafe(self, t, cv):
        self._set(cv, 0.0, 0.5, 0.0)

    def _spin(self, t, cv):
        self._set(cv, 0.0, 0.0, 0.5)

    def _figure8(self, t, cv):
        w = self._fig8_w
        self._set(cv, 0.3 * _cos(w * t), 0.3 * _cos(2.0 * w * t), 0.35)

    def _return(self, t, cv):
        self._set(cv, -0.5, -0.5, 0.0)

    def _stop(self, t, cv):
        self._set(cv, 0.0, 0.0, 0.0)


