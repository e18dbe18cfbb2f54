"""Normal modes of several coupled degrees of freedom about the stable equilibrium.

The equilibrium solves grad V = 0 in all coordinates at once (a coordinate V does not depend on is
free: it is set to 0 and its zero-frequency mode left out); it must be stable (the Hessian of V has no
negative eigenvalue at sampled domain points) and inside the coordinates' declared ranges. Where the rests
form a continuum along which the mass and stiffness matrices stay the same (carts joined by a spring, a
linear molecule: a free translation), the modes are those about any point of it, the translation's
zero-frequency ones left out as well. Each method
gives its own mass and stiffness matrices there; the squared frequencies are the non-zero roots of
det(K - omega^2 M), ordered by their value at a domain point (and checked to keep that order).
"""

from __future__ import annotations

from collections.abc import Sequence

import mpmath
import sympy

from physics.answer_text import typed_text
from physics.engine import tidy
from physics.engine.mechanics import Mechanics
from physics.engine.model import Model, Quantity
from physics.engine.proof import domain_points
from physics.errors import DerivationError

ORDER_POINTS = 6


def no_single_mode(values: Sequence[sympy.Expr], coordinate: str, partners: Sequence[str]) -> str:
    """Why a coordinate has no one frequency (NotApplicable's message), and, where its small oscillations
    mix with other coordinates', what the teacher can ask instead."""
    found = f"expected one oscillating mode, found eigenvalues {typed_text(list(values))}"
    if len([v for v in values if v != 0]) < 2 or not partners:
        return found
    return (
        f"{found}: {coordinate} oscillates together with {', '.join(partners)} about the equilibrium, so it "
        "has no frequency of its own; ask for normal_frequency (n: the n-th lowest mode of all the "
        "coordinates) or mode_shape instead"
    )


def continuum(free: Sequence[str], where: str) -> str:
    """Why a continuum of equilibria has no one equilibrium (DerivationError's message)."""
    return (
        f"the bodies rest {where}, {' and '.join(free)} taking any value: a continuum of equilibria, with no "
        "one point to oscillate about"
    )


def coupled(matrices: Sequence[sympy.Matrix], index: int) -> list[int]:
    """The coordinates that move with coordinate `index`: linked to it, directly or through others, by a
    non-zero off-diagonal entry of any of the matrices. Two pendulums side by side are two blocks, each
    with its own frequency."""
    block, pending = {index}, [index]
    while pending:
        i = pending.pop()
        for matrix in matrices:
            for j in range(matrix.shape[0]):
                if j not in block and (tidy.simplify(matrix[i, j]) != 0 or tidy.simplify(matrix[j, i]) != 0):
                    block.add(j)
                    pending.append(j)
    return sorted(block)


def equilibrium_point(
    model: Model, mech: Mechanics, translation: bool = False
) -> dict[sympy.Symbol, sympy.Expr]:
    """The stable equilibrium of all coordinates together; with `translation`, where the rests form a
    continuum along which nothing changes (carts joined by a spring, anywhere on the track), a point of it."""
    potential = mech.potential
    moving = [q for q in mech.q if potential.has(q)]
    gradient = [sympy.diff(potential, q) for q in moving]
    solutions = sympy.solve(gradient, moving, dict=True) if moving else [{}]
    if not any(all(q in solution for q in moving) for solution in solutions):
        solutions = _one_at_a_time(list(zip(gradient, moving, strict=True)))
    stable = [
        {q: tidy.simplify(solution.get(q, sympy.Integer(0))) for q in mech.q}
        for solution in solutions
        if all(q in solution for q in moving)
    ]
    continua = [solution for solution in solutions if not all(q in solution for q in moving)]
    # sympy gives a ring's top, {x: 0, y: L0}, beside the ring x = sqrt(L0^2 - y^2) as if isolated
    stable = [point for point in stable if not any(_lies_on(point, line) for line in continua)]
    stable = [point for point in stable if _in_ranges(model, point) and _stable(model, mech, point)]
    if not stable and continua:
        line = continua[0]
        free = [q for q in moving if q not in line]
        where = ", ".join(f"{q} = {typed_text(v)}" for q, v in line.items())
        where = f"wherever {where}" if where else "anywhere"
        if translation:
            return _on_translation(model, mech, line, free, where)
        raise DerivationError(continuum([str(q) for q in free], where), path=("domain",))
    if len(stable) != 1:
        raise DerivationError(
            f"expected one stable equilibrium of {', '.join(map(str, moving))}, found {len(stable)} among "
            f"{typed_text(solutions)}; declare the coordinates' ranges under domain.ranges",
            path=("domain",),
        )
    return stable[0]


def _lies_on(point: dict[sympy.Symbol, sympy.Expr], line: dict[sympy.Symbol, sympy.Expr]) -> bool:
    """The point is one of the continuum's rests: each coordinate the line ties is where the line puts it."""
    return all(tidy.simplify(value.subs(point) - point[q]) == 0 for q, value in line.items())


