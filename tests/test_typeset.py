"""Worked solutions write products as a physics text does (m g sin θ, m ÿ), not in sympy's alphabetical
order (g m sin θ, ÿ m), and single angles where simplify chose double ones; only the form changes."""

from __future__ import annotations

import pytest
import sympy

from physics.engine import derive, load_model
from physics.engine.tidy import single_angles
from physics.typeset import latex
from problems.compiled import compile_problem
from tests.bank import bank_documents

m, M, g, s, theta, N, mu, X, k, x, v, h, r, omega, T = sympy.symbols(
    "m M g s theta N_1 mu X k x v h r omega T", positive=True
)
SIN, COS = sympy.sin(theta), sympy.cos(theta)
REAL, OTHER_REAL = sympy.symbols("x y", real=True)
ACCELERATION = sympy.Symbol("a_block")  # sorts before m, as the engine's accelerations do
WRITTEN = {ACCELERATION: r"\ddot{x}_{\mathrm{block}}"}


@pytest.mark.parametrize(
    ("expr", "written"),
    [
        (-g * m * s * SIN, r"- m g s \sin{\left(\theta \right)}"),
        (
            M * g * m * COS / (M + m * SIN**2),
            r"\frac{M m g \cos{\left(\theta \right)}}{M + m \sin^{2}{\left(\theta \right)}}",
        ),
        (mu * m * g * COS, r"\mu m g \cos{\left(\theta \right)}"),
        (X * (M + m) + m * s * COS, r"\left(M + m\right) X + m s \cos{\left(\theta \right)}"),
        (
            sympy.Eq(ACCELERATION * m, N * SIN),
            r"m \ddot{x}_{\mathrm{block}} = N_{1} \sin{\left(\theta \right)}",
        ),
        (m * omega**2 * r, r"m \omega^{2} r"),
        ((h**6 - r**6) * k * h**6 / r**13, r"\frac{h^{6} k \left(h^{6} - r^{6}\right)}{r^{13}}"),
        (
            (M + m) * (COS - 1) * g * h,
            r"\left(M + m\right) g h \left(\cos{\left(\theta \right)} - 1\right)",
        ),
        # square roots as one, where that is exact
        (
            sympy.sqrt(2) * sympy.sqrt(g) * sympy.sqrt(h) * sympy.sqrt(1 - COS) * (M + m) / m,
            r"\frac{\left(M + m\right) \sqrt{2 g h \left(1 - \cos{\left(\theta \right)}\right)}}{m}",
        ),
        (sympy.sqrt(REAL) * sympy.sqrt(OTHER_REAL), r"\sqrt{x} \sqrt{y}"),  # both may be negative
        (2 * sympy.pi * sympy.sqrt(r / g), r"2 \pi \sqrt{\frac{r}{g}}"),  # one root over and under the line
        (sympy.sqrt(g / h), r"\sqrt{\frac{g}{h}}"),
        (  # roots only under the line: one root there too, as the typed 1/sqrt(M*g)
            2 * sympy.pi * (h + r) ** sympy.Rational(3, 2) / (sympy.sqrt(M) * sympy.sqrt(g)),
            r"\frac{2 \pi \left(h + r\right)^{\frac{3}{2}}}{\sqrt{M g}}",
        ),
        (1 / (sympy.sqrt(M) * sympy.sqrt(g)), r"\frac{1}{\sqrt{M g}}"),
        (sympy.sqrt(g) * sympy.sqrt(4 * h - 4 * r), r"2 \sqrt{g \left(h - r\right)}"),  # the number outside
        (sympy.sqrt(4 * h - 4 * r), r"2 \sqrt{h - r}"),
        (m * v * sympy.exp(-k * x), r"m v e^{- k x}"),
        (sympy.atan(1 / (2 * mu)), r"\arctan{\left(\frac{1}{2 \mu} \right)}"),
        (m * v**2 / 2, r"\frac{m v^{2}}{2}"),
        (-M * g - N * COS + T, r"T - M g - N_{1} \cos{\left(\theta \right)}"),
        (
            (sympy.sin(X) - mu * sympy.cos(X)) * g,
            r"g \left(\sin{\left(X \right)} - \mu \cos{\left(X \right)}\right)",
        ),
        (sympy.Eq(ACCELERATION * m, T - m * g), r"m \ddot{x}_{\mathrm{block}} = T - m g"),
        (-x / 2, r"- \frac{x}{2}"),
        (g * (-M - m) * SIN**2, r"- \left(M + m\right) g \sin^{2}{\left(\theta \right)}"),
        ((-M - m) * (-g - x), r"\left(M + m\right) \left(g + x\right)"),
        (-(M + m), r"- M - m"),  # nothing added to start with
        (-(M + m) * g * h * (COS - 1), r"\left(M + m\right) g h \left(1 - \cos{\left(\theta \right)}\right)"),
        (-x * (h - 1), r"x \left(1 - h\right)"),
        (-5 * g / (7 * (r - h)), r"\frac{5 g}{7 h - 7 r}"),
    ],
)
def test_products_are_written_in_a_physics_texts_order(expr, written):
    assert latex(expr, symbol_names=WRITTEN) == written


