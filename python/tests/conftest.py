"""Makes the built package importable: scripts/test.sh sets PYTHONPATH to <build>/python; a
manual run finds it through MESH_REPAIR_BUILD_DIR (default: build/ of the repository). The
path also goes into the environment, for the child processes and Dask workers of the batch
tests."""
import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD_PYTHON = os.path.join(os.environ.get("MESH_REPAIR_BUILD_DIR", os.path.join(ROOT, "build")),
                            "python")
if os.path.isdir(os.path.join(BUILD_PYTHON, "mesh_repair")):
    sys.path.insert(0, BUILD_PYTHON)
    os.environ["PYTHONPATH"] = os.pathsep.join(
        filter(None, [BUILD_PYTHON, os.environ.get("PYTHONPATH")]))

DEMO_DATA = os.environ.get("MESH_REPAIR_DEMO_DATA",
                           os.path.join(ROOT, ".cache", "cgal-demo", "meshes"))


@pytest.fixture
def demo_mesh():
    """The path of a libcgal-demo mesh, or a skip when the corpus is absent."""

    def find(name):
        path = os.path.join(DEMO_DATA, name)
        if not os.path.isfile(path):
            pytest.skip(f"{path} absent (scripts/fetch_demo_data.sh downloads libcgal-demo)")
        return path

    return find
