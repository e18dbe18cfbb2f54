"""Model expressions are read by the whitelist parser: instructor text is never evaluated."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy

from physics.engine.text import read_expr
from physics.errors import SpecError

m, g, theta = sympy.symbols("m g theta", positive=True)
NAMES = {"m": m, "g": g, "theta": theta}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("m*g*sin(theta)", m * g * sympy.sin(theta)),
        ("-m g cos(θ)", -m * g * sympy.cos(theta)),
        (2, sympy.Integer(2)),
        (0.5, sympy.Rational(1, 2)),
    ],
)
def test_model_text_reads_as_the_expression(text, expected):
    assert read_expr(text, NAMES, ("model",)) == expected


@pytest.mark.parametrize("text", ["__import__('os').system('touch {marker}')", "m +", "h", True, None, [1]])
def test_model_text_that_is_not_an_expression_is_a_spec_error_with_its_path(text, tmp_path: Path):
    marker = tmp_path / "ran"
    source = text.format(marker=marker) if isinstance(text, str) else text
    with pytest.raises(SpecError) as raised:
        read_expr(source, NAMES, ("bodies", "m", "mass"))
    assert raised.value.path == ("bodies", "m", "mass")
    assert not marker.exists()
