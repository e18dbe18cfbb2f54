"""The issue's speed targets, measured side by side in one run on this machine.

    .venv/bin/python bench/targets.py [--rounds 3] [--duration 10] [--concurrency 16] [--warmup 2]

Starts a trivial FastAPI app and a naive parse_expr + simplify service (bench/trivial_app.py, uvicorn)
and physcheck's own server (bench/load.py's OwnServer), then drives each with the same closed-loop
client, one phase after another. The client is wrk (Debian's `wrk`, as the issue measured: a C client
that leaves the cores to the servers) when it is installed, with a Lua script cycling through the
phase's request bodies; else, or with `--client python`, bench/load.py's `drive` (httpx, which itself
takes much of a core and so lowers every figure, the floor's too):

  floor      POST /echo on the trivial app: FastAPI's own cost per request here
  distinct   POST /v1/check, the typical bank answers of bench/load.py, every request's text new
             (each answer times a factor that equals 1 but is a new expression for each n, numeric
             answers spaced anew for each n, within their 200 characters): no verdict and no
             remembered judgement is reused
  identical  POST /v1/check, one typical request over and over: the verdict cache's case
  same       POST /v1/check, bench/check_bench.py's typical answers (parse_expr's syntax) in the
             distinct phase's forms, every text new
  new        POST /v1/check, new references over the usual names: distinct's checks with the
             reference and the answer each times (n + 1)/(n + 2), a new n per request (a course
             script's own references, new uploads): every reference is read and prepared anew
  renamed    POST /v1/check, new references under names never seen: every symbol renamed `m` ->
             `m_n` in the reference, the answer and the declarations (new symbols, a new domain)
  naive      POST /naive: the same texts as `same`, parse_expr + simplify per request, in one uvicorn
             process as the issue measured it (simplify holds the GIL: one core)
  naive x2   the same on two uvicorn processes, one per core as physcheck's workers: how much of the
             ratio is physcheck using both cores

in turn, `--rounds` times with new texts each round, and prints requests/s, p50 and p99 of each, then
each target as the median over the rounds of its ratio within a round (this machine's speed moves by
a third within minutes; a ratio of two phases a minute apart moves less): distinct >= 40 % of the
floor's requests/s and new >= 25 %, each with p99 <= 25 ms; renamed >= 15 %; identical >= 60 % of
the floor; naive >= 100x slower than physcheck on the same texts (`same`; also printed: how much
slower than `distinct`, a different mix of answers). The numeric checks of `new` and `renamed` are
distinct's (a numeric reference is a number: nothing to read or prepare). The python client also checks every verdict; wrk counts only statuses (the verdicts of the
same bodies are checked by the python client).
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import dataclasses
import functools
import json
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import httpx
from check_bench import CASES
from load import (
    LOOPBACK,
    NUMERIC,
    SYMBOLIC,
    Call,
    OwnServer,
    Phase,
    _new_session_dying_with_parent,
    drive,
    free_port,
    percentile,
    post,
)

from physics.checking import SymbolDecl

HERE = Path(__file__).resolve().parent
# More texts than a phase sends at 6,000 requests/s (`same` has ten per form): none repeated.
DISTINCT_VARIANTS = 6000
ROUND_STRIDE = DISTINCT_VARIANTS  # between the first forms of two rounds' texts
# `spaced` makes 90,000 numeric forms: the warm-up's are the last of them, past every round's.
WARM_UP_FIRST = 90_000 - DISTINCT_VARIANTS
MAX_ROUNDS = (WARM_UP_FIRST - 2) // ROUND_STRIDE


# Two symbols of one dimension in each symbol set of bench/load.py's typical answers.
SAME_DIMENSION = [("m", "M"), ("r", "k"), ("r0", "r"), ("alpha", "mu"), ("m1", "m2")]


def unit_factor(symbols: dict[str, object], n: int) -> str:
    """(a + n b)^2/(a^2 + 2n ab + n^2 b^2): equal to 1, yet a new expression for each n. A plain `*n/n`
    would read as the answer itself, whose judgement the worker remembers from the first spelling."""
    a, b = next(pair for pair in SAME_DIMENSION if set(pair) <= symbols.keys())
    return f"({a} + {n} {b})^2/({a}^2 + {2 * n} {a} {b} + {n * n} {b}^2)"


def spaced(answer: str, n: int) -> str:
    """A numeric answer with spaces that make it new for each n: before it, and between its number and
    its units (or after it). Within the 200 characters a numeric answer may have: past them it is
    refused unread, a cheaper check than any real one."""
    number, _, units = answer.partition(" ")
    before, between, after = " " * (n % 30), " " * (1 + n // 30 % 100), " " * (n // 3000 % 30)
    return f"{before}{number}{between}{units}{after}"


def distinct_checks(first: int = 2) -> list[Call]:
    """Every typical check in DISTINCT_VARIANTS forms of the same value: no two bodies and no two answer
    expressions equal (a warm-up draws its forms from another `first`, so the measured phase reuses no
    verdict and no judgement)."""
    calls = []
    for n in range(first, first + DISTINCT_VARIANTS):
        for answer, expected, symbols, verdict in SYMBOLIC:
            body = {
                "kind": "symbolic",
                "answer": f"({answer}) {unit_factor(symbols, n)}",
                "expected": expected,
                "symbols": symbols,
            }
            calls.append(post("/v1/check", body, expect=verdict))
        for answer, value, units, tolerance, verdict in NUMERIC:
            numeric: dict[str, object] = {"kind": "numeric", "answer": spaced(answer, n), "expected": value}
            if units is not None:
                numeric["units"] = units
            if tolerance is not None:
                numeric["tolerance"] = tolerance
            calls.append(post("/v1/check", numeric, expect=verdict))
    return calls


def scaled(text: str, n: int) -> str:
    """`text` times (n + 1)/(n + 2): a new expression for each n, scaled as its partner is."""
    return f"({text})*({n} + 1)/({n} + 2)"


def _numeric_calls(n: int) -> list[Call]:
    """The typical numeric checks, spaced anew for n: a numeric reference is a number, nothing to prepare."""
    calls = []
    for answer, value, units, tolerance, verdict in NUMERIC:
        numeric: dict[str, object] = {"kind": "numeric", "answer": spaced(answer, n), "expected": value}
        if units is not None:
            numeric["units"] = units
        if tolerance is not None:
            numeric["tolerance"] = tolerance
        calls.append(post("/v1/check", numeric, expect=verdict))
    return calls


def new_reference_checks(first: int = 2, variants: int = DISTINCT_VARIANTS) -> list[Call]:
    """Every typical check with a reference never sent before, over the usual names: the reference and
    the answer each scaled by the same new factor (a course script's own references, new uploads)."""
    calls = []
    for n in range(first, first + variants):
        for answer, expected, symbols, verdict in SYMBOLIC:
            body = {
                "kind": "symbolic",
                "answer": scaled(answer, n),
                "expected": scaled(expected, n),
                "symbols": symbols,
            }
            calls.append(post("/v1/check", body, expect=verdict))
        calls += _numeric_calls(n)
    return calls


# A declared name and every spelling of it that bench/load.py's typical answers use.
_SPELLINGS = {"theta": ("theta", "θ"), "alpha": ("alpha", "α"), "mu": ("mu", "μ")}


def renamed(text: str, names: Iterable[str], n: int) -> str:
    """`text` with each of `names` (as a whole word, in any of its spellings) suffixed `_n`: `m` -> `m_7`."""
    for name in names:
        for spelling in _SPELLINGS.get(name, (name,)):
            text = re.sub(rf"(?<![^\W\d_]){re.escape(spelling)}(?![\w])", f"{spelling}_{n}", text)
    return text


def renamed_checks(first: int = 2, variants: int = DISTINCT_VARIANTS) -> list[Call]:
    """Every typical check under names never seen (`m` -> `m_n`, `theta` -> `theta_n`): a new domain,
    new symbols, a new reference and a new answer for each n."""
    calls = []
    for n in range(first, first + variants):
        for answer, expected, symbols, verdict in SYMBOLIC:
            body = {
                "kind": "symbolic",
                "answer": renamed(answer, symbols, n),
                "expected": renamed(expected, symbols, n),
                "symbols": {f"{name}_{n}": spec for name, spec in symbols.items()},
            }
            calls.append(post("/v1/check", body, expect=verdict))
        calls += _numeric_calls(n)
    return calls


def identical_check() -> list[Call]:
    answer, expected, symbols, verdict = SYMBOLIC[0]
    return [
        post(
            "/v1/check",
            {"kind": "symbolic", "answer": answer, "expected": expected, "symbols": symbols},
            expect=verdict,
        )
    ]


def with_same_dimension_pair(symbols: tuple[SymbolDecl, ...]) -> tuple[SymbolDecl, ...]:
    """The symbols, plus the partner of a SAME_DIMENSION pair (declared alike) when none is complete."""
    names = {s.name: s for s in symbols}
    if any(set(pair) <= names.keys() for pair in SAME_DIMENSION):
        return symbols
    have, partner = next((a, b) if a in names else (b, a) for a, b in SAME_DIMENSION if {a, b} & names.keys())
    return (*symbols, dataclasses.replace(names[have], name=partner))


def same_answers(first: int = 2) -> list[tuple[str, str, tuple[SymbolDecl, ...]]]:
    """check_bench's typical answers (parse_expr's syntax, which physcheck reads too) in the distinct
    phase's forms: (answer, expected, symbols), every answer text new."""
    cases = []
    for n in range(first, first + DISTINCT_VARIANTS):
        for answer, expected, symbols in CASES:
            symbols = with_same_dimension_pair(symbols)
            factor = unit_factor({s.name: s for s in symbols}, n).replace("^", "**")
            cases.append((f"({answer})*{factor}", expected, symbols))
    return cases


def same_checks(first: int = 2) -> list[Call]:
    """`same_answers` as physcheck's /v1/check bodies."""
    calls = []
    for answer, expected, symbols in same_answers(first):
        declared: dict[str, dict[str, object]] = {}
        for symbol in symbols:
            declared[symbol.name] = {"dimension": symbol.dimension}
            if symbol.range is not None:
                declared[symbol.name]["range"] = list(symbol.range)
        body = {"kind": "symbolic", "answer": answer, "expected": expected, "symbols": declared}
        calls.append(post("/v1/check", body))
    return calls


def naive_checks(first: int = 2) -> list[Call]:
    """`same_answers` as the naive service's bodies: the very texts of `same_checks`."""
    return [
        Call(
            "POST",
            "/naive",
            json.dumps({"answer": a, "expected": e, "symbols": [s.name for s in symbols]}).encode(),
        )
        for a, e, symbols in same_answers(first)
    ]


@contextlib.contextmanager
def trivial_app(directory: Path, workers: int = 1) -> Iterator[str]:
    port = free_port()
    with (directory / "trivial.log").open("ab") as log:
        process = subprocess.Popen(
            [
                sys.executable,
                "-m",
                "uvicorn",
                "trivial_app:app",
                "--app-dir",
                str(HERE),
                "--host",
                LOOPBACK,
                "--port",
                str(port),
                "--log-level",
                "warning",
                "--no-access-log",
                "--workers",
                str(workers),
            ],
            stdout=log,
            stderr=subprocess.STDOUT,
            preexec_fn=_new_session_dying_with_parent,
        )
    url = f"http://{LOOPBACK}:{port}"
    try:
        deadline = time.monotonic() + 60
        with httpx.Client(trust_env=False, timeout=2) as client:
            while time.monotonic() < deadline:
                with contextlib.suppress(httpx.HTTPError):
                    if client.post(f"{url}/echo", json={}).status_code == 200:
                        break
                time.sleep(0.1)
        yield url
    finally:
        process.terminate()
        process.wait(timeout=15)


@dataclass(frozen=True)
class Result:
    name: str
    requests: int
    rate: float  # requests/s
    p50: float  # ms
    p99: float  # ms
    statuses: str


def show(result: Result) -> Result:
    print(
        f"{result.name:<12}{result.requests:>9}{result.rate:>10.1f}{result.p50:>10.1f}"
        f"{result.p99:>10.1f}   {result.statuses}"
    )
    sys.stdout.flush()
    return result


def lua_string(text: str) -> str:
    level = "=" * 4
    assert f"]{level}]" not in text
    return f"[{level}[{text}]{level}]"


def wrk_script(calls: Sequence[Call], key: str | None) -> str:
    """A wrk script sending `calls` in turn; each wrk thread starts at its own share of them."""
    bodies = ",\n".join(lua_string((call.body or b"").decode()) for call in calls)
    auth = f'wrk.headers["Authorization"] = {lua_string("Bearer " + key)}\n' if key else ""
    return f"""
local paths = {{{", ".join(lua_string(call.path) for call in calls)}}}
local bodies = {{
{bodies}
}}
local threads = 0
function setup(thread)
  thread:set("first", threads)
  threads = threads + 1
end
local i = 0
function init(args)
  i = (first or 0) * 7919 % #bodies
end
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
{auth}
function request()
  i = i % #bodies + 1
  return wrk.format(nil, paths[i], nil, bodies[i])
end
"""


UNITS = {"us": 1e-3, "ms": 1.0, "s": 1000.0, "m": 60000.0}


def wrk_ms(text: str) -> float:
    match = re.fullmatch(r"([\d.]+)(us|ms|s|m)", text)
    assert match, text
    return float(match[1]) * UNITS[match[2]]


def wrk_measure(
    url: str, key: str | None, name: str, calls: Sequence[Call], args: argparse.Namespace, tmp: Path
) -> Result:
    script = tmp / f"{name}.lua"
    script.write_text(wrk_script(calls, key))
    # wrk's default 2 s timeout would count the naive service's slow answers as errors, not latencies.
    command = ["wrk", f"-t{args.threads}", f"-c{args.concurrency}", "--timeout", "120s", "--latency"]
    command += ["-s", str(script), url]
    if args.warmup > 0:
        subprocess.run([*command[:1], f"-d{args.warmup:g}s", *command[1:]], check=True, capture_output=True)
    out = subprocess.run(
        [*command[:1], f"-d{args.duration:g}s", *command[1:]], check=True, capture_output=True, text=True
    ).stdout
    percentiles = {p: wrk_ms(v) for p, v in re.findall(r"^\s+(50|99)%\s+(\S+)\s*$", out, re.M)}
    if len(percentiles) < 2:
        raise SystemExit(f"wrk printed no latency distribution for {name}:\n{out}")
    requests = int(re.search(r"(\d+) requests in", out)[1])  # type: ignore[index]
    bad = re.search(r"Non-2xx or 3xx responses: (\d+)", out)
    errors = re.search(r"Socket errors: (.*)$", out, re.M)
    statuses = f"2xx: {requests - (int(bad[1]) if bad else 0)}" + (f", non-2xx: {bad[1]}" if bad else "")
    if errors:
        statuses += f", socket errors: {errors[1]}"
    rate_ = float(re.search(r"Requests/sec:\s+([\d.]+)", out)[1])  # type: ignore[index]
    return show(Result(name, requests, rate_, percentiles["50"], percentiles["99"], statuses))


async def measure(
    url: str, key: str | None, name: str, calls: Sequence[Call], args: argparse.Namespace
) -> Result:
    limits = httpx.Limits(max_connections=args.concurrency, max_keepalive_connections=args.concurrency)
    headers = {"authorization": f"Bearer {key}"} if key else {}
    async with httpx.AsyncClient(
        base_url=url, headers=headers, timeout=60, limits=limits, trust_env=False
    ) as client:
        if args.warmup > 0:
            await drive(client, name, calls, args.concurrency, args.warmup)
        phase = await drive(client, name, calls, args.concurrency, args.duration)
    for what, count in phase.honest.unexpected.most_common():
        print(f"    NOT THE EXPECTED VERDICT ({count}x): {what}")
    return show(summary(name, phase))


def summary(name: str, phase: Phase) -> Result:
    n = len(phase.honest.latencies)
    statuses = ", ".join(f"{s}: {c}" for s, c in sorted(phase.honest.statuses.items()))
    latencies = phase.honest.latencies
    return Result(name, n, n / phase.elapsed, percentile(latencies, 50), percentile(latencies, 99), statuses)


def measure_phase(
    client: str, tmp: Path, url: str, key: str | None, name: str, calls: list[Call], args: argparse.Namespace
) -> Result:
    if client == "wrk":
        return wrk_measure(url, key, name, calls, args, tmp)
    return asyncio.run(measure(url, key, name, calls, args))


@dataclass(frozen=True)
class Round:
    floor: Result
    distinct: Result
    identical: Result
    same: Result
    new: Result
    renamed: Result
    naive: Result
    naive_two: Result


def summarize(rounds: Sequence[Round]) -> None:
    """Each target as the median over the rounds of its ratio within a round (the machine's speed moves
    between rounds, and within one the phases are a minute apart at most), with every round's value."""

    def line(ratios: list[float], form: str) -> str:
        return f"median {form.format(statistics.median(ratios))} (rounds: {', '.join(form.format(r) for r in ratios)})"

    share = [r.distinct.rate / r.floor.rate for r in rounds]
    p99 = [r.distinct.p99 for r in rounds]
    new = [r.new.rate / r.floor.rate for r in rounds]
    new_p99 = [r.new.p99 for r in rounds]
    renamed = [r.renamed.rate / r.floor.rate for r in rounds]
    identical = [r.identical.rate / r.floor.rate for r in rounds]
    naive = [r.same.rate / max(r.naive.rate, 1e-9) for r in rounds]
    naive_distinct = [r.distinct.rate / max(r.naive.rate, 1e-9) for r in rounds]
    naive_two = [r.same.rate / max(r.naive_two.rate, 1e-9) for r in rounds]
    print(f"floor:     median {statistics.median(r.floor.rate for r in rounds):,.0f} requests/s")
    print(f"distinct:  {line(share, '{:.1%}')} of the floor (target >= 40 %)")
    print(f"           p99 {line(p99, '{:.0f} ms')} (target <= 25 ms)")
    print(f"new:       {line(new, '{:.1%}')} of the floor (target >= 25 %)")
    print(f"           p99 {line(new_p99, '{:.0f} ms')} (target <= 25 ms)")
    print(f"renamed:   {line(renamed, '{:.1%}')} of the floor (target >= 15 %)")
    print(f"identical: {line(identical, '{:.0%}')} of the floor (target >= 60 %)")
    print(f"naive:     {line(naive, '{:.0f}x')} slower than physcheck on the same answers (target >= 100x)")
    print(f"           {line(naive_distinct, '{:.0f}x')} slower than distinct")
    print(
        f"           {line(naive_two, '{:.0f}x')} slower on the same answers when it runs in two processes, "
        "one per core, as physcheck's workers do (the issue's naive service ran in one)"
    )


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--duration", type=float, default=10.0)
    parser.add_argument("--concurrency", type=int, default=16)
    parser.add_argument("--warmup", type=float, default=2.0)
    parser.add_argument("--naive-duration", type=float, default=10.0)
    parser.add_argument(
        "--rounds", type=int, default=3, help="every phase, this many times in turn (medians are quoted)"
    )
    parser.add_argument(
        "--client", choices=["wrk", "python"], default="wrk" if shutil.which("wrk") else "python"
    )
    parser.add_argument(
        "--threads", type=int, default=1, help="wrk's threads (default 1: the servers need the cores)"
    )
    args = parser.parse_args(argv)
    if args.rounds > MAX_ROUNDS:
        parser.error(f"--rounds: at most {MAX_ROUNDS}, or a round's numeric answers would repeat another's")
    with (
        tempfile.TemporaryDirectory(prefix="physcheck-targets-") as tmp,
        trivial_app(Path(tmp)) as trivial,
        trivial_app(Path(tmp), workers=2) as trivial_two,
    ):
        server = OwnServer(Path(tmp), None)
        server.env["PHYSCHECK_WARM_UP"] = "false"  # /v1/check needs no bank: ready without deriving it
        try:
            key = server.create_key()
            server.start()
            server.wait_ready()
            print(
                f"client {args.client}, {args.concurrency} connections, {args.duration:g} s per phase "
                f"after {args.warmup:g} s warm-up"
            )
            print(f"{'phase':<12}{'requests':>9}{'req/s':>10}{'p50 ms':>10}{'p99 ms':>10}   statuses")
            # A phase of new texts warms up on other texts (`first`), or the verdicts it cached would
            # serve the measured phase; the floor and identical phases warm up on their own request.
            cold = argparse.Namespace(**{**vars(args), "warmup": 0})
            naive_args = argparse.Namespace(**{**vars(cold), "duration": args.naive_duration})
            warm = argparse.Namespace(**{**vars(cold), "duration": args.warmup})
            run = functools.partial(measure_phase, args.client, Path(tmp))
            if args.warmup > 0:
                warm_up = distinct_checks(WARM_UP_FIRST) + same_checks(WARM_UP_FIRST)
                # (their references: a few hundred of each suffice, and a script of 150,000 is large)
                warm_up += new_reference_checks(WARM_UP_FIRST, 400) + renamed_checks(WARM_UP_FIRST, 400)
                run(server.url, key, "(warm-up)", warm_up, warm)
            rounds = []
            for number in range(args.rounds):
                # Each round's texts are new (`first`): none is answered from an earlier round's verdict.
                first = 2 + number * ROUND_STRIDE
                distinct_calls, same_calls = distinct_checks(first), same_checks(first)
                new_calls, renamed_calls = new_reference_checks(first), renamed_checks(first)
                print(f"round {number + 1}")
                result = Round(
                    floor=run(trivial, None, "floor", [Call("POST", "/echo", b"{}")], args),
                    distinct=run(server.url, key, "distinct", distinct_calls, cold),
                    identical=run(server.url, key, "identical", identical_check(), args),
                    same=run(server.url, key, "same", same_calls, cold),
                    new=run(server.url, key, "new", new_calls, cold),
                    renamed=run(server.url, key, "renamed", renamed_calls, cold),
                    naive=run(trivial, None, "naive", naive_checks(first), naive_args),
                    naive_two=run(trivial_two, None, "naive x2", naive_checks(first), naive_args),
                )
                sent_texts = (
                    (result.distinct, distinct_calls),
                    (result.same, same_calls),
                    (result.new, new_calls),
                    (result.renamed, renamed_calls),
                )
                for phase, sent in sent_texts:
                    if phase.requests > len(sent):
                        print(
                            f"WARNING: {phase.name} sent {phase.requests} requests of {len(sent)} texts: some repeated"
                        )
                rounds.append(result)
        finally:
            server.stop()
    summarize(rounds)
    return 0


if __name__ == "__main__":
    sys.exit(main())
