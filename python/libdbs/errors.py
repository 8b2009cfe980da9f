"""The exceptions of libdbs: one class per kind of failure, each a DbsError and a subclass
of the built-in exception a Python user would catch (a missing file is a FileNotFoundError,
an out-of-range value a ValueError, ...). `status` is the DBS_ERR_* code; the message is
libdbs's own, naming the function and what is wrong."""
import errno as _errno

from . import _capi
from ._library import lib


class DbsError(Exception):
    """A failed libdbs call; `status` is its DBS_ERR_* code."""

    status = None


class CancelledError(DbsError):
    """The run was cancelled (by a callback, or by an exception raised in one: see __cause__)."""


class DbsValueError(DbsError, ValueError):
    """An argument libdbs refuses: NULL, empty, out of range, not finite, degenerate, malformed."""


class DbsMemoryError(DbsError, MemoryError):
    """libdbs ran out of memory."""


class DbsOSError(DbsError, OSError):
    """A file could not be read or written; `errno` is the system's reason."""


class DbsFileNotFoundError(DbsOSError, FileNotFoundError):
    """The file does not exist."""


class DbsPermissionError(DbsOSError, PermissionError):
    """The file may not be read or written."""


class UnsupportedError(DbsError, NotImplementedError):
    """This libdbs was built without the feature (e.g. Draco, the validation, Ceres)."""


class NumericalError(DbsError, ArithmeticError):
    """A computation failed numerically."""


class InternalError(DbsError, RuntimeError):
    """A bug in libdbs."""


class InvalidViewError(DbsError, ReferenceError):
    """A view handed to a callback was used after the callback returned."""


_BY_STATUS = {
    _capi.ERR_CANCELLED: CancelledError,
    _capi.ERR_NO_MEMORY: DbsMemoryError,
    _capi.ERR_UNSUPPORTED: UnsupportedError,
    _capi.ERR_NUMERICAL: NumericalError,
    _capi.ERR_INTERNAL: InternalError,
}


def error_of(status, message, system_errno=0):
    """The exception for a failed status with libdbs's message."""
    if status == _capi.ERR_IO:
        cls = {_errno.ENOENT: DbsFileNotFoundError, _errno.EACCES: DbsPermissionError, _errno.EPERM: DbsPermissionError}.get(system_errno, DbsOSError)
        error = cls(system_errno, message) if system_errno else cls(message)
    else:
        error = _BY_STATUS.get(status, DbsValueError)(message)
    error.status = status
    return error


def check(status):
    """Raises the exception of a failed status; returns None for DBS_OK."""
    if status == _capi.OK:
        return
    message = lib.dbs_last_error_message().decode("utf-8", "replace") or lib.dbs_status_string(status).decode()
    raise error_of(status, message, lib.dbs_last_error_errno() if status == _capi.ERR_IO else 0)
