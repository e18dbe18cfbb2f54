"""After a perfectly inelastic impact the bodies touch at one velocity, and the motion asked about next
is taken without the contact: it must part them, or keep them just touching. A cart that does not bounce
off one resting on a spring pushes it along (they move on as one body), and free of each other it would
pass through it: refused at the impact. One held back by its own spring parts from the other, and
derives."""

from __future__ import annotations

from typing import Any

import pytest
import sympy

from physics.engine import derivation, load_model
from physics.errors import DerivationError

uncached = derivation._derive.__wrapped__
m1, m2, k, L0, u = (sympy.Symbol(n, positive=True) for n in ("m1", "m2", "k", "L0", "u"))
TABLE = {str(s): s for s in (m1, m2, k, L0, u)}


def carts(sprung: str, spring_end: dict[str, str], side: list[str]) -> dict[str, Any]:
    """Cart 1 at u runs into cart 2 at rest, without bouncing; `sprung` is on a spring of natural length
    L0 to a wall at `spring_end`."""
    return {
        "coordinates": ["x1", "x2"],
        "bodies": {
            "cart1": {"mass": "m1", "position": {"x": "x1"}},
            "cart2": {"mass": "m2", "position": {"x": "x2"}},
        },
        "elements": {
            "spring": {"kind": "spring", "between": [sprung, spring_end], "stiffness": "k", "length": "L0"}
        },
        "state": {"x1": 0, "x2": 0, "x1_dot": "u", "x2_dot": 0},
        "impact": {"bodies": ["cart1", "cart2"], "normal": {"x": 1}, "restitution": 0},
        "domain": {"ranges": {sprung.replace("cart", "x"): side}},
        "quantities": {"far": {"turning_point": sprung.replace("cart", "x"), "after": "impact"}},
    }


# cart 2 on a spring to a wall ahead: slowed, pushed on by cart 1 (squeezed by m1 u/sqrt(k (m1 + m2)),
# not m1 u sqrt(m2/k)/(m1 + m2) as if cart 1 passed through); cart 1 held back by a spring behind it
PRESSED = carts("cart2", {"x": "L0"}, ["-oo", "L0"])
PARTING = carts("cart1", {"x": "-L0"}, ["-L0", "oo"])


def test_bodies_that_would_close_on_each_other_after_a_perfectly_inelastic_impact_are_refused() -> None:
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(PRESSED, TABLE))
    assert caught.value.path == ("impact",)
    assert "cart1 and cart2 would close on each other" in caught.value.message


def test_bodies_that_part_after_a_perfectly_inelastic_impact_derive() -> None:
    far = uncached(load_model(PARTING, TABLE)).quantities["far"]
    assert sympy.simplify(far - m1 * u / (m1 + m2) * sympy.sqrt(m1 / k)) == 0


def _bouncing(restitution: str) -> dict[str, Any]:
    """Equal carts: cart 1 bounces off cart 2, which runs on into a spring ahead."""
    model = carts("cart2", {"x": "L0"}, ["-oo", "L0"])
    model["bodies"]["cart2"]["mass"] = "m1"
    model["impact"]["restitution"] = restitution
    return model


def test_bodies_that_meet_again_before_the_quantity_after_a_weak_bounce_are_refused() -> None:
    # e = 1/10: cart 1 goes on at 0.45 u, cart 2 at 0.55 u slowed by the spring, caught before it stops
    with pytest.raises(DerivationError) as caught:
        uncached(load_model(_bouncing("1/10"), TABLE))
    assert caught.value.path == ("quantities", "far")
    assert "meet again" in caught.value.message


def test_an_elastic_bounce_that_leaves_the_struck_cart_alone_derives() -> None:
    # e = 1: cart 1 stops dead, cart 2 takes u into the spring
    far = uncached(load_model(_bouncing("1"), TABLE)).quantities["far"]
    assert sympy.simplify(far - u * sympy.sqrt(m1 / k)) == 0
