"""The one fork server every worker process (grading, upload vetting) is forked from.

It imports the checker and builds its lazily made tables once (`PRELOAD`), so each worker starts warm
in milliseconds. `physcheck serve` starts it first thing, so that its imports run beside the server's own
instead of after them (a restart is ready sooner); a pool started without it starts it itself.
"""

from __future__ import annotations

import multiprocessing
import multiprocessing.context
from multiprocessing import forkserver

PRELOAD = ["app.grading.preload"]


def context() -> multiprocessing.context.ForkServerContext:
    """The forkserver context with the checker preloaded (set before the server first starts)."""
    found = multiprocessing.get_context("forkserver")
    assert isinstance(found, multiprocessing.context.ForkServerContext)
    found.set_forkserver_preload(PRELOAD)
    return found


def start_early() -> None:
    """Start the fork server now, in the background: it loads the checker while the caller goes on."""
    context()
    forkserver.ensure_running()
