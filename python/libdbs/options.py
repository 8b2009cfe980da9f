"""Options of a run: every DBS_OPT_* as Option, values checked for their type, callbacks
whose exceptions are kept and raised after the run."""
import ctypes
import enum
import numbers

from . import _capi
from ._library import lib
from .errors import CancelledError, InvalidViewError, check

Option = enum.IntEnum("Option", {name[len("OPT_"):]: value for name, value in vars(_capi).items() if name.startswith("OPT_")})
Option.__doc__ = "The options of dbs.h (DBS_OPT_*), by name: Option.MAX_LEVEL, ..."
INTEGER_OPTIONS = frozenset(Option(value) for value in _capi.INTEGER_OPTIONS)

Solver = enum.IntEnum("Solver", {"LINEAR": _capi.SOLVER_LINEAR, "CERES": _capi.SOLVER_CERES})
Loss = enum.IntEnum("Loss", {name[len("LOSS_"):]: value for name, value in vars(_capi).items() if name.startswith("LOSS_")})


def _option(key):
    """An Option from an Option, its number or its name ("max_level")."""
    if isinstance(key, str):
        try:
            return Option[key.upper()]
        except KeyError:
            raise ValueError(f"unknown option '{key}' (options: {', '.join(o.name.lower() for o in Option)})") from None
    return Option(key)


class Options:
    """The options of a run. Options(max_level=3, accuracy=0.1) sets them by name;
    integer options take integers only (2.7 is refused, not rounded)."""

    def __init__(self, **values):
        handle = ctypes.c_void_p()
        check(lib.dbs_options_create(ctypes.byref(handle)))
        self._handle = handle
        self._callbacks = {}  # ctypes callback objects must outlive their use by libdbs
        self.failure = None  # the exception a callback raised during the last run
        for key, value in values.items():
            self.set(key, value)

    @property
    def handle(self):
        return self._handle

    def __del__(self):
        if getattr(self, "_handle", None):
            lib.dbs_options_destroy(self._handle)
            self._handle = None

    def set(self, option, value):
        option = _option(option)
        if option in INTEGER_OPTIONS:
            if not isinstance(value, numbers.Integral):  # 2.7 is refused, not rounded
                raise TypeError(f"option {option.name.lower()} takes an integer, not {value!r}")
            check(lib.dbs_options_set_int(self._handle, option, int(value)))
        else:
            if not isinstance(value, numbers.Real) or isinstance(value, bool):
                raise TypeError(f"option {option.name.lower()} takes a number, not {value!r}")
            check(lib.dbs_options_set_double(self._handle, option, float(value)))
        return self

    def get(self, option):
        option = _option(option)
        if option in INTEGER_OPTIONS:
            out = ctypes.c_int32()
            check(lib.dbs_options_get_int(self._handle, option, ctypes.byref(out)))
        else:
            out = ctypes.c_double()
            check(lib.dbs_options_get_double(self._handle, option, ctypes.byref(out)))
        return out.value

    def __repr__(self):
        values = ", ".join(f"{o.name.lower()}={self.get(o)!r}" for o in Option)
        return f"Options({values})"

    def check_run(self, status):
        """After a call that ran these options' callbacks: Ctrl-C in a callback is raised again;
        a cancellation is raised with the callback's exception as its cause; any other failed
        status is raised. Returns the exception a callback raised without cancelling the call
        (a warning's), for the caller to raise once it owns the call's output."""
        failure, self.failure = self.failure, None
        if isinstance(failure, KeyboardInterrupt):
            raise failure
        try:
            check(status)
        except CancelledError as cancelled:
            if failure is not None:
                raise cancelled from failure
            raise
        return failure

    # ---- callbacks: an exception raised in one (KeyboardInterrupt included) cancels the run
    # and is kept in `failure`; the run's caller raises it (parameterize does).

    def _guarded(self, function, default):
        def call(*args):
            try:
                return function(*args)
            except BaseException as error:  # never unwind through C; Ctrl-C lands here too
                if self.failure is None:
                    self.failure = error
                return default
        return call

    def on_progress(self, function):
        """function(fraction, stage) -> True to cancel; None clears it."""
        if function is None:
            callback = _capi.PROGRESS_FN()
        else:
            guarded = self._guarded(lambda fraction, stage: 1 if function(fraction, stage.decode()) else 0, 1)
            callback = _capi.PROGRESS_FN(lambda fraction, stage, _payload: guarded(fraction, stage))
        check(lib.dbs_options_set_progress(self._handle, callback, None))
        self._callbacks["progress"] = callback
        return self

    def on_level(self, function):
        """function(level, patches) -> True to cancel; `patches` (a Patches view) is valid only
        during the call: using it afterwards raises InvalidViewError. None clears it."""
        from .result import Patches

        def adaptor(level, handle):
            view = Patches(handle, owner=None)
            try:
                return 1 if function(level, view) else 0
            finally:
                view._invalidate()

        if function is None:
            callback = _capi.LEVEL_FN()
        else:
            guarded = self._guarded(adaptor, 1)
            callback = _capi.LEVEL_FN(lambda level, handle, _payload: guarded(level, handle))
        check(lib.dbs_options_set_level_callback(self._handle, callback, None))
        self._callbacks["level"] = callback
        return self

    def on_warning(self, function):
        """function(message): a likely mistake in the inputs; the run goes on. None clears it."""
        if function is None:
            callback = _capi.WARNING_FN()
        else:
            guarded = self._guarded(lambda message: function(message.decode()), None)
            callback = _capi.WARNING_FN(lambda message, _payload: guarded(message))
        check(lib.dbs_options_set_warning(self._handle, callback, None))
        self._callbacks["warning"] = callback
        return self


__all__ = ["Option", "Options", "Solver", "Loss", "InvalidViewError"]
