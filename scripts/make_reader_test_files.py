#!/usr/bin/env python3
"""Writes the reader test files of test/data/readers/ (small variants real files contain) and
the regression corpus test/fuzz/corpus-regression/ (inputs that crashed, hung or ran away with
the release tool before our own readers). Run from anywhere; the files are committed."""
import os
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
READERS = os.path.join(ROOT, "test", "data", "readers")
CORPUS = os.path.join(ROOT, "test", "fuzz", "corpus-regression")

# A unit tetrahedron: 4 points, 4 outward triangles.
P = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
T = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


def off_variants():
    pts = "".join("%g %g %g\n" % p for p in P)
    tris = "".join("3 %d %d %d\n" % t for t in T)
    write(READERS, "counts_on_header.off", "OFF 4 4 0\n" + pts + tris)
    write(READERS, "comments.off",
          "# exported by a tool\nOFF # keyword\n\n# counts next\n4 4 6 # v f e\n" +
          "".join("%g %g %g # vertex\n" % p for p in P) + "\n" +
          "".join("3 %d %d %d  # face\n" % t for t in T))
    write(READERS, "coff.off", "COFF\n4 4 0\n" +
          "".join("%g %g %g 255 0 0 255\n" % p for p in P) +
          "".join("3 %d %d %d 0.5 0.5 0.5\n" % t for t in T))
    write(READERS, "noff.off", "NOFF\n4 4 0\n" +
          "".join("%g %g %g 0 0 1\n" % p for p in P) + tris)
    write(READERS, "stoff.off", "STOFF\n4 4 0\n" +
          "".join("%g %g %g 0.25 0.75\n" % p for p in P) + tris)
    write(READERS, "ndim.off", "nOFF\n3\n4 4 0\n" + pts + tris)
    write(READERS, "homogeneous.off", "4OFF\n4 4 0\n" +
          "".join("%g %g %g 2\n" % tuple(2 * c for c in p) for p in P) + tris)
    write(READERS, "crlf_tabs.off", ("OFF\r\n4\t4\t0\r\n" + pts + tris).replace("\n", "\r\n").replace("\r\r", "\r"))
    binary = b"OFF BINARY\n" + struct.pack(">iii", 4, 4, 0)
    for p in P:
        binary += struct.pack(">fff", *p)
    for t in T:
        binary += struct.pack(">iiiii", 3, *t, 0)
    write(READERS, "binary.off", binary)
    write(READERS, "cr_only_bom.off", "\ufeffOFF\r4 4 0\r" + (pts + tris).replace("\n", "\r"))
    write(READERS, "no_keyword.off", "# Geomview: the keyword is optional\n4 4 0\n" + pts + tris)
    write(READERS, "utf16le.off", ("\ufeffOFF\n4 4 0\n" + pts + tris).encode("utf-16-le"))
    write(READERS, "quad_and_short.off",
          "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n2 0 1\n1 3\n")


