"""Pydantic models of the HTTP edge, named by role (`...In` for requests, `...Public` for responses)."""
