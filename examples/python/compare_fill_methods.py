"""Fill the holes of one mesh with every method and compare: faces made, time, closedness.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/compare_fill_methods.py \
        .cache/cgal-demo/meshes/elephant-with-holes.off
"""
import sys
import time

import mesh_repair

path = sys.argv[1] if len(sys.argv) > 1 else ".cache/cgal-demo/meshes/elephant-with-holes.off"
vertices, faces, report = mesh_repair.read(path)
holes = mesh_repair.check(vertices, faces, self_intersections=False)["border_cycles"]
print(f"{path}: {len(faces)} faces, {holes} holes")
print(f"{'method':<22}{'filled':>8}{'new faces':>11}{'closed':>8}{'seconds':>9}")
for method in mesh_repair.FILL_METHODS:
    start = time.perf_counter()
    result = mesh_repair.fill_holes(vertices, faces, method=method)
    seconds = time.perf_counter() - start
    filled = result.report["result"]["filled"]
    print(f"{method:<22}{filled:>8}{len(result.faces) - len(faces):>11}"
          f"{str(result.report['output_closed']):>8}{seconds:>9.2f}")
