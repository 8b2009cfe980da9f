"""libdbs from Python: load a cloud and its boundary, parameterize, inspect the result.

usage: python3 example.py CLOUD BOUNDARY [RESULT]
(with the package installed, or PYTHONPATH=python and DBS_LIBRARY=build/capi/libdbs.so)
"""
import sys

import numpy as np

import libdbs


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    print(f"libdbs {libdbs.library_version()}")
    cloud = libdbs.Cloud.load(argv[1])
    boundary = libdbs.Boundary.load(argv[2])
    print(cloud, boundary)

    stages = []
    warnings = []
    result = libdbs.parameterize(cloud, boundary, max_level=3, relative_accuracy=1e-3,
                                 progress=lambda fraction, stage: stages.append(stage), warning=warnings.append)
    if warnings:
        raise SystemExit(f"the example's inputs fit each other, yet: {warnings}")
    print(result)
    uv = result.uv
    print(f"u in [{uv[:, 0].min():.3g}, {uv[:, 0].max():.3g}], v in [{uv[:, 1].min():.3g}, {uv[:, 1].max():.3g}]; {len(set(stages))} stages reported")

    # The surface at the points' own (u, v) lies within their distance of them.
    surface = result.evaluate(uv[:, 0], uv[:, 1], normals=True)
    gap = np.linalg.norm(surface.points - cloud.points, axis=1) - result.distances
    print(f"surface points at the points' (u,v): within {np.abs(gap).max():.3g} of their distances")
    if np.abs(gap).max() > 1e-6 * np.linalg.norm(cloud.bounds[1] - cloud.bounds[0]):
        raise SystemExit("the surface does not lie at the points' distances")

    try:
        libdbs.parameterize(cloud, boundary, max_level=99)
        raise SystemExit("max level 99 was not refused")
    except ValueError as error:  # libdbs.DbsValueError: a ValueError with the library's message
        print(f"refused as expected: {error}")

    if len(argv) == 4:
        result.save(cloud, argv[3])
        print(f"result          {argv[3]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