def _rotation(potential: sympy.Expr, free: Sequence[sympy.Symbol], moving: Sequence[sympy.Symbol]) -> str:
    """Where the potential depends on two coordinates only through their distance from the origin (a spring
    to it, free in x and y), the continuum is a ring, and the drift along it a rotation: said, with what to do."""
    for i, a in enumerate(moving):
        for b in moving[i + 1 :]:
            if (a in free or b in free) and tidy.simplify(
                b * sympy.diff(potential, a) - a * sympy.diff(potential, b)
            ) == 0:
                return (
                    f"; the potential depends on {a} and {b} only through sqrt({a}^2 + {b}^2), so the rests are a "
                    "ring about the origin and the drift along it a rotation, not a translation: write the position "
                    "by a distance and an angle about the origin (coordinates of their own) and ask for the "
                    "distance's oscillation"
                )
    return ""


def _on_translation(
    model: Model,
    mech: Mechanics,
    line: dict[sympy.Symbol, sympy.Expr],
    free: list[sympy.Symbol],
    where: str,
) -> dict[sympy.Symbol, sympy.Expr]:
    """A point of the continuum of rests `line` (the free coordinates at any value; `where` says it) inside
    the declared ranges, where it is a free translation: the mass and stiffness matrices the same at every
    point of it, so the small oscillations are too and its zero-frequency modes are the drift along it."""
    said = continuum([str(q) for q in free], where)
    mass = mech.mass_matrix.subs(line).applyfunc(tidy.simplify)
    stiffness = sympy.hessian(mech.potential, list(mech.q)).subs(line).applyfunc(tidy.simplify)
    varying = sorted({str(q) for q in free if mass.has(q) or stiffness.has(q)})
    if varying:
        raise DerivationError(
            f"{said}: the mass or stiffness matrix changes with {', '.join(varying)} along it, so it is no "
            "free translation whose small oscillations are the same everywhere"
            + _rotation(mech.potential, free, [q for q in mech.q if mech.potential.has(q)]),
            path=("domain",),
        )
    for shift in _shifts(model, line, free):
        at = {**dict.fromkeys(free, sympy.Integer(0)), **shift}
        point = {q: tidy.simplify(line.get(q, at.get(q, sympy.Integer(0))).subs(at)) for q in mech.q}
        if _in_ranges(model, point):
            if not _stable(model, mech, point):
                raise DerivationError(
                    f"the bodies rest {where}, {' and '.join(map(str, free))} taking any value, but unstably: the "
                    "potential's Hessian has a negative eigenvalue there, so a mode grows instead of oscillating "
                    "(check the sign of a spring's energy)",
                    path=("domain",),
                )
            return point
    raise DerivationError(f"{said}, and none of it inside the coordinates' declared ranges", path=("domain",))


def _shifts(
    model: Model, line: dict[sympy.Symbol, sympy.Expr], free: list[sympy.Symbol]
) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """Values of the free coordinates to try, the first free one moved: the middle of a finite declared
    range (its own, or that of a coordinate the line ties to it), 0, then the ranges' ends."""
    by_name = {c.name: c.symbol for c in model.coordinates}
    middles: list[tuple[sympy.Symbol, sympy.Expr]] = []
    ends: list[tuple[sympy.Symbol, sympy.Expr]] = []
    for name, low, high in model.coordinate_ranges:
        if low.is_finite and high.is_finite:
            middles.append((by_name[name], (low + high) / 2))
        ends += [(by_name[name], bound) for bound in (low, high) if bound.is_finite]

    def solved(targets: list[tuple[sympy.Symbol, sympy.Expr]]) -> list[dict[sympy.Symbol, sympy.Expr]]:
        return [
            {free[0]: root}
            for q, value in targets
            for root in tidy.solve(line.get(q, q) - value, free[0])
            if not root.has(*free)
        ]

    return [*solved(middles), {}, *solved(ends)]


def _one_at_a_time(pairs: list[tuple[sympy.Expr, sympy.Symbol]]) -> list[dict[sympy.Symbol, sympy.Expr]]:
    """The roots of the equations, each (equation, unknown) solved alone and put into the rest, branch by
    branch: sympy finds none of a bob's on a spring free in x, y and z all at once (the distance's root in
    each), but X = 0 and Z = 0 (factors of their own equations, so solved first), then Y = -(L0 + m g/k).
    Every root is followed, those in the unknowns still to solve too (X = Y where the bob hangs at X - Y):
    a root that leaves no isolated point (X = Y + sqrt(L0^2 - Y^2), the spring at its natural length,
    where the weight is left unbalanced) ends its branch with no solution; an equation that vanishes
    whatever its unknown leaves it free (every point of a line rests). Conditional roots are dropped."""
    if not pairs:
        return [{}]
    pairs = sorted(pairs, key=lambda pair: not _factor_of(pair[1], pair[0]))
    (equation, unknown), rest = pairs[0], pairs[1:]
    if equation == 0:  # every value of the unknown is a rest: it stays free, a continuum
        return _one_at_a_time(rest)
    found: list[dict[sympy.Symbol, sympy.Expr]] = []
    for root in tidy.solve(equation, unknown):
        if root.has(sympy.Piecewise, sympy.nan) or root.is_real is False:
            continue
        remaining = [(tidy.simplify(e.subs(unknown, root)), u) for e, u in rest]
        for solution in _one_at_a_time(remaining):
            value = tidy.simplify(root.subs(solution))
            if value.is_real is not False:
                found.append({**solution, unknown: value})
    return found


