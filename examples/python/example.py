"""libdbs from Python: load a cloud and its boundary, parameterize, inspect the result.

usage: DBS_LIBRARY=path/to/libdbs.so python3 example.py CLOUD BOUNDARY [RESULT]
"""
import sys

import dbs


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    cloud_path, boundary_path = argv[1], argv[2]
    print(f"libdbs {dbs.version()}, Draco {'yes' if dbs.has_feature(dbs.FEATURE_DRACO) else 'no'}")

    cloud = dbs.Cloud.load(cloud_path)
    boundary = dbs.Boundary.load(boundary_path)
    # The same boundary as one closed loop cut at its four corners (an outline traced around
    # a scan would come this way): bottom, right, then top and left backwards.
    bottom, right, top, left = (boundary.side(s) for s in (dbs.SIDE_BOTTOM, dbs.SIDE_RIGHT, dbs.SIDE_TOP, dbs.SIDE_LEFT))
    loop = bottom + right[1:] + top[::-1][1:] + left[::-1][1:-1]
    corners = [0, len(bottom) - 1, len(bottom) + len(right) - 2, len(bottom) + len(right) + len(top) - 3]
    cut = dbs.Boundary.from_loop(loop, corners)
    if [cut.side(s) for s in range(4)] != [bottom, right, top, left]:
        raise SystemExit("Boundary.from_loop did not give back the sides")
    # Sides exported from CAD at 1e-3 miss their corners a little: a tolerance snaps them.
    low_y, high_y = min(p[1] for p in right), max(p[1] for p in right)
    moved = [(x, y + 1e-4 * (high_y - low_y), z) for (x, y, z) in right]
    try:
        dbs.Boundary.from_sides(bottom, moved, top, left)
        raise SystemExit("corners 1e-4 apart were accepted without a tolerance")
    except dbs.DbsError as error:
        assert error.status == dbs.ERR_DEGENERATE, error.status
    snapped = dbs.Boundary.from_sides(bottom, moved, top, left, tolerance=1e-3)
    # Each corner end moves half the miss.
    if abs(snapped.max_snap - 0.5e-4 * (high_y - low_y)) > 1e-9 * (high_y - low_y):
        raise SystemExit(f"unexpected corner snap {snapped.max_snap}")
    low, high = cloud.bounds()
    print(f"{len(cloud)} points in [{low[0]:.4g}, {high[0]:.4g}] x [{low[1]:.4g}, {high[1]:.4g}] x [{low[2]:.4g}, {high[2]:.4g}]")

    options = dbs.Options().set(dbs.OPT_MAX_LEVEL, 3).set(dbs.OPT_RELATIVE_ACCURACY, 1e-3)
    # A value out of range raises DbsError with the library's message and status.
    try:
        options.set(dbs.OPT_MAX_LEVEL, 99)
        raise SystemExit("max level 99 was not refused")
    except dbs.DbsError as error:
        assert error.status == dbs.ERR_OUT_OF_RANGE, error.status
        print(f"refused as expected: {error}")

    fractions = []
    options.on_progress(lambda fraction, stage: fractions.append(fraction))
    levels = []
    options.on_level(lambda level, patches: levels.append((level, len(patches))))

    warnings = []
    options.on_warning(warnings.append)
    result = dbs.parameterize(cloud, boundary, options)
    if warnings:
        raise SystemExit(f"the example's inputs fit each other, yet: {warnings}")
    # The boundary in other units (1000 times larger) is named by a warning; the run goes on.
    scaled = dbs.Boundary.from_sides(*[[(1000 * x, 1000 * y, 1000 * z) for (x, y, z) in side] for side in (bottom, right, top, left)])
    dbs.parameterize(cloud, scaled, dbs.Options().set(dbs.OPT_MAX_LEVEL, 0).on_warning(warnings.append))
    if not any("same units" in w for w in warnings):
        raise SystemExit(f"no warning for a boundary 1000 times the cloud: {warnings}")
    print(f"warned as expected: {warnings[0]}")
    if fractions[-1] != 1.0 or fractions != sorted(fractions):
        raise SystemExit(f"progress did not rise to exactly 1.0: {fractions[-3:]}")
    uv = result.uv()
    if any(not (0.0 <= c <= 1.0) for pair in uv for c in pair):
        raise SystemExit("a parameter lies outside [0, 1]")

    print(f"mean distance {result.stat(dbs.STAT_MEAN_DISTANCE):.4g}, max {result.stat(dbs.STAT_MAX_DISTANCE):.4g}, "
          f"target {result.stat(dbs.STAT_ACCURACY):.4g} ({'met' if result.stat(dbs.STAT_ACCURACY_MET) else 'not met'})")
    print(f"{int(result.stat(dbs.STAT_PATCHES))} patches ({int(result.stat(dbs.STAT_LEAVES))} leaves) on "
          f"{int(result.stat(dbs.STAT_LEVELS))} levels; per level: {levels}")
    points = cloud.points()
    for i in range(0, len(points), max(1, len(points) // 5)):
        x, y, z = points[i]
        print(f"  point {i:6d} ({x:9.4f} {y:9.4f} {z:9.4f}) -> u {uv[i][0]:.4f} v {uv[i][1]:.4f}")

    patches = result.patches()
    for i in range(min(len(patches), 5)):
        info = patches.info(i)
        print(f"  patch {info['id']}: level {info['level']} rect {tuple(round(c, 4) for c in info['rect'])} "
              f"grid {info['grid'][0]}x{info['grid'][1]} points {info['points']} mean {info['mean_distance']:.3g}")
    point, normal = result.evaluate(0.5, 0.5)
    print(f"S(0.5, 0.5) = {tuple(round(c, 5) for c in point)}, normal {tuple(round(c, 5) for c in normal)}")

    # Validation: a Delaunay mesh of the (u,v) over the cloud, its distortion, the distances.
    # A libdbs built without it (DBS_WITH_VALIDATION=OFF) refuses every validation call.
    if dbs.has_feature(dbs.FEATURE_VALIDATION):
        mesh = dbs.Mesh.create(result, cloud)
        triangles = mesh.triangles()
        distortion = mesh.distortion(dbs.SCALING_PER_AXIS)
        distances = dbs.Distances.create(result)
        print(f"mesh: {len(triangles)} triangles, {len(mesh.suspicious())} suspicious, "
              f"{int(distortion.stat(dbs.DISTORTION_FOLDED))} folded, conformal distortion mean "
              f"{distortion.summary(dbs.MEASURE_CONFORMAL, dbs.SUMMARY_MEAN):.3f} p95 "
              f"{distortion.summary(dbs.MEASURE_CONFORMAL, dbs.SUMMARY_P95):.3f}")
        print(f"distances: p50 {distances.stat(dbs.DISTANCES_P50):.4g}, p95 {distances.stat(dbs.DISTANCES_P95):.4g}, "
              f"{distances.stat(dbs.DISTANCES_WITHIN):.1%} within the target")
        if len(distortion.values(dbs.MEASURE_AREA)) != len(triangles):
            raise SystemExit("one distortion value per triangle was expected")
    else:
        try:
            dbs.Mesh.create(result, cloud)
            raise SystemExit("a libdbs without validation made a mesh")
        except dbs.DbsError as error:
            if error.status != dbs.ERR_UNSUPPORTED:
                raise
            print(f"validation refused as expected: {error}")

    try:
        dbs.Cloud.load(cloud_path + ".missing.xyz")
        raise SystemExit("a missing file was accepted")
    except dbs.DbsError as error:
        print(f"missing file refused as expected: {error}")

    if len(argv) == 4:
        result.save(cloud, argv[3])
        print(f"wrote {argv[3]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
