"""Makes the built package importable: scripts/test.sh sets PYTHONPATH to <build>/python; a
manual run finds it through MESH_REPAIR_BUILD_DIR (default: build/ of the repository). The
path also goes into the environment, for the child processes and Dask workers of the batch
tests."""
import os
import shutil
import sys
import tempfile

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


def pytest_configure(config):
    """pytest 7.2 (Debian 12) keeps the tmp_path folders of the last three runs under
    /tmp/pytest-of-USER; tests must leave nothing in /tmp, so each run gets a folder of its own
    (unless --basetemp names one), removed at the end of the session."""
    if not config.option.basetemp:
        config.option.basetemp = tempfile.mkdtemp(prefix="mesh_repair_pytest_")
        config._mesh_repair_own_basetemp = True


def pytest_unconfigure(config):
    if getattr(config, "_mesh_repair_own_basetemp", False):
        shutil.rmtree(config.option.basetemp, ignore_errors=True)
