"""Repair many mesh files, one file per task, on a Dask cluster or in local processes.

``repair_many(paths, out_dir, client=None, timeout=600)`` repairs each file in its own child
process (the task only supervises it), so a file that crashes, hangs past ``timeout`` or runs
out of memory fails alone, and its worker lives on. With a ``distributed.Client`` the tasks run
on its cluster (the paths and ``out_dir`` must then be on a file system every worker sees);
without one, ``jobs`` local child processes at a time. Writes what ``mesh_repair repair --batch``
writes: each repaired mesh, ``NAME.report.json``, ``NAME.log``, and ``summary.csv`` and
``summary.jsonl`` with the same columns. Each finished file leaves ``.NAME.done.json`` in
``out_dir``: a second run skips those files (resumable). See doc/python.md.
"""

import json
import os
import signal
import subprocess
import sys
import time

__all__ = ["repair_many", "FIGURE_KEYS"]

MESH_EXTENSIONS = (".off", ".obj", ".stl", ".ply")

#: The per-file figures of the summary, in the CLI's column order (Mesh_repair/cli/batch.cpp).
FIGURE_KEYS = (
    "repair_status",
    "faces_before",
    "faces_after",
    "holes",
    "holes_filled",
    "holes_failed",
    "holes_too_large",
    "sheet_borders_left_open",
    "border_cycles_after",
    "closed",
    "valid",
    "manifold",
    "self_intersections_before",
    "self_intersections_after",
    "only_holes_before",
)

# The child exits like the CLI: 0 repaired, 1 incomplete, 2 bad input, 3 repaired except what
# was kept on purpose (Mesh_repair/cli/common.h); and beyond the CLI's:
_EXIT_COMPLETE_EXCEPT_KEPT = 3
_EXIT_OUT_OF_MEMORY = 4
_EXIT_ERROR = 5
_OUTCOME_OF_STATUS = {0: "repaired", 1: "incomplete", _EXIT_COMPLETE_EXCEPT_KEPT: "repaired_except_kept"}
_EXIT_OF_REPAIR_STATUS = {"complete": 0, "incomplete": 1,
                          "complete_except_kept": _EXIT_COMPLETE_EXCEPT_KEPT}


def repair_many(paths, out_dir, client=None, timeout=600, jobs=None, memory_limit=None,
                retry_failed=False, python_executable=None, **repair_options):
    """Repairs every file of ``paths`` (a list of files, or one folder: its entries, sorted)
    into ``out_dir`` and returns the summary rows (dicts with the CSV's columns).

    client: a ``distributed.Client``; its workers run one supervising task per file.
    timeout: seconds allowed per file; past it the child is killed (outcome "timeout").
    jobs: files at once without a client (default: the number of cores).
    memory_limit: bytes of address space per child (outcome "failed", note "out of memory").
    retry_failed: also run again the files a previous run left failed, crashed or timed out.
    python_executable: the interpreter of the children (default: the worker's own).
    repair_options: passed to ``mesh_repair.repair`` (e.g. ``fill="liepa"``); ``threads``
        defaults to 1 here: the parallelism is across files, one per worker thread.
    Outcomes: repaired, repaired_except_kept, incomplete, failed, crashed, timeout, skipped (as
    the CLI's; ``repair_status`` is the report's ``complete``, ``complete_except_kept`` or
    ``incomplete``).
    """
    if not (isinstance(timeout, (int, float)) and timeout > 0):
        raise ValueError("timeout must be positive")
    if jobs is not None and (not isinstance(jobs, int) or jobs < 1):
        raise ValueError("jobs must be at least 1")
    repair_options.setdefault("threads", 1)
    out_dir = os.path.abspath(os.fspath(out_dir))
    inputs = _inputs(paths, out_dir)
    os.makedirs(out_dir, exist_ok=True)
    spec = {
        "out_dir": out_dir,
        "timeout": float(timeout),
        "memory_limit": memory_limit,
        "python": python_executable,
        "options": repair_options,
    }
    rows = {}
    todo = []
    for path in inputs:
        done = _previous_row(path, out_dir, retry_failed)
        if done is not None:
            rows[path] = done
        else:
            todo.append(path)
    run = _run_on_cluster if client is not None else _run_locally
    rows.update(run(todo, spec, client if client is not None else jobs))
    ordered = [rows[path] for path in inputs]
    _write_summaries(out_dir, ordered)
    return ordered


