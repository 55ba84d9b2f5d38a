#!/usr/bin/env python3
# Copyright (c) 2026 Mesh_repair developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Pictures of filled holes for `mesh_repair bench holes` and `mesh_repair fill --picture`.

usage: render_patches.py SCENE.json OUT.png [SCENE.json OUT.png ...]

A scene (written by the tool, doc/bench_holes.md "Pictures") is one hole, or one fill, seen in
several panels side by side from one camera looking along the hole's average normal:

  {"title": str, "normal": [x, y, z],
   "mode": "distance" | "category",
   "scale_label": str, "scale_max": float,      # distance mode: one scale for every panel,
   "scale_clipped": bool,                       #   larger values in its top colour
   "legend": [str, ...],                        # category mode: the names of the values
   "panels": [{"title": str, "subtitle": str,
               "vertices": [x0, y0, z0, x1, ...], "faces": [i0, j0, k0, ...],
               "values": [v or null per face],  # null: surroundings, drawn grey
               "borders": [[i, j, ...], ...],   # closed polylines, drawn black
               "normal": [x, y, z]}]}           # optional: a panel of its own region and camera

Panels without a normal of their own share the scene's camera and framing (one hole seen by
several methods); a panel with its own (one of several holes) is framed on its own region.

Faces are shaded by a light near the camera. Each PNG is written to a temporary file and
renamed, so a reader never sees half a picture. Needs Debian's python3-matplotlib; without it
prints one line and exits 3 (the tool checks first and says so itself).
"""
import json
import math
import os
import sys
import textwrap

SURROUNDINGS = (0.74, 0.77, 0.82)  # blue-grey: tells the kept surface from any patch colour
CATEGORY_COLOURS = ["#4c72b0", "#dd8452", "#55a868", "#c44e52", "#8172b3", "#937860",
                    "#da8bc3", "#8c8c8c", "#ccb974", "#64b5cd"]
# Light at 0 (shading stays visible), dark red at the scale's maximum, in ten steps: a face's
# band is read off the colour bar, and matched across panels, more surely than a shade.
DISTANCE_MAP, DISTANCE_STEPS = "YlOrRd", 10


def normalised(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v] if length > 0 else [0.0, 0.0, 1.0]


def camera_angles(normal):
    """matplotlib's elevation and azimuth (degrees) of a camera placed along `normal`."""
    x, y, z = normalised(normal)
    return math.degrees(math.asin(max(-1.0, min(1.0, z)))), math.degrees(math.atan2(y, x))


def light_direction(elevation, azimuth):
    """A light above and left of the camera: a headlight alone flattens the relief."""
    e, a = math.radians(elevation + 25), math.radians(azimuth - 30)
    return [math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)]


