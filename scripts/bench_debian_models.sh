#!/bin/sh
# Repairs real models from Debian packages that the project never tuned on. MODELS=furniture
# (default): a fixed sample of the furniture OBJ files of sweethome3d-furniture (multi-part,
# open, interpenetrating, polygons), the dirty STL files of openscad-testing-data and the OBJ
# models of minetest-data. MODELS=more: every OFF/OBJ/STL/PLY file of geomview and
# assimp-testmodels (format variants, invalid files, game and Blender models) and of cura and
# prusa-slicer (printer beds and parts: CAD STLs and OBJs). MODELS=science: the OBJ shape models
# of stellarium-data (asteroids and moons from spacecraft images, test scenes, a scanned
# observatory garden of 71,000 faces), the STL meshes of gmsh-doc (a scanned aneurysm, terrain,
# CAD parts; gzipped), netgen-doc and freecad-common. MODELS=cfd: the surfaces of the OpenFOAM
# tutorials (openfoam-examples: snappyHexMesh's motorBike and other multi-part CAD models,
# terrain, ducts, baffles and region interfaces; gzipped, duplicates dropped). Downloads the packages with
# `apt-get download` (no install) into .cache/debian-models, runs `mesh_repair repair --batch`
# on the files and prints the count of each outcome, the total time and the slowest files. Extra
# arguments go to `repair` (e.g. --merge-intersecting-solids).
# Usage: [MODELS=more|science|cfd] scripts/bench_debian_models.sh [repair options]
# MESH_REPAIR (default build/bin/mesh_repair), SAMPLE (default 60 furniture files), SEED (of the
# furniture draw, default 7; another seed draws models held out from the default sample), JOBS (2),
# TIMEOUT (seconds per file, default 120; the science corpus's garden scenes need about 240),
# KEEP (a folder that receives the inputs, the repaired files, summary.csv and the reports).
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
TOOL=${MESH_REPAIR:-$ROOT/build/bin/mesh_repair}
SAMPLE=${SAMPLE:-60}
JOBS=${JOBS:-2}
TIMEOUT=${TIMEOUT:-120}
CACHE=$ROOT/.cache/debian-models
mkdir -p "$CACHE/debs" "$CACHE/extracted"
MODELS=${MODELS:-furniture}
case $MODELS in
  furniture) PACKAGES="sweethome3d-furniture openscad-testing-data minetest-data" ;;
  more) PACKAGES="geomview assimp-testmodels cura prusa-slicer" ;;
  science) PACKAGES="stellarium-data gmsh-doc netgen-doc freecad-common" ;;
  cfd) PACKAGES="openfoam-examples" ;;
  *) echo "MODELS must be furniture, more, science or cfd, not $MODELS" >&2; exit 2 ;;
esac
for package in $PACKAGES; do
  if ! ls "$CACHE/debs/${package}_"*.deb >/dev/null 2>&1; then
    (cd "$CACHE/debs" && apt-get download "$package" >/dev/null 2>&1) ||
      { echo "cannot download $package (apt-get download)" >&2; exit 1; }
  fi
  [ -d "$CACHE/extracted/$package" ] ||
    dpkg -x "$CACHE/debs/${package}_"*.deb "$CACHE/extracted/$package"
