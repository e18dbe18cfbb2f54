"""The few HTML pages the LTI flow shows: refusals, the deep-linking picker, the auto-posted form back
to the platform. Everything interpolated is escaped; pages are framable only by registered platforms."""

from __future__ import annotations

import secrets
from collections.abc import Sequence
from dataclasses import dataclass
from html import escape
from urllib.parse import urlsplit

from fastapi.responses import HTMLResponse

from app.lti.errors import LaunchRefused

_STYLE = (
    "body{font-family:system-ui,sans-serif;max-width:42rem;margin:2rem auto;padding:0 1rem;line-height:1.5}"
    "code{background:#f3f3f3;padding:0 .25rem}"
    "button{font-size:1rem;padding:.4rem 1rem}"
    "fieldset{border:1px solid #ccc}"
    "input[type=text],input[type=password]{font-size:1.1rem;padding:.3rem;width:100%;box-sizing:border-box}"
    ".preview{color:#333;min-height:1.5em;margin:.25rem 0 .75rem;font-family:ui-monospace,monospace}"
    ".hint{color:#4d4d4d;margin:.25rem 0}"
    "[data-verdict=correct]{color:#0a6b2d}[data-verdict=incorrect]{color:#a11}"
    "[data-verdict=invalid]{color:#7a4100}"
    ".earlier{margin:.25rem 0}"
    ".part{border-top:1px solid #ddd;margin-top:1.5rem}"
    ":focus-visible{outline:3px solid #1a5fb4;outline-offset:2px}"
    ".visually-hidden{position:absolute;width:1px;height:1px;overflow:hidden;clip:rect(0 0 0 0);"
    "white-space:nowrap}"
)


def origin_of(url: str) -> str | None:
    parts = urlsplit(url)
    if parts.scheme in ("https", "http") and parts.netloc:
        return f"{parts.scheme}://{parts.netloc}"
    return None


def html_page(
    title: str,
    body: str,
    *,
    status: int = 200,
    frame_ancestors: Sequence[str] = (),
    form_targets: Sequence[str] = (),
    script: str | None = None,
    script_src: str | None = None,
    meta: dict[str, str] | None = None,
) -> HTMLResponse:
    """`body` is HTML the caller built with escaped values; `script` (ours, constant) and the script
    file at `script_src` (ours) run by nonce; `meta` adds `<meta name content>` tags."""
    nonce = secrets.token_urlsafe(16)
    ancestors = " ".join(["'self'", *frame_ancestors])
    form_action = " ".join(["'self'", *form_targets])
    csp = (
        f"default-src 'none'; style-src 'nonce-{nonce}'; script-src 'nonce-{nonce}'; connect-src 'self'; "
        f"form-action {form_action}; frame-ancestors {ancestors}; base-uri 'none'"
    )
    script_tag = f'<script nonce="{nonce}">{script}</script>' if script else ""
    if script_src:
        script_tag += f'<script nonce="{nonce}" src="{escape(script_src)}"></script>'
    meta_tags = "".join(
        f'<meta name="{escape(name)}" content="{escape(value)}">' for name, value in (meta or {}).items()
    )
    document = (
        '<!doctype html><html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f'{meta_tags}<title>{escape(title)}</title><style nonce="{nonce}">{_STYLE}</style></head>'
        f"<body><main>{body}</main>{script_tag}</body></html>"
    )
    headers = {
        "Content-Security-Policy": csp,
        "X-Content-Type-Options": "nosniff",
        "Referrer-Policy": "no-referrer",
        "Cache-Control": "no-store",
    }
    return HTMLResponse(document, status_code=status, headers=headers)


def refusal_page(error: LaunchRefused, *, frame_ancestors: Sequence[str] = ()) -> HTMLResponse:
    body = (
        "<h1>This launch was refused</h1>"
        f'<p role="alert">{escape(error.message)}</p>'
        f"<p>Reason code: <code>{escape(error.code)}</code>. Go back to your course and open the "
        "activity again; if this keeps happening, tell your instructor or the LMS administrator.</p>"
    )
    return html_page("Launch refused", body, status=error.status, frame_ancestors=frame_ancestors)


def unavailable_page(message: str, *, status: int = 502) -> HTMLResponse:
    body = f'<h1>The LMS could not be reached</h1><p role="alert">{escape(message)}</p>'
    return html_page("LMS unavailable", body, status=status)


@dataclass(frozen=True)
class ProblemChoice:
    id: str
    title: str
    score_maximum: float


def picker_page(
    request_id: str,
    csrf_token: str,
    choices: Sequence[ProblemChoice],
    *,
    frame_ancestors: Sequence[str],
    multiple: bool = True,
) -> HTMLResponse:
    """Checkboxes, or radio buttons when the platform takes one item (`accept_multiple: false`)."""
    kind = "checkbox" if multiple else "radio"
    items = "".join(
        "<li><label>"
        f'<input type="{kind}" name="problem" value="{escape(choice.id)}"> '
        f"{escape(choice.title)} <code>{escape(choice.id)}</code></label></li>"
        for choice in choices
    )
    legend = (
        "Assignments and problems to add to the course (an assignment is one link with one grade)"
        if multiple
        else "The assignment or problem to add (this LMS takes one per link)"
    )
    body = (
        "<h1>Add physcheck problems</h1>"
        f'<form method="post" action="/lti/deep-link/{escape(request_id)}">'
        f'<input type="hidden" name="csrf_token" value="{escape(csrf_token)}">'
        f"<fieldset><legend>{legend}</legend><ul>{items}</ul></fieldset>"
        f'<p><button type="submit">Add selected problem{"s" if multiple else ""}</button></p></form>'
    )
    return html_page("Add physcheck problems", body, frame_ancestors=frame_ancestors)


def auto_post_page(action: str, fields: dict[str, str], *, frame_ancestors: Sequence[str]) -> HTMLResponse:
    """A form that posts itself (the LTI way back to the platform), with a button if scripts are off."""
    inputs = "".join(
        f'<input type="hidden" name="{escape(name)}" value="{escape(value)}">'
        for name, value in fields.items()
    )
    body = (
        f'<form id="return" method="post" action="{escape(action)}">{inputs}'
        "<p>Returning to your course…</p>"
        '<noscript><button type="submit">Continue</button></noscript></form>'
    )
    target = origin_of(action)
    return html_page(
        "Returning to your course",
        body,
        frame_ancestors=frame_ancestors,
        form_targets=[target] if target else [],
        script='document.getElementById("return").submit();',
    )