def _factor_of(unknown: sympy.Symbol, equation: sympy.Expr) -> bool:
    """unknown is a factor of the equation's numerator (k (d - L0) Z/d): its root 0 comes at once."""
    numerator = sympy.factor_terms(sympy.together(equation)).as_numer_denom()[0]
    return unknown in sympy.Mul.make_args(numerator)


def _numbers(model: Model, count: int) -> list[dict[sympy.Symbol, float]]:
    return domain_points(model, count, seed=23)


def _in_ranges(model: Model, point: dict[sympy.Symbol, sympy.Expr]) -> bool:
    by_name = {c.name: c.symbol for c in model.coordinates}
    for name, low, high in model.coordinate_ranges:
        value = point[by_name[name]]
        for at in _numbers(model, 4):
            number = float(value.subs(at))
            if not float(low.subs(at)) <= number <= float(high.subs(at)):
                return False
    return all(
        not (q.is_positive and v.is_negative) and not (q.is_negative and v.is_positive)
        for q, v in point.items()
    )


def _stable(model: Model, mech: Mechanics, point: dict[sympy.Symbol, sympy.Expr]) -> bool:
    hessian = sympy.hessian(mech.potential, list(mech.q)).subs(point)
    for at in _numbers(model, ORDER_POINTS):
        matrix = mpmath.matrix([[float(v) for v in row] for row in hessian.subs(at).tolist()])
        values = mpmath.eig(matrix, left=False, right=False)
        if isinstance(values, tuple):  # mpmath returns (E, EL, ER) for a 1 x 1 matrix whatever is asked
            values = values[0]
        scale = max([abs(complex(v)) for v in values] + [1e-300])
        if any(complex(v).real < -1e-9 * scale for v in values):
            return False
    return True


def squared_frequencies(model: Model, mass: sympy.Matrix, stiffness: sympy.Matrix) -> list[sympy.Expr]:
    """Non-zero roots of det(K - lambda M), in increasing order on the whole domain."""
    lam = sympy.Dummy("lambda")
    polynomial = sympy.Poly(sympy.expand((stiffness - lam * mass).det()), lam)
    roots = [tidy.simplify(r) for r in sympy.roots(polynomial, multiple=True)]
    if len(roots) != polynomial.degree():
        raise DerivationError("the characteristic polynomial of the normal modes has no closed-form roots")
    nonzero = [r for r in roots if r != 0]
    points = _numbers(model, ORDER_POINTS)
    values = [[complex(sympy.N(r.subs(at))) for r in nonzero] for at in points]
    nonzero = [
        r for r, v in zip(nonzero, values[0], strict=True) if abs(v) > 1e-12 * max(1.0, *map(abs, values[0]))
    ]
    order = sorted(range(len(nonzero)), key=lambda i: complex(sympy.N(nonzero[i].subs(points[0]))).real)
    ordered = [nonzero[i] for i in order]
    for at in points[1:]:
        numbers = [complex(sympy.N(r.subs(at))).real for r in ordered]
        if numbers != sorted(numbers):
            raise DerivationError("the normal modes change order across the domain; narrow it under domain")
    return ordered


def pick(frequencies: Sequence[sympy.Expr], quantity: Quantity) -> sympy.Expr:
    index = int(quantity.target)
    check_mode_number(index, len(frequencies), ("quantities", quantity.name, "normal_frequency"))
    return tidy.simplify(sympy.sqrt(frequencies[index - 1]))


def check_mode_number(number: int, count: int, path: tuple[str | int, ...]) -> None:
    """The loader bounds a mode's number by the coordinates; how many of their modes oscillate (a free
    drift's zero frequency left out) is known only here, so a number beyond them is refused at its path."""
    if number <= count:
        return
    has = f"{count} oscillating mode{'' if count == 1 else 's'}" if count else "no oscillating mode"
    bounds = "" if not count else f": ask for 1 (the lowest){f' to {count}' if count > 1 else ''}"
    raise DerivationError(f"mode {number} asked for, but the system has {has}{bounds}", path=path)
