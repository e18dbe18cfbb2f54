"""What the fork server imports before forking any worker: the checker, with its tables built.

Every lazily built table (the parser's, the unit registry, the sampler's) is touched once here by the
warm-up jobs, so workers inherit them on fork instead of each building them again.
"""

from __future__ import annotations

from app.grading.worker import grade, warm_up_jobs
from app.heap import freeze_long_lived

for _job in warm_up_jobs():
    grade(_job)
freeze_long_lived()  # before any fork: every worker inherits the checker frozen
