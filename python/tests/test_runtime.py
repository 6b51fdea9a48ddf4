"""Threads from Python, progress, Ctrl-C."""

import io
import os
import signal
import subprocess
import sys
import textwrap
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import ridt
from conftest import triangle_set


def test_concurrent_calls_from_a_thread_pool():
    # Calls run at the same time (the GIL is released) and each gets its own exact answer.
    sets = [np.random.default_rng(s).random((20000, 2)) for s in range(8)]
    want = [triangle_set(ridt.Delaunay(p).simplices) for p in sets]
    with ThreadPoolExecutor(max_workers=4) as pool:
        got = list(pool.map(lambda p: ridt.Delaunay(p, threads=2), sets))
        found = list(pool.map(lambda d: d.find_simplex(d.points), got))
    for w, g, f in zip(want, got, found):
        assert triangle_set(g.simplices) == w
        assert (f >= 0).all()


@pytest.mark.skipif(not hasattr(os, "fork"), reason="no fork() on this platform")
def test_threads_after_fork():
    # The library keeps its threads parked between calls; a forked child (multiprocessing's
    # default start on Linux) has none of them, and must triangulate on threads of its own.
    pts = np.random.default_rng(5).random((200_000, 2))
    want = triangle_set(ridt.Delaunay(pts, threads=2).simplices)
    pid = os.fork()
    if pid == 0:  # the child: its answer is its exit status; a hang is ended by the alarm
        signal.alarm(120)
        try:
            ok = triangle_set(ridt.Delaunay(pts, threads=2).simplices) == want
        except BaseException:
            ok = False
        os._exit(0 if ok else 1)
    _, status = os.waitpid(pid, 0)
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0


def test_gil_is_released_while_triangulating():
    # A Python thread keeps counting while the main thread is inside the library.
    pts = np.random.default_rng(1).random((1_500_000, 2))
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1

    t = threading.Thread(target=count)
    t.start()
    try:
        before = ticks
        ridt.triangulate(pts)
        during = ticks - before
    finally:
        done.set()
        t.join()
    assert during > 1000


def test_progress_callable_and_bar():
    pts = np.random.default_rng(2).random((300_000, 2))
    shares = []
    ridt.Delaunay(pts, progress=shares.append)
    assert shares and shares == sorted(shares) and shares[-1] == 1.0 and len(shares) >= 4

    from tqdm import tqdm
    with tqdm(file=io.StringIO()) as bar:
        ridt.Delaunay(pts, threads=2, progress=bar)
        assert bar.total == len(pts) and bar.n == len(pts)


def test_an_exception_in_progress_abandons_the_run():
    pts = np.random.default_rng(3).random((300_000, 2))

    class Stop(Exception):
        pass

    def stop(share):
        if share > 0.3:
            raise Stop("enough")

    for method, threads in [("serial", 1), ("partition", 2), ("optimistic", 2)]:
        with pytest.raises(Stop, match="enough"):
            ridt.triangulate(pts, method=method, threads=threads, progress=stop)
    # And the library works as before afterwards.
    assert ridt.check(pts, ridt.triangulate(pts).triangles)[0]


def test_ctrl_c_stops_a_long_run():
    # A child process triangulates a large set; SIGINT must end it with KeyboardInterrupt well
    # before the run would have finished.
    code = textwrap.dedent("""
        import signal, sys, time, numpy as np, ridt
        # Python leaves SIGINT ignored when it starts with it ignored (as a shell's background
        # job does): Ctrl-C's handler, as in an interactive session.
        signal.signal(signal.SIGINT, signal.default_int_handler)
        pts = np.random.default_rng(0).random((6_000_000, 2))
        print("ready", flush=True)
        start = time.monotonic()
        try:
            ridt.triangulate(pts, method="serial")
            print("finished", flush=True)
        except KeyboardInterrupt:
            print(f"interrupted {time.monotonic() - start:.3f}", flush=True)
    """)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True, env=env)
    assert child.stdout.readline().strip() == "ready"
    threading.Timer(0.5, child.send_signal, args=(signal.SIGINT,)).start()
    out, _ = child.communicate(timeout=120)
    assert out.startswith("interrupted"), out


def test_the_process_limits_on_memory_are_room_too():
    # Under ulimit -v (as batch systems set it) the room is what the limit leaves of what the
    # process maps already: a run that would not fit is refused before it starts, with the
    # numbers, rather than running out part way; the quality mesher stops with its warning and a
    # valid mesh, wherever the limit falls.
    code = textwrap.dedent("""
        import resource, warnings, numpy as np, ridt
        pts = np.random.default_rng(0).random((4_000_000, 2))
        before = ridt.available_memory() >> 20
        size = int(open("/proc/self/statm").read().split()[0]) * resource.getpagesize()
        resource.setrlimit(resource.RLIMIT_AS, (size + (200 << 20), resource.getrlimit(resource.RLIMIT_AS)[1]))
        print("room", ridt.available_memory() >> 20, before, flush=True)
        try:
            ridt.triangulate(pts)
            print("ran", flush=True)
        except MemoryError as e:
            print("refused", "needs about" in str(e) and "is available" in str(e), flush=True)
        for extra in (200, 300, 450):  # (where the limit falls among the mesh's growths varies)
            size = int(open("/proc/self/statm").read().split()[0]) * resource.getpagesize()
            resource.setrlimit(resource.RLIMIT_AS, (size + (extra << 20), resource.getrlimit(resource.RLIMIT_AS)[1]))
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                m = ridt.ConstrainedDelaunay([(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 1), (1, 2), (2, 3), (3, 0)],
                                             max_area=1e-12)
            print("mesh", len(m.simplices) > 100000, m.check()[0], [str(w.message) for w in caught], flush=True)
            del m
    """)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
    lines = out.stdout.splitlines()
    assert out.returncode == 0, out.stderr
    room, before = map(int, lines[0].split()[1:])
    assert room <= 200 and (room >= 150 or before < 300), lines  # the limit's room, or less where less is free
    assert lines[1] == "refused True", lines
    assert len(lines) == 5, lines
    for line in lines[2:]:  # a valid mesh, cut short with the warning, never a MemoryError
        assert line.startswith("mesh True True") and "the memory left holds no more" in line, lines


def test_memory_is_planned_before_the_run():
    import ridt
    pts = np.random.default_rng(1).random((50000, 2))
    need = ridt.estimate_memory(50000, locate="dag")
    with pytest.raises(MemoryError, match="needs about .* is available"):
        ridt.triangulate(pts, locate="dag", memory_limit=need - 1)
    t = ridt.triangulate(pts, locate="dag", memory_limit=need)
    assert t.stats["memory_estimate"] == need
    assert ridt.estimate_memory(10**6) < ridt.estimate_memory(10**6, locate="dag")
    assert ridt.available_memory() > 0
    with pytest.raises(ValueError):
        ridt.triangulate(pts, memory_limit=0)
