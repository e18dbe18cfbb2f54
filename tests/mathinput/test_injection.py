"""Code in an answer is never run: each payload is refused as an answer error and leaves no trace."""

from __future__ import annotations

import pytest

from physics.errors import AnswerError, ParseError, UnknownFunction, UnknownSymbol
from tests.mathinput.support import read


def payloads(marker: str) -> list[str]:
    return [
        f"__import__('os').system('touch {marker}')",
        f'__import__("os").system("touch {marker}")',
        "().__class__.__bases__[0].__subclasses__()",
        "().__class__",
        "x.__class__",
        f"lambda: __import__('os').system('touch {marker}')",
        "lambda x: x",
        f"`touch {marker}`",
        f'f\'{{__import__("os").system("touch {marker}")}}\'',
        f"exec('import os; os.system(\"touch {marker}\")')",
        "eval('1')",
        "exec(x)",
        "open(x)",
        "getattr(x, x)",
        "os.system(x)",
        "import os",
        "x if x else x",
        "[x for x in x]",
        "Symbol('x')",
        "sympify(x)",
        "x; import os",
        "$(touch /tmp/x)",
        "x\\n",
        "{'a': 1}",
        "x@x",
        "x & x",
        "x == x",
        "x < x",
        "~x",
    ]


def test_payloads_are_refused_and_nothing_runs(tmp_path):
    marker = tmp_path / "pwned"
    for payload in payloads(str(marker)):
        with pytest.raises((ParseError, UnknownSymbol, UnknownFunction)):
            read(payload, "x")
    assert not marker.exists()


@pytest.mark.parametrize("payload", payloads("/nonexistent/marker"))
def test_each_payload_is_an_answer_error(payload):
    with pytest.raises(AnswerError):
        read(payload, "x")
