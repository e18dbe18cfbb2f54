"""What the fork server imports before forking any worker: the checker, with its tables built.

Every lazily built table (the parser's, the unit registry, the sampler's) is touched once here by the
warm-up jobs, so workers inherit them on fork instead of each building them again.
"""

from __future__ import annotations

import signal

# sympy imports this on the first comparison of two expressions (a range's bounds), not at import.
import sympy.assumptions.wrapper  # noqa: F401

from app.grading.worker import grade, warm_up_jobs
from app.heap import freeze_long_lived

# A SIGTERM to the whole process group (systemd's default, a terminal's job control) is the server's to
# act on: it kills its workers itself as it shuts down, and the fork server exits when the server's end
# of its pipe closes. Dying of it first, they left the server logging each worker's death and failing
# to start replacements while it shut down. Workers inherit this; the pools kill them with SIGKILL.
signal.signal(signal.SIGTERM, signal.SIG_IGN)
for _job in warm_up_jobs():
    grade(_job)
freeze_long_lived()  # before any fork: every worker inherits the checker frozen
