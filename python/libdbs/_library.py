"""Finding and loading libdbs.

In order: the environment variable DBS_LIBRARY (a path to libdbs.so), the library this
package was installed with (`_installed.py`, written by `cmake --install`), then the
system's search (ctypes.util.find_library("dbs")).
"""
import ctypes
import ctypes.util
import os

from . import _capi


def _installed_path():
    try:
        from ._installed import LIBRARY  # written by cmake --install
    except ImportError:
        return None
    return LIBRARY if os.path.exists(LIBRARY) else None


def load():
    path = os.environ.get("DBS_LIBRARY") or _installed_path() or ctypes.util.find_library("dbs")
    if not path:
        raise ImportError("libdbs not found: install libdbs (cmake --install), or set DBS_LIBRARY to the path of libdbs.so")
    return _capi.declare(ctypes.CDLL(path))


lib = load()
