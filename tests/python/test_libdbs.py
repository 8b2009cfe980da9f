"""The Python package libdbs: NumPy in and out without copies, options by keyword with type
checks, exceptions that are the built-ins a Python user catches, callbacks whose exceptions
and Ctrl-C come back out, views that expire, evaluation of the surface with derivatives.

Run by ctest (tests/CMakeLists.txt) against the build's libdbs (DBS_LIBRARY) or an installed
package; DBS_DATA names the example data."""
import errno
import os
import signal

import numpy as np
import pytest

import libdbs
from libdbs import _arrays
from libdbs.errors import error_of

DATA = os.environ.get("DBS_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def plane(nx=41, ny=21):
    """The 2 x 1 plane z = 0.5 on an nx x ny grid, and its boundary: (u, v) = (x / 2, y)."""
    x, y = np.meshgrid(np.linspace(0.0, 2.0, nx), np.linspace(0.0, 1.0, ny))
    points = np.stack([x.ravel(), y.ravel(), np.full(x.size, 0.5)], axis=1)
    t = np.linspace(0.0, 1.0, 11)
    side = lambda a, b: np.array([a + s * (np.asarray(b) - np.asarray(a)) for s in t])
    c00, c10, c11, c01 = [0, 0, 0.5], [2, 0, 0.5], [2, 1, 0.5], [0, 1, 0.5]
    return points, libdbs.Boundary(side(c00, c10), side(c10, c11), side(c01, c11), side(c00, c01))


def test_points_go_in_without_a_copy_and_wrong_shapes_are_refused():
    points, _ = plane()
    assert np.shares_memory(_arrays.as_points(points), points)
    fortran_order = np.asfortranarray(points)
    assert not np.shares_memory(_arrays.as_points(fortran_order), fortran_order)  # converted once
    assert np.array_equal(_arrays.as_points(fortran_order), points)
    with pytest.raises(ValueError, match=r"shape \(N, 3\), not \(3, 861\): transpose it"):
        libdbs.Cloud(points.T)
    with pytest.raises(ValueError, match="must be an \\(N, 3\\) array"):
        libdbs.Cloud([[0.0, 0.0, 0.0], [1.0, 2.0]])
    assert len(libdbs.Cloud(points.tolist())) == len(points)


def test_parameterize_with_keywords_gives_numpy_arrays():
    points, boundary = plane()
    result = libdbs.parameterize(points, boundary, accuracy=1e-6, max_level=0)
    uv = result.uv
    assert uv.shape == (len(points), 2) and uv.dtype == np.float64
    assert np.abs(uv[:, 0] - points[:, 0] / 2.0).max() < 1e-9
    assert np.abs(uv[:, 1] - points[:, 1]).max() < 1e-9
    assert result.distances.shape == (len(points),) and result.distances.max() < 1e-9
    assert result.patches_of_points.dtype == np.int32 and (result.patches_of_points == 0).all()
    assert (result.levels == 0).all() and (result.flags == 0).all()
    assert result.stat("levels") == 1.0 and result.stat(libdbs.Stat.LEVELS) == 1.0
    assert "mean_distance" in result.stats
    # a plane's surface agrees with its (u,v) everywhere: no point on a turned sheet
    assert result.stats["turned_points"] == 0.0 and result.stat("turned_share") == 0.0
    assert repr(result).startswith("<libdbs.Result of 861 points: 1 leaves on 1 levels")
    assert len(result.patches) == 1 and result.patches[0]["leaf"]


def test_evaluate_is_vectorised_with_normals_and_derivatives():
    points, boundary = plane()
    result = libdbs.parameterize(points, boundary, max_level=0)
    u, v = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 1, 3))
    e = result.evaluate(u, v, normals=True, derivatives=True)
    assert e.points.shape == (3, 5, 3)
    assert np.abs(e.points[..., 0] - 2.0 * u).max() < 1e-9 and np.abs(e.points[..., 1] - v).max() < 1e-9
    assert np.abs(np.abs(e.normals[..., 2]) - 1.0).max() < 1e-9
    assert np.abs(e.su - [2.0, 0.0, 0.0]).max() < 1e-6 and np.abs(e.sv - [0.0, 1.0, 0.0]).max() < 1e-6
    single = result.evaluate(0.25, 0.5)
    assert single.points.shape == (3,) and single.normals is None and single.su is None
    with pytest.raises(ValueError, match="outside \\[0, 1\\]"):
        result.evaluate([0.5, 1.5], [0.5, 0.5])


