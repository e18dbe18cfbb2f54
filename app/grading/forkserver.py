"""The one fork server every worker process (grading, upload vetting) is forked from.

It imports the checker and builds its lazily made tables once (`PRELOAD`), so each worker starts warm
in milliseconds. `physcheck serve` starts it first thing, so that its imports run beside the server's own
instead of after them (a restart is ready sooner); a pool started without it starts it itself.
"""

from __future__ import annotations

import multiprocessing
import multiprocessing.context
import os
from multiprocessing import forkserver

# app.cli: each worker runs the program's main script again when it starts, and the `physcheck` script
# imports app.cli (with the settings: a sixth of a CPU-second), so the fork server imports it once for
# them all, at start and at every replacement. ("__main__" would say so for any script, but Python
# 3.11's fork server never receives the main script's path.)
# app.grading.processes: every grading worker's loop, which a worker would otherwise import as it starts.
PRELOAD = ["app.cli", "app.grading.preload", "app.grading.processes"]


def context() -> multiprocessing.context.ForkServerContext:
    """The forkserver context with the checker preloaded (set before the server first starts)."""
    found = multiprocessing.get_context("forkserver")
    assert isinstance(found, multiprocessing.context.ForkServerContext)
    found.set_forkserver_preload(PRELOAD)
    # The fork server runs as `python -c`, which puts the current directory first on sys.path: started
    # from a directory holding an `app`, `physics` or `problems` folder (another checkout, another
    # project), every worker imported that instead of this program, or did not start. Python 3.11's
    # fork server ignores the parent's sys.path, so it is told by the environment it inherits.
    os.environ["PYTHONSAFEPATH"] = "1"
    return found


def start_early() -> None:
    """Start the fork server now, in the background: it loads the checker while the caller goes on."""
    context()
    forkserver.ensure_running()
