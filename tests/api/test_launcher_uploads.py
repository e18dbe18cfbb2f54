"""A spring launcher uploaded as an instructor writes it (the block leaves a spring that only pushes,
then slides up a smooth incline): derived past where it leaves the spring and graded; its wrong variants
(the distance typed from the spring's natural length, the spring's energy with the wrong sign) refused
where written."""

from __future__ import annotations

from typing import Any

import pytest
import yaml

from tests.api.test_engine_uploads import _details, upload

LAUNCHER = """
id: my-launcher
title: A spring launcher at the foot of an incline
topics: [energy, springs]
statement: |
  A block of mass $m$ is held against a spring of stiffness $k$ and natural length $L_0$ at the foot of a
  frictionless incline at angle $\theta$, compressing it by $d$, and released. The spring is not fixed
  to the block. Use $g$ for the acceleration due to gravity; write $L_0$ as `L0`.

  For the numerical part: $m$ = {m}, $k$ = {k}, $d$ = {d}, $\theta$ = {theta}, $g$ = {g}.
symbols:
  m: {meaning: mass of the block, dimension: kg}
  k: {meaning: stiffness of the spring, dimension: N/m}
  d: {meaning: how far the spring is compressed, dimension: m}
  L0: {meaning: natural length of the spring, dimension: m}
  theta: {meaning: angle of the incline, dimension: "1", range: [0, "pi/2"]}
  g: {meaning: acceleration due to gravity, dimension: m/s^2}
constraints: ["k*d > 2*m*g*sin(theta)", "d < L0"]
given:
  m: {min: 0.2, max: 0.5, unit: kg, sigfigs: 2}
  k: {min: 400, max: 900, unit: N/m, sigfigs: 2}
  d: {min: 0.05, max: 0.10, unit: m, sigfigs: 2}
  L0: {min: 0.3, max: 0.3, unit: m}
  theta: {min: 20, max: 40, unit: deg, step: 1}
  g: {min: 9.81, max: 9.81, unit: m/s^2}
parts:
  - id: launch_speed
    kind: symbolic
    prompt: Find the block's speed when it leaves the spring.
    answer: sqrt(k*d^2/m - 2*g*d*sin(theta))
  - id: distance
    kind: symbolic
    prompt: How far up the incline from where it was released does the block get?
    answer: k*d^2/(2*m*g*sin(theta))
  - id: distance_numeric
    kind: numeric
    prompt: Using the values given, find that distance in metres.
    of: distance
    units: m
model:
  # s: the block's distance up the slope from the spring's fixed end at the foot
  elements:
    ramp: {kind: incline, body: block, mass: m, angle: theta, coordinate: s, direction: up}
    launcher: {kind: spring, between: [{x: 0, y: 0}, block], stiffness: k, length: L0, attached: false}
  gravity: g
  state: {s: L0 - d}
  domain:
    ranges: {theta: ["0", "pi/2"], s: ["0", "oo"]}
    positive: ["L0 - d", "k*d - 2*m*g*sin(theta)"]
  quantities:
    launch_speed: {speed: block, at: {s: L0}}
    highest: {turning_point: s}
    distance: {expression: "highest - (L0 - d)"}
  unused: [highest]
"""


def launcher() -> dict[str, Any]:
    doc = yaml.safe_load(LAUNCHER)
    assert isinstance(doc, dict)
    return doc


@pytest.mark.slow
def test_an_uploaded_launcher_derives_how_far_up_the_block_goes_past_the_spring(
    client, instructor_headers, student_headers
):
    response = upload(client, instructor_headers, launcher())
    assert response.status_code == 201, response.text
    graded = {
        answer: client.post(
            "/v1/problems/my-launcher/parts/distance/submissions",
            json={"answer": answer},
            headers=student_headers,
        ).json()["verdict"]
        for answer in ("k*d^2/(2*m*g*sin(theta))", "k*d^2/(2*m*g*sin(theta)) - d")
    }
    assert graded == {"k*d^2/(2*m*g*sin(theta))": "correct", "k*d^2/(2*m*g*sin(theta)) - d": "incorrect"}


def _distance_from_the_natural_length(doc: dict[str, Any]) -> None:
    doc["parts"][1]["answer"] = "k*d^2/(2*m*g*sin(theta)) - d"


def _energy_with_the_wrong_sign(doc: dict[str, Any]) -> None:
    del doc["model"]["elements"]["launcher"]
    doc["model"]["potentials"] = [
        {
            "bodies": ["block"],
            "anchor": {"x": 0, "y": 0},
            "distance": "D",
            "energy": "-k*(D - L0)^2/2",
            "reach": "L0",
        }
    ]


WRONG = [
    # (the variant, where it is refused, what that says)
    (_distance_from_the_natural_length, "parts[1].answer", "disagrees with the model"),
    (_energy_with_the_wrong_sign, "model.potentials[0]", "check its sign"),
]


@pytest.mark.slow
@pytest.mark.parametrize(("change", "path", "said"), WRONG)
@pytest.mark.sample(3)
def test_an_uploaded_launcher_written_wrong_is_refused_where_written(
    client, instructor_headers, change: Any, path: str, said: str
):
    doc = launcher()
    change(doc)
    details = _details(upload(client, instructor_headers, doc))
    assert said in details[path], details
