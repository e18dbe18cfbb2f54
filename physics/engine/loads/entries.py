"""The kinds of entry of the model's `forces:` section, each read by its load's module: the key an entry
gives (`{body: block, drag: b}`) chooses the reader. A new kind is its module and one line here."""

from __future__ import annotations

from collections.abc import Callable

from physics.engine.loads import Entry, ForceEntryLoad, applied, torque

__all__ = ["READERS", "Entry"]

Reader = Callable[[str, Entry], ForceEntryLoad | None]

READERS: dict[str, Reader] = {
    **{kind.value: applied.read for kind in applied.ForceKind},
    torque.KEY: torque.read,
}