# ---- inputs and resuming -----------------------------------------------------------------------


def _inputs(paths, out_dir):
    if isinstance(paths, (str, bytes, os.PathLike)):
        folder = os.fspath(paths)
        if not os.path.isdir(folder):
            raise ValueError(f"{folder}: not a directory (give a folder or a list of files)")
        if os.path.realpath(folder) == os.path.realpath(out_dir):
            raise ValueError("out_dir must differ from the input folder")
        paths = [os.path.join(folder, name) for name in sorted(os.listdir(folder))]
    inputs = [os.path.abspath(os.fspath(p)) for p in paths]
    names = {}
    for path in inputs:
        name = os.path.basename(path)
        if name in names:
            raise ValueError(f"{path} and {names[name]} share the file name {name}; "
                             "their outputs would collide in out_dir")
        names[name] = path
        if os.path.dirname(path) == out_dir:
            raise ValueError(f"{path}: inputs must not be in out_dir")
    return inputs


def _done_marker(path, out_dir):
    return os.path.join(out_dir, "." + os.path.basename(path) + ".done.json")


def _previous_row(path, out_dir, retry_failed):
    try:
        with open(_done_marker(path, out_dir)) as f:
            row = json.load(f)
    except (OSError, ValueError):
        return None
    if retry_failed and row.get("outcome") in ("failed", "crashed", "timeout"):
        return None
    return row


# ---- running: locally or on a Dask cluster -------------------------------------------------------


def _run_locally(todo, spec, jobs):
    # Threads are enough: each one only waits for its child process.
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=jobs or os.cpu_count() or 1) as pool:
        return dict(zip(todo, pool.map(lambda p: _repair_file_or_row(p, spec), todo)))


def _run_on_cluster(todo, spec, client):
    from distributed import as_completed

    futures = {client.submit(repair_file, path, spec, pure=False): path for path in todo}
    rows = {}
    for future in as_completed(futures):
        path = futures[future]
        try:
            rows[path] = future.result()
        except Exception as error:  # the worker itself died, again and again (KilledWorker)
            lost = type(error).__name__ == "KilledWorker"
            rows[path] = _failure_row(path, spec, "crashed" if lost else "failed",
                                      ("worker lost: " if lost else "") + repr(error))
    return rows


def _repair_file_or_row(path, spec):
    try:
        return repair_file(path, spec)
    except Exception as error:  # e.g. out_dir became unwritable: this file fails, not the batch
        return _failure_row(path, spec, "failed", repr(error))


def _failure_row(path, spec, outcome, note):
    row = _row(path, outcome, -1, 0.0, {}, note[:300])
    try:
        _save_json(_done_marker(path, spec["out_dir"]), row)
    except OSError:
        pass
    return row


# ---- one file: the supervising task ----------------------------------------------------------------


