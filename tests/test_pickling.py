"""Values pickled as their constructor's arguments come back whole, every field set away from its default."""

from __future__ import annotations

import dataclasses
import pickle

import pytest

from physics.checking import SymbolDecl
from physics.mathinput import InputLimits
from physics.pickling import pickled_by_fields
from problems.kinds.symbolic import SymbolicJob

LIMITS = InputLimits(
    max_length=11,
    max_tokens=12,
    max_depth=13,
    max_number_digits=14,
    max_exponent=15,
    max_int_bits=16,
    max_sci_exponent=17,
    max_factorial=18,
)
DECL = SymbolDecl("theta", "1", real=True, nonzero=True, negative=True, integer=True, range=("0", "pi/2"))
JOB = SymbolicJob("m g", "g*m", (DECL, SymbolDecl("m", "kg")), ("m > 0",), (("2*m*g", "twice"),), LIMITS)


@pytest.mark.parametrize("value", [LIMITS, DECL, JOB], ids=["limits", "symbol", "symbolic-job"])
def test_a_value_pickled_by_its_fields_comes_back_equal_field_by_field(value):
    for protocol in (2, pickle.HIGHEST_PROTOCOL):
        back = pickle.loads(pickle.dumps(value, protocol=protocol))
        assert type(back) is type(value)
        assert dataclasses.astuple(back) == dataclasses.astuple(value)
    fields = tuple(getattr(value, field.name) for field in dataclasses.fields(value))
    assert value.__reduce__() == (type(value), fields)  # its constructor's arguments, not a dict


def test_a_dataclass_whose_init_does_more_than_set_its_fields_is_refused():
    @dataclasses.dataclass(frozen=True)
    class Checked:
        x: int

        def __post_init__(self) -> None:
            pass

    with pytest.raises(TypeError):
        pickled_by_fields(Checked)
