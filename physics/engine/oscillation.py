"""Small oscillations from a method's own equations of motion: q'' = f(q) at rest, linearized.

Shared by the methods that solve for the accelerations directly (fictitious forces, d'Alembert) rather
than through energies or mass and stiffness matrices: K = -df/dq at the equilibrium, omega^2 its one
non-zero eigenvalue (a coordinate that f does not pull back, a cyclic one, gives the zero eigenvalue).
"""

from __future__ import annotations

import sympy

from physics.engine import modes, tidy
from physics.engine.method import Method, NotApplicable


def frequency_from_accelerations(
    method: Method, coordinate: str, equilibrium: sympy.Expr, accelerations: dict[sympy.Symbol, sympy.Expr]
) -> sympy.Expr:
    """omega of small oscillations of `coordinate` about `equilibrium` (the others where `Method.rest`
    puts them, as the other methods take them), from the coordinates' accelerations at rest as functions
    of q."""
    mech = method.mech
    q = method.model.coordinate(coordinate).symbol
    at = {**method.rest(coordinate), q: equilibrium}
    stiffness = sympy.Matrix([[-sympy.diff(accelerations[a], c) for c in mech.q] for a in mech.qdd]).subs(at)
    block = modes.coupled([stiffness], list(mech.q).index(q))  # other, uncoupled systems apart
    values = [tidy.simplify(v) for v in stiffness.extract(block, block).eigenvals()]
    nonzero = [v for v in values if v != 0]
    if len(nonzero) != 1:
        partners = [str(mech.q[j]) for j in block if mech.q[j] != q]
        raise NotApplicable(modes.no_single_mode(values, coordinate, partners))
    method.step(
        "Small oscillations of the equation of motion",
        rf"\ddot{{{method.tex(q)}}} = f({method.tex(q)}),\quad \omega^2 = -\left.\frac{{\partial f}}"
        rf"{{\partial {method.tex(q)}}}\right|_0 = " + method.tex(nonzero[0]),
    )
    return tidy.simplify(sympy.sqrt(nonzero[0]))