def repair_file(path, spec):
    """Repairs one file in a child process and returns its summary row; leaves the row in
    ``out_dir`` as the resume marker. Runs on a Dask worker or a local thread."""
    out_dir = spec["out_dir"]
    name = os.path.basename(path)
    outcome, note = _not_run_reason(path)
    if outcome:
        row = _row(path, outcome, 2 if outcome == "failed" else -1, 0.0, {}, note)
        _save_json(_done_marker(path, out_dir), row)
        return row
    summary = os.path.join(out_dir, "." + name + ".summary.json")
    child = dict(options=spec["options"], input=path, output=os.path.join(out_dir, name),
                 summary=summary, report=os.path.join(out_dir, name + ".report.json"),
                 memory_limit=spec["memory_limit"])
    start = time.monotonic()
    status, outcome = _run_child(child, os.path.join(out_dir, name + ".log"), spec)
    seconds = time.monotonic() - start
    figures = _read_and_remove(summary)
    note = {_EXIT_OUT_OF_MEMORY: "out of memory", _EXIT_ERROR: "internal error (see the log)"}
    row = _row(path, outcome, status, seconds, figures, note.get(status, ""))
    _save_json(_done_marker(path, out_dir), row)
    return row


def _not_run_reason(path):
    """The CLI's rules: other extensions and folders are skipped, broken links and special
    files fail, without running."""
    if os.path.isdir(path):
        return "skipped", "a folder"
    if not path.lower().endswith(MESH_EXTENSIONS):
        return "skipped", "not a mesh file (.off .obj .stl .ply)"
    if not os.path.exists(path):
        return "failed", "a dangling link" if os.path.islink(path) else "no such file"
    if not os.path.isfile(path):
        return "failed", "not a regular file"
    return "", ""


def _run_child(child, log_path, spec):
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [package_parent, env.get("PYTHONPATH")]))
    command = [spec["python"] or sys.executable, "-m", "mesh_repair.batch", "--child",
               json.dumps(child)]
    with open(log_path, "wb") as log:
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=env,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            code = process.wait(timeout=spec["timeout"])
        except subprocess.TimeoutExpired:
            _kill_session(process)
            return -1, "timeout"
        except BaseException:  # the task was cancelled: never leave the child running
            _kill_session(process)
            raise
    if code < 0:
        return -1, "crashed"
    return code, _OUTCOME_OF_STATUS.get(code, "failed")


def _kill_session(process):
    """Kills the child and whatever it started (its own session, so nothing else)."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    process.wait()


def _row(path, outcome, status, seconds, figures, note):
    row = {"file": os.path.basename(path), "outcome": outcome, "exit_status": status,
           "seconds": seconds}
    for key in FIGURE_KEYS:
        row[key] = figures.get(key)
    row["note"] = note
    return row


# ---- files -------------------------------------------------------------------------------------------


def _save_json(path, value):
    temporary = os.path.join(os.path.dirname(path), f".tmp-{os.getpid()}-{os.path.basename(path)}")
    with open(temporary, "w") as f:
        json.dump(value, f)
    os.replace(temporary, path)


def _read_and_remove(path):
    try:
        with open(path) as f:
            figures = json.load(f)
        os.remove(path)
        return figures
    except (OSError, ValueError):
        return {}


def _text(value):
    """A value as the CLI prints it: integers and 0/1 flags as such, seconds as %g."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, float):
        return format(value, "g")
    return str(value)


def _json_value(value):
    """A figure as the CLI's summary.jsonl has it: numbers bare, text quoted, missing null."""
    if isinstance(value, str):
        return json.dumps(value)
    return _text(value) or "null"


def _write_summaries(out_dir, rows):
    columns = ["file", "outcome", "exit_status", "seconds", *FIGURE_KEYS, "note"]
    csv = [",".join(columns)]
    jsonl = []
    for row in rows:
        # The CLI writes unquoted CSV; a note (an exception's text) must not add columns.
        cells = [_text(row[c]) for c in columns]
        cells[-1] = cells[-1].replace(",", ";").replace("\n", " ")
        csv.append(",".join(cells))
        fields = [f'"file":{json.dumps(row["file"])}', f'"outcome":"{row["outcome"]}"',
                  f'"exit_status":{row["exit_status"]}', f'"seconds":{_text(row["seconds"])}']
        fields += [f'"{k}":{_json_value(row[k])}' for k in FIGURE_KEYS]
        fields.append(f'"note":{json.dumps(row["note"])}')
        jsonl.append("{" + ",".join(fields) + "}")
    for name, lines in (("summary.csv", csv), ("summary.jsonl", jsonl)):
        temporary = os.path.join(out_dir, f".tmp-{os.getpid()}-{name}")
        with open(temporary, "w") as f:
            f.write("\n".join(lines) + "\n")
        os.replace(temporary, os.path.join(out_dir, name))


