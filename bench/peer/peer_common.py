"""What the peer benchmarks' drivers share (standard library only): each run in its own subprocess with its own
wall time and peak memory, and the interpreter that runs GetFEM."""
import os
import subprocess
import sys
import time


def measured_run(cmd, log_path, cwd):
    """Run cmd with stdout+stderr to log_path; return (exit code, wall seconds, the process's peak RSS MB)."""
    t0 = time.perf_counter()
    with open(log_path, "w") as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, cwd=cwd)
        _, status, usage = os.wait4(proc.pid, 0)  # this child's own rusage, not all children's
    return os.waitstatus_to_exitcode(status), time.perf_counter() - t0, usage.ru_maxrss / 1024.0  # kB on Linux


def getfem_python(explicit, modules="getfem, numpy"):
    """An interpreter that imports `modules`: --python, this one, or Debian's."""
    for cand in [explicit] if explicit else [sys.executable, "/usr/bin/python3"]:
        if cand and subprocess.run([cand, "-c", f"import {modules}"], capture_output=True).returncode == 0:
            return cand
    return None
