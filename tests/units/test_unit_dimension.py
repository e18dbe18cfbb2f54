"""`unit_dimension` for symbol declarations, and the catalogue's spelling table."""

from __future__ import annotations

import pytest

from physics.dimensions import Dimension
from physics.errors import SpecError
from physics.units import unit_dimension
from physics.units.catalogue import CATALOGUE
from physics.units.registry import lookup, spelling_table

DECLARATIONS = [
    ("kg", Dimension({"mass": 1})),
    ("m/s^2", Dimension({"length": 1, "time": -2})),
    ("J", Dimension({"mass": 1, "length": 2, "time": -2})),
    ("1", Dimension()),
    ("N/m", Dimension({"mass": 1, "time": -2})),
]


@pytest.mark.parametrize(("text", "dimension"), DECLARATIONS, ids=[c[0] for c in DECLARATIONS])
def test_declared_unit_has_dimension(text: str, dimension: Dimension) -> None:
    assert unit_dimension(text) == dimension


@pytest.mark.parametrize("text", ["smoot", "m/", "", "2 m"])
def test_bad_declaration_is_a_spec_error(text: str) -> None:
    with pytest.raises(SpecError) as caught:
        unit_dimension(text)
    assert caught.value.path == ("dimension",)


@pytest.mark.parametrize("entry", CATALOGUE, ids=[e.name for e in CATALOGUE])
def test_every_catalogue_unit_is_reachable_by_its_name(entry: object) -> None:
    name = getattr(entry, "name")
    atom = lookup(name)
    assert atom is not None
    assert atom.name == name


def test_pint_only_units_are_not_accepted() -> None:
    # pint knows these, but the contract's reading does not include them.
    for spelling in ("number_meter", "a", "t", "Ki", "Kim", "julian_year"):
        assert spelling not in spelling_table()


def test_spelling_table_stays_small_enough_to_build_quickly() -> None:
    assert 1000 < len(spelling_table()) < 10_000