# ---- the child process -----------------------------------------------------------------------------


def _figures(report, status, seconds):
    """The CLI's per-file figures (Mesh_repair/cli/cmd_repair.cpp, write_summary)."""
    r, before = report["repair"], report["defects_before"]
    only_holes = (before["border_cycles"] > 0 and r["self_intersections_checked"]
                  and r["self_intersections_input"] == 0
                  and all(before[k] == 0 for k in (
                      "non_manifold_edges", "non_manifold_vertices", "duplicated_faces",
                      "inconsistent_orientation", "degenerate_faces", "needles", "caps",
                      "small_gaps", "t_junctions", "overlaps")))
    return {
        "status": status, "repair_status": r["status"], "faces_before": r["input_faces"], "faces_after": r["output_faces"],
        "holes": len(r["holes"]), "holes_filled": r["holes_filled"],
        "holes_failed": r["holes_failed"], "holes_too_large": r["holes_too_large"],
        "sheet_borders_left_open": r["sheet_borders_left_open"],
        "border_cycles_after": r["border_cycles_left"], "closed": int(r["closed"]),
        "valid": int(r["valid"]), "manifold": int(r["manifold"]),
        "self_intersections_before": r["self_intersections_input"],
        "self_intersections_after": r["self_intersections_output"],
        "only_holes_before": int(only_holes), "seconds": seconds,
    }


def _child_main(child):
    """Repairs one file; exits like the CLI (0, 1, 2, 3), 4 when out of memory."""
    import numpy  # noqa: F401 - imported before the memory limit, which is for the repair

    import mesh_repair

    if child.get("memory_limit"):
        import resource

        limit = int(child["memory_limit"])
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    start = time.monotonic()
    parent = os.getppid()

    def stop_when_orphaned(step, fraction):
        # The supervisor died with its Dask worker, and Dask runs the file elsewhere.
        if os.getppid() != parent:
            raise SystemExit(_EXIT_ERROR)

    try:
        result = mesh_repair.repair(child["input"], progress=stop_when_orphaned,
                                    **child["options"])
        mesh_repair.write(child["output"], result.vertices, result.faces)
    except ValueError as error:
        print(f"mesh_repair: {error}", file=sys.stderr)
        return 2
    except MemoryError:
        print("mesh_repair: out of memory", file=sys.stderr)
        return _EXIT_OUT_OF_MEMORY
    except RuntimeError as error:
        # Under the address-space limit a thread's stack is memory too: TBB's pool cannot start.
        if "pthread_create" not in str(error):
            raise
        print(f"mesh_repair: out of memory ({error})", file=sys.stderr)
        return _EXIT_OUT_OF_MEMORY
    seconds = time.monotonic() - start
    report = result.report
    report["output"], report["seconds"] = child["output"], seconds
    status = _EXIT_OF_REPAIR_STATUS[report["repair"]["status"]]
    _save_json(child["report"], report)
    _save_json(child["summary"], _figures(report, status, seconds))
    print(f"{child['input']}: {report['repair']['output_faces']} faces, "
          f"{report['repair']['status']}, {seconds:.3g} s")
    return status


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--child":
        try:
            sys.exit(_child_main(json.loads(sys.argv[2])))
        except SystemExit:
            raise
        except BaseException as error:  # noqa: B902 - any other failure is "failed", logged
            import traceback

            traceback.print_exc()
            sys.exit(_EXIT_ERROR)
    print("usage: python -m mesh_repair.batch --child SPEC (used by repair_many)", file=sys.stderr)
    sys.exit(2)
