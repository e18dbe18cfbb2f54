"""The two reference services of bench/targets.py, served by uvicorn like physcheck itself.

POST /echo   the trivial floor: FastAPI parses a JSON body and answers a small JSON object.
POST /naive  what many graders do: parse_expr on both texts and simplify(a - b) == 0 (benchmark only:
             parse_expr evaluates text, which physcheck never does).
"""

from __future__ import annotations

from typing import Any

import sympy
from fastapi import FastAPI
from sympy.parsing.sympy_parser import (
    convert_xor,
    implicit_multiplication_application,
    parse_expr,
    standard_transformations,
)

app = FastAPI()
TRANSFORMATIONS = (*standard_transformations, implicit_multiplication_application, convert_xor)


@app.post("/echo")
async def echo(body: dict[str, Any]) -> dict[str, Any]:
    return {"verdict": "correct", "reason": "equivalent", "length": len(body)}


@app.post("/naive")
def naive(body: dict[str, Any]) -> dict[str, Any]:
    table = {name: sympy.Symbol(name, positive=True) for name in body["symbols"]}
    answer = parse_expr(body["answer"], local_dict=table, transformations=TRANSFORMATIONS)
    expected = parse_expr(body["expected"], local_dict=table, transformations=TRANSFORMATIONS)
    correct = sympy.simplify(answer - expected) == 0
    return {"verdict": "correct" if correct else "incorrect", "reason": "naive"}
