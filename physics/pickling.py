"""Small values that cross into grading workers with every job, pickled as their constructor's arguments.

A dataclass pickles by default as its class and a dict of field names: twice the bytes, and a slower
read in the worker (where each job is unpickled before it is graded).
"""

from __future__ import annotations

import dataclasses
import operator
from typing import TypeVar

T = TypeVar("T")


def pickled_by_fields(cls: type[T]) -> type[T]:
    """Class decorator (below @dataclass): pickle as `cls(*field values)`. For dataclasses whose every
    field is an __init__ argument and whose __init__ does no work beyond setting them."""
    fields = dataclasses.fields(cls)  # type: ignore[arg-type]
    if not all(field.init for field in fields) or hasattr(cls, "__post_init__"):
        raise TypeError(f"{cls.__name__} is not made from its fields alone")
    names = tuple(field.name for field in fields)
    values = operator.attrgetter(*names)

    def __reduce__(self: T) -> tuple[type[T], tuple[object, ...]]:
        found = values(self)
        return cls, (found if len(names) > 1 else (found,))

    setattr(cls, "__reduce__", __reduce__)  # noqa: B010 - a method added to a class made elsewhere
    return cls
