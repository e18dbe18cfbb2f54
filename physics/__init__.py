"""The physics core: reading answers, deciding them, and deriving reference answers.

Imports only sympy, pint and the standard library; the web layer lives in `app/`.
"""