@pytest.mark.parametrize(
    "expr",
    [m * v**2 / 2, -x / 2, k * x**2 / 2, N * SIN],
)
def test_an_expression_already_in_order_prints_as_sympy_prints_it(expr):
    assert latex(expr) == sympy.latex(expr)


def test_a_worked_solution_writes_newtons_law_mass_first():
    model = {
        "coordinates": ["y"],
        "bodies": {"ball": {"mass": "m", "position": {"y": "y"}}},
        "gravity": "g",
        "quantities": {"fall": {"acceleration": "y"}},
    }
    result = derive(load_model(model, {"m": m, "g": g}))
    newton = next(report for report in result.methods if report.name == "newton")
    shown = [step.latex for step in newton.steps]
    assert r"m \ddot{y}_{\mathrm{ball}} = - m g" in shown, shown


THETA_2 = 2 * theta


@pytest.mark.parametrize(
    ("expr", "written"),
    [
        (
            sympy.Eq(X, m * g * sympy.sin(THETA_2) / (-2 * M + m * sympy.cos(THETA_2) - m)),
            r"X = - \frac{m g \sin{\left(\theta \right)} \cos{\left(\theta \right)}}{M + m \sin^{2}{\left(\theta \right)}}",
        ),
        (
            M * g * sympy.sin(THETA_2) / (2 * M - m * sympy.cos(THETA_2) + m),
            r"\frac{M g \sin{\left(\theta \right)} \cos{\left(\theta \right)}}{M + m \sin^{2}{\left(\theta \right)}}",
        ),
        (sympy.cos(THETA_2), r"\cos{\left(2 \theta \right)}"),  # 2cos²θ - 1 would be longer
        (g * SIN, r"g \sin{\left(\theta \right)}"),
    ],
)
def test_worked_solutions_write_single_angles_where_no_longer(expr, written):
    rewritten = single_angles(expr)
    assert latex(rewritten) == written
    sides = zip(rewritten.args, expr.args, strict=True) if isinstance(expr, sympy.Eq) else [(rewritten, expr)]
    for new, old in sides:
        assert sympy.simplify(sympy.expand_trig(new - old)) == 0


def test_an_impacts_worked_solution_writes_its_own_symbols_as_physics_does():
    derived = compile_problem(bank_documents()["ballistic-pendulum"]).derived
    assert derived is not None
    shown = " ".join(step.latex for method in derived.raw.methods for step in method.steps)
    assert (
        r"v'_{x,\mathrm{block}}" in shown and r"J_{\mathrm{string}}" in shown
    )  # were u_{x block}, J_{string}
    assert r"\dot{\phi}" in shown and "phi_{dot}" not in shown
    assert r"\sqrt{2 g L \left(1 - \cos{\left(\theta \right)}\right)}" in shown


def test_small_oscillations_write_the_inertia_as_one_factor():
    # it was ½ 7mR²/5 - 14mRr/5 + 7mr²/5 θ̇²: a sum multiplied without brackets
    derived = compile_problem(bank_documents()["bowl-rolling"]).derived
    assert derived is not None
    energy = next(
        step.latex
        for method in derived.raw.methods
        for step in method.steps
        if step.title.startswith("Small oscillations from the energy")
    )
    assert r"\tfrac12\, \frac{7 m \left(" in energy and r"- \frac{14 m R r}{5}" not in energy, energy


def test_an_impacts_velocities_after_are_primed_and_its_constraint_impulses_named():
    derived = compile_problem(bank_documents()["ball-hits-rod"]).derived
    assert derived is not None
    shown = " ".join(step.latex for method in derived.raw.methods for step in method.steps)
    assert r"v'_{x,\mathrm{ball}}" in shown and r"\Lambda_{\mathrm{axlePivotX}}" in shown
    assert r"\dot{\phi}'" in shown
    assert "after}" not in shown  # were v_{x ball after}, \phi_{after}


def test_a_numeric_parts_expression_is_written_as_its_symbolic_reference_is():
    # "Evaluated from" printed 2 g m₂/(…) beside part 1's 2 m₂ g/(…): sympy's order, not the text's
    compiled = compile_problem(bank_documents()["table-pulley-friction"])
    symbolic, numeric = compiled.part("acceleration"), compiled.part("acceleration_numeric")
    assert numeric.expression == symbolic.expression
    assert numeric.solution().latex == symbolic.solution().latex == latex(symbolic.expression)
