"""OFF reading and writing shared by the scripts that make test and benchmark meshes."""


def read_off(path):
    """OFF, COFF, NOFF, ... with one vertex or face per line (extra values such as colours are
    ignored) and the counts on their own line or after the keyword. Returns (vertices, faces)."""
    with open(path) as f:
        lines = [line.split("#", 1)[0].split() for line in f]
    lines = [words for words in lines if words]
    if not lines or not lines[0][0].endswith("OFF"):
        raise SystemExit(f"{path}: not an OFF file")
    counts = lines[0][1:] if len(lines[0]) > 1 else lines[1]
    first = 1 if len(lines[0]) > 1 else 2
    nv, nf = int(counts[0]), int(counts[1])
    vertices = [[float(w) for w in words[:3]] for words in lines[first:first + nv]]
    faces = [[int(w) for w in words[1:1 + int(words[0])]]
             for words in lines[first + nv:first + nv + nf]]
    return vertices, faces


def write_off(path, vertices, faces):
    """Coordinates written exactly (repr), so a mesh read back is the mesh written."""
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for v in vertices:
            f.write(f"{v[0]!r} {v[1]!r} {v[2]!r}\n")
        for face in faces:
            f.write(f"{len(face)} {' '.join(map(str, face))}\n")
