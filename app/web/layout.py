"""Server-rendered pages: one Jinja2 environment (FastAPI's `Jinja2Templates`, autoescaped), one base
layout (`base.html`), one stylesheet and our scripts under `/static`, and `page()` to answer with a
template under a strict Content-Security-Policy (no inline scripts or styles; nothing from elsewhere).

Templates get the renderer as filters: `{{ text | markdown }}` (paragraphs), `{{ text | inline }}`
(one line: prompts, feedback), `{{ tex | tex }}` (one formula), `{{ tex | tex_block }}`.
"""

from __future__ import annotations

import html
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from fastapi import Request
from fastapi.responses import HTMLResponse
from fastapi.staticfiles import StaticFiles
from fastapi.templating import Jinja2Templates
from markupsafe import Markup

from app.courses.policy import shown
from app.web.rendering import render_inline, render_markdown, tex_to_mathml
from physics.mathinput.render import in_student_style
from problems import kinds as answer_kinds

HERE = Path(__file__).resolve().parent
STATIC_PATH = "/static"

# Each answer kind's own templates (`<kind>/student.html`, `<kind>/described.html`) live beside its module.
templates = Jinja2Templates(directory=[HERE / "templates", Path(answer_kinds.__file__).resolve().parent])
templates.env.filters["markdown"] = render_markdown
templates.env.filters["inline"] = render_inline
templates.env.filters["tex"] = tex_to_mathml
templates.env.filters["in_zone"] = shown  # a moment as its course reads it, as the banner gives the due date


def _tex_block(tex: str) -> Markup:
    return tex_to_mathml(tex, display=True)


templates.env.filters["tex_block"] = _tex_block
_SCALE_NOTE = re.compile(r'^<svg[^>]*\sdata-scale-note="([^"]*)"')


def scale_note(svg: str | None) -> str:
    """What a figure could not draw at its value ("Not to scale: α = 2° is drawn as 5°."), or ""."""
    found = _SCALE_NOTE.match(svg or "")
    return html.unescape(found.group(1)) if found else ""


templates.env.filters["scale_note"] = scale_note


def marks_coordinates(svg: str | None) -> bool:
    """Whether a figure draws a coordinate's blue arrow (physics/figures/shapes.py mark_coordinate says
    so in its description): only then may a caption point the reader to blue arrows."""
    return "grows along the blue arrow" in (svg or "")


templates.env.filters["marks_coordinates"] = marks_coordinates
# an answer as read, in the student style of typing (`r0/2^(1/6)`), never the contract's `**`
templates.env.filters["typed"] = in_student_style


def still_deriving(request: Request) -> str | None:
    """While a first start still derives the bank (what `/ready` calls compiling): how far it is, said
    on the pages users land on ("12 of 40"; "" before it counts); None once every problem is ready."""
    services = getattr(request.app.state, "services", None)
    if services is None or services.catalog.warm.is_set():
        return None
    progress = services.catalog.deriving
    return "" if progress is None else f"{progress[0]} of {progress[1]}"


templates.env.globals["still_deriving"] = still_deriving


def static_files() -> StaticFiles:
    """Mounted at STATIC_PATH by the app: physcheck.css and the pages' scripts."""
    return StaticFiles(directory=HERE / "static")


def security_headers(frame_ancestors: Sequence[str] = ()) -> dict[str, str]:
    ancestors = " ".join(["'self'", *frame_ancestors])
    csp = (
        "default-src 'none'; style-src 'self'; script-src 'self'; img-src 'self' data:; font-src 'self'; "
        f"connect-src 'self'; form-action 'self'; frame-ancestors {ancestors}; base-uri 'none'"
    )
    return {
        "Content-Security-Policy": csp,
        "X-Content-Type-Options": "nosniff",
        "Referrer-Policy": "no-referrer",
        "Cache-Control": "no-store",
    }


def page(
    request: Request,
    template: str,
    context: Mapping[str, Any] | None = None,
    *,
    status: int = 200,
    frame_ancestors: Sequence[str] = (),
) -> HTMLResponse:
    """`template` (which extends base.html) rendered with `context`; framable only by
    `frame_ancestors` (an LMS's origins) besides ourselves."""
    return templates.TemplateResponse(
        request,
        template,
        dict(context or {}),
        status_code=status,
        headers=security_headers(frame_ancestors),
    )
