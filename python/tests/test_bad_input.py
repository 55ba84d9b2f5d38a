"""Bad input is a ValueError with one line (the CLI's reason), never a crash; Ctrl-C cancels."""
import _thread
import signal
import threading
import time

import numpy as np
import pytest

import mesh_repair
from meshes import cube, icosphere, punch_holes, sphere_points


def message(call):
    with pytest.raises(ValueError) as error:
        call()
    text = str(error.value)
    assert "\n" not in text
    return text


def test_messages_name_the_problem(tmp_path):
    v, f = cube()
    nan = v.copy()
    nan[1, 2] = np.nan
    assert message(lambda: mesh_repair.check(nan, f)) == \
        "input arrays: vertex 1 has a non-finite coordinate (NaN or inf)"
    bad = f.copy()
    bad[3, 1] = 8
    assert message(lambda: mesh_repair.check(v, bad)) == \
        "input arrays: face 3 refers to vertex 8 but there are only 8 vertices"
    bad[3, 1] = -1
    assert "face 3 refers to vertex -1" in message(lambda: mesh_repair.check(v, bad))
    assert "shape (n, 3), got shape (8, 2)" in message(lambda: mesh_repair.check(v[:, :2], f))
    assert "shape (n, 3), got shape (24,)" in message(lambda: mesh_repair.check(v.ravel(), f))
    assert "got dtype float64" in message(lambda: mesh_repair.check(v, f.astype(float)))
    assert "got dtype complex128" in message(lambda: mesh_repair.check(v + 0j, f))
    assert "contains no faces" in message(lambda: mesh_repair.check(v, f[:0]))
    assert "contains no vertices" in message(lambda: mesh_repair.check(v[:0], f))
    assert "faces are missing" in message(lambda: mesh_repair.check(v))
    assert "not both" in message(lambda: mesh_repair.check("a.off", f))
    assert "continuity must be in [0, 2]" in message(lambda: mesh_repair.repair(v, f, continuity=5))
    assert "method expects one of" in message(lambda: mesh_repair.fill_holes(v, f, method="x"))
    assert "holds a non-integer" in message(lambda: mesh_repair.check(v, [[0, 1, "a"]]))
    huge = [list(range(8)) * 1251]  # 10008 corners: the readers' limit is 10000
    assert "exceeds the limit of 10000 vertices per face" in message(
        lambda: mesh_repair.check(v, huge))


def test_file_messages_are_the_cli_ones(tmp_path):
    missing = tmp_path / "missing.off"
    assert message(lambda: mesh_repair.read(missing)) == f"{missing}: no such file"
    text = tmp_path / "mesh.txt"
    text.write_text("hello")
    assert "unknown format 'txt'" in message(lambda: mesh_repair.check(str(text)))
    broken = tmp_path / "broken.off"
    broken.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    assert message(lambda: mesh_repair.check(str(broken))).startswith(f"{broken}:")
    nan = tmp_path / "nan.off"
    nan.write_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    assert message(lambda: mesh_repair.read(nan)) == \
        f"{nan}: line 4: non-finite vertex coordinate 'nan' (NaN or inf)"
    v, f = cube()
    assert "unknown output format" in message(lambda: mesh_repair.write(tmp_path / "a.xyz", v, f))
    assert not list(tmp_path.glob(".tmp-*"))


def test_smooth_and_bench_holes_reject_bad_arrays_as_every_operator():
    v, f = icosphere(1)
    nan = v.copy()
    nan[2, 0] = np.nan
    for call in (mesh_repair.smooth, mesh_repair.bench_holes):
        assert message(lambda: call(nan, f)) == \
            "input arrays: vertex 2 has a non-finite coordinate (NaN or inf)"
        assert "shape (n, 3), got shape (42, 2)" in message(lambda: call(v[:, :2], f))
        assert "got dtype float64" in message(lambda: call(v, f.astype(float)))
        assert "contains no faces" in message(lambda: call(v, f[:0]))
        assert "contains no vertices" in message(lambda: call(v[:0], f))
        assert "faces are missing" in message(lambda: call(v))
        with pytest.raises(TypeError):
            call(v, f, no_such_option=1)


