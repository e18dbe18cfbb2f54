"""Our typesetting beside MathJax's, on the same page: every `<math>` the server made is swapped for
MathJax's SVG of the same TeX (its `alttext`), and both are screenshotted at the same width.

MathJax (npm `mathjax-full` 3.2.2) is a test-only tool: `npm install --prefix .mathjax mathjax-full@3.2.2`
(or PHYSCHECK_MATHJAX=<its node_modules>). Pages never load it. Used by the browser test and by hand:

    .venv/bin/python -m tests.web.side_by_side URL OUT_PREFIX [SELECTOR] [--width 390] [--key KEY]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
RENDER = HERE / "mathjax_render.js"


def mathjax_dir() -> Path | None:
    """Where mathjax-full is installed, or None."""
    candidates = [os.environ.get("PHYSCHECK_MATHJAX"), str(HERE.parent.parent / ".mathjax" / "node_modules")]
    for candidate in candidates:
        if candidate and (Path(candidate) / "mathjax-full" / "js" / "mathjax.js").exists():
            return Path(candidate)
    return None


def mathjax_svgs(items: list[dict[str, Any]]) -> dict[str, Any]:
    """{css, svgs} for [{tex, display}] from MathJax in node."""
    where = mathjax_dir()
    node = shutil.which("node")
    if where is None or node is None:
        raise RuntimeError("MathJax (npm mathjax-full) or node is not installed")
    done = subprocess.run(
        [node, str(RENDER)],
        input=json.dumps(items),
        capture_output=True,
        text=True,
        check=True,
        env={**os.environ, "PHYSCHECK_MATHJAX": str(where)},
        timeout=120,
    )
    result: dict[str, Any] = json.loads(done.stdout)
    return result


_FORMULAS = """() => Array.from(document.querySelectorAll('math')).map(
  m => ({tex: m.getAttribute('alttext') || '', display: m.getAttribute('display') === 'block'}))"""
_SWAP = """([css, svgs]) => {
  const style = document.createElement('style'); style.textContent = css; document.head.appendChild(style);
  Array.from(document.querySelectorAll('math')).forEach((m, i) => {
    const holder = document.createElement('span'); holder.innerHTML = svgs[i]; m.replaceWith(holder.firstChild);
  });
}"""


def swap_in_mathjax(page: Any) -> int:
    """Replace every <math> on the Playwright `page` (opened with bypass_csp) by MathJax's rendering of
    its TeX; returns how many were swapped."""
    items = page.evaluate(_FORMULAS)
    if not items:
        return 0
    rendered = mathjax_svgs(items)
    page.evaluate(_SWAP, [rendered["css"], rendered["svgs"]])
    return len(items)


def screenshot_pair(page: Any, out: Path, selector: str | None = None) -> tuple[Path, Path]:
    """`out`-ours.png and `out`-mathjax.png of the page (or its `selector`) as it stands."""
    ours, theirs = out.with_name(out.name + "-ours.png"), out.with_name(out.name + "-mathjax.png")
    target = page.locator(selector).first if selector else page
    kwargs: dict[str, Any] = {} if selector else {"full_page": True}
    target.screenshot(path=str(ours), **kwargs)
    swap_in_mathjax(page)
    page.wait_for_timeout(100)
    target.screenshot(path=str(theirs), **kwargs)
    return ours, theirs


def main() -> None:  # pragma: no cover - a tool run by hand
    from playwright.sync_api import sync_playwright

    from tests.browser import CHROMIUM, CHROMIUM_ARGS

    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("url")
    parser.add_argument("out")
    parser.add_argument("selector", nargs="?")
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--scale", type=float, default=1.0, help="device pixels per CSS pixel")
    parser.add_argument("--instructor-key")
    parser.add_argument("--student-key")
    args = parser.parse_args()
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        context = browser.new_context(
            viewport={"width": args.width, "height": 900}, bypass_csp=True, device_scale_factor=args.scale
        )
        page = context.new_page()
        base = "/".join(args.url.split("/")[:3])
        if args.instructor_key:
            page.goto(base + "/instructor/sign-in")
            page.fill("input[name=key]", args.instructor_key)
            page.click("button[type=submit]")
            page.wait_for_load_state()
        if args.student_key:
            page.goto(base + "/problems")
            page.evaluate("k => sessionStorage.setItem('physcheck-student-key', k)", args.student_key)
        page.goto(args.url, timeout=240_000)
        page.wait_for_load_state("networkidle")
        page.wait_for_timeout(300)  # the math font
        for path in screenshot_pair(page, Path(args.out), args.selector):
            print(path)
        browser.close()


if __name__ == "__main__":  # pragma: no cover
    main()
