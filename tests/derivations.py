"""Counting what is sent to the derivation workers (rather than loaded from a store or a shipped bank)."""

from __future__ import annotations

from typing import Any

import pytest

from app.derivation import DerivationPool


def count_derivations(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    """The ids of the documents sent to `DerivationPool.submit` from now on, in order."""
    sent: list[str] = []
    real = DerivationPool.submit

    def counting(self: DerivationPool, document: Any, **options: Any) -> Any:
        sent.append(document["id"])
        return real(self, document, **options)

    monkeypatch.setattr(DerivationPool, "submit", counting)
    return sent
