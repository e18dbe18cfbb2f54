"""Bar charts as SVG drawn on the server: no script, no web font, readable at 390 px and on a desktop.

Each chart is an image with a title and a description for screen readers; the page puts the same
numbers in a table beside it, which is the chart's full text alternative.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from markupsafe import Markup, escape

WIDTH = 320  # user units; the CSS scales the chart to the column's width (text ~15 px on a phone)
ROW = 40  # label line above, bar below
FORMULA_ROW = 54  # a label typeset as a formula (a fraction) needs more room above its bar
TOP = 8
LABEL_CHARS = 42
BAR_COLOUR = "#1a5fb4"
TEXT_COLOUR = "#1a1a1a"


@dataclass(frozen=True)
class Bar:
    label: str  # plain text: the chart's description for screen readers, and the label when no `shown`
    value: float
    text: str  # written after the bar, e.g. "12 (40 %)"
    shown: Markup | None = None  # the label as the page typesets it (a known mistake's formula, as MathML)


def _short(label: str) -> str:
    label = " ".join(label.split())
    return label if len(label) <= LABEL_CHARS else label[: LABEL_CHARS - 1] + "…"


def bar_chart(chart_id: str, title: str, bars: Sequence[Bar], *, maximum: float | None = None) -> Markup:
    """Horizontal bars, each with its label above it and its number after it; `maximum` fixes the
    scale (100 for percentages), else the largest value fills the width."""
    top = maximum if maximum is not None else max((bar.value for bar in bars), default=0.0)
    scale = 0.0 if top <= 0 else 1.0 / top
    room = WIDTH - 100  # space kept for the number after the longest bar
    row = FORMULA_ROW if any(bar.shown is not None for bar in bars) else ROW
    label_room = row - 22  # above the bar
    height = TOP + row * max(len(bars), 1) + 4
    summary = "; ".join(f"{bar.label}: {bar.text}" for bar in bars) or "nothing to show yet"
    rows = []
    for index, bar in enumerate(bars):
        y = TOP + row * index
        bar_top = y + label_room
        length = max(room * bar.value * scale, 0.0)
        label = (
            f'<text x="0" y="{bar_top - 5}" fill="{TEXT_COLOUR}" font-size="13">{escape(_short(bar.label))}</text>'
            if bar.shown is None
            # typeset like the page's formulas (MathML in an HTML island), clipped to the chart's width
            else f'<foreignObject x="0" y="{y - 4}" width="{WIDTH}" height="{label_room + 2}"><div '
            f'xmlns="http://www.w3.org/1999/xhtml" class="chart-label">{bar.shown}</div></foreignObject>'
        )
        rows.append(
            label + f'<rect x="0" y="{bar_top}" width="{length:.1f}" height="14" fill="{BAR_COLOUR}"/>'
            f'<text x="{length + 6:.1f}" y="{bar_top + 12}" fill="{TEXT_COLOUR}" font-size="13">'
            f"{escape(bar.text)}</text>"
        )
    if not bars:
        rows.append(f'<text x="0" y="{TOP + 20}" fill="{TEXT_COLOUR}" font-size="13">No data yet.</text>')
    # Every value above went through escape(); the rest is our own constant markup.
    return Markup(  # noqa: S704
        f'<svg class="chart" viewBox="0 0 {WIDTH} {height}" role="img" '
        f'aria-labelledby="{escape(chart_id)}-title {escape(chart_id)}-desc" '
        f'xmlns="http://www.w3.org/2000/svg" font-family="system-ui, sans-serif">'
        f'<title id="{escape(chart_id)}-title">{escape(title)}</title>'
        f'<desc id="{escape(chart_id)}-desc">{escape(summary)}</desc>'
        f"{''.join(rows)}</svg>"
    )
