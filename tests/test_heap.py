"""A start pauses the cyclic garbage collector while its modules load; what is loaded is frozen, and
every process collects garbage again from then on (a worker that never did would grow without bound)."""

from __future__ import annotations

import gc
import subprocess
import sys

from app.grading import forkserver
from app.grading.processes import WorkerPool


def test_freezing_what_is_loaded_resumes_collection_after_a_start_paused_it() -> None:
    script = (
        "import gc; from app.heap import freeze_long_lived, pause_collection\n"
        "pause_collection(); assert not gc.isenabled()\n"
        "freeze_long_lived(); assert gc.isenabled() and gc.get_freeze_count() > 0\n"
    )
    subprocess.run([sys.executable, "-c", script], check=True)


def test_a_grading_worker_forked_from_the_fork_server_collects_garbage() -> None:
    pool = WorkerPool("test", forkserver.context(), workers=1, max_tasks=100)
    pool.start()
    try:
        assert pool.schedule(gc.isenabled, (), 30).result(timeout=60) is True
        assert pool.schedule(gc.get_freeze_count, (), 30).result(timeout=60) > 0  # the checker, frozen
    finally:
        pool.close()
