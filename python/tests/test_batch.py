"""repair_many: local processes and a two-worker Dask LocalCluster; crashes, hangs and bad files
fail alone; the summary matches the CLI's; a second run resumes."""
import csv
import json
import os
import stat
import sys

import pytest

import mesh_repair
from mesh_repair.batch import FIGURE_KEYS, repair_many
from meshes import holed_sphere, wavy_sheet

CLI_COLUMNS = ["file", "outcome", "exit_status", "seconds", *FIGURE_KEYS, "note"]


@pytest.fixture
def inputs(tmp_path):
    """Four holed spheres, an open sheet, a crash, a hang, a broken file and a text file."""
    folder = tmp_path / "in"
    folder.mkdir()
    for k in range(4):
        mesh_repair.write(folder / f"sphere{k}.off", *holed_sphere(3, holes=k % 3 + 1))
    mesh_repair.write(folder / "sheet.off", *wavy_sheet())
    mesh_repair.write(folder / "crash.off", *holed_sphere(2))
    mesh_repair.write(folder / "hang.off", *holed_sphere(2))
    (folder / "broken.off").write_text("OFF\n3 1 0\n0 0 0\n")
    (folder / "notes.txt").write_text("not a mesh")
    return folder


@pytest.fixture
def faulty_python(tmp_path):
    """An interpreter for the children that crashes (SIGSEGV) on crash.off and hangs on
    hang.off: how a real crash or endless loop in the library would look to the batch."""
    script = tmp_path / "python"
    script.write_text(f"""#!/bin/sh
case "$*" in
  *crash.off*) kill -SEGV $$ ;;
  *hang.off*) sleep 600 ;;
esac
exec {sys.executable} "$@"
""")
    script.chmod(script.stat().st_mode | stat.S_IEXEC)
    return str(script)


def check_outcomes(rows, out_dir):
    outcome = {row["file"]: row["outcome"] for row in rows}
    assert outcome == {
        "broken.off": "failed", "crash.off": "crashed", "hang.off": "timeout",
        "notes.txt": "skipped", "sphere0.off": "repaired", "sphere1.off": "repaired",
        "sphere2.off": "repaired", "sphere3.off": "repaired", "sheet.off": "repaired_except_kept"}
    for k in range(4):
        row = next(r for r in rows if r["file"] == f"sphere{k}.off")
        assert row["holes_filled"] == row["holes"] == k % 3 + 1
        assert row["closed"] == 1 and row["valid"] == 1 and row["exit_status"] == 0
        assert row["repair_status"] == "complete"
        back = mesh_repair.read(out_dir / f"sphere{k}.off")
        assert mesh_repair.check(*back[:2], self_intersections=False)["border_cycles"] == 0
        report = json.loads((out_dir / f"sphere{k}.off.report.json").read_text())
        assert report["repair"]["holes_filled"] == k % 3 + 1
    # The open sheet's outline is kept, as the CLI does it: exit 3, counted, the file valid.
    sheet = next(r for r in rows if r["file"] == "sheet.off")
    assert (sheet["exit_status"], sheet["repair_status"]) == (3, "complete_except_kept")
    assert sheet["sheet_borders_left_open"] == 1 and sheet["border_cycles_after"] == 1
    assert sheet["valid"] == 1 and sheet["closed"] == 0
    with open(out_dir / "summary.csv") as f:
        table = list(csv.reader(f))
    assert table[0] == CLI_COLUMNS
    assert sorted(r[0] for r in table[1:]) == sorted(outcome)
    lines = (out_dir / "summary.jsonl").read_text().splitlines()
    assert [json.loads(line)["outcome"] for line in lines] == [r["outcome"] for r in rows]
    assert [json.loads(line)["repair_status"] for line in lines] == [r["repair_status"] for r in rows]
    # No temporary or summary file of a child is left behind.
    assert not [p for p in os.listdir(out_dir) if p.startswith(".tmp-") or "summary.json" in p
                and p.startswith(".")]


def test_local_processes_isolate_crash_and_hang_and_resume(inputs, faulty_python, tmp_path):
    out_dir = tmp_path / "out"
    rows = repair_many(inputs, out_dir, timeout=5, jobs=2, python_executable=faulty_python)
    check_outcomes(rows, out_dir)
    # Resumable: a second run runs nothing (the hang would take the whole timeout again).
    mtime = (out_dir / "sphere0.off").stat().st_mtime_ns
    again = repair_many(inputs, out_dir, timeout=5, jobs=2, python_executable=faulty_python)
    assert again == rows
    assert (out_dir / "sphere0.off").stat().st_mtime_ns == mtime


def test_bad_arguments_are_value_errors(inputs, tmp_path):
    with pytest.raises(ValueError, match="timeout must be positive"):
        repair_many(inputs, tmp_path / "out", timeout=0)
    with pytest.raises(ValueError, match="out_dir must differ"):
        repair_many(inputs, inputs)
    with pytest.raises(ValueError, match="share the file name"):
        repair_many([inputs / "sphere0.off", tmp_path / "sphere0.off"], tmp_path / "out")


def test_dask_local_cluster_of_two_workers(inputs, faulty_python, tmp_path):
    distributed = pytest.importorskip("distributed")
    out_dir = tmp_path / "out"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, local_directory=tmp_path / "dask") as cluster, \
            distributed.Client(cluster) as client:
        rows = repair_many(inputs, out_dir, client=client, timeout=5,
                           python_executable=faulty_python)
        assert len(client.scheduler_info()["workers"]) == 2  # no worker died
    check_outcomes(rows, out_dir)


def test_every_file_accounted_for_when_a_dask_worker_process_dies(tmp_path):
    """A worker process killed in the middle of the batch (as the OOM killer would): Dask runs
    its tasks again on the other worker; every file still gets its row."""
    distributed = pytest.importorskip("distributed")
    import threading

    folder = tmp_path / "in"
    folder.mkdir()
    for k in range(6):
        mesh_repair.write(folder / f"sphere{k}.off", *holed_sphere(5, holes=k % 3 + 1))
    out_dir = tmp_path / "out"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, local_directory=tmp_path / "dask") as cluster, \
            distributed.Client(cluster) as client:
        victim = sorted(client.scheduler_info()["workers"])[0]

        def kill_victim():
            try:
                client.run(os._exit, 1, workers=[victim])
            except Exception:  # the worker died before it could answer
                pass

        killer = threading.Timer(1.0, kill_victim)
        killer.start()
        rows = repair_many(folder, out_dir, client=client, timeout=120)
        killer.join()
        # The nanny restarted the killed worker under a new address.
        assert victim not in client.scheduler_info()["workers"]
    assert sorted(r["file"] for r in rows) == [f"sphere{k}.off" for k in range(6)]
    assert all(r["outcome"] in ("repaired", "crashed") for r in rows)
    assert sum(r["outcome"] == "repaired" for r in rows) >= 5
    lines = (out_dir / "summary.jsonl").read_text().splitlines()
    assert len(lines) == 6


def test_memory_limit_fails_the_file_as_out_of_memory(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    mesh_repair.write(folder / "sphere.off", *holed_sphere(3))
    rows = repair_many(folder, tmp_path / "tight", memory_limit=60 * 2**20, jobs=1)
    assert (rows[0]["outcome"], rows[0]["note"]) == ("failed", "out of memory")
    rows = repair_many(folder, tmp_path / "ample", memory_limit=2**31, jobs=1)
    assert rows[0]["outcome"] == "repaired"
