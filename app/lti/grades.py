"""From a graded submission to the score the LMS shows: the sum over the problem's parts of the best
score on each (so a later wrong attempt never lowers a grade), out of the number of parts, which is the
line item's `scoreMaximum` that deep linking sets. The stores queue it as a submission is filed."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any


def score_of(document: Mapping[str, Any], best: Mapping[str, float]) -> tuple[float, float]:
    """(score given, score maximum) from the best score on each part: one point per part."""
    parts = document.get("parts")
    part_ids = [p.get("id") for p in parts if isinstance(p, dict)] if isinstance(parts, list) else []
    given = sum(best.get(str(part_id), 0.0) for part_id in part_ids)
    return given, float(max(len(part_ids), 1))
