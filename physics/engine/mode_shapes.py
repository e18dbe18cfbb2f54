"""The shape of a normal mode: the amplitude ratio of two coordinates when the system oscillates in mode n.

`mode_shape: {mode: n, ratio: [x2, x1]}` asks for the amplitude of x2 over that of x1 (signed: negative
when they move oppositely). Each method solves (K - omega_n^2 M) v = 0 with its own matrices (see
`modes`): Lagrange's linearized equations and the energy's second-order expansion in the coordinates,
Newton's Cartesian equations on the bodies' axes, whose mode is carried back to the coordinates through
the Jacobian of the positions at the equilibrium.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import sympy

from physics.engine import modes, tidy
from physics.engine.mechanics import solve_linear
from physics.engine.model import Coordinate, Model, Quantity, QuantityKind
from physics.engine.proof import domain_points
from physics.engine.quantity_table import derives
from physics.engine.text import Path
from physics.errors import DerivationError, SpecError, SpecErrors

if TYPE_CHECKING:
    from physics.engine.method import Method

CARTESIAN = frozenset({"newton"})  # methods whose mode matrices are on the bodies' Cartesian axes
CHECK_POINTS = 6


def read(name: str, spec: Any, path: Path, coordinates: tuple[Coordinate, ...]) -> Quantity:
    """`{mode: n, ratio: [numerator, denominator]}`; SpecErrors listing every fault."""
    if not isinstance(spec, dict):
        raise SpecError("expected {mode: n, ratio: [coordinate, coordinate]}", path)
    faults: list[SpecError] = []
    for key in spec:
        if key not in ("mode", "ratio"):
            faults.append(SpecError(f"unknown key {key!r}; expected one of ['mode', 'ratio']", (*path, key)))
    mode = spec.get("mode")
    if isinstance(mode, bool) or not isinstance(mode, int) or not 1 <= mode <= len(coordinates):
        faults.append(SpecError(f"the mode's number, 1 (lowest) to {len(coordinates)}", (*path, "mode")))
    ratio = spec.get("ratio")
    names = {c.name for c in coordinates}
    if not isinstance(ratio, list) or len(ratio) != 2 or ratio[0] == ratio[1]:
        faults.append(SpecError("two different coordinates: [numerator, denominator]", (*path, "ratio")))
    else:
        for index, member in enumerate(ratio):
            if member not in names:
                faults.append(SpecError(f"unknown coordinate {member!r}", (*path, "ratio", index)))
    if faults:
        raise SpecErrors(faults)
    assert isinstance(ratio, list)
    return Quantity(name, QuantityKind.MODE_SHAPE, str(mode), ratio=(str(ratio[0]), str(ratio[1])))


def answer(method: Method, quantity: Quantity, point: dict[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    model = method.model
    squares = method.mode_frequencies  # ordered, lowest first
    number = int(quantity.target)
    modes.check_mode_number(number, len(squares), ("quantities", quantity.name, "mode_shape", "mode"))
    omega2 = squares[number - 1]
    mass, stiffness = method.mode_matrices(point)
    vector = _null_vector(stiffness - omega2 * mass, model, quantity.name)
    if method.name in CARTESIAN:
        mech = method.mech
        jacobian = sympy.Matrix([[sympy.diff(d.mapping, q) for q in mech.q] for d in mech.dofs]).subs(point)
        vector = jacobian.LUsolve(vector)
    names = [c.name for c in model.coordinates]
    top, bottom = (vector[names.index(n)] for n in quantity.ratio)
    if tidy.simplify(bottom) == 0:
        raise DerivationError(f"{quantity.ratio[1]} does not move in mode {number}", quantity=quantity.name)
    ratio = tidy.simplify(top / bottom)
    method.step(
        f"Shape of mode {number}",
        r"(K - \omega_{"
        + str(number)
        + r"}^2 M)\,v = 0 \Rightarrow \frac{"
        + method.tex(model.coordinate(quantity.ratio[0]).symbol)
        + "}{"
        + method.tex(model.coordinate(quantity.ratio[1]).symbol)
        + "} = "
        + method.tex(ratio),
    )
    return ratio


def _null_vector(matrix: sympy.Matrix, model: Model, name: str) -> sympy.Matrix:
    """A non-zero v with matrix v = 0: one component set to 1, the others from all rows but one, the
    left-out row checked at domain points (the matrix is singular only once its entries simplify)."""
    size = matrix.shape[0]
    points = domain_points(model, CHECK_POINTS, seed=29)
    unknowns = [sympy.Dummy(f"v{i}") for i in range(size)]
    for fixed in range(size):
        for dropped in range(size):
            values = {unknowns[fixed]: sympy.Integer(1)}
            rows = [r for r in range(size) if r != dropped]
            others = [u for i, u in enumerate(unknowns) if i != fixed]
            equations = [
                sympy.Add(*(matrix[r, c] * unknowns[c] for c in range(size))).subs(values) for r in rows
            ]
            try:
                values.update(solve_linear(equations, others, name) if others else {})
            except DerivationError:
                continue
            vector = sympy.Matrix([values[u] for u in unknowns])
            if _vanishes(matrix, vector, points):
                return vector
    raise DerivationError(f"{name}: no mode shape found (the mode's matrix is not singular)", quantity=name)


def _vanishes(matrix: sympy.Matrix, vector: sympy.Matrix, points: list[dict[sympy.Symbol, float]]) -> bool:
    """matrix * vector is zero, relative to the sizes of both, at every point."""
    for at in points:
        try:
            numeric = [[complex(sympy.N(e.subs(at), 30)) for e in row] for row in matrix.tolist()]
            v = [complex(sympy.N(e.subs(at), 30)) for e in vector]
        except (TypeError, ValueError):
            return False
        scale = max(abs(x) for row in numeric for x in row) * max(abs(x) for x in v)
        for row in numeric:
            if abs(sum(a * b for a, b in zip(row, v, strict=True))) > 1e-12 * max(scale, 1e-300):
                return False
    return True


@derives(QuantityKind.MODE_SHAPE)
def derived(method: Method, quantity: Quantity) -> sympy.Expr:
    from physics.engine.method import stable_equilibrium

    return answer(method, quantity, stable_equilibrium(method.model, True))
