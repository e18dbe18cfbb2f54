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

# The preload imports the checker, the workers' loop and app.cli (app/grading/preload.py says why).
PRELOAD = ["app.grading.preload"]


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
