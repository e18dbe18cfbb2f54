"""The cyclic garbage collector at start-up, and long-lived objects kept out of its full passes.

Importing the service makes hundreds of thousands of objects that live as long as the process and
almost no garbage (under a thousand objects of cycles), yet the collector's passes over them while the
modules load took a sixth of the CPU of `import app.main`: a start pauses it (`pause_collection`)
until what it loaded is frozen. A full collection walks every tracked object. After start-up a server
or worker holds millions that live as long as the process (sympy, the checker's tables, the bank's
compiled problems), and each full pass over them stalled every request in flight for tens of
milliseconds: the p99 of distinct checks under load (bench/targets.py) fell from over 200 ms to about
55 ms once they were frozen. What is made later is collected as usual.
"""

from __future__ import annotations

import gc


def pause_collection() -> None:
    """No cyclic collection until `freeze_long_lived` (call first thing in a process that is starting)."""
    gc.disable()


def freeze_long_lived() -> None:
    """Move every object alive now to the permanent generation (call once what is loaded will stay), and
    collect what is made from now on (after `pause_collection`: the garbage of loading, a few hundred
    objects, is frozen with the rest rather than paid for with a full pass)."""
    gc.freeze()
    gc.enable()
