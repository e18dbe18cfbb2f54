"""Typical physics answers for the parser micro-benchmark (`bench/` times parse_math on these)."""

from __future__ import annotations

import sympy


def _symbols(*names: str) -> dict[str, sympy.Symbol]:
    return {name: sympy.Symbol(name, positive=True) for name in names}


def bench_cases() -> list[tuple[str, dict[str, sympy.Symbol]]]:
    """About ten answer strings, each with the declared names it may use."""
    wedge = _symbols("m", "M", "theta", "g")
    return [
        ("-m g sin(θ)cos(θ)/(M + m sin^2 θ)", wedge),
        ("(M + m) g sin(theta) / (M + m*sin(theta)**2)", wedge),
        ("m g M cos θ/(M + m sin²θ)", wedge),
        ("g/(1 + k^2/r^2)", _symbols("m", "r", "k", "g")),
        ("m g k²/(r² + k²)", _symbols("m", "r", "k", "g")),
        ("sqrt(72 U0/(m r0^2))", _symbols("U0", "r0", "r", "m")),
        ("12 U0/r0 * ((r0/r)^13 - (r0/r)^7)", _symbols("U0", "r0", "r", "m")),
        ("(m + M)/m * sqrt(2 g L (1 - cos(theta)))", _symbols("m", "M", "L", "theta", "g")),
        ("M/(m + M)", _symbols("m", "M", "L", "theta", "g")),
        ("g (sin α - μ cos α)", _symbols("alpha", "mu", "g", "m")),
        ("tan(alpha)", _symbols("alpha", "mu", "g", "m")),
        ("1/2 m v_0^2 + m g h", _symbols("m", "v_0", "g", "h")),
    ]