def triangles(panel):
    v, f = panel["vertices"], panel["faces"]
    points = [(v[3 * i], v[3 * i + 1], v[3 * i + 2]) for i in range(len(v) // 3)]
    return points, [[points[f[3 * k]], points[f[3 * k + 1]], points[f[3 * k + 2]]]
                    for k in range(len(f) // 3)]


def shade(triangle, light):
    a, b, c = triangle
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = normalised([u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                    u[0] * w[1] - u[1] * w[0]])
    return 0.45 + 0.55 * abs(sum(n[i] * light[i] for i in range(3)))


def base_colour(value, scene, colour_map):
    if value is None:
        return SURROUNDINGS
    if scene["mode"] == "category":
        return to_rgb(CATEGORY_COLOURS[int(value) % len(CATEGORY_COLOURS)])
    top = scene.get("scale_max") or 1.0
    return colour_map(min(1.0, max(0.0, value / top)))[:3]


def bounds(panels):
    """Centre and half-width of a cube holding every vertex of `panels`."""
    low, high = [math.inf] * 3, [-math.inf] * 3
    for panel in panels:
        v = panel["vertices"]
        for i in range(0, len(v), 3):
            for k in range(3):
                low[k], high[k] = min(low[k], v[i + k]), max(high[k], v[i + k])
    centre = [(low[k] + high[k]) / 2 for k in range(3)]
    return centre, max(high[k] - low[k] for k in range(3)) / 2 or 1.0


def draw_panel(axes, panel, scene, light, colour_map):
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection
    points, tris = triangles(panel)
    colours = []
    for triangle, value in zip(tris, panel["values"]):
        s = shade(triangle, light)
        colours.append([c * s for c in base_colour(value, scene, colour_map)])
    # One collection for every face: mplot3d sorts depth within a collection only. Edges show
    # each method's triangulation; past a few thousand faces they would only darken the panel.
    edges = (0, 0, 0, 0.18) if len(tris) <= 4000 else "none"
    axes.add_collection3d(Poly3DCollection(tris, facecolors=colours, edgecolors=edges,
                                           linewidths=0.25))
    segments = []
    for loop in panel.get("borders", []):
        segments += [[points[loop[k]], points[loop[(k + 1) % len(loop)]]]
                     for k in range(len(loop))]
    if segments:
        axes.add_collection3d(Line3DCollection(segments, colors="black", linewidths=1.4))
    axes.set_title("\n".join(title_lines(panel)), fontsize=8)


def title_lines(panel):
    return ([panel["title"]] + textwrap.wrap(panel.get("subtitle", ""), 40))[:3]


def grid_shape(n):
    rows = max(1, math.ceil(n / 5))
    return rows, math.ceil(n / rows)


def render(scene, out_path, plt, colour_map):
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize
    from matplotlib.patches import Patch
    panels = scene["panels"]
    rows, cols = grid_shape(len(panels))
    # Inches: the figure's title and the panels' titles above, the scale or legend below.
    top = 0.42 + 0.13 * max(len(title_lines(p)) for p in panels)
    height = 2.6 * rows + top + 0.75
    figure = plt.figure(figsize=(max(2.6 * cols, 4.4), height), dpi=100)
    shared_frame = bounds([p for p in panels if "normal" not in p] or panels)
    for k, panel in enumerate(panels):
        elevation, azimuth = camera_angles(panel.get("normal", scene["normal"]))
        centre, half = bounds([panel]) if "normal" in panel else shared_frame
        axes = figure.add_subplot(rows, cols, k + 1, projection="3d")
        axes.computed_zorder = False  # the border lines stay in front of the faces
        axes.set_proj_type("ortho")
        axes.view_init(elev=elevation, azim=azimuth)
        draw_panel(axes, panel, scene, light_direction(elevation, azimuth), colour_map)
        for k_axis, setter in enumerate((axes.set_xlim, axes.set_ylim, axes.set_zlim)):
            setter(centre[k_axis] - half, centre[k_axis] + half)
        axes.set_box_aspect((1, 1, 1), zoom=1.5)
        axes.set_axis_off()
    figure.subplots_adjust(left=0.01, right=0.99, top=1 - top / height, bottom=0.75 / height,
                           wspace=0.02, hspace=0.15)
    figure.suptitle(scene.get("title", ""), fontsize=9)
    if scene["mode"] == "category":
        handles = [Patch(facecolor=CATEGORY_COLOURS[i % len(CATEGORY_COLOURS)], label=name)
                   for i, name in enumerate(scene.get("legend", []))]
        handles.append(Patch(facecolor=SURROUNDINGS, label="surroundings (kept)"))
        figure.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.1 / height),
                      ncol=min(len(handles), 5), fontsize=8, frameon=False)
    else:
        mappable = ScalarMappable(Normalize(0, scene.get("scale_max") or 1.0), colour_map)
        bar_axes = figure.add_axes([0.2, 0.42 / height, 0.6, 0.14 / height])
        bar = figure.colorbar(mappable, cax=bar_axes, orientation="horizontal",
                              extend="max" if scene.get("scale_clipped") else "neither")
        bar.set_label(scene.get("scale_label", ""), fontsize=8)
        bar.ax.tick_params(labelsize=7)
    save_png(figure, out_path)
    plt.close(figure)


def save_png(figure, out_path):
    """Writes a temporary file renamed over `out_path`. With 256 colours (Pillow, which
    python3-matplotlib depends on) a picture takes a third of the bytes and looks the same."""
    temporary = out_path + ".tmp-%d.png" % os.getpid()
    try:
        import io
        from PIL import Image
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png")
        buffer.seek(0)
        Image.open(buffer).convert("RGB").quantize(256).save(temporary, optimize=True)
    except ImportError:
        figure.savefig(temporary, format="png")
    os.replace(temporary, out_path)


def to_rgb(colour):
    from matplotlib.colors import to_rgb as convert
    return convert(colour)


def main(args):
    if len(args) < 2 or len(args) % 2:
        print("usage: render_patches.py SCENE.json OUT.png [SCENE.json OUT.png ...]",
              file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("render_patches.py: python3-matplotlib is missing, no pictures "
              "(Debian: scripts/setup.sh --with-plots)", file=sys.stderr)
        return 3
    colour_map = matplotlib.colormaps[DISTANCE_MAP].resampled(DISTANCE_STEPS)
    failed = 0
    for scene_path, out_path in zip(args[0::2], args[1::2]):
        try:
            with open(scene_path) as stream:
                render(json.load(stream), out_path, plt, colour_map)
        except Exception as error:  # one bad scene must not cost the other pictures
            print("render_patches.py: %s: %s: %s" % (scene_path, type(error).__name__, error),
                  file=sys.stderr)
            failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
