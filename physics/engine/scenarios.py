"""Several scenarios of one system in one model: each overrides part of the model and is derived apart.

    impact: {bodies: [cart1, cart2], restitution: 1}
    quantities: {v2: {final_velocity: cart2}}
    scenarios:
      sticking:                          # the same carts, a perfectly inelastic impact
        impact: {restitution: 0}         # merged into the model's own impact
        quantities: {v: {final_velocity: cart2}}

A scenario's sections are merged into the model's (mappings key by key, so `impact: {restitution: 0}`
keeps the impact's bodies; a list, such as `forces`, is replaced whole; `null` removes a key). Its
`quantities` (required), `unused` and `limits` are its own, never inherited: a scenario asks its own
questions, and each is derived, proved and simulated as a model of its own. Its quantities are named
`<scenario>.<quantity>` in the derivation, which is how a part asks for one (`quantity: sticking.v`).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from typing import Any

from physics.engine.model import Model, Quantity
from physics.engine.results import Derivation, MethodReport, Step
from physics.errors import DerivationError, SpecError, SpecErrors

KEY = "scenarios"
OWN = ("quantities", "unused", "limits")  # a scenario's own: never inherited from the model
MAX_SCENARIOS = 6  # each is a whole derivation


def split(data: Any) -> tuple[Any, Mapping[str, Any]]:
    """(the model without its scenarios, the scenarios' overrides by name)."""
    if not isinstance(data, Mapping) or KEY not in data:
        return data, {}
    base = {k: v for k, v in data.items() if k != KEY}
    given = data[KEY]
    if not isinstance(given, Mapping) or not given:
        raise SpecErrors([SpecError("a mapping of scenario names to what each changes", (KEY,))])
    if len(given) > MAX_SCENARIOS:
        raise SpecErrors([SpecError(f"at most {MAX_SCENARIOS} scenarios", (KEY,))])
    faults: list[SpecError] = []
    for name, override in given.items():
        path = (KEY, str(name))
        if not isinstance(name, str) or not name.isidentifier() or "." in name:
            faults.append(SpecError("a scenario's name is a plain name (letters, digits, _)", path))
        elif not isinstance(override, Mapping):
            faults.append(SpecError("a mapping of the sections this scenario changes", path))
        elif KEY in override:
            faults.append(SpecError("a scenario cannot hold scenarios of its own", (*path, KEY)))
        elif not isinstance(override.get("quantities"), Mapping) or not override["quantities"]:
            faults.append(
                SpecError(
                    "a scenario asks its own quantities (the model's are not inherited): give them here",
                    (*path, "quantities"),
                )
            )
    if faults:
        raise SpecErrors(faults)
    return base, given


def merged(base: Mapping[str, Any], override: Mapping[str, Any]) -> dict[str, Any]:
    """The model as the scenario has it: the model's sections but its own questions, the scenario's
    sections merged in."""
    return _deep({k: v for k, v in base.items() if k not in OWN}, override)


def _deep(base: Mapping[str, Any], override: Mapping[str, Any]) -> dict[str, Any]:
    """Mappings merged key by key, anything else replaced; None removes the key."""
    result = dict(base)
    for key, value in override.items():
        if value is None:
            result.pop(key, None)
        elif isinstance(value, Mapping) and isinstance(result.get(key), Mapping):
            result[key] = _deep(result[key], value)
        else:
            result[key] = value
    return result


def load(
    base: Mapping[str, Any], overrides: Mapping[str, Any], load_one: Callable[[Mapping[str, Any]], Model]
) -> tuple[tuple[str, Model], ...]:
    """Each scenario's model, every fault at its path under `scenarios.<name>`."""
    loaded: list[tuple[str, Model]] = []
    faults: list[SpecError] = []
    for name, override in overrides.items():
        try:
            loaded.append((name, load_one(merged(base, override))))
        except SpecErrors as group:
            faults += [SpecError(e.message, (KEY, name, *e.path)) for e in group.errors]
        except SpecError as error:
            faults.append(SpecError(error.message, (KEY, name, *error.path)))
    if faults:
        raise SpecErrors(faults)
    return tuple(loaded)


def qualified(scenario: str, quantity: str) -> str:
    return f"{scenario}.{quantity}"


def quantity_path(name: str) -> tuple[str, ...]:
    """Where a quantity named in the derivation is written in the model: a scenario's under its own."""
    scenario, dot, own = name.partition(".")
    return (KEY, scenario, "quantities", own) if dot else ("quantities", name)


def quantity_names(model: Model) -> dict[str, tuple[str, ...]]:
    """Every quantity the model derives, by its name in the derivation, with the names it uses."""
    names = {q.name: _used(q) for q in model.quantities}
    for scenario, own in model.scenarios:
        for q in own.quantities:
            names[qualified(scenario, q.name)] = tuple(qualified(scenario, n) for n in _used(q))
    return names


def _used(quantity: Quantity) -> tuple[str, ...]:
    """The other quantities this one uses: its own `uses`, and those its inner quantity names (a `solve`'s
    `zero:` or an extremum's `of:` may name another quantity)."""
    inner = quantity.inner.uses if quantity.inner is not None else ()
    return tuple(n for _, n in (*quantity.uses, *inner))


def unused(model: Model) -> tuple[str, ...]:
    return (*model.unused, *(qualified(s, n) for s, own in model.scenarios for n in own.unused))


def relocated(error: DerivationError, scenario: str) -> DerivationError:
    """A scenario's failure, placed under `scenarios.<name>` and saying which scenario."""
    items = [
        ((KEY, scenario, *path), f"in scenario {scenario!r}: {message}") for path, message in error.items()
    ]
    return DerivationError(
        "; ".join(message for _, message in items),
        quantity=qualified(scenario, error.quantity) if error.quantity else None,
        path=items[0][0],
        findings=items,
    )


def combined(base: Derivation, scenarios: list[tuple[str, Derivation]]) -> Derivation:
    """One derivation: the model's quantities, and each scenario's under `<scenario>.<name>`; each
    method's worked steps for a scenario follow its own, titled with the scenario."""
    quantities = dict(base.quantities)
    agreement, simulation = dict(base.agreement), dict(base.simulation)
    mistakes, limits, proofs = dict(base.mistakes), dict(base.limits), dict(base.proofs)
    checks = dict(base.checks)
    reports = {r.name: r for r in base.methods}
    order = [r.name for r in base.methods]
    for scenario, derived in scenarios:

        def named(mapping: Mapping[str, Any], scenario: str = scenario) -> dict[str, Any]:
            return {qualified(scenario, k): v for k, v in mapping.items()}

        quantities |= named(derived.quantities)
        agreement |= named(derived.agreement)
        simulation |= named(derived.simulation)
        mistakes |= named(derived.mistakes)
        limits |= named(derived.limits)
        proofs |= named(derived.proofs)
        checks |= {f"{k} (scenario {scenario})": v for k, v in derived.checks.items()}
        for report in derived.methods:
            if report.name not in reports:
                order.append(report.name)
            reports[report.name] = _joined(reports.get(report.name), report, scenario)
    return Derivation(
        quantities,
        tuple(reports[name] for name in order),
        agreement,
        simulation,
        mistakes,
        limits,
        proofs,
        checks,
        base.notation,
    )


def _joined(first: MethodReport | None, then: MethodReport, scenario: str) -> MethodReport:
    said = _in_words(scenario)
    steps = tuple(
        Step(f"{step.title} (scenario {said})", step.latex, step.kind, step.unknowns, step.symbols)
        for step in then.steps
    )
    results = {qualified(scenario, k): v for k, v in then.results.items()}
    notes = tuple(f"{scenario}: {note}" for note in then.notes)
    if first is None:
        return MethodReport(then.name, then.title, steps, results, notes, then.forces)
    return MethodReport(
        first.name,
        first.title,
        first.steps + steps,
        {**first.results, **results},
        first.notes + notes,
        tuple(dict.fromkeys(first.forces + then.forces)),
    )


def _in_words(scenario: str) -> str:
    """A scenario's name as a worked solution's reader reads it: `other_side` and `otherSide` are
    "other side", `case2` "case 2" (the name itself is the model's, never shown)."""
    return re.sub(r"(?<=[a-z])(?=[A-Z0-9])", " ", scenario).replace("_", " ").lower()
