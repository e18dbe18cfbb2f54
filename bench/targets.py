"""The issue's speed targets, measured side by side in one run on this machine.

    .venv/bin/python bench/targets.py [--duration 10] [--concurrency 16] [--warmup 2]

Starts a trivial FastAPI app and a naive parse_expr + simplify service (bench/trivial_app.py, uvicorn)
and physcheck's own server (bench/load.py's OwnServer), then drives each with the same closed-loop
client (bench/load.py's `drive`), one phase after another:

  floor      POST /echo on the trivial app: FastAPI's own cost per request here
  distinct   POST /v1/check, the typical bank answers of bench/load.py, every request's text new
             (`(answer)*n/n`, numeric answers with n leading spaces): no verdict is reused
  identical  POST /v1/check, one typical request over and over: the verdict cache's case
  naive      POST /naive: bench/check_bench.py's typical answers, parse_expr + simplify per request

and prints requests/s, p50 and p99, then each target: distinct >= 20 % of the floor's requests/s
with p99 <= 50 ms, identical >= 60 % of the floor, naive >= 100x slower than distinct. The machine's
load moves every figure; the ratios are measured in one run.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator, Sequence
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

HERE = Path(__file__).resolve().parent
DISTINCT_VARIANTS = 400


def distinct_checks() -> list[Call]:
    """Every typical check in DISTINCT_VARIANTS spellings that read the same: no two bodies equal."""
    calls = []
    for n in range(2, DISTINCT_VARIANTS + 2):
        for answer, expected, symbols, verdict in SYMBOLIC:
            body = {
                "kind": "symbolic",
                "answer": f"({answer})*{n}/{n}",
                "expected": expected,
                "symbols": symbols,
            }
            calls.append(post("/v1/check", body, expect=verdict))
        for answer, value, units, tolerance, verdict in NUMERIC:
            numeric: dict[str, object] = {"kind": "numeric", "answer": " " * n + answer, "expected": value}
            if units is not None:
                numeric["units"] = units
            if tolerance is not None:
                numeric["tolerance"] = tolerance
            calls.append(post("/v1/check", numeric, expect=verdict))
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


def naive_checks() -> list[Call]:
    return [
        Call(
            "POST",
            "/naive",
            json.dumps({"answer": a, "expected": e, "symbols": [s.name for s in symbols]}).encode(),
        )
        for a, e, symbols in CASES
    ]


@contextlib.contextmanager
def trivial_app(directory: Path) -> Iterator[str]:
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


async def measure(
    url: str, key: str | None, name: str, calls: Sequence[Call], args: argparse.Namespace
) -> Phase:
    limits = httpx.Limits(max_connections=args.concurrency, max_keepalive_connections=args.concurrency)
    headers = {"authorization": f"Bearer {key}"} if key else {}
    async with httpx.AsyncClient(
        base_url=url, headers=headers, timeout=60, limits=limits, trust_env=False
    ) as client:
        if args.warmup > 0:
            await drive(client, name, calls, args.concurrency, args.warmup)
        phase = await drive(client, name, calls, args.concurrency, args.duration)
    n = len(phase.honest.latencies)
    statuses = ", ".join(f"{s}: {c}" for s, c in sorted(phase.honest.statuses.items()))
    print(
        f"{name:<12}{n:>9}{n / phase.elapsed:>10.1f}{percentile(phase.honest.latencies, 50):>10.1f}"
        f"{percentile(phase.honest.latencies, 99):>10.1f}   {statuses}"
    )
    for what, count in phase.honest.unexpected.most_common():
        print(f"    NOT THE EXPECTED VERDICT ({count}x): {what}")
    sys.stdout.flush()
    return phase


def rate(phase: Phase) -> float:
    return len(phase.honest.latencies) / phase.elapsed


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--duration", type=float, default=10.0)
    parser.add_argument("--concurrency", type=int, default=16)
    parser.add_argument("--warmup", type=float, default=2.0)
    parser.add_argument("--naive-duration", type=float, default=10.0)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="physcheck-targets-") as tmp, trivial_app(Path(tmp)) as trivial:
        server = OwnServer(Path(tmp), None)
        server.env["PHYSCHECK_WARM_UP"] = "false"  # /v1/check needs no bank: ready without deriving it
        try:
            key = server.create_key()
            server.start()
            server.wait_ready()
            print(
                f"{args.concurrency} connections, {args.duration:g} s per phase after {args.warmup:g} s warm-up"
            )
            print(f"{'phase':<12}{'requests':>9}{'req/s':>10}{'p50 ms':>10}{'p99 ms':>10}   statuses")
            floor = asyncio.run(measure(trivial, None, "floor", [Call("POST", "/echo", b"{}")], args))
            distinct = asyncio.run(measure(server.url, key, "distinct", distinct_checks(), args))
            identical = asyncio.run(measure(server.url, key, "identical", identical_check(), args))
            naive_args = argparse.Namespace(**{**vars(args), "duration": args.naive_duration, "warmup": 0})
            naive = asyncio.run(measure(trivial, None, "naive", naive_checks(), naive_args))
        finally:
            server.stop()
    share = rate(distinct) / rate(floor)
    p99 = percentile(distinct.honest.latencies, 99)
    print(f"distinct:  {share:.1%} of the floor (target >= 20 %), p99 {p99:.0f} ms (target <= 50 ms)")
    print(f"identical: {rate(identical) / rate(floor):.1%} of the floor (target >= 60 %)")
    print(f"naive:     {rate(distinct) / max(rate(naive), 1e-9):.0f}x slower than distinct (target >= 100x)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
