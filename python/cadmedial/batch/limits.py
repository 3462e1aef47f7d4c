"""Runs one command in its own process under a wall-time and an address-space limit, and says how
it ended: the exit status or signal, whether the timeout killed it, its peak memory."""

import ctypes
import ctypes.util
import os
import resource
import signal
import subprocess
import threading
import time
from typing import NamedTuple, Optional, Sequence


class Outcome(NamedTuple):
    returncode: Optional[int]  # exit status; None when a signal ended the process
    signal: Optional[int]      # the signal that ended it, if any (SIGKILL after a timeout)
    timed_out: bool
    seconds: float             # wall time
    peak_rss_mb: float         # the process's own peak resident set (wait4), children excluded
    stderr: str                # its last 4 KiB of stderr


_STDERR_TAIL = 4096


try:
    _libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
except OSError:  # not glibc: no parent-death signal, the rest works
    _libc = None
_PR_SET_PDEATHSIG = 1


def _child_setup(memory_bytes):
    # Runs in the child between fork and exec. RLIMIT_AS bounds what malloc (and so new) can get:
    # past it the engine sees bad_alloc and says "out of memory" instead of the whole machine
    # swapping or the kernel's OOM killer picking a victim among other people's processes.
    parent = os.getpid()

    def apply():
        if memory_bytes:
            resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
        # A worker killed mid-part (a node lost, `kill -9`) takes its part with it instead of
        # leaving it running unlimited in time; Dask runs the part again elsewhere. The signal is
        # tied to the thread that forks, which is the task's thread and outlives the child.
        if _libc is not None:
            _libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
            if os.getppid() != parent:  # the worker died before prctl took effect
                os._exit(137)
    return apply


def run_limited(argv: Sequence[str], timeout: Optional[float] = None, memory_bytes: Optional[int] = None,
                cwd: Optional[str] = None, env=None, stderr_path: Optional[str] = None) -> Outcome:
    """Runs argv (stdout discarded, stderr kept in stderr_path or a temporary file) and waits at
    most ``timeout`` seconds; then kills its whole process group (a FreeCAD child may have its
    own children). Raises OSError only when the program cannot be started."""
    import tempfile
    owned = stderr_path is None
    if owned:
        fd, stderr_path = tempfile.mkstemp(prefix="cadmedial-stderr-")
        os.close(fd)
    start = time.monotonic()
    try:
        with open(stderr_path, "wb") as err:
            proc = subprocess.Popen(list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                    stderr=err, cwd=cwd, env=env, start_new_session=True,
                                    preexec_fn=_child_setup(memory_bytes))
        status = {}

        # os.wait4 gives this child's own rusage (its peak RSS); Popen.wait would not. It blocks, so
        # it runs in a thread and the timeout is the join's: no polling delay on each part.
        def reap():
            _, code, usage = os.wait4(proc.pid, 0)
            status["code"], status["usage"] = code, usage

        waiter = threading.Thread(target=reap, daemon=True)
        waiter.start()
        waiter.join(timeout)
        timed_out = waiter.is_alive()
        if timed_out:
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            waiter.join()
        seconds = time.monotonic() - start
        proc.returncode = 0  # reaped by wait4 above; keeps Popen from waiting again or warning
        code = status["code"]
        with open(stderr_path, "rb") as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - _STDERR_TAIL))
            tail = f.read().decode("utf-8", errors="replace")
    finally:
        if owned:
            os.unlink(stderr_path)
    # ru_maxrss is in KiB on Linux.
    peak = status["usage"].ru_maxrss / 1024.0
    if os.WIFSIGNALED(code):
        return Outcome(None, os.WTERMSIG(code), timed_out, seconds, peak, tail)
    return Outcome(os.WEXITSTATUS(code), None, timed_out, seconds, peak, tail)
