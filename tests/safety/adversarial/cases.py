"""The adversarial cases, generated from the registry. ``GROUPS[name]()`` returns an
ordered {case id: zero-argument check}; a check raises AssertionError on failure. The
groups run in a child process (isolate.py), so a crash fails only its own case.

Groups: ``args`` (hostile arguments at every position; a failed call changes nothing),
``gc`` (finalizers that mutate the caller's list or re-enter the receiver mid-call),
``reentry`` (re-entrant __float__/__index__/__iter__/__len__), ``threads``,
``lifecycle`` (repeated/failed __init__, __new__, copies, crafted pickles), ``misc``
(huge counts, str/repr under hostile decimal contexts) and ``datalog`` (hostile
``.wpilog`` files: tests/_support/wpilog_bytes.py).
"""
from __future__ import annotations

import copy
import decimal
import functools
import pickle
import sys
import threading
import time

import numpy as np

import drivekin
import drivekin.wpistruct as wpistruct
from tests.safety.adversarial import registry as reg
from tests.safety.adversarial.registry import (Arr, Bytes, Const, Floats, Int, Num, Obj, Out,
                                               OutArr, OutBytes, OutRawArr, OutSeq, Prop,
                                               RawArr, Seq, Type)
from tests.safety.adversarial.support import (CLEAN, BadNumber, Boom, Fail, armed_gc, bound,
                                              describe, expect_clean, finite, is_module, label,
                                              member_specs, outcome, receiver, short, snap)

try:
    import wpimath.geometry
    import wpimath.kinematics
    _FOREIGN = (wpimath.geometry, wpimath.kinematics)
except ImportError:  # pragma: no cover - robotpy is a test dependency
    _FOREIGN = ()


def foreign(cls):
    """An instance of robotpy's class of the same name, or None."""
    for mod in _FOREIGN:
        f = getattr(mod, cls.__name__, None)
        if f is not None:
            try:
                return f()
            except TypeError:
                pass
    return None


def _wrong(cls):
    return drivekin.ChassisVelocities() if cls is drivekin.Twist2d else drivekin.Twist2d()


# ---- hostile values per kind: (name, make, extra allowed exceptions, needle) ---------

def _obj_hostiles(k):
    h = [("str", lambda: "abc", (), None), ("object", object, (), None)]
    if not isinstance(k, reg.StructObj):
        h.append(("wrong-class", lambda: _wrong(k.cls), (), None))
    if not k.none_ok:
        h.append(("None", lambda: None, (), None))
    if not k.float_ok:
        h.append(("float", lambda: 0.5, (), None))
    if foreign(k.cls) is not None:
        h.append(("foreign", lambda: foreign(k.cls), (), "wpimath"))
    return h


def _seq_hostiles(k):
    def with_item(i, make):
        def build():
            s = k.valid()
            s[i] = make()
            return s
        return build

    def raising_gen():
        yield from k.valid()[:-1]
        raise Boom("iterator")

    h = [("None", lambda: None, (), None), ("str", lambda: "abc", (), None),
         ("float", lambda: 0.5, (), None), ("all-None", lambda: [None] * len(k.valid()), (), None),
         ("None-item", with_item(1, lambda: None), (), None),
         ("None-last", with_item(-1, lambda: None), (), None),
         ("wrong-item", with_item(1, lambda: _wrong(k.cls)), (), None),
         ("raising-iterator", raising_gen, (Boom,), None)]
    if foreign(k.cls) is not None:
        h.append(("foreign-item", with_item(1, lambda: foreign(k.cls)), (), "wpimath"))
    if k.n:
        h += [("short", lambda: k.valid()[:-1], (), None),
              ("long", lambda: k.valid() + k.valid()[:1], (), None),
              ("empty", list, (), None)]
    elif k.least:
        h.append(("too-few", lambda: k.valid()[:k.least - 1], (), None))
    return h


def _num_hostiles(k):
    h = [("str", lambda: "abc", (), None), ("object", object, (), None),
         ("raising-float", BadNumber, (Boom,), None), ("complex", lambda: 1j, (), None),
         ("translation", drivekin.Translation2d, (), None)]
    if not k.none_ok:
        h.append(("None", lambda: None, (), None))
    return h


def _misaligned(a):
    raw = np.zeros(a.nbytes + 1, dtype=np.uint8)
    m = raw[1:].view(a.dtype).reshape(a.shape)
    m[...] = a
    return m


def _strided(a):
    big = np.zeros((2 * a.shape[0],) + a.shape[1:])
    big[::2] = a
    return big[::2]


def _arr_hostiles(k):
    """(name, make, must_raise): layout variants may instead be read correctly."""
    v = k.valid
    h = [("object-dtype", lambda: v().astype(object), True),
         ("float32", lambda: v().astype(np.float32), True),
         ("int64", lambda: v().astype(np.int64), True),
         ("wrong-shape", lambda: np.resize(v(), (k.shape[0] + 1,) + k.shape[1:]), True),
         ("flat" if len(k.shape) > 1 else "2-d", lambda: v().reshape(
             (-1,) if len(k.shape) > 1 else (1, -1)), True),
         ("memoryview-2d" if len(k.shape) > 1 else "memoryview", lambda: memoryview(v()), True),
         ("bytearray", lambda: bytearray(v().tobytes()), True),
         ("nested-list", lambda: v().tolist(), True),
         ("strided", lambda: _strided(v()), False),
         ("misaligned", lambda: _misaligned(v()), False),
         ("byteswapped", lambda: v().astype(v().dtype.newbyteorder(">")), False)]
    if len(k.shape) > 1:
        h.append(("fortran", lambda: np.asfortranarray(v()), False))
    if isinstance(k, OutArr):
        def readonly():
            a = v()
            a.flags.writeable = False
            return a
        h.append(("read-only", readonly, True))
    if k.rows_free:
        h = [x for x in h if x[0] != "wrong-shape"]
    if k.list_ok:
        h = [x for x in h if x[0] != "nested-list"]
    if isinstance(k, RawArr):  # raw bytes: only pointers and read-only targets are hostile
        h = [x for x in h if x[0] in ("object-dtype", "read-only", "strided", "misaligned")]
    return h