def test_smooth_options_are_checked_with_the_cli_reasons():
    v, f = icosphere(1)
    assert "method must be mga, cg or cgal" in message(lambda: mesh_repair.smooth(v, f, method="x"))
    assert "triangles only" in message(lambda: mesh_repair.smooth(v, f, method="cgal", quads=True))
    assert "threads must be in [1, 1024]" in message(lambda: mesh_repair.smooth(v, f, threads=0))
    assert "generations must be in [1," in message(lambda: mesh_repair.smooth(v, f, generations=0))
    assert "iterations must be in [0," in message(lambda: mesh_repair.smooth(v, f, iterations=-1))
    assert "tangent_scale must be in [0, 1]" in message(
        lambda: mesh_repair.smooth(v, f, tangent_scale=1.5))
    assert "feature_angle expects a number" in message(
        lambda: mesh_repair.smooth(v, f, feature_angle="a"))
    assert "feature_angle must be in" in message(
        lambda: mesh_repair.smooth(v, f, feature_angle=float("nan")))


def test_mesh_points_rejects_bad_points(tmp_path):
    p = sphere_points(100)
    p[5, 1] = np.inf
    assert message(lambda: mesh_repair.mesh_points(p)) == \
        "input points: vertex 5 has a non-finite coordinate (NaN or inf)"
    assert message(lambda: mesh_repair.mesh_points(p[:, :2])) == \
        "points must be an array of shape (n, 3), got shape (100, 2)"
    assert "points must hold real numbers" in message(lambda: mesh_repair.mesh_points(p + 0j))
    assert "got shape (300,)" in message(lambda: mesh_repair.mesh_points(p.ravel()))
    assert "fewer than three points" in message(lambda: mesh_repair.mesh_points(p[:2]))
    assert "fewer than three points" in message(lambda: mesh_repair.mesh_points(np.zeros((0, 3))))
    assert "cannot be read as an array" in message(lambda: mesh_repair.mesh_points([[1, 2], [3]]))
    missing = tmp_path / "missing.xyz"
    assert message(lambda: mesh_repair.mesh_points(missing)) == f"{missing}: no such file"
    # A point file is read by the strict readers: its line and the reason.
    letters = tmp_path / "letters.xyz"
    letters.write_text("0 0 0\n1 0 0\n0 one 0\n")
    assert message(lambda: mesh_repair.mesh_points(letters)) == \
        f"{letters}: line 3: expected a number, found 'one'"
    # Points that span no surface: a one-line reason, not a crash.
    for flat in (np.zeros((10, 3)), np.c_[np.arange(10.0), np.zeros(10), np.zeros(10)]):
        assert "no triangle" in message(lambda: mesh_repair.mesh_points(flat))
    assert "iterations must be in [0," in message(
        lambda: mesh_repair.mesh_points(sphere_points(50), iterations=-1))
    assert "threads must be in [0, 1024]" in message(
        lambda: mesh_repair.mesh_points(sphere_points(50), threads=-1))
    with pytest.raises(TypeError):
        mesh_repair.mesh_points(sphere_points(50), no_smooth=True)


def test_bench_holes_options_are_checked_with_the_cli_reasons():
    v, f = icosphere(2)
    bench = mesh_repair.bench_holes
    assert "radius must be in (0, 0.5)" in message(lambda: bench(v, f, radius=0.5))
    assert "radius must be in (0, 0.5)" in message(lambda: bench(v, f, radius=[0.1, 0]))
    assert "radius needs at least one value" in message(lambda: bench(v, f, radius=[]))
    assert "holes must be in [1," in message(lambda: bench(v, f, holes=0))
    assert "seeds must be in [0," in message(lambda: bench(v, f, seeds=[1, -2]))
    assert "unknown method 'x'" in message(lambda: bench(v, f, methods="liepa,x"))
    assert "needs at least one method" in message(lambda: bench(v, f, methods=","))
    assert "shape expects disc, jagged, elongated or ring" in message(
        lambda: bench(v, f, shape="square"))


DTYPES = [np.float64, np.float32, np.int64, np.int32, np.uint8, np.bool_, np.complex128, object]


