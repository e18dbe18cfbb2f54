"""How a worked solution writes, and says in words, everything it uses: the coordinates, each body's
Cartesian coordinates, the force of every constraint, and the methods' own letters (energies, the
Lagrangian, the generalized force).

A name comes, in this order, from the model's `notation:` section (the author's), from the problem's
symbols (a coordinate named like a problem symbol is that quantity), from physics (a surface's force is
the normal force N, a string's the tension T, a rolling contact's the static friction f, an axle's
components R_x and R_y), and only last from a list of spare letters. No two things get one written
name, none takes the name of a problem symbol it is not, and no coordinate is written `d`, which reads
as the d of d/dt (derivatives are written with an upright d as well).

    notation:                       # in a model, every entry optional
      d: {symbol: s, says: "the length of string unwound: how far the yo-yo has fallen"}
      string: {symbol: T, says: the tension in the string}
      yoyo: {says: the yo-yo}

Words are Markdown with TeX; «body» in them stands for that body's words, which the page fills from
the problem's symbol meanings ("mass of the yo-yo" gives "the yo-yo"), see `fill_bodies`.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from functools import lru_cache
from typing import Any

import sympy

from physics import typeset
from physics.engine.model import Body, Constraint, ConstraintKind, Model
from physics.errors import SpecError
from physics.mathinput.render import latex_name

Path = tuple[str | int, ...]
# Written names no coordinate or force may take: the d of d/dt, Euler's e, the imaginary unit.
RESERVED = frozenset({"d", "e", "i"})
SPARE_COORDINATES = ("q", "u", "w", r"\xi", r"\eta", r"\zeta")
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]*(_[A-Za-z0-9]+)?$")
_SUBSCRIPT = str.maketrans("0123456789xy", "₀₁₂₃₄₅₆₇₈₉ₓᵧ")
_SURFACE_NOUNS = (
    "floor",
    "wall",
    "slope",
    "incline",
    "ramp",
    "table",
    "track",
    "bank",
    "lane",
    "bowl",
    "ground",
    "ceiling",
    "wire",
    "hoop",
    "surface",
)
_STRING_NOUNS = ("string", "rope", "cord", "rod", "cable", "thread")
_PIN_NOUNS = ("axle", "pivot", "hinge")
BODY_MARK = re.compile("«([A-Za-z0-9_]+)»")


class Source(StrEnum):
    AUTHOR = "author"  # the model's notation section
    PROBLEM = "problem"  # the problem's own symbol of that name
    PHYSICS = "physics"  # the usual letter for that kind of force or coordinate
    GENERATED = "generated"  # a spare letter: nothing better was known


@dataclass(frozen=True)
class Name:
    tex: str
    words: str  # Markdown with TeX; «body» marks a body's words
    source: Source
    text: str = ""  # plain Unicode, for figures (N₁); empty where the TeX has no plain form

    @property
    def plain(self) -> str:
        return self.text or self.tex


@dataclass(frozen=True)
class Letters:
    """The methods' own letters, chosen so that none is a problem symbol or a force's name."""

    kinetic: str = "T"
    potential: str = "V"
    lagrangian: str = r"\mathcal{L}"
    energy: str = "E"
    generalized: str = "Q"

    def legend(self) -> tuple[tuple[str, str], ...]:
        return (
            (self.kinetic, "the kinetic energy of all the bodies"),
            (self.potential, "the potential energy (gravity, springs, other potentials)"),
            (self.lagrangian, f"the Lagrangian, ${self.lagrangian} = {self.kinetic} - {self.potential}$"),
            (self.energy, f"the total mechanical energy ${self.kinetic} + {self.potential}$"),
            (self.generalized, "a generalized force: the work done per unit change of a coordinate"),
        )


@dataclass(frozen=True)
class Notation:
    coordinates: Mapping[str, Name]  # coordinate name -> its name
    forces: Mapping[str, Name]  # constraint name -> its force's name
    conditions: Mapping[str, str]  # constraint name -> what it keeps, in words
    frictions: tuple[Name, ...]  # kinetic friction, in the model's order
    bodies: Mapping[str, str]  # body name -> default words ("the block"); «» marks are filled from these
    cartesian: Mapping[str, Name]  # "x_block" -> its name
    letters: Letters
    masses: Mapping[str, str] = field(default_factory=dict)  # body -> its mass symbol's name, if one
    gravity: str = ""  # TeX of gravity's acceleration, "" without gravity

    def tex_names(self, model: Model) -> dict[sympy.Symbol, str]:
        """sympy symbol -> TeX for every symbol a step may print that is not a problem symbol."""
        names: dict[sympy.Symbol, str] = {}
        for c in model.coordinates:
            tex = self.coordinates[c.name].tex
            names[c.symbol] = tex
            names[c.velocity] = dotted(tex, 1)
            names[c.acceleration] = dotted(tex, 2)
        for key, symbol in model.cartesian:
            tex = self.cartesian[key].tex
            names[symbol] = tex
            names[sympy.Symbol(f"v_{key}", real=True)] = dotted(tex, 1)
            names[sympy.Symbol(f"a_{key}", real=True)] = dotted(tex, 2)
        for constraint in model.constraints:
            names[sympy.Symbol(f"lambda_{constraint.name}", real=True)] = self.forces[constraint.name].tex
        return names


def dotted(tex: str, dots: int) -> str:
    """ẋ of a name, with its subscript kept outside the dot: x_{\\mathrm{block}} -> \\dot{x}_{\\mathrm{block}}."""
    accent = r"\dot" if dots == 1 else r"\ddot"
    base, sub = split_subscript(tex)
    return rf"{accent}{{{base}}}" + (f"_{{{sub}}}" if sub else "")


def split_subscript(tex: str) -> tuple[str, str]:
    """(base, subscript) of a written name: `N_{1}` -> (N, 1), `x'_{\\mathrm{b}}` -> (x', \\mathrm{b})."""
    depth = 0
    for index, char in enumerate(tex):
        if char == "{":
            depth += 1
        elif char == "}":
            depth -= 1
        elif char == "_" and depth == 0:
            sub = tex[index + 1 :]
            if sub.startswith("{") and sub.endswith("}"):
                sub = sub[1:-1]
            return tex[:index], sub
    return tex, ""


def read_notation(value: Any, known: Iterable[str]) -> tuple[tuple[str, str | None, str | None], ...]:
    """The model's `notation:` section: (coordinate, constraint or body name, symbol, words); SpecError
    at the first fault (the loader collects it beside the others)."""
    if value is None:
        return ()
    if not isinstance(value, Mapping):
        raise SpecError("expected a mapping of coordinate, constraint or body names", ("notation",))
    names = set(known)
    entries = []
    for key, spec in value.items():
        path: Path = ("notation", str(key))
        if key not in names:
            raise SpecError(f"unknown name {key!r}; expected one of {sorted(names)}", path)
        if not isinstance(spec, Mapping) or not spec or set(spec) - {"symbol", "says"}:
            raise SpecError("expected {symbol: a name, says: words}, either or both", path)
        symbol, says = spec.get("symbol"), spec.get("says")
        if symbol is not None and (not isinstance(symbol, str) or not _NAME.match(symbol)):
            raise SpecError("a symbol is a plain name such as T, N1, x_rel or theta", (*path, "symbol"))
        if says is not None and (not isinstance(says, str) or not says.strip() or len(says) > 300):
            raise SpecError("words of at most 300 characters", (*path, "says"))
        entries.append((str(key), symbol, None if says is None else " ".join(says.split())))
    return tuple(entries)


def humanize(name: str) -> str:
    """`inclineFloor` -> "incline floor", `floor1` -> "floor", `stringWheel` -> "string wheel"."""
    spaced = re.sub(r"(?<=[a-z])(?=[A-Z])", " ", name).lower()
    return re.sub(r"\d+$", "", spaced).strip() or name


def _noun(name: str, nouns: tuple[str, ...]) -> str | None:
    words = humanize(name).split()
    return next((w for w in reversed(words) if w in nouns or w.rstrip("s") in nouns), None)


def _body_words(name: str) -> str:
    if re.fullmatch(r"[A-Za-z]\d*", name):  # a body named by its mass symbol (m1, M)
        return f"the mass ${latex_name(name)}$"
    return "the " + humanize(name)


def _bodies_said(model: Model, author: Mapping[str, tuple[str | None, str | None]]) -> dict[str, str]:
    """Each body's words: the author's, else its name's ("the cart"); bodies whose names say alike
    are told apart by their own mass ("the cart $m_{1}$"), else by their names' numbers ("cart 2"),
    as "Newton's second law for the cart" twice, for two carts, read as one body's law said twice."""
    alike = [_body_words(b.name) for b in model.bodies]
    masses = [b.mass for b in model.bodies]
    said = {}
    for body, words in zip(model.bodies, alike, strict=True):
        number = re.search(r"\d+$", body.name)
        if author.get(body.name, (None, None))[1]:
            words = str(author[body.name][1])
        elif alike.count(words) == 1:
            pass
        elif isinstance(body.mass, sympy.Symbol) and masses.count(body.mass) == 1:
            words = f"{words} ${typeset.latex(body.mass)}$"
        elif number is not None:
            words = f"{humanize(body.name)} {number.group()}"
        said[body.name] = words
    return said


def fill_bodies(text: str, bodies: Mapping[str, str]) -> str:
    """`text` with each «body» replaced by that body's words (its default words if not in `bodies`)."""
    return BODY_MARK.sub(lambda m: bodies.get(m.group(1), _body_words(m.group(1))), text)


def constraint_bodies(constraint: Constraint, model: Model) -> list[str]:
    """The bodies a constraint's gap involves, in the model's order."""
    free = {str(s) for s in constraint.gap.free_symbols}
    return [b.name for b in model.bodies if any(n in free for n in b.cartesian_names())]


@lru_cache(maxsize=128)
def notation_of(model: Model) -> Notation:
    """Every name a worked solution of `model` uses (cached: models are immutable)."""
    author = {key: (symbol, says) for key, symbol, says in model.notation}
    problem = {str(p): typeset.latex(p) for p in model.parameters}
    taken: set[str] = set(problem.values()) | RESERVED

    coordinates: dict[str, Name] = {}
    for c in model.coordinates:
        symbol, says = author.get(c.name, (None, None))
        if symbol is not None:
            tex, source = latex_name(symbol), Source.AUTHOR
        elif c.name in problem:
            tex, source = problem[c.name], Source.PROBLEM
        else:
            tex, source = latex_name(c.name), Source.PHYSICS
        if source is not Source.PROBLEM and tex in taken:
            tex, source = _spare(SPARE_COORDINATES, taken), Source.GENERATED
        taken.add(tex)
        coordinates[c.name] = Name(tex, says or _coordinate_words(c.name, model), source)

    bodies = _bodies_said(model, author)
    forces, conditions = _forces(model, author, taken, problem)
    frictions = _frictions(model, forces, taken)
    cartesian = _cartesian(model, taken, coordinates)
    letters = _letters(taken | {n.tex for n in forces.values()} | {n.tex for n in frictions})
    masses = {b.name: str(b.mass) for b in model.bodies if isinstance(b.mass, sympy.Symbol)}
    gravity = "" if model.gravity is None else str(typeset.latex(model.gravity))
    return Notation(coordinates, forces, conditions, frictions, bodies, cartesian, letters, masses, gravity)


def _spare(candidates: Iterable[str], taken: set[str]) -> str:
    for tex in candidates:
        if tex not in taken:
            return tex
    for index in range(1, 100):
        if (tex := f"q_{{{index}}}") not in taken:
            return tex
    raise ValueError("no spare name")


def _coordinate_words(name: str, model: Model) -> str:
    """What a coordinate is, from how the bodies move with it: a distance along a fixed direction, or an
    angle; the model's `notation` says it better."""
    c = model.coordinate(name)
    moved: list[tuple[Body, dict[str, sympy.Expr]]] = []
    for body in model.bodies:
        changes = [sympy.diff(expr, c.symbol) for _, expr in body.position]
        if any(d != 0 for d in changes):
            moved.append((body, dict(zip((a for a, _ in body.position), changes, strict=True))))
        elif body.angle is not None and sympy.diff(body.angle, c.symbol) != 0:
            moved.append((body, {}))
    if not moved:
        return "a coordinate of the motion"
    body, direction = moved[0]
    if not direction:
        return f"the angle «{body.name}» has turned through"
    if all(d.free_symbols & {c.symbol} for d in direction.values() if d != 0):
        # a model with z is drawn from the side, or its bodies side by side: no figure marks the coordinate
        seen = "" if "z" in direction else " (see the figure)"
        return f"an angle that sets where «{body.name}» is{seen}"
    says: dict[tuple[int, ...], str] = {
        (1, 0, 0): "to the right, the $+x$ direction",
        (-1, 0, 0): "to the left, the $-x$ direction",
        (0, 1, 0): "upwards",
        (0, -1, 0): "downwards",
        (0, 0, 1): "horizontally along $+z$",
        (0, 0, -1): "horizontally along $-z$",
    }
    parts = [direction.get(axis, sympy.Integer(0)) for axis in ("x", "y", "z")]
    key = tuple(int(p) if p.is_Integer else 9 for p in parts)
    way = says.get(key, "along the direction its position changes with it")
    others = [f"«{b.name}»" for b, _ in moved[1:]]
    tail = f"; {' and '.join(others)} move{'s' if len(others) == 1 else ''} with it" if others else ""
    return f"how far «{body.name}» has moved {way}, from where it starts{tail}"


def _forces(
    model: Model,
    author: Mapping[str, tuple[str | None, str | None]],
    taken: set[str],
    problem: Mapping[str, str],
) -> tuple[dict[str, Name], dict[str, str]]:
    """Each constraint's force: the author's name, else the physical letter of its kind, numbered when
    several share one (contacts between two bodies first: the wedge's N₁ on the block, the floor's N₂)."""
    kinds: dict[str, tuple[str, str, str]] = {}  # constraint -> (letter family, words, condition)
    for constraint in model.constraints:
        kinds[constraint.name] = _force_kind(constraint, model)
    # normal forces between two bodies first (the wedge's on the block is N₁, the floor's N₂)
    order = sorted(
        model.constraints,
        key=lambda c: -len(constraint_bodies(c, model)) if kinds[c.name][0] == "normal" else 0,
    )
    families: dict[str, list[str]] = {}
    for constraint in order:
        if author.get(constraint.name, (None, None))[0] is None:
            families.setdefault(kinds[constraint.name][0], []).append(constraint.name)
    forces: dict[str, Name] = {}
    for constraint in model.constraints:
        symbol, says = author.get(constraint.name, (None, None))
        if symbol is not None:
            tex = latex_name(symbol)
            forces[constraint.name] = Name(tex, says or kinds[constraint.name][1], Source.AUTHOR, _plain(tex))
            taken.add(tex)
    letters: dict[str, str] = {}
    for family in families:  # a family's bare letter is kept for it: N₁ and N₂, never N beside them
        partner = _PIN_PARTNERS.get(family)  # a support's R_x and R_y share their letter, no one else
        letters[family] = (letters.get(partner) if partner else None) or _letter(family, taken, problem)
        taken.add(letters[family])
    supports = _support_numbers(families, model)
    for family, members in families.items():
        letter = letters[family]
        for index, member in enumerate(members, start=1):
            if family in ("pin_x", "pin_y"):
                number = supports.get(member)
                tex = f"{letter}_{{{family[-1]}{'' if number is None else f',{number}'}}}"
            else:
                tex = letter if len(members) == 1 else f"{letter}_{{{index}}}"
            source = Source.PHYSICS if letter in _LETTERS[family] else Source.GENERATED
            says = author.get(member, (None, None))[1]  # the author's words, with the letter physics gives
            forces[member] = Name(tex, says or kinds[member][1], source, _plain(tex))
            taken.add(tex)
    conditions = {name: kinds[name][2] for name in kinds}
    return forces, conditions


def _support_numbers(families: Mapping[str, list[str]], model: Model) -> dict[str, int]:
    """Each support's number where there are several (an axle's R_{x,1} and R_{y,1}, a wall's R_{x,2}):
    by the body it holds, so a body's horizontal and vertical forces share it; where two hold one body
    along one axis, by their order. None where one support holds along each axis: its R_x and R_y."""
    pins = {family: families.get(family, []) for family in ("pin_x", "pin_y")}
    if all(len(members) <= 1 for members in pins.values()):
        return {}
    by_name = {c.name: c for c in model.constraints}
    held = {
        name: tuple(constraint_bodies(by_name[name], model)) for members in pins.values() for name in members
    }
    if any(len({held[m] for m in members}) < len(members) for members in pins.values()):
        return {m: i for members in pins.values() for i, m in enumerate(members, start=1)}
    order = list(dict.fromkeys(held[m] for members in pins.values() for m in members))
    return {m: order.index(held[m]) + 1 for members in pins.values() for m in members}


_PIN_PARTNERS = {"pin_x": "pin_y", "pin_y": "pin_x"}
_LETTERS = {
    "normal": ("N", r"\mathcal{N}"),
    "tension": ("T", r"\mathcal{T}"),
    "static": ("f", r"f_{\mathrm{s}}"),
    "pin_x": ("R", "P", r"\mathcal{R}"),
    "pin_y": ("R", "P", r"\mathcal{R}"),
}


def _letter(family: str, taken: set[str], problem: Mapping[str, str]) -> str:
    """The family's first letter that is no problem symbol (a radius R keeps R off an axle's force)."""
    for letter in _LETTERS[family]:
        if letter not in problem.values() and letter not in taken:
            return letter
    return _spare(("F", "P", "S"), taken)


def _plain(tex: str) -> str:
    base, sub = split_subscript(tex)
    if not re.fullmatch(r"[A-Za-z]", base):
        return ""
    if not sub:
        return base
    return base + sub.translate(_SUBSCRIPT) if re.fullmatch(r"[0-9xy,]+", sub) else ""


def _force_kind(constraint: Constraint, model: Model) -> tuple[str, str, str]:
    """(letter family, the force in words, what the constraint keeps in words)."""
    bodies = [f"«{b}»" for b in constraint_bodies(constraint, model)]
    first = bodies[0] if bodies else "the body"
    kind = constraint.kind
    if kind is ConstraintKind.STRING:
        noun = _noun(constraint.name, _STRING_NOUNS)
        what = f"the {noun}" if noun else f"the {humanize(constraint.name)} string"
        joins = f", which pulls on {' and '.join(bodies)}" if bodies else ""
        return "tension", f"the tension in {what}{joins}", f"{what} stays taut: its length does not change"
    if kind is ConstraintKind.ROLLING:
        return (
            "static",
            f"the static friction from the surface on {first} at its point of contact",
            f"{first} rolls without slipping",
        )
    if kind is ConstraintKind.SURFACE:
        if len(bodies) == 2:
            return (
                "normal",
                f"the normal force between {bodies[1]} and {bodies[0]}: each pushes the other, at right "
                "angles to the surface where they touch",
                f"{bodies[0]} stays in contact with {bodies[1]}",
            )
        noun = _noun(constraint.name, _SURFACE_NOUNS)
        if noun is None and constraint.name in {b.name for b in model.bodies}:
            noun = "surface"  # a rolling element names the surface after its body
        surface = f"the {noun or humanize(constraint.name)}"
        return "normal", f"the normal force from {surface} on {first}", f"{first} stays on {surface}"
    if (grip := _grip(constraint, model)) is not None:
        return (
            "static",
            f"the static friction from {grip} on {first}, along it",
            f"{first} does not slip along {grip}",
        )
    pin = _noun(constraint.name, _PIN_NOUNS)
    axis = _pin_axis(constraint, model)
    if axis is not None:
        where = pin or "support"
        way = "horizontal" if axis == "x" else "vertical"
        return (
            f"pin_{axis}",
            f"the {way} component of the force from the {where} on {first}",
            f"the {where} holds {first} in place {way}ly",
        )
    noun = humanize(constraint.name)
    return "normal", f"the force from the {noun} on {first}, across it", f"{first} stays on the {noun}"


def _pin_axis(constraint: Constraint, model: Model) -> str | None:
    """ "x" or "y" if the gap holds one of a body's x and y (not both), linearly: an axle or a pivot,
    which may sit off the body's centre (then its angle is in the gap too)."""
    names = {str(s): s for s in constraint.gap.free_symbols}
    held = [n for n in names if n.startswith(("x_", "y_", "z_"))]
    if len(held) != 1 or held[0].startswith("z_") or sympy.diff(constraint.gap, names[held[0]], 2) != 0:
        return None
    return held[0][0]


def _grip(constraint: Constraint, model: Model) -> str | None:
    """The surface (its words) along which the constraint holds a body that also rests on it: the
    foot of a ladder kept from slipping along the floor is held by static friction."""
    bodies = constraint_bodies(constraint, model)
    if len(bodies) != 1:
        return None
    axes = [
        model.cartesian_symbol(f"{a}_{bodies[0]}")
        for a in "xy"
        if f"{a}_{bodies[0]}" in dict(model.cartesian)
    ]
    for surface in model.constraints:
        if surface.kind is not ConstraintKind.SURFACE or constraint_bodies(surface, model) != bodies:
            continue
        across = sympy.Add(*(sympy.diff(constraint.gap, a) * sympy.diff(surface.gap, a) for a in axes))
        if sympy.simplify(across) == 0:
            return "the " + (_noun(surface.name, _SURFACE_NOUNS) or humanize(surface.name))
    return None


def _frictions(model: Model, forces: Mapping[str, Name], taken: set[str]) -> tuple[Name, ...]:
    letter = "f" if "f" not in taken else r"f_{\mathrm{k}}"
    result = []
    count = len(model.frictions)
    for index, friction in enumerate(model.frictions, start=1):
        tex = letter if count == 1 else f"{letter}_{{{index}}}"
        if any(n.tex == tex for n in forces.values()):
            tex = rf"f_{{\mathrm{{k}}{index if count > 1 else ''}}}"
        normal = forces[friction.constraint].tex
        words = (
            f"the kinetic friction on «{friction.body}», against its sliding, of magnitude "
            f"${latex_coefficient(friction.coefficient)}\\,{normal}$"
        )
        result.append(Name(tex, words, Source.PHYSICS, _plain(tex)))
        taken.add(tex)
    return tuple(result)


def latex_coefficient(expr: sympy.Expr) -> str:
    return str(typeset.latex(expr))


def _cartesian(model: Model, taken: set[str], coordinates: Mapping[str, Name]) -> dict[str, Name]:
    """x, y and φ of each body: bare for a model of one body, else with the body's name below; the
    subscripted form where the bare one is taken (a coordinate x that is the block's x)."""
    single = len(model.bodies) == 1
    result: dict[str, Name] = {}
    letters = {key: symbol for key, symbol, _ in model.notation if symbol}
    for body in model.bodies:
        if body.name in letters:  # the letter the author gives the body, as the figures name it
            label = typeset.latex(sympy.Symbol(letters[body.name]))
        elif re.fullmatch(r"[A-Za-z]\d+", body.name):
            label = body.name[1:]
        else:
            label = rf"\mathrm{{{body.name}}}"
        for key in body.cartesian_names():
            axis = key.split("_", 1)[0]
            base = r"\varphi" if axis == "phi" else axis
            tex = base if single and base not in taken else f"{base}_{{{label}}}"
            if tex in taken:
                tex = _spare((f"{base}_{{{label}{n}}}" for n in range(1, 10)), taken)
            taken.add(tex)
            words = {
                "x": f"the horizontal position of «{body.name}»'s centre, positive to the right ($+x$)",
                "y": f"the height of «{body.name}»'s centre, positive upwards ($+y$)",
                "z": f"the horizontal position of «{body.name}»'s centre along $+z$, at right angles to $x$",
                "phi": f"the angle «{body.name}» has turned through, positive anticlockwise",
            }[axis]
            result[key] = Name(tex, words, Source.PHYSICS, _plain(tex))
    return result


def _letters(taken: set[str]) -> Letters:
    def pick(*candidates: str) -> str:
        return next((c for c in candidates if c not in taken), candidates[-1])

    return Letters(
        kinetic=pick("T", "K", r"E_{\mathrm{k}}"),
        potential=pick("V", "U", r"E_{\mathrm{p}}"),
        energy=pick("E", r"\mathcal{E}"),
        generalized=pick("Q", r"\mathcal{Q}"),
    )


# --- the audit: what `physcheck bank verify` and the tests hold every worked solution to -----------------

_INTERNAL_WORD = re.compile(r"\b[A-Za-z]+(?:_[A-Za-z0-9]+|[a-z][A-Z][A-Za-z]*|\d+)\b")
_MATH = re.compile(r"\$[^$]*\$")
_ITALIC_D = re.compile(r"\\frac\{d[A-Za-z]?\}|\\frac\{d\(")
_ENGINE_TEX = re.compile(r"\\lambda_\{|\\mathrm\{phi|\bg_k\b|\\nabla g")


# symbols a method brings and its step says in words: a root of the characteristic equation, a flight's
# apex height and the vertical velocity on landing
METHOD_SYMBOLS = frozenset({"lambda", "H", "v_y1"})


def defined_symbols(model: Model) -> set[str]:
    """The names of every symbol a worked solution may print: the problem's, the coordinates and their
    rates, each body's Cartesian coordinates and rates (also relative to a moving frame), the
    constraint forces and the time."""
    names = {str(p) for p in model.parameters} | {"t"} | METHOD_SYMBOLS
    for c in model.coordinates:
        names |= {c.name, str(c.velocity), str(c.acceleration)}
    for key, _ in model.cartesian:
        names |= {key, f"v_{key}", f"a_{key}", f"{key}_rel", f"v_{key}_rel", f"a_{key}_rel"}
    names |= {f"lambda_{c.name}" for c in model.constraints}
    for _, scenario in model.scenarios:  # its steps print what it adds (a crate lifted gets y)
        names |= defined_symbols(scenario)
    return names


def _rename(what: str) -> str:
    """How an author tells two things written alike apart: `notation:` names a coordinate or a force."""
    kind, _, key = what.partition(" ")
    if kind not in ("coordinate", "force"):
        return ""
    return f": give {key} a symbol of its own under the model's `notation:`, as {key}: {{symbol: Q, says: …}}"


def audit(model: Model, notation: Notation, methods: Iterable[Any]) -> list[str]:
    """Why the worked solutions (the derivation's method reports) do not read cleanly: a constraint
    force without a physical name, two things written alike, a name that reads as the d of d/dt, a
    symbol no set-up defines, or an engine name shown to a reader. Empty when they read cleanly."""
    faults: list[str] = []
    for key, name in notation.forces.items():
        if name.source is Source.GENERATED or not name.words.strip():
            faults.append(f"the force of constraint {key!r} has no physical name ({name.tex})")
    problem = {str(p): typeset.latex(p) for p in model.parameters}
    written: dict[str, str] = {}
    mine = [
        *((f"coordinate {k}", n) for k, n in notation.coordinates.items()),
        *((f"force {k}", n) for k, n in notation.forces.items()),
        *((f"friction {i + 1}", n) for i, n in enumerate(notation.frictions)),
        *((f"position {k}", n) for k, n in notation.cartesian.items()),
    ]
    for what, name in mine:
        own = name.source is Source.PROBLEM
        if name.tex in RESERVED and not own:
            faults.append(f"{what} is written {name.tex!r}, which reads as a constant or the d of d/dt")
        if name.tex in written:
            faults.append(f"{what} and {written[name.tex]} are both written {name.tex!r}" + _rename(what))
        elif name.tex in problem.values() and not own:
            faults.append(f"{what} is written {name.tex!r}, like the problem's symbol")
        written[name.tex] = what
    letters = notation.letters
    for letter in (letters.kinetic, letters.potential, letters.energy, letters.generalized):
        if letter in written or letter in problem.values():
            faults.append(f"the methods' letter {letter!r} is also {written.get(letter, 'a problem symbol')}")
    defined = defined_symbols(model)
    bodies = {b.name for b in model.bodies}
    for report in methods:
        for step in report.steps:
            where = f"{report.name}: {step.title!r}"
            for symbol in step.symbols:
                if symbol not in defined:
                    faults.append(f"{where} prints {symbol!r}, which no set-up defines")
            for mark in BODY_MARK.findall(step.title):
                if mark not in bodies:
                    faults.append(f"{where} names an unknown body {mark!r}")
            prose = _MATH.sub("", BODY_MARK.sub("", step.title))
            for word in _INTERNAL_WORD.findall(prose):
                faults.append(f"{where} shows the engine's name {word!r}")
            if _ITALIC_D.search(step.latex):
                faults.append(f"{where} writes d/dt with an italic d")
            if _ENGINE_TEX.search(step.latex + " " + step.title):
                faults.append(
                    f"{where} shows the engine's notation: {_ENGINE_TEX.search(step.latex + step.title)}"
                )
    return faults
