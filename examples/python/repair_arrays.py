"""Repair a mesh given as numpy arrays: punch two holes into a sphere, repair, check the result.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/repair_arrays.py
"""
import numpy as np

import mesh_repair

# An octahedron split three times and pushed onto the unit sphere (512 faces).
vertices = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
faces = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                  [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
for _ in range(3):
    edges = np.sort(np.vstack([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    unique, index = np.unique(edges, axis=0, return_inverse=True)
    middle = vertices[unique].mean(axis=1)
    vertices = np.vstack([vertices, middle / np.linalg.norm(middle, axis=1)[:, None]])
    m = len(faces)
    a, b, c = faces.T
    ab, bc, ca = (index[k * m:(k + 1) * m] + len(vertices) - len(unique) for k in range(3))
    faces = np.vstack([np.c_[a, ab, ca], np.c_[b, bc, ab], np.c_[c, ca, bc], np.c_[ab, bc, ca]])

# Two holes: the faces around the poles go.
centroids = vertices[faces].mean(axis=1)
holed = faces[np.abs(centroids[:, 2]) < 0.9]

before = mesh_repair.check(vertices, holed)
print(f"input: {len(holed)} faces, {before['border_cycles']} border cycles")

result = mesh_repair.repair(vertices, holed, fill="self_validated")
repair = result.report["repair"]
print(f"repaired: {len(result.faces)} faces, closed={repair['closed']}, valid={repair['valid']}, "
      f"{repair['holes_filled']} holes filled")
for step in repair["steps"]:
    print(f"  {step['name']}: {step['seconds']:.3f} s")

after = mesh_repair.check(result.vertices, result.faces)
radii = np.linalg.norm(result.vertices, axis=1)
print(f"after: {after['border_cycles']} border cycles; radius of the vertices "
      f"{radii.min():.3f}..{radii.max():.3f}")