def obj_variants():
    pts = "".join("v %g %g %g\n" % p for p in P)
    write(READERS, "continuation.obj", pts +
          "".join("f %d \\\n  %d \\\n %d\n" % tuple(i + 1 for i in t) for t in T))
    write(READERS, "cr_only.obj", "# classic Mac line ends\r" + (pts + "".join(
        "f %d %d %d\n" % tuple(i + 1 for i in t) for t in T)).replace("\n", "\r"))
    write(READERS, "bom.obj", "\ufeff" + pts + "".join(
        "f %d %d %d\r\n" % tuple(i + 1 for i in t) for t in T))
    write(READERS, "utf16be.obj", ("\ufeff# saved as Unicode text\n" + pts + "".join(
        "f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1) for t in T)).encode("utf-16-be"))
    write(READERS, "negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -1 -2\n"
          "v 0 0 1\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n")
    write(READERS, "texture_normal.obj", "mtllib a.mtl\no tet\n" + pts +
          "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nusemtl red\ns 1\n"
          "f 1/1/1 3/3/1 2/2/1\nf 1//1 2//1 4//1\nf 1/1 4/2 3/3\ng side\nf 2/2/1 3/3/1 4/1/1\n")
    write(READERS, "polygon.obj", "# a pentagon with a colour per vertex\n" +
          "".join("v %g %g 0 1 0 0\n" % (x, y) for x, y in
                  [(0, 0), (2, 0), (3, 1), (1, 2), (-1, 1)]) + "f 1 2 3 4 5\nl 1 2\np 3\n")


def stl_variants():
    data = b"solid exported by a tool that writes solid in binary files".ljust(80, b" ")
    data += struct.pack("<I", len(T))
    for t in T:
        data += struct.pack("<fff", 0, 0, 0)
        for i in t:
            data += struct.pack("<fff", *P[i])
        data += struct.pack("<H", 0)
    write(READERS, "binary_solid.stl", data)
    text = "  solid\ttet  \r\n"
    for t in T:
        text += "facet   normal 0 0 0\r\n\touter loop\n"
        for i in t:
            text += "\t\tvertex  %g\t%g   %g \n" % P[i]
        text += "   endloop\nendfacet\n\n"
    text += "endsolid tet\n"
    write(READERS, "ascii_whitespace.stl", text)
    write(READERS, "ascii_bom_cr_only.stl", "\ufeff" + text.replace("\r\n", "\n").replace("\n", "\r"))
    write(READERS, "binary_header_utf16_mark.stl", b"\xff\xfe" + data[2:])
    write(READERS, "ascii_utf16le.stl", ("\ufeff" + text).encode("utf-16-le"))
    write(READERS, "ascii_one_line.stl", "solid t " + " ".join(
        "FACET NORMAL 0 0 1 OUTER LOOP " + " ".join("VERTEX %g %g %g" % P[i] for i in t) +
        " ENDLOOP ENDFACET" for t in T) + "\nENDSOLID t\n")


PLY_TYPES = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
             "float": "f", "double": "d"}


def ply_binary(endian):
    order = "<" if endian == "little" else ">"
    header = ("ply\nformat binary_%s_endian 1.0\ncomment every type once\n"
              "element vertex 4\nproperty double x\nproperty float y\nproperty float z\n"
              "property uchar red\nproperty short s\nproperty list uchar float extra\n"
              "element face 4\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
              "property ushort u\nproperty list int uint more\n"
              "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n" % endian)
    data = header.encode()
    for p in P:
        data += struct.pack(order + "dffBhBff", p[0], p[1], p[2], 200, -5, 2, 0.5, 0.25)
    for t in T:
        data += struct.pack(order + "BBiiiHiII", 7, 3, t[0], t[1], t[2], 9, 2, 1, 2)
    data += struct.pack(order + "ii", 0, 1)
    return data


def ply_variants():
    write(READERS, "binary_little.ply", ply_binary("little"))
    write(READERS, "binary_big.ply", ply_binary("big"))
    write(READERS, "extra_properties.ply",
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
          "property uchar red\nproperty uchar green\nproperty uchar blue\n"
          "element face 4\nproperty list uchar int vertex_indices\nproperty uchar red\n"
          "end_header\n" + "".join("%g %g %g 0 0 1 255 128 0\n" % p for p in P) +
          "".join("3 %d %d %d 17\n" % t for t in T))
    write(READERS, "extra_fields.ply",
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
          "end_header\n" + "".join("%g %g %g\n" % p for p in P) +
          "".join("3 %d %d %d 0.1 0.2 0.3 255\n" % t for t in T))
    # The tetrahedron as one strip 1 0 3 2 1 0 ... (here two strips separated by -1).
    write(READERS, "tristrips.ply",
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
          "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
          "end_header\n" + "".join("%g %g %g\n" % p for p in P) +
          "9 0 2 1 3 -1 1 3 0 2\n")
    write(READERS, "free_text_header.ply",
          "ply\nformat ascii 1.0\nCreated by Blender3D 249 - www.blender.org, source file: 't'\n"
          "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 4\nproperty list uchar int vertex_indices\nend_header\n" +
          "".join("%g %g %g\n" % p for p in P) + "".join("3 %d %d %d\n" % t for t in T))
    write(READERS, "vertex_index.ply",
          "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\nproperty float32 x\r\nproperty float32 y\r\n"
          "property float32 z\r\nelement face 4\r\nproperty list uint8 int32 vertex_index\r\n"
          "end_header\r\n" + "".join("%g %g %g\r\n" % p for p in P) +
          "".join("3 %d %d %d\r\n" % t for t in T))


def regression_corpus():
    """Each input that broke the release tool, made small."""
    ply_head = "ply\nformat ascii 1.0\n"
    write(CORPUS, "property_before_element.ply",
          ply_head + "property float x\nelement vertex 3\nproperty float y\nend_header\n0\n0\n0\n")
    write(CORPUS, "vertex_x_is_a_list.ply",
          ply_head + "element vertex 3\nproperty list uchar float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n1 0 0 0\n1 1 0 0\n1 0 1 0\n3 0 1 2\n")
    write(CORPUS, "face_of_a_million_indices.off",
          "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000 " + " ".join(["0 1 2"] * 10) + "\n")
    n = 10001  # one past the limit of vertices per face
    write(CORPUS, "polygon_past_the_limit.obj",
          "".join("v %d 0 0\n" % i for i in range(3)) + "f " + " ".join(
              str(1 + i % 3) for i in range(n)) + "\n")
    write(CORPUS, "huge_counts.off", "OFF\n1000000000 1000000000 0\n0 0 0\n")
    write(CORPUS, "huge_counts.ply",
          ply_head + "element vertex 1000000000\nproperty float x\nproperty float y\n"
          "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
          "end_header\n0 0 0\n")
    write(CORPUS, "huge_counts_binary.stl", b"solid".ljust(80, b"\0") + struct.pack("<I", 10**9))
    write(CORPUS, "zeros_after_header.off", b"OFF\n3 1 0\n" + b"\0" * 4096)
    write(CORPUS, "zeros.obj", b"\0" * 4096)
    write(CORPUS, "coordinates_1e308.off",
          "OFF\n4 2 0\n1e308 1e308 1e308\n-1e308 -1e308 1e308\n1e308 -1e308 -1e308\n"
          "-1e308 1e308 -1e308\n3 0 1 2\n3 0 2 3\n")
    write(CORPUS, "coordinates_1e308.obj",
          "v 1e308 0 0\nv -1e308 0 0\nv 0 1e308 0\nv 0 0 -1e308\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n")
    write(CORPUS, "tristrips.ply",
          ply_head + "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
          "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
          "0 0 0\n1 0 0\n0 1 0\n0 0 1\n6 0 1 2 3 0 1\n")
    write(CORPUS, "face_rows_with_extra_fields.ply",
          ply_head + "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 255 255\n")
    write(CORPUS, "line_continuation.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n2 3\n")
    write(CORPUS, "counts_on_off_line.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    write(CORPUS, "negative_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n")
    write(CORPUS, "nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    write(CORPUS, "truncated_binary.stl", b"x" * 80 + struct.pack("<I", 16) + b"abc")
    write(CORPUS, "truncated_ascii.stl",
          "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\n")
    write(CORPUS, "ply_list_count_huge.ply",
          "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nelement face 1\n"
          "property list uint int vertex_indices\nend_header\n".encode() +
          struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<I", 0xffffffff) + b"\0" * 16)
    write(CORPUS, "ply_binary_zero_faces.ply",
          "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
          "property float y\nproperty float z\nelement face 64\n"
          "property list uchar int vertex_indices\nend_header\n".encode() +
          struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + b"\0" * 64)
    write(CORPUS, "obj_relative_index_out_of_range.obj", "v 0 0 0\nf -1 -2 -3\n")


if __name__ == "__main__":
    off_variants()
    obj_variants()
    stl_variants()
    ply_variants()
    regression_corpus()
    print("wrote", READERS, "and", CORPUS)
