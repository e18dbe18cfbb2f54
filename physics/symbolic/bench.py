"""Typical physics checks (answer, expected, context), for benchmarks and as test fixtures."""

from __future__ import annotations

import sympy

from physics.dimensions import DIMENSIONLESS, Dimension
from physics.symbolic.domain import LimitCase, SymbolicContext, SymbolSpec, make_symbol

KG = Dimension({"mass": 1})
METRE = Dimension({"length": 1})
ACCELERATION = Dimension({"length": 1, "time": -2})
ENERGY = Dimension({"mass": 1, "length": 2, "time": -2})

BenchCase = tuple[sympy.Expr, sympy.Expr, SymbolicContext]


def _context(*specs: SymbolSpec) -> tuple[dict[str, sympy.Symbol], SymbolicContext]:
    table = {spec.name: make_symbol(spec) for spec in specs}
    return table, SymbolicContext({table[spec.name]: spec for spec in specs})


def wedge_context() -> tuple[dict[str, sympy.Symbol], SymbolicContext]:
    """Block m on a frictionless wedge M of angle theta (0, pi/2) on a frictionless floor."""
    table, context = _context(
        SymbolSpec("m", KG),
        SymbolSpec("M", KG),
        SymbolSpec("g", ACCELERATION),
        SymbolSpec("theta", DIMENSIONLESS, low=sympy.Integer(0), high=sympy.pi / 2),
    )
    immovable = LimitCase({table["M"]: sympy.oo}, "an immovable wedge (M → ∞)")
    return table, SymbolicContext(context.symbols, limits=(immovable,))


def lennard_jones_context() -> tuple[dict[str, sympy.Symbol], SymbolicContext]:
    return _context(
        SymbolSpec("U0", ENERGY), SymbolSpec("r0", METRE), SymbolSpec("r", METRE), SymbolSpec("m", KG)
    )


def bench_equivalence_cases() -> list[BenchCase]:
    """About ten (answer, expected, context) triples; most are correct, as in real use."""
    w, wedge = wedge_context()
    m, M, g, th = w["m"], w["M"], w["g"], w["theta"]
    s, c, t = sympy.sin(th), sympy.cos(th), sympy.tan(th)
    wedge_a = -m * g * s * c / (M + m * s**2)
    relative = (M + m) * g * s / (M + m * s**2)
    normal = M * m * g * c / (M + m * s**2)
    lj, lennard = lennard_jones_context()
    u0, r0, r, mass = lj["U0"], lj["r0"], lj["r"], lj["m"]
    force = 12 * u0 / r * ((r0 / r) ** 12 - (r0 / r) ** 6)
    omega = sympy.sqrt(72 * u0 / (r0**2) / (mass / 2))
    return [
        (-m * g * t / (M * (1 + t**2) + m * t**2), wedge_a, wedge),
        (-(m * g * sympy.sin(2 * th) / 2) / (M + m * (1 - c**2)), wedge_a, wedge),
        (m * g * s * c / (M + m * s**2), wedge_a, wedge),
        ((M + m) * g * s / (M + m - m * c**2), relative, wedge),
        ((M + m) * g * s / (M + m), relative, wedge),
        (M * m * g / (M / c + m * s * t), normal, wedge),
        (m * g * c, normal, wedge),
        (12 * u0 * (r0**12 / r**13 - r0**6 / r**7), force, lennard),
        (12 * u0 * r0**6 * (r0**6 - r**6) / r**13, force, lennard),
        (12 * sympy.sqrt(u0 / mass) / r0, omega, lennard),
    ]
