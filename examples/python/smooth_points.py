"""Mesh a point cloud sampled on a sphere, then smooth the mesh with each smoother and compare
the element quality and how far the nodes moved off the input surface.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/smooth_points.py
"""
import numpy as np

import mesh_repair

# 3000 points on the unit sphere (a Fibonacci lattice), shaken a little along the surface.
n = 3000
i = np.arange(n) + 0.5
z = 1 - 2 * i / n
theta = np.pi * (1 + 5 ** 0.5) * i
points = np.c_[np.sqrt(1 - z * z) * np.cos(theta), np.sqrt(1 - z * z) * np.sin(theta), z]
points += np.random.default_rng(1).normal(scale=0.01, size=points.shape)
points /= np.linalg.norm(points, axis=1)[:, None]

meshed = mesh_repair.mesh_points(points, smooth=False)
report = meshed.report
print(f"{report['points']} points -> {report['vertices']} vertices, {report['faces']} faces, "
      f"{report['edge_flips']} edge flips, closed="
      f"{mesh_repair.check(meshed.vertices, meshed.faces)['closed']}")

print(f"{'method':<8}{'worst':>8}{'mean':>8}{'distance/diag':>15}{'seconds':>9}")
for method in mesh_repair.SMOOTHING_METHODS:
    result = mesh_repair.smooth(meshed.vertices, meshed.faces, method=method)
    r = result.report
    print(f"{method:<8}{r['worst_quality_before']:.3f}->{r['worst_quality_after']:.3f}"
          f"  {r['mean_quality_before']:.3f}->{r['mean_quality_after']:.3f}"
          f"{r['max_distance_to_input_relative']:>11.2e}{r['seconds']:>9.2f}")