done
WORK=$(mktemp -d "${TMPDIR:-/tmp}/mesh_repair_debian.XXXXXX")
KEEP=${KEEP:-}
trap '[ -z "$KEEP" ] || { mkdir -p "$KEEP" && cp -r "$WORK"/. "$KEEP"/; }; rm -rf "$WORK"' EXIT INT TERM
mkdir -p "$WORK/in" "$WORK/out"
python3 - "$CACHE/extracted" "$WORK/in" "$SAMPLE" "$MODELS" "${SEED:-7}" <<'EOF'
import glob, gzip, hashlib, os, random, shutil, sys, zipfile
extracted, out, sample = sys.argv[1], sys.argv[2], int(sys.argv[3])
if sys.argv[4] == "cfd":
    # The tutorials share surfaces: each content is run once, named by its tutorial.
    root = extracted + "/openfoam-examples/usr/share/doc/openfoam-examples/examples/"
    seen = set()
    for p in sorted(glob.glob(root + "**/*", recursive=True)):
        name = os.path.basename(p)
        plain = name[:-3] if name.lower().endswith(".gz") else name
        if not os.path.isfile(p) or plain.lower().rsplit(".", 1)[-1] not in ("off", "obj", "stl", "ply"):
            continue
        with (gzip.open(p) if plain != name else open(p, "rb")) as f:
            data = f.read()
        digest = hashlib.sha1(data).hexdigest()
        if digest in seen:
            continue
        seen.add(digest)
        parts = p[len(root):].split("/")
        with open("%s/%s_%s" % (out, parts[2] if len(parts) > 3 else parts[0], plain), "wb") as g:
            g.write(data)
    sys.exit(0)
if sys.argv[4] == "science":
    for package in ("stellarium-data", "gmsh-doc", "netgen-doc", "freecad-common"):
        for p in sorted(glob.glob("%s/%s/usr/share/**/*" % (extracted, package), recursive=True)):
            name = os.path.basename(p)
            plain = name[:-3] if name.lower().endswith(".gz") else name
            if os.path.isfile(p) and plain.lower().rsplit(".", 1)[-1] in ("off", "obj", "stl", "ply"):
                with (gzip.open(p) if plain != name else open(p, "rb")) as f, \
                        open(out + "/" + plain, "wb") as g:
                    g.write(f.read())
    sys.exit(0)
if sys.argv[4] == "more":
    for package in ("geomview", "assimp-testmodels", "cura", "prusa-slicer"):
        root = "%s/%s/usr/share/" % (extracted, package)
        for p in sorted(glob.glob(root + "**/*", recursive=True)):
            if os.path.isfile(p) and p.lower().rsplit(".", 1)[-1] in ("off", "obj", "stl", "ply"):
                shutil.copy(p, out + "/" + p[len(root):].replace("/", "_").replace(" ", "_"))
    sys.exit(0)
objs = []
for archive in sorted(glob.glob(extracted + "/sweethome3d-furniture/**/*.sh3f", recursive=True)):
    with zipfile.ZipFile(archive) as z:
        objs += [(archive, n) for n in sorted(z.namelist()) if n.lower().endswith(".obj")]
random.seed(int(sys.argv[5]))
for i, (archive, name) in enumerate(random.sample(objs, min(sample, len(objs)))):
    with zipfile.ZipFile(archive) as z, open("%s/sh%02d_%s" % (out, i, os.path.basename(name).replace(" ", "_")), "wb") as f:
        f.write(z.read(name))
scad = extracted + "/openscad-testing-data/usr/share/openscad/testdata"
for p in glob.glob(scad + "/scad/misc/bad-stl-*.stl") + glob.glob(scad + "/scad/bugs/*.stl") + \
        glob.glob(scad + "/stl/adns*.stl"):
    shutil.copy(p, out + "/os_" + os.path.basename(p))
for p in glob.glob(extracted + "/minetest-data/**/*.obj", recursive=True):
    shutil.copy(p, out + "/mt_" + os.path.basename(p))
EOF
start=$(date +%s.%N)
"$TOOL" repair --batch "$WORK/in" --out-dir "$WORK/out" --jobs "$JOBS" --timeout "$TIMEOUT" "$@" \
  >"$WORK/batch.log" 2>&1 || true
seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
echo "files: $(ls "$WORK/in" | wc -l), wall time ${seconds} s (jobs $JOBS)"
echo "outcomes:"
tail -n +2 "$WORK/out/summary.csv" | cut -d, -f2 | sort | uniq -c
echo "slowest:"
tail -n +2 "$WORK/out/summary.csv" | awk -F, '{ print $4, $1 }' | sort -rn | head -5
