"""Reading student and instructor math without evaluating text: a tokenizer, a precedence parser of
our own, and a builder that calls sympy constructors directly (never eval, sympify or parse_expr)."""

from physics.mathinput.bench import bench_cases
from physics.mathinput.limits import DEFAULT_LIMITS, InputLimits
from physics.mathinput.reader import ParsedMath, parse_expression, parse_math

__all__ = ["DEFAULT_LIMITS", "InputLimits", "ParsedMath", "bench_cases", "parse_expression", "parse_math"]