def random_array(rng, kind):
    """An array of random shape, dtype and values (mostly small ints or normal floats)."""
    ndim = rng.choice([1, 2, 2, 2, 3])
    rows = int(rng.integers(0, 7))
    cols = int(rng.choice([3, 3, 3, 1, 2, 4]))
    shape = {1: (rows * cols,), 2: (rows, cols), 3: (rows, cols, 2)}[ndim]
    dtype = DTYPES[int(rng.integers(len(DTYPES)))] if rng.random() < 0.3 else kind
    if dtype == np.float64:
        return rng.normal(size=shape) * 10.0 ** rng.integers(-3, 120)
    return rng.integers(-2, 9, size=shape).astype(dtype)


def mutated_cube(rng):
    """The cube with a few random faults: special coordinates, wrong indices, dtypes, shapes."""
    v, f = cube()
    v = v.astype(float)
    # Value faults first, while the arrays still have the cube's dtypes and shapes.
    for fault in sorted(int(rng.integers(6)) for _ in range(int(rng.integers(0, 3)))):
        if fault == 0:
            v[rng.integers(len(v)), rng.integers(3)] = rng.choice(
                [np.nan, np.inf, -np.inf, 1e300, -1e-300, 0.0])
        elif fault == 1:
            f[rng.integers(len(f)), rng.integers(3)] = rng.integers(-3, 12)
        elif fault == 2:
            v = v.astype(DTYPES[int(rng.integers(len(DTYPES)))])
        elif fault == 3:
            f = f.astype(DTYPES[int(rng.integers(len(DTYPES)))])
        elif fault == 4:
            v, f = v[: int(rng.integers(0, 9))], f[: int(rng.integers(0, 13))]
        elif f.ndim == 2:
            f = f[:, : int(rng.integers(1, 4))] if rng.random() < 0.5 else f.reshape(-1)
    return v, f


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # numpy's, on casting NaN to integers
def test_fuzz_random_arrays_never_crash():
    """3000 random (vertices, faces): a valid result or a one-line ValueError, nothing else."""
    rng = np.random.default_rng(2026)
    outcomes = {"ok": 0, "error": 0}
    for trial in range(3000):
        if rng.random() < 0.5:
            vertices, faces = mutated_cube(rng)
        else:
            vertices, faces = random_array(rng, np.float64), random_array(rng, np.int64)
        if rng.random() < 0.1:
            faces = [list(p) for p in np.atleast_2d(faces)][: int(rng.integers(0, 13))]
        try:
            if trial % 10 == 0:
                result = mesh_repair.repair(vertices, faces, self_intersections=False)
                assert result.vertices.dtype == np.float64 and result.vertices.shape[1] == 3
                if len(result.faces):
                    assert 0 <= result.faces.min() and result.faces.max() < len(result.vertices)
            else:
                mesh_repair.check(vertices, faces, self_intersections=False)
            outcomes["ok"] += 1
        except ValueError as error:
            assert "\n" not in str(error) and str(error)
            outcomes["error"] += 1
    assert outcomes["ok"] > 300 and outcomes["error"] > 1000, outcomes


def test_ctrl_c_raises_keyboard_interrupt_promptly_and_input_is_untouched():
    v, f = icosphere(7)  # 327,680 faces: repair takes seconds
    v, f = punch_holes(v, f, [[0, 0, 1], [0, 0, -1]], 0.2)
    v_before, f_before = v.copy(), f.copy()
    # interrupt_main does nothing where SIGINT is ignored, as in a background job of a
    # non-interactive shell: Python's own handler is put in place for this test.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.monotonic()
    finished = False
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            mesh_repair.repair(v, f)
            finished = True  # the repair ended before the interrupt: the test proves nothing
            time.sleep(5)
    finally:
        elapsed = time.monotonic() - start
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert not finished
    np.testing.assert_array_equal(v, v_before)
    np.testing.assert_array_equal(f, f_before)
    # Seen at the next progress point: the soup stage (CGAL, ~2 s here) has none; an
    # uncancelled repair of this mesh takes about 10 s on the loaded test machine.
    assert elapsed < 5.0
