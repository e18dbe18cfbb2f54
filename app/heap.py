"""Long-lived objects kept out of the cyclic garbage collector's full passes.

A full collection walks every tracked object. After start-up a server or worker holds millions that
live as long as the process (sympy, the checker's tables, the bank's compiled problems), and each full
pass over them stalled every request in flight for tens of milliseconds: the p99 of distinct checks
under load (bench/targets.py) fell from over 200 ms to about 55 ms once they were frozen. What is made
later is collected as usual.
"""

from __future__ import annotations

import gc


def freeze_long_lived() -> None:
    """Move every object alive now to the permanent generation (call once what is loaded will stay)."""
    gc.freeze()
