"""Small meshes built in numpy for the tests: a cube, an icosphere, holes punched into them."""
import numpy as np

CUBE_VERTICES = np.array([[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)])
# Twelve outward-oriented triangles (vertex index = 4x + 2y + z).
CUBE_FACES = np.array([
    [0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
    [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3],
], dtype=np.int64)


def cube():
    return CUBE_VERTICES.copy(), CUBE_FACES.copy()


def icosphere(subdivisions=2):
    """A unit sphere: an icosahedron split `subdivisions` times (20 * 4^s faces)."""
    t = (1 + 5 ** 0.5) / 2
    v = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t],
         [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4],
         [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8],
         [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    vertices = [np.array(p, float) / np.linalg.norm(p) for p in v]
    faces = f
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = vertices[a] + vertices[b]
                vertices.append(p / np.linalg.norm(p))
                middle[key] = len(vertices) - 1
            return middle[key]

        faces = [g for a, b, c in faces for g in
                 ([a, mid(a, b), mid(c, a)], [b, mid(b, c), mid(a, b)],
                  [c, mid(c, a), mid(b, c)], [mid(a, b), mid(b, c), mid(c, a)])]
    return np.array(vertices), np.array(faces, dtype=np.int64)


def punch_holes(vertices, faces, centres, radius):
    """Removes the faces with a corner within `radius` of a centre (one hole each) and the
    vertices left unused: a valid mesh with one border cycle per centre."""
    keep = np.ones(len(faces), bool)
    for c in np.atleast_2d(centres):
        near = np.linalg.norm(vertices - c, axis=1) < radius
        keep &= ~near[faces].any(axis=1)
    faces = faces[keep]
    used = np.unique(faces)
    renumber = np.full(len(vertices), -1)
    renumber[used] = np.arange(len(used))
    return vertices[used], renumber[faces]


def holed_sphere(subdivisions=3, holes=2, radius=0.3):
    v, f = icosphere(subdivisions)
    centres = [[0, 0, 1], [0, 0, -1], [1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0]][:holes]
    return punch_holes(v, f, centres, radius)


def wavy_sheet(n=12):
    """An open sheet over the unit square (z = 0.1 sin(3x) cos(2y)), n x n cells: its outline is
    the border of an open surface, not a hole (the repair keeps it open, counted as kept)."""
    x, y = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1), indexing="ij")
    v = np.column_stack([x.ravel(), y.ravel(), 0.1 * np.sin(3 * x.ravel()) * np.cos(2 * y.ravel())])
    k = lambda i, j: i * (n + 1) + j  # noqa: E731
    f = [[k(i, j), k(i + 1, j), k(i + 1, j + 1)] for i in range(n) for j in range(n)]
    f += [[k(i, j), k(i + 1, j + 1), k(i, j + 1)] for i in range(n) for j in range(n)]
    return v, np.array(f, dtype=np.int64)


def jittered_sphere(subdivisions=3, amount=0.3, seed=1):
    """The icosphere with each vertex moved along the surface by up to `amount` x the local edge
    length, then back onto the sphere: the same closed surface with worse triangles."""
    v, f = icosphere(subdivisions)
    rng = np.random.default_rng(seed)
    edge = np.linalg.norm(v[f[0, 0]] - v[f[0, 1]])
    v = v + rng.uniform(-amount, amount, v.shape) * edge
    return v / np.linalg.norm(v, axis=1)[:, None], f


def sphere_points(n=2000):
    """n points spread evenly on the unit sphere (a Fibonacci lattice)."""
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    r = np.sqrt(1 - z * z)
    theta = np.pi * (1 + 5 ** 0.5) * i
    return np.c_[r * np.cos(theta), r * np.sin(theta), z]
