"""How a call behaves as a Python citizen: it releases the GIL, passes progress lines to a
callback, passes the callback's exception on, and runs safely from several threads."""
import threading
import time

import pytest

import superpack


def long_call(progress=None):
    """About a second: 64 spheres grown to jamming and certified."""
    return superpack.md("1", 64, "0.05", progress=progress)


def test_a_long_call_releases_the_gil():
    done = threading.Event()
    worker = threading.Thread(target=lambda: (long_call(), done.set()))
    started = time.monotonic()
    worker.start()
    longest_pause, last = 0.0, time.monotonic()
    while not done.is_set():
        now = time.monotonic()
        longest_pause, last = max(longest_pause, now - last), now
    worker.join()
    duration = time.monotonic() - started
    # Holding the GIL, the call would stop this loop for its whole duration.
    assert duration > 0.3
    assert longest_pause < duration / 4


def test_progress_lines_reach_the_callback_in_order():
    lines = []
    long_call(progress=lines.append)
    assert lines[0].startswith("md: certifying the best lattice")
    assert any(line.startswith("md: 64 particles") for line in lines)
    assert lines[-1] == "md: proving the final packing"
    assert all("\n" not in line for line in lines)


def test_the_callbacks_exception_is_raised_after_the_call():
    calls = []

    def stop(line):
        calls.append(line)
        raise KeyboardInterrupt("stop")

    with pytest.raises(KeyboardInterrupt, match="stop"):
        superpack.best("2", progress=stop)
    assert len(calls) == 1  # no further line once it has raised
    assert superpack.best("2").phi.contains("0.869889189721015")  # and the next call runs normally


def test_calls_from_several_threads_each_get_their_own_answer():
    families = ["C0", "C1", "O1", "C0", "C1", "O1"]
    results = [None] * len(families)

    def work(index):
        results[index] = superpack.density(families[index], "1.25" if families[index] != "O1" else "0.6")

    threads = [threading.Thread(target=work, args=(index,)) for index in range(len(families))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for family, result in zip(families, results):
        assert result.family == family
    assert results[0].phi == results[3].phi and results[2].phi == results[5].phi