def hostiles(k):
    """(name, make, extra, needle, must_raise) for argument kind ``k``."""
    if isinstance(k, Arr):
        return [(n, m, (), None, r) for n, m, r in _arr_hostiles(k)]
    if isinstance(k, Obj):
        h = _obj_hostiles(k)
    elif isinstance(k, Seq):
        h = _seq_hostiles(k)
    elif isinstance(k, Num):
        h = _num_hostiles(k)
    elif isinstance(k, Floats):
        def with_item(make):
            def build():
                v = k.valid()
                v[-1] = make()
                return v
            return build
        h = [("str", lambda: "abc", (), None)]
        if not k.float_ok:
            h.append(("float", lambda: 0.5, (), None))
        h += [("short", lambda: k.valid()[:-1], (), None),
             ("long", lambda: k.valid() + [1.0], (), None), ("empty", list, (), None),
             ("None-item", with_item(lambda: None), (), None),
             ("str-item", with_item(lambda: "1.0"), (), None),
             ("bool-item", with_item(lambda: True), (), None),
             ("raising-float-item", with_item(BadNumber), (), None),
             ("huge-int-item", with_item(lambda: 10 ** 400), (), None),
             ("generator", lambda: (x for x in k.valid()), (), None),
             ("object-array", lambda: np.array(k.valid(), dtype=object), (), None),
             ("float32-array", lambda: np.array(k.valid(), dtype=np.float32), (), None)]
        if not k.none_ok:
            h.append(("None", lambda: None, (), None))
    elif isinstance(k, Int):
        h = [("None", lambda: None, (), None), ("float", lambda: 0.5, (), None),
             ("str", lambda: "abc", (), None), ("raising-index", BadNumber, (Boom,), None),
             ("negative", lambda: -1, (), None), ("huge", lambda: 10 ** 30, (), None)]
    elif isinstance(k, reg.State):
        good = k.valid()
        h = [("None", lambda: None, (), None), ("str", lambda: "abc", (), None),
             ("empty", tuple, (), None), ("list", lambda: list(good), (), None),
             ("None-items", lambda: (None,) * len(good), (), None),
             ("short", lambda: good[:-1], (), None),
             ("float-items", lambda: (0.5,) * len(good), (), None)]
    elif isinstance(k, (Bytes, OutBytes)):
        h = [("None", lambda: None, (), None), ("str", lambda: "abc", (), None),
             ("short", lambda: bytearray(k.valid()[:-1]), (), None),
             ("object-array", lambda: np.zeros(len(k.valid()) // 8, dtype=object), (), None)]
        if isinstance(k, OutBytes):
            h.append(("immutable-bytes", lambda: bytes(k.valid()), (), None))
    elif isinstance(k, Type):
        h = [("None", lambda: None, (), None), ("str", lambda: "abc", (), None),
             ("unsupported-class", lambda: object, (), None),
             ("foreign-class", lambda: type(foreign(k.cls)), (), "wpimath")]
    else:
        h = []
    return [(n, m, e, nd, True) for n, m, e, nd in h]


# ---- group: args -------------------------------------------------------------------

def _call_with(cls, name, sig, replace=None, extra_pos=(), extra_kw=None, alt=False):
    """Build a fresh receiver and valid args, apply ``replace`` {pos: value}; return
    (receiver, args, kwargs, call)."""
    recv = receiver(cls)
    args, kw = sig.build(alt)
    for pos, value in (replace or {}).items():
        args[pos] = value
    args += list(extra_pos)
    kw.update(extra_kw or {})
    fn = bound(cls, recv, name)
    return recv, args, kw, lambda: fn(*args, **kw)


def check_valid(cls, name, sig):
    _, _, _, call = _call_with(cls, name, sig)
    r = outcome(call)
    if r[0] == "raised":
        raise Fail(f"the registry's valid call raised {describe(r[1])}")


def check_hostile(cls, name, sig, replace, extra=(), needle=None, must_raise=True,
                  extra_pos=(), extra_kw=None):
    recv, args, kw, call = _call_with(cls, name, sig, replace, extra_pos, extra_kw)
    if name == "__eq__":  # == never raises: foreign/ill-typed operands compare unequal
        r = outcome(call)
        if r != ("ok", False):
            raise Fail(f"== with a hostile operand gave {short(r)}")
        return
    items = [list(a) if isinstance(a, list) else None for a in args]
    before = snap((recv, args, kw, items))
    if must_raise:
        expect_clean(call, extra, needle)
    else:  # a layout variant: raise cleanly, or give the answer of a clean copy
        r = outcome(call)
        if r[0] == "raised":
            if not isinstance(r[1], CLEAN):
                raise Fail(f"wrong exception {describe(r[1])}")
        else:
            pos = next(iter(replace))
            clean = np.ascontiguousarray(args[pos], dtype=np.float64)
            recv2, args2, kw2, call2 = _call_with(cls, name, sig, {pos: clean})
            r2 = outcome(call2)
            got = snap((r[1], recv, np.array(args[pos], dtype=np.float64)), ids=False)
            want = snap((r2[1], recv2, clean), ids=False)
            if got != want:
                raise Fail(f"accepted a {type(args[pos]).__name__} with flags "
                           f"{args[pos].flags.c_contiguous, args[pos].flags.aligned} "
                           f"and computed a different answer: {short(got)} != {short(want)}")
            return
    after = snap((recv, args, kw, items))
    for what, b, a in zip(("the receiver", "an argument", "a keyword", "a list's items"),
                          before[1], after[1]):
        if b != a:
            raise Fail(f"the failed call changed {what}: {short(b[1], 300)} -> "
                       f"{short(a[1], 300)}")


def check_iterables(cls, name, sig, pos, wrap):
    """A tuple or generator in place of a list gives the same answer."""
    recv, args, kw, call = _call_with(cls, name, sig)
    want = snap((outcome(call)[1], recv, args), ids=False)
    recv2, args2, kw2, call2 = _call_with(cls, name, sig)
    original = args2[pos]
    args2[pos] = wrap(original)
    r = outcome(call2)
    if r[0] == "raised":
        raise Fail(f"rejected a {type(args2[pos]).__name__}: {describe(r[1])}")
    args2[pos] = original
    got = snap((r[1], recv2, args2), ids=False)
    if got != want:
        raise Fail(f"{short(got)} != {short(want)}")


def check_prop(cls, name, prop, how, value=None, extra=()):
    obj = receiver(cls)
    before = snap(obj)
    if how == "get":
        v = getattr(obj, name)
        if snap(obj) != before or v is None:
            raise Fail(f"reading {name} gave {short(v)} / changed the object")
        return
    if how == "del":
        try:
            delattr(obj, name)
        except (TypeError, AttributeError):
            pass
        except Exception as e:
            raise Fail(f"del raised {describe(e)}") from None
        else:
            raise Fail("del succeeded")
    elif how == "set-readonly":
        try:
            setattr(obj, name, 1.0)
        except (TypeError, AttributeError):
            pass
        except Exception as e:
            raise Fail(f"setting a read-only property raised {describe(e)}") from None
        else:
            raise Fail("a read-only property was set")
    else:
        expect_clean(lambda: setattr(obj, name, value()), extra)
    if snap(obj) != before:
        raise Fail(f"{short(before)} -> {short(snap(obj))}")


def group_args():
    cases = {}
    for cls, name, spec in member_specs():
        if isinstance(spec, Const):
            cases[f"{label(cls, name)} constant"] = functools.partial(
                _check_const, cls, name, spec)
            continue
        if isinstance(spec, Prop):
            cases[f"{label(cls, name)} get"] = functools.partial(check_prop, cls, name, spec, "get")
            cases[f"{label(cls, name)} del"] = functools.partial(check_prop, cls, name, spec, "del")
            if spec.kind is None:
                cases[f"{label(cls, name)} set"] = functools.partial(
                    check_prop, cls, name, spec, "set-readonly")
            else:
                for hname, make, extra, _, _ in hostiles(spec.kind):
                    if hname != "foreign":
                        cases[f"{label(cls, name)} set={hname}"] = functools.partial(
                            check_prop, cls, name, spec, "set", make, extra)
            continue
        longest = max(len(s.kinds) for s in spec)
        for si, sig in enumerate(spec):
            base = label(cls, name, si if len(spec) > 1 else None)
            cases[f"{base} valid"] = functools.partial(check_valid, cls, name, sig)
            for pos, kind in enumerate(sig.kinds):
                for hname, make, extra, needle, must in hostiles(kind):
                    cases[f"{base} arg{pos}={hname}"] = _lazy_hostile(
                        cls, name, sig, pos, make, extra, needle, must)
                if isinstance(kind, Seq) and not isinstance(kind, OutSeq):
                    for w, wrap in (("tuple", tuple), ("generator", lambda s: (x for x in s))):
                        cases[f"{base} arg{pos}={w} accepted"] = functools.partial(
                            check_iterables, cls, name, sig, pos, wrap)
            if name in reg.OPERATORS:
                continue
            if len(sig.kinds) == longest or any(isinstance(k, Arr) for k in sig.kinds):
                cases[f"{base} extra-argument"] = functools.partial(
                    check_hostile, cls, name, sig, {}, extra_pos=(99,))
            cases[f"{base} unknown-keyword"] = functools.partial(
                check_hostile, cls, name, sig, {}, extra_kw={"bogus": 1.0})
    # Kinematics must not be built on non-finite geometry.
    for cls, sig, pos in ((drivekin.SwerveDriveKinematics, 1, 2),
                          (drivekin.MecanumDriveKinematics, 0, 1)):
        for v in ("nan", "inf"):
            t = drivekin.Translation2d(float(v), 0.0)
            cases[f"{cls.__name__}.__init__ module={v}"] = functools.partial(
                check_hostile, cls, "__init__", reg.API[cls]["__init__"][sig]
                if isinstance(reg.API[cls]["__init__"], list) else reg.API[cls]["__init__"],
                {pos: t})
    for v in ("nan", "inf", "-1.0", "0.0"):
        cases[f"DifferentialDriveKinematics.__init__ trackwidth={v}"] = functools.partial(
            check_hostile, drivekin.DifferentialDriveKinematics, "__init__",
            reg.API[drivekin.DifferentialDriveKinematics]["__init__"], {0: float(v)})
    dsk = drivekin.DifferentialSwerveModuleKinematics
    for pos, what in enumerate(("azimuth_gear_ratio", "wheel_gear_ratio", "wheel_radius")):
        for v in ("nan", "inf", "-1.0", "0.0"):
            cases[f"{dsk.__name__}.__init__ {what}={v}"] = functools.partial(
                check_hostile, dsk, "__init__", reg.API[dsk]["__init__"][0], {pos: float(v)},
                needle=what)
    for v in ("nan", "-1.0"):
        cases[f"{dsk.__name__}.desaturate* max_motor_velocity={v}"] = functools.partial(
            check_hostile, dsk, "desaturateModuleVelocitiesInPlace",
            reg.API[dsk]["desaturateModuleVelocitiesInPlace"][0], {2: float(v)},
            needle="max_motor_velocity")
    return cases


def _lazy_hostile(cls, name, sig, pos, make, extra, needle, must):
    return lambda: check_hostile(cls, name, sig, {pos: make()}, extra, needle, must)


def _check_const(cls, name, spec):
    v = getattr(cls, name)
    if type(v) is not cls or snap(v) != snap(spec.value):
        raise Fail(f"{short(v)} != {short(spec.value)}")


# ---- group: gc (finalizers mutating lists / re-entering mid-call) -------------------

MUTATIONS = {
    "clear": lambda s: s.clear(),
    "all-None": lambda s: s.__setitem__(slice(None), [None] * len(s)),
    "append-None": lambda s: s.append(None),
}


def _outs(args, items):
    """The objects a call may write: out arguments and the items of listed arguments
    (as they were before the call, so a cleared list still shows its old items)."""
    return [a for a in args if not isinstance(a, list)] + [i for i in items if i]


def check_gc_mutation(cls, name, sig, pos, mode, fuse):
    recv0, args0, kw0, call0 = _call_with(cls, name, sig)
    ref = outcome(call0)
    want = snap((ref[1], recv0, _outs(args0, [list(a) if isinstance(a, list) else None
                                              for a in args0])), ids=False)
    recv, args, kw, call = _call_with(cls, name, sig)
    items = [list(a) if isinstance(a, list) else None for a in args]
    before = snap((recv, _outs(args, items)), ids=False)
    target = args[pos]
    with armed_gc(lambda: MUTATIONS[mode](target), fuse) as bomb:
        r = outcome(call)
    if r[0] == "raised":
        if not isinstance(r[1], CLEAN):
            raise Fail(f"wrong exception {describe(r[1])}")
        if snap((recv, _outs(args, items)), ids=False) != before:
            raise Fail("the failed call changed something")
        if not bomb.fired:
            raise Fail(f"raised {describe(r[1])} without any mutation")
        return
    got = snap((r[1], recv, _outs(args, items)), ids=False)
    if got != want and bomb.fired:
        # A finalizer that runs before the call has read anything is no different from a
        # caller who mutated the list first: that answer is fine too.
        recv1, args1, kw1, call1 = _call_with(cls, name, sig)
        items1 = [list(a) if isinstance(a, list) else None for a in args1]
        MUTATIONS[mode](args1[pos])
        r1 = outcome(call1)
        if r1[0] == "ok" and got == snap((r1[1], recv1, _outs(args1, items1)), ids=False):
            return
    if got != want:
        raise Fail(f"result differs from the untouched list's (finalizer "
                   f"{'ran' if bomb.fired else 'did not run'}): {short(got, 300)} != "
                   f"{short(want, 300)}")


def _reentrant_refs(cls, name, sig, nested_first):
    recv, args, kw, call = _call_with(cls, name, sig)
    if nested_first:
        _call_with_recv(recv, cls, name, sig)
    r = outcome(call)
    return r, recv, args


def _call_with_recv(recv, cls, name, sig):
    args, kw = sig.build(alt=True)
    return outcome(lambda: bound(cls, recv, name)(*args, **kw))


def check_reentrant(cls, name, sig, make_call):
    """``make_call(recv, nested)`` builds the call under test, arranging for ``nested()``
    (the same method, other valid args, same receiver) to run during it. The result
    must be the plain one or the one with the nested call first."""
    refs = []
    for nested_first in (False, True):
        r, recv, args = _reentrant_refs(cls, name, sig, nested_first)
        refs.append(snap((r, args), ids=False))
    recv = receiver(cls)
    fired = []

    def nested():
        fired.append(1)
        _call_with_recv(recv, cls, name, sig)

    r, args = make_call(recv, nested)
    if r[0] == "raised" and not isinstance(r[1], CLEAN + (Boom,)):
        raise Fail(f"wrong exception {describe(r[1])}")
    if r[0] == "raised":
        return
    got = snap((r, args), ids=False)
    if got not in (refs if fired else refs[:1]):
        raise Fail(f"re-entrant call corrupted the result: {short(got, 300)} not in "
                   f"{short(refs, 300)}")


def _gc_reentry(cls, name, sig, fuse):
    def make_call(recv, nested):
        args, kw = sig.build()
        fn = bound(cls, recv, name)
        with armed_gc(nested, fuse):
            r = outcome(lambda: fn(*args, **kw))
        return r, args
    return functools.partial(check_reentrant, cls, name, sig, make_call)


def group_gc():
    cases = {}
    for cls, name, spec in member_specs():
        if isinstance(spec, (Prop, Const)) or name in reg.OPERATORS or cls in reg.NAMESPACES:
            continue
        for si, sig in enumerate(spec):
            base = label(cls, name, si if len(spec) > 1 else None)
            for pos, kind in enumerate(sig.kinds):
                if isinstance(kind, (Seq, Floats)):
                    for mode in MUTATIONS:
                        for fuse in (1, 2, 4):
                            cases[f"{base} arg{pos} finalizer-{mode} fuse={fuse}"] = \
                                functools.partial(check_gc_mutation, cls, name, sig, pos,
                                                  mode, fuse)
            if not is_module(cls) and name != "__init__":
                for fuse in (1, 2, 4):
                    cases[f"{base} finalizer-reenters fuse={fuse}"] = _gc_reentry(
                        cls, name, sig, fuse)
    return cases


# ---- group: reentry (__float__, __index__, __iter__, __len__, __getitem__) ----------

class ReentrantNumber:
    def __init__(self, value, nested):
        self.value, self.nested = value, nested

    def __float__(self):
        self.nested()
        return float(self.value)

    def __index__(self):
        self.nested()
        return int(self.value)


class ReentrantSeq:
    """A non-list sequence whose protocol methods run ``nested`` (``where`` says which)."""

    def __init__(self, items, nested, where):
        self.items, self.nested, self.where = items, nested, where

    def _hook(self, w):
        if w == self.where:
            self.nested()

    def __len__(self):
        self._hook("len")
        return len(self.items)

    def __iter__(self):
        self._hook("iter")
        for x in self.items:
            yield x
            self._hook("next")

    def __getitem__(self, i):
        self._hook("getitem")
        return self.items[i]


def _reentry(cls, name, sig, pos, where):
    def make_call(recv, nested):
        args, kw = sig.build()
        wrapped = list(args)
        if isinstance(sig.kinds[pos], (Num, Int)):
            wrapped[pos] = ReentrantNumber(args[pos], nested)
        else:
            wrapped[pos] = ReentrantSeq(args[pos], nested, where)
        fn = bound(cls, recv, name)
        return outcome(lambda: fn(*wrapped, **kw)), args
    return functools.partial(check_reentrant, cls, name, sig, make_call)


def group_reentry():
    cases = {}
    for cls, name, spec in member_specs():
        if isinstance(spec, (Prop, Const)) or name in reg.OPERATORS or name == "__init__":
            continue
        if is_module(cls) or cls in reg.NAMESPACES:
            continue
        for si, sig in enumerate(spec):
            base = label(cls, name, si if len(spec) > 1 else None)
            for pos, kind in enumerate(sig.kinds):
                if isinstance(kind, (Num, Int)):
                    cases[f"{base} arg{pos} reentrant-__float__"] = _reentry(
                        cls, name, sig, pos, None)
                elif isinstance(kind, Seq):
                    for where in ("iter", "next", "len", "getitem"):
                        cases[f"{base} arg{pos} reentrant-{where}"] = _reentry(
                            cls, name, sig, pos, where)
    return cases


# ---- group: threads ----------------------------------------------------------------

class PySeq:
    """A Python sequence that hands the GIL to the other thread at every access, so a
    call that runs its protocol mid-computation is interleaved with the other call."""

    def __init__(self, items):
        self.items = items

    def __len__(self):
        time.sleep(0)
        return len(self.items)

    def __getitem__(self, i):
        time.sleep(0)
        return self.items[i]

    def __iter__(self):
        for x in self.items:
            time.sleep(0)
            yield x


def check_threads(cls, name, sig, rounds=100, wrap=True):
    def one(alt):
        args, kw = sig.build(alt)
        wrapped = [PySeq(a) if wrap and isinstance(k, Seq) else a
                   for a, k in zip(args, sig.kinds)]
        return args, kw, wrapped

    def single(alt):
        recv = receiver(cls)
        args, kw, wrapped = one(alt)
        return snap((outcome(lambda: bound(cls, recv, name)(*wrapped, **kw)), args),
                     ids=False)

    want = [single(False), single(True)]
    if "raised" in repr(want):
        if not wrap:
            raise Fail(f"the registry's valid call raised: {short(want)}")
        return check_threads(cls, name, sig, rounds, wrap=False)  # sequences: lists only
    shared = receiver(cls)
    bad = []

    def worker(alt):
        for _ in range(rounds):
            args, kw, wrapped = one(alt)
            got = snap((outcome(lambda: bound(cls, shared, name)(*wrapped, **kw)), args),
                       ids=False)
            if got != want[alt]:
                bad.append(got)

    saved = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)
    try:
        ts = [threading.Thread(target=worker, args=(alt,)) for alt in (False, True)]
        for t in ts:
            t.start()
        for t in ts:
            t.join()
    finally:
        sys.setswitchinterval(saved)
    if bad:
        raise Fail(f"{len(bad)}/{2 * rounds} results differ from the single-thread "
                   f"answer, e.g. {short(bad[0], 300)}")


def group_threads():
    cases = {}
    for cls in sorted(reg.KINEMATICS, key=lambda c: c.__name__):
        for _, name, spec in member_specs([cls]):
            if isinstance(spec, (Prop, Const)) or name in ("__init__", "resetHeadings"):
                continue
            for si, sig in enumerate(spec):
                cases[f"{label(cls, name, si if len(spec) > 1 else None)} two-threads"] = \
                    functools.partial(check_threads, cls, name, sig)
    return cases


# ---- group: lifecycle --------------------------------------------------------------

def _init_sigs(cls):
    s = reg.API[cls]["__init__"]
    return [x for x in (s if isinstance(s, list) else [s]) if not x.kw]


def check_reinit(cls, obj_factory):
    obj = obj_factory()
    before = snap(obj)
    args, _ = _init_sigs(cls)[-1].build(alt=cls in reg.ALT)
    if cls in reg.INIT_ONCE:
        try:
            obj.__init__(*args)
        except (TypeError, RuntimeError):
            pass
        except Exception as e:
            raise Fail(f"re-init raised {describe(e)}") from None
        else:
            raise Fail("__init__ ran again on an initialised object")
        if snap(obj) != before:
            raise Fail(f"a refused re-init changed the object: {short(before)} -> "
                       f"{short(snap(obj))}")
    else:
        obj.__init__(*args)
        if snap(obj, ids=False) != snap(cls(*args), ids=False):
            raise Fail("re-init did not set every field")


def _methods(cls):
    for name, spec in reg.members(cls):
        if isinstance(spec, (Prop, Const)) or name in ("__init__", "__eq__"):
            continue
        if isinstance(cls.__dict__.get(name), staticmethod):
            continue        # needs no instance, so an uninitialised one is irrelevant
        for sig in spec:
            yield name, sig


def _refuses_everything(cls, obj, how):
    for name, sig in _methods(cls):
        args, kw = sig.build()
        r = outcome(lambda: bound(cls, obj, name)(*args, **kw))
        if r[0] == "ok" and name != "__reduce__":
            raise Fail(f"{how} object computed {name} -> {short(r[1])}")
        if r[0] == "raised" and not isinstance(r[1], (TypeError, RuntimeError, ValueError)):
            raise Fail(f"{how} object: {name} raised {describe(r[1])}")
    for f in (repr, str, copy.copy, pickle.dumps):
        outcome(lambda: f(obj))  # must not crash


def check_new(cls):
    obj = cls.__new__(cls)
    if cls in reg.IMMUTABLE:
        if snap(obj, ids=False) != snap(cls(), ids=False):
            raise Fail(f"__new__ gave {short(snap(obj))}, not the default value")
    elif cls in reg.INIT_ONCE:
        _refuses_everything(cls, obj, "never-initialised")
    else:
        for name, sig in _methods(cls):
            args, kw = sig.build()
            r = outcome(lambda: bound(cls, obj, name)(*args, **kw))
            if r[0] == "raised" and not isinstance(r[1], (TypeError, RuntimeError, ValueError)):
                raise Fail(f"{name} on a __new__ object raised {describe(r[1])}")


def check_new_then_init(cls):
    for sig in _init_sigs(cls):
        obj = cls.__new__(cls)
        args, _ = sig.build()
        obj.__init__(*args)
        ref_args, _ = sig.build()
        if snap(obj, ids=False) != snap(cls(*ref_args), ids=False):
            raise Fail("__new__ + __init__ differs from the constructor")


def check_failed_init(cls, sig, pos, make):
    obj = cls.__new__(cls)
    args, _ = sig.build()
    args[pos] = make()
    expect_clean(lambda: obj.__init__(*args), (Boom,))
    _refuses_everything(cls, obj, "failed-init")


def _replay(cls, obj):
    """Every method's valid call on ``obj``, in registry order (results as a snapshot)."""
    out = []
    for name, sig in _methods(cls):
        args, kw = sig.build()
        out.append((name, snap((outcome(lambda: bound(cls, obj, name)(*args, **kw)), args),
                               ids=False)))
    return out


def _with_history(cls):
    obj = reg.VALID[cls]()
    if cls is drivekin.SwerveDriveKinematics:  # sticky centre of rotation + memory
        obj.toSwerveModuleVelocities(drivekin.ChassisVelocities(1.0, -2.0, 3.0),
                                     drivekin.Translation2d(0.1, 0.2))
    if cls is drivekin.MecanumDriveKinematics:
        obj.toWheelVelocities(drivekin.ChassisVelocities(1.0, -2.0, 3.0),
                              drivekin.Translation2d(0.1, 0.2))
    return obj


COPIERS = {"copy": copy.copy, "deepcopy": copy.deepcopy,
           "pickle": lambda o: pickle.loads(pickle.dumps(o, protocol=pickle.HIGHEST_PROTOCOL)),
           "pickle-0": lambda o: pickle.loads(pickle.dumps(o, protocol=0))}


def check_copy(cls, how):
    orig, twin = _with_history(cls), _with_history(cls)
    try:
        dup = COPIERS[how](twin)
    except TypeError:
        if cls in reg.STATEFUL:
            return  # odometry and estimators may declare themselves uncopyable
        raise
    if type(dup) is not cls:
        raise Fail(f"{how} gave a {type(dup).__name__}")
    if snap(dup, ids=False) != snap(orig, ids=False):
        raise Fail(f"{how} differs: {short(snap(dup))} != {short(snap(orig))}")
    if _replay(cls, dup) != _replay(cls, orig):
        raise Fail(f"the {how} behaves differently from the original")


class Payload:
    """Pickles as an arbitrary (callable, args[, state]) reduce tuple."""

    def __init__(self, reduce_value):
        self.reduce_value = reduce_value

    def __reduce__(self):
        return self.reduce_value


def _leaves_replaced(x, value):
    if isinstance(x, float):
        return value
    if isinstance(x, drivekin.Translation2d):
        return drivekin.Translation2d(value, value)
    if isinstance(x, drivekin.Pose2d):
        return drivekin.Pose2d(value, value, x.getRotation())
    if isinstance(x, drivekin.Translation3d):
        return drivekin.Translation3d(value, value, value)
    if isinstance(x, (tuple, list)):
        return type(x)(_leaves_replaced(i, value) for i in x)
    return x


def _invariants(cls, obj):
    if cls is drivekin.Rotation2d:
        c, s = obj.getCos(), obj.getSin()
        if c == c and s == s and not abs(c * c + s * s - 1.0) <= 1e-9:  # NaN propagates
            raise Fail(f"unpickled a non-unit rotation (cos={c!r}, sin={s!r})")
    if cls is drivekin.Rotation3d:
        q = obj.getQuaternion()
        n = q.norm()
        if n == n and not abs(n - 1.0) <= 1e-9:  # NaN propagates
            raise Fail(f"unpickled a non-unit Rotation3d ({q!r})")
    if cls is drivekin.DifferentialDriveKinematics and not 0 < obj.trackwidth < float("inf"):
        raise Fail(f"unpickled a trackwidth of {obj.trackwidth!r}")
    if cls is drivekin.DifferentialSwerveModuleKinematics and not finite(obj):
        raise Fail(f"unpickled non-finite differential swerve kinematics: {short(snap(obj))}")
    if cls in (drivekin.SwerveDriveKinematics, drivekin.MecanumDriveKinematics):
        if not finite(obj):
            raise Fail(f"unpickled non-finite kinematics: {short(snap(obj))}")


def check_crafted(cls, tamper):
    reduced = reg.VALID[cls]().__reduce_ex__(pickle.HIGHEST_PROTOCOL)
    fn, args, *state = reduced
    if tamper == "args=None-each":
        variants = [tuple(None if j == i else a for j, a in enumerate(args))
                    for i in range(len(args))]
    elif tamper == "args-missing":
        variants = [args[:-1]] if args else []
    elif tamper == "args-extra":
        variants = [tuple(args) + (1.0,)]
    else:
        variants = [_leaves_replaced(args, float(tamper))]
    for v in variants:
        payload = pickle.dumps(Payload((fn, v, *state)))
        try:
            obj = pickle.loads(payload)
        except CLEAN:
            continue
        except Exception as e:
            raise Fail(f"unpickling raised {describe(e)}") from None
        if type(obj) is not cls:
            continue  # a pickle may name another callable; not drivekin's to check
        if cls in reg.KINEMATICS and tamper in ("nan", "inf"):
            raise Fail(f"built a kinematics object from {tamper} geometry: {short(obj)}")
        _invariants(cls, obj)
    if state and state[0] is not None:
        for bad in (None, "abc", (), _leaves_replaced(state[0], float("nan"))):
            obj = fn(*args)
            r = outcome(lambda: obj.__setstate__(bad))
            if r[0] == "raised":
                if not isinstance(r[1], CLEAN):
                    raise Fail(f"__setstate__({short(bad)}) raised {describe(r[1])}")
            else:
                _invariants(cls, obj)


def check_rotation_from_cos_sin():
    fn = getattr(drivekin.geometry, "_rotation_from_cos_sin", None)
    if fn is None:
        return
    for c, s in ((2.0, 0.0), (0.0, 0.0), (float("nan"), 0.0), (float("inf"), 1.0)):
        r = outcome(lambda: fn(c, s))
        if r[0] == "raised":
            if not isinstance(r[1], CLEAN):
                raise Fail(f"raised {describe(r[1])}")
        else:
            _invariants(drivekin.Rotation2d, r[1])


def group_lifecycle():
    cases = {}
    for cls in reg.public_classes():
        if cls in reg.NAMESPACES:
            continue  # no instances (Units: refused, see tests/behaviour/test_units.py)
        n = cls.__name__
        cases[f"{n} re-init"] = functools.partial(check_reinit, cls, reg.VALID[cls])
        for cname, spec in reg.members(cls):
            if isinstance(spec, Const):
                cases[f"{n}.{cname} re-init"] = functools.partial(
                    check_reinit, cls, functools.partial(getattr, cls, cname))
        if cls in reg.IMMUTABLE:
            cases[f"{n} result-of-operation re-init"] = functools.partial(
                check_reinit, cls, lambda cls=cls: copy.copy(reg.VALID[cls]()))
        cases[f"{n} __new__ then methods"] = functools.partial(check_new, cls)
        if cls not in reg.IMMUTABLE:  # whether a __new__'d immutable may be init'ed is open
            cases[f"{n} __new__ then __init__"] = functools.partial(check_new_then_init, cls)
        if cls in reg.INIT_ONCE - reg.IMMUTABLE:
            for si, sig in enumerate(_init_sigs(cls)):
                for pos, kind in enumerate(sig.kinds):
                    for hname, make, *_ in hostiles(kind)[:2] + [
                            h for h in hostiles(kind) if h[0] in ("None-last", "raising-float")]:
                        cases[f"{n}#{si} failed __init__ arg{pos}={hname} then methods"] = \
                            functools.partial(check_failed_init, cls, sig, pos, make)
        for how in COPIERS:
            cases[f"{n} {how}"] = functools.partial(check_copy, cls, how)
        if cls not in reg.STATEFUL:
            for tamper in ("nan", "inf", "2.0", "args=None-each", "args-missing",
                           "args-extra"):
                cases[f"{n} crafted pickle {tamper}"] = functools.partial(
                    check_crafted, cls, tamper)
    cases["geometry._rotation_from_cos_sin non-unit"] = check_rotation_from_cos_sin
    return cases


# ---- group: misc (huge counts, str/repr) --------------------------------------------

EXTREMES = (1.5, 1e300, -1e300, -0.0, float("nan"), float("inf"), float("-inf"), 5e-324, 1e26)


def _extreme_instance(cls, x):
    sig = _init_sigs(cls)[0]
    args = []
    for k in sig.kinds:
        if isinstance(k, Num):
            args.append(x)
        elif isinstance(k, Obj) and k.cls is drivekin.Rotation2d:
            args.append(drivekin.Rotation2d(x))
        elif isinstance(k, Obj) and k.cls is drivekin.Translation2d:
            args.append(drivekin.Translation2d(x, -x))
        elif isinstance(k, Seq) and k.cls is drivekin.Translation2d:
            args.append([drivekin.Translation2d(a * x, b * x)
                         for a, b in ((1, 1), (1, -1), (-1, 1), (-1, -1))])
        else:
            args.append(k.valid())
    return cls(*args)


def check_str(cls, x):
    try:
        obj = _extreme_instance(cls, x)
    except CLEAN:
        return  # e.g. a NaN trackwidth: nothing to print
    plain = (str(obj), repr(obj))
    ctx = decimal.Context(prec=2, Emax=5, Emin=-5, traps=[
        decimal.InvalidOperation, decimal.Inexact, decimal.Rounded, decimal.Overflow,
        decimal.Underflow, decimal.Subnormal, decimal.Clamped, decimal.DivisionByZero,
        decimal.FloatOperation])
    with decimal.localcontext(ctx):
        try:
            hostile = (str(obj), repr(obj))
        except Exception as e:
            raise Fail(f"str/repr raised {describe(e)} under a trapping decimal context") \
                from None
    if hostile != plain:
        raise Fail(f"str depends on the decimal context: {hostile} != {plain}")


HUGE = 10 ** 18


def check_wpistruct_count(fn, n):
    k = drivekin.SwerveDriveKinematics
    calls = {"getSize": lambda: wpistruct.getSize(k, numModules=n),
             "getTypeName": lambda: wpistruct.getTypeName(k, numModules=n),
             "getSchema": lambda: wpistruct.getSchema(k, numModules=n),
             "unpack": lambda: wpistruct.unpack(k, b"\0" * 64, numModules=n),
             "unpackArray": lambda: wpistruct.unpackArray(k, b"\0" * 64, numModules=n)}
    expect_clean(calls[fn], (Boom,))


def check_spec_cache_bounded():
    import tracemalloc
    k = drivekin.SwerveDriveKinematics
    for n in range(2, 200):
        wpistruct.getTypeName(k, numModules=n)
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        for n in range(1000, 21000):
            wpistruct.getTypeName(k, numModules=n)
        grown = tracemalloc.get_traced_memory()[0] - start
    finally:
        tracemalloc.stop()
    if grown > 4 << 20:
        raise Fail(f"20000 distinct module counts kept {grown / 2**20:.1f} MiB")


def check_many_modules(n=3000):
    mods = [drivekin.Translation2d(np.cos(i), np.sin(i)) for i in range(n)]
    k = drivekin.SwerveDriveKinematics(mods)
    states = k.toSwerveModuleVelocities(drivekin.ChassisVelocities(1.0, 2.0, 0.5))
    back = k.toChassisVelocities(list(states))
    if not (abs(back.vx - 1.0) < 1e-6 and abs(back.vy - 2.0) < 1e-6
            and abs(back.omega - 0.5) < 1e-6):
        raise Fail(f"round trip with {n} modules gave {back!r}")
    desat = k.desaturateWheelVelocities(list(states), 0.1)
    if max(s.velocity for s in desat) > 0.1 + 1e-12:
        raise Fail("desaturation with many modules failed")
    if pickle.loads(pickle.dumps(k)).getNumModules() != n:
        raise Fail("pickle lost modules")


# ---- the porting issue's hostile inputs (issue 15, items 1 and 6-10) ---------------

def _traced_growth(run):
    import tracemalloc
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        run()
        return tracemalloc.get_traced_memory()[0] - start
    finally:
        tracemalloc.stop()


def _finite_pose(p, what):
    if not all(np.isfinite((p.x, p.y, p.getRotation().getRadians()))):
        raise Fail(f"{what}: {p!r}")


def check_estimator_std_devs(state):
    R, P = drivekin.Rotation2d, drivekin.Pose2d
    e = drivekin.DifferentialDrivePoseEstimator(R(), 0.0, 0.0, P(), state, (0.5,) * 3)
    e.updateWithTime(0.0, R(), 0.0, 0.0)
    e.updateWithTime(0.02, R(), 0.02, 0.02)
    e.addVisionMeasurement(P(1.0, 0.0, R()), 0.01)
    _finite_pose(e.getEstimatedPosition(), f"state std devs {state}")
    _finite_pose(e.sampleAt(0.015), f"state std devs {state}, sampleAt")
    expect_clean(lambda: e.setVisionMeasurementStdDevs((float("nan"), 1.0, 1.0)),
                 needle="finite")


def check_buffer_huge_timestamps():
    b = drivekin.TimeInterpolatableBuffer.createDoubleBuffer(1.5)
    b.addSample(1e308, 1.0)
    b.addSample(-1e308, 0.0)
    for t in (9e307, -9e307, 0.0, 1e308, -1e308):
        v = b.getSample(t)
        if v is not None and not (np.isfinite(v) and 0.0 <= v <= 1.0):
            raise Fail(f"getSample({t!r}) = {v!r}")


def check_estimator_backwards_clock():
    R, P = drivekin.Rotation2d, drivekin.Pose2d
    e = drivekin.DifferentialDrivePoseEstimator(R(), 0.0, 0.0, P())
    for i in range(200):
        e.updateWithTime(-0.02 * i, R(), 0.001 * i, 0.001 * i)

    def run():
        for i in range(200, 20200):
            e.updateWithTime(-0.02 * i, R(), 0.001 * i, 0.001 * i)
    grown = _traced_growth(run)
    if grown > 64 << 10:
        raise Fail(f"20,000 backwards updates kept {grown} bytes")


def check_estimator_vision_clock():
    import warnings
    R, P = drivekin.Rotation2d, drivekin.Pose2d
    e = drivekin.DifferentialDrivePoseEstimator(R(), 0.0, 0.0, P())
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for i in range(200):
            e.updateWithTime(0.02 * i, R(), 0.02 * i, 0.02 * i)
            e.addVisionMeasurement(P(), 1.7e9 + 0.02 * i)

        def run():
            for i in range(200, 20200):
                e.updateWithTime(0.02 * i, R(), 0.02 * i, 0.02 * i)
                e.addVisionMeasurement(P(), 1.7e9 + 0.02 * i)
        grown = _traced_growth(run)
    if grown > 64 << 10:
        raise Fail(f"20,000 vision measurements from another clock kept {grown} bytes")
    kinds = [w.category for w in caught]
    if kinds != [drivekin.ClockMismatchWarning]:
        raise Fail(f"expected one ClockMismatchWarning, got {kinds}")


def check_desaturate_aliased_chassis():
    from drivekin import batch
    buf = np.array([1., 2, 4, 3, 5, 3, 2, 2, 5, 4, 6, 2, 3, 4, 5, 1])
    mv, cv = buf.reshape(2, 4, 2), buf[:6].reshape(2, 3)
    before = buf.copy()
    expect_clean(lambda: batch.desaturateWheelVelocities(mv, cv, 4.0, 3.0, 5.0, out=mv),
                 needle="overlap")
    if not np.array_equal(buf, before, equal_nan=True):
        raise Fail("a refused call changed its input")


def porting_cases():
    cases = {f"estimator state std devs {s}": functools.partial(check_estimator_std_devs, s)
             for s in [(1e200,) * 3, (float("inf"),) * 3, (-1e300, 1e-300, 0.0)]}
    cases["TimeInterpolatableBuffer at ±1e308"] = check_buffer_huge_timestamps
    cases["estimator clock running backwards"] = check_estimator_backwards_clock
    cases["estimator vision from another clock"] = check_estimator_vision_clock
    cases["batch.desaturateWheelVelocities aliased chassis"] = check_desaturate_aliased_chassis
    return cases


# ---- hostile .wpilog files (issue 17, item 5) ------------------------------------------

def check_wpilog(case):
    from tests._support import wpilog_bytes as W
    make, needle = W.HOSTILE[case]
    data = make()
    errors = W.exercise(data)
    if needle is None and errors:
        raise Fail(f"refused a readable file: {errors[0]}")
    if needle is not None and not any(needle in e for e in errors):
        raise Fail(f"no DataLogError naming {needle!r}: {errors[:2]}")


def check_wpilog_truncations():
    from tests._support import wpilog_bytes as W
    data = W.small_log()
    for cut in range(len(data)):
        W.exercise(data[:cut])
        W.exercise(data[:cut], allowTruncated=True)


def datalog_cases():
    from tests._support import wpilog_bytes as W
    cases = {f"datalog.read {case}": functools.partial(check_wpilog, case)
             for case in W.HOSTILE}
    cases["datalog.read truncated at every byte"] = check_wpilog_truncations
    return cases


def group_misc():
    cases = {}
    for cls in reg.public_classes():
        if cls in reg.STATEFUL | reg.NAMESPACES:
            continue
        for x in EXTREMES:
            cases[f"{cls.__name__} str/repr x={x!r}"] = functools.partial(check_str, cls, x)
    for fn in ("getSize", "getTypeName", "getSchema", "unpack", "unpackArray"):
        for n in (HUGE, -1, 0, 1, 2.5, "4", BadNumber()):
            cases[f"wpistruct.{fn} numModules={short(n, 20)}"] = functools.partial(
                check_wpistruct_count, fn, n)
    cases["wpistruct spec cache is bounded"] = check_spec_cache_bounded
    cases["SwerveDriveKinematics with 3000 modules"] = check_many_modules
    cases.update(porting_cases())
    return cases


GROUPS = {"args": group_args, "gc": group_gc, "reentry": group_reentry,
          "threads": group_threads, "lifecycle": group_lifecycle, "misc": group_misc,
          "datalog": datalog_cases}
