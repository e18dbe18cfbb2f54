"""What the fork server imports before forking any worker: the checker, with its tables built.

Every lazily built table (the parser's, the unit registry, the sampler's) is touched once here by the
warm-up jobs, so workers inherit them on fork instead of each building them again.
"""

from __future__ import annotations

from app.heap import freeze_long_lived, pause_collection

pause_collection()  # until every worker's modules are loaded and frozen, below

import signal  # noqa: E402

# sympy imports this on the first comparison of two expressions (a range's bounds), not at import.
import sympy.assumptions.wrapper  # noqa: E402, F401

# app.cli: each worker runs the program's main script again when it starts, and the `physcheck` script
# imports app.cli (with the settings: a sixth of a CPU-second), so the fork server imports it once for
# them all, at start and at every replacement. ("__main__" would say so for any script, but Python
# 3.11's fork server never receives the main script's path.)
import app.cli  # noqa: E402

# Every grading worker's loop, which a worker would otherwise import as it starts.
import app.grading.processes  # noqa: E402, F401
from app.grading.worker import grade, warm_up_jobs  # noqa: E402

# A SIGTERM to the whole process group (systemd's default, a terminal's job control) is the server's to
# act on: it kills its workers itself as it shuts down, and the fork server exits when the server's end
# of its pipe closes. Dying of it first, they left the server logging each worker's death and failing
# to start replacements while it shut down. Workers inherit this; the pools kill them with SIGKILL.
signal.signal(signal.SIGTERM, signal.SIG_IGN)
for _job in warm_up_jobs():
    grade(_job)
freeze_long_lived()  # before any fork: every worker inherits the checker frozen, and collects again