def test_options_are_checked_for_their_type():
    options = libdbs.Options(max_level=2, accuracy=0.5, crop=True)
    assert options.get("max_level") == 2 and options.get(libdbs.Option.ACCURACY) == 0.5 and options.get("crop") == 1
    with pytest.raises(TypeError, match="max_level takes an integer, not 2.7"):
        options.set("max_level", 2.7)
    with pytest.raises(TypeError, match="accuracy takes a number"):
        options.set("accuracy", "0.1")
    with pytest.raises(ValueError, match="unknown option 'maximum_level'"):
        options.set("maximum_level", 1)
    with pytest.raises(ValueError, match="max_level = 9 is outside its range"):
        options.set("max_level", 9)
    assert "max_level=2" in repr(options)


def test_errors_are_the_builtin_exceptions():
    with pytest.raises(FileNotFoundError) as missing:
        libdbs.Cloud.load(os.path.join(DATA, "no_such.xyz"))
    assert missing.value.errno == errno.ENOENT and isinstance(missing.value, libdbs.DbsError)
    assert missing.value.status == libdbs.capi.ERR_IO and "no_such.xyz" in str(missing.value)
    points, boundary = plane()
    result = libdbs.parameterize(points, boundary, max_level=0)
    # A directory where a file is wanted: an OSError that is no FileNotFoundError.
    with pytest.raises(OSError) as blocked:
        result.save(libdbs.Cloud(points), os.path.join(DATA, "panel.xyz", "out.csv"))
    assert blocked.value.errno == errno.ENOTDIR and not isinstance(blocked.value, FileNotFoundError)
    # Refused access (root may read anything, so the mapping itself is checked too).
    assert isinstance(error_of(libdbs.capi.ERR_IO, "f: cannot open", errno.EACCES), PermissionError)
    assert isinstance(error_of(libdbs.capi.ERR_NO_MEMORY, "f: out of memory"), MemoryError)
    with pytest.raises(ValueError):
        libdbs.Cloud(np.array([[0.0, 0.0, np.nan]]))


def test_an_exception_in_a_callback_is_the_cause_of_the_cancellation():
    points, boundary = plane()

    def progress(fraction, stage):
        raise ZeroDivisionError("from the progress callback")

    with pytest.raises(libdbs.CancelledError) as cancelled:
        libdbs.parameterize(points, boundary, progress=progress)
    assert isinstance(cancelled.value.__cause__, ZeroDivisionError)
    calls = []
    with pytest.raises(libdbs.CancelledError):
        libdbs.parameterize(points, boundary, progress=lambda f, s: calls.append(f) or True)
    assert len(calls) == 1  # cancelled on the first call


def test_ctrl_c_cancels_the_run_and_is_raised():
    points, boundary = plane()
    calls = []

    def progress(fraction, stage):
        calls.append(stage)
        if len(calls) == 1:
            signal.raise_signal(signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        libdbs.parameterize(points, boundary, progress=progress)
    assert len(calls) == 1


def test_a_level_view_expires_with_its_callback():
    rng = np.random.default_rng(3)
    xy = rng.random((3000, 2))
    points = np.column_stack([xy, 0.2 * np.sin(6.0 * xy[:, 0]) * np.sin(6.0 * xy[:, 1])])
    t = np.linspace(0.0, 1.0, 41)
    f = lambda x, y: 0.2 * np.sin(6.0 * x) * np.sin(6.0 * y)
    boundary = libdbs.Boundary(np.column_stack([t, 0 * t, f(t, 0 * t)]), np.column_stack([1 + 0 * t, t, f(1 + 0 * t, t)]),
                               np.column_stack([t, 1 + 0 * t, f(t, 1 + 0 * t)]), np.column_stack([0 * t, t, f(0 * t, t)]))
    kept = []

    def level(number, patches):
        assert len(patches) >= 1 and patches[0]["level"] == number
        kept.append(patches)

    libdbs.parameterize(points, boundary, level=level, max_level=2, relative_accuracy=1e-4)
    assert len(kept) >= 2
    with pytest.raises(libdbs.InvalidViewError, match="no longer valid"):
        len(kept[0])
    assert "invalid" in repr(kept[0])


def test_boundaries_round_trip_and_detect():
    cloud = libdbs.Cloud.load(os.path.join(DATA, "panel.xyz"))
    boundary = libdbs.Boundary.load(os.path.join(DATA, "panel_boundary.txt"))
    assert boundary.side("bottom").shape == (21, 3)
    detected = libdbs.Boundary.detect(cloud)
    assert detected.holes == []
    assert "holes" in repr(detected)


def test_loading_reports_progress_and_can_be_cancelled():
    path = os.path.join(DATA, "panel.xyz")
    stages = []
    cloud = libdbs.Cloud.load(path, progress=lambda fraction, stage: stages.append((fraction, stage)))
    assert len(cloud) == 2000 and stages[-1] == (1.0, "done")
    assert all(a[0] <= b[0] for a, b in zip(stages, stages[1:]))
    with pytest.raises(libdbs.CancelledError):
        libdbs.Cloud.load(path, progress=lambda fraction, stage: True)
