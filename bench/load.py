"""Requests/s and p50/p99 latency of a running physcheck server on loopback, phase after phase in one run.

By default it starts its own server (`physcheck serve`) on a free 127.0.0.1 port, in its own process
group, with a fresh SQLite database in a temporary directory and the rate limits raised, creates an
instructor key, waits for `/ready`, then runs against that one server, one phase after another:

  1. floor        `GET /health`: the HTTP floor (routing, middleware, no auth, no grading);
  2. check        typical `POST /v1/check`: the bank's answers, symbolic and numeric with units,
                  correct and wrong;
  3. submissions  typical `POST /v1/problems/{id}/parts/{part}/submissions` (graded and stored), with
                  numeric answers computed from each student's own given values;
  4. hostile      the check load with about 10 % hostile answers mixed in (`9^9^9`, `(m+2)^10000`,
                  100 000 nested parentheses, `1e999999`, a 1 MB answer, `m^(m^(m^m))`, injection
                  text, ...); honest and hostile requests are reported apart.

Each phase runs a fixed number of concurrent clients (httpx.AsyncClient) for a bounded time after an
untimed warm-up, and prints requests/s, p50 and p99 in ms and the counts by status; at the end, each
phase's p50 over the floor's. The client runs on the same machine as the server and takes CPU from it.

    .venv/bin/python bench/load.py [--duration 10] [--concurrency 8] [--warmup 2] [--check-workers N]
    .venv/bin/python bench/load.py --url http://127.0.0.1:8000 --key <instructor key>

It sends traffic only to 127.0.0.1 and stops by itself; its own server is shut down (the whole process
group, grading workers included) on the way out, also on Ctrl-C, SIGTERM or an error.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import ctypes
import itertools
import json
import math
import os
import random
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import FrameType
from typing import Any
from urllib.parse import urlsplit

import httpx

LOOPBACK = "127.0.0.1"
REPO = Path(__file__).resolve().parent.parent
# Far above what a run can send: the limits are not what this measures.
RATE_LIMIT = "100000000"
REQUEST_TIMEOUT = 60.0
READY_TIMEOUT = 180.0
SEED = 20261121

# --------------------------------------------------------------------------------------------------
# The requests


@dataclass(frozen=True)
class Call:
    """One request, its body encoded once so the client spends its CPU on sending, not on json.dumps."""

    method: str
    path: str
    body: bytes | None
    hostile: bool = False
    expect: str | None = None  # the verdict a correct server gives (honest requests only)
    label: str = ""  # names the request where its verdict is not the expected one


def post(path: str, body: dict[str, Any], *, hostile: bool = False, expect: str | None = None) -> Call:
    label = f"{path.removeprefix('/v1/problems/')} {str(body.get('answer'))[:40]!r}"
    return Call("POST", path, json.dumps(body).encode(), hostile, expect, label)


KG, ACC = {"dimension": "kg"}, {"dimension": "m/s^2"}
ANGLE = {"dimension": "1", "range": [0, "pi/2"]}
WEDGE = {"m": KG, "M": KG, "g": ACC, "theta": ANGLE}
YOYO = {"m": KG, "r": {"dimension": "m"}, "k": {"dimension": "m"}, "g": ACC}
LJ = {"U0": {"dimension": "J"}, "r0": {"dimension": "m"}, "r": {"dimension": "m"}, "m": KG}
PENDULUM = {"m": KG, "M": KG, "L": {"dimension": "m"}, "theta": ANGLE, "g": ACC}
SKIER = {"alpha": ANGLE, "mu": {"dimension": "1"}, "g": ACC, "m": KG}

# (answer, expected, symbols, verdict): typical student answers to the bank's parts, a third wrong.
SYMBOLIC: list[tuple[str, str, dict[str, Any], str]] = [
    (
        "-m g sin(θ)cos(θ)/(M + m sin^2 θ)",
        "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)",
        WEDGE,
        "correct",
    ),
    ("-m g sin(theta) cos(theta)/M", "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)", WEDGE, "incorrect"),
    ("(M + m) g sin θ/(M + m sin^2 θ)", "(M + m)*g*sin(theta)/(M + m*sin(theta)**2)", WEDGE, "correct"),
    ("g sin(theta)", "(M + m)*g*sin(theta)/(M + m*sin(theta)**2)", WEDGE, "incorrect"),
    ("M m g cos(theta)/(M + m sin(theta)^2)", "M*m*g*cos(theta)/(M + m*sin(theta)**2)", WEDGE, "correct"),
    ("g r^2/(r^2 + k^2)", "g*r**2/(r**2 + k**2)", YOYO, "correct"),
    ("2g/3", "g*r**2/(r**2 + k**2)", YOYO, "incorrect"),
    ("m g/(1 + r^2/k^2)", "m*g*k**2/(r**2 + k**2)", YOYO, "correct"),
    ("12 sqrt(U0/m)/r0", "12*sqrt(U0/m)/r0", LJ, "correct"),
    ("sqrt(72 U0/(m r0^2))", "12*sqrt(U0/m)/r0", LJ, "incorrect"),
    ("72 U0/r0^2", "72*U0/r0**2", LJ, "correct"),
    ("2(m + M) sqrt(g L) sin(θ/2)/m", "(m + M)/m*sqrt(2*g*L*(1 - cos(theta)))", PENDULUM, "correct"),
    ("M/(m + M)", "M/(m + M)", PENDULUM, "correct"),
    ("g(sin α - μ cos α)", "g*(sin(alpha) - mu*cos(alpha))", SKIER, "correct"),
    ("g (sin(alpha) + mu cos(alpha))", "g*(sin(alpha) - mu*cos(alpha))", SKIER, "incorrect"),
    ("sin(alpha)", "tan(alpha)", SKIER, "incorrect"),
]

# (answer, expected, units, tolerance, verdict)
NUMERIC: list[tuple[str, float, str | None, dict[str, Any] | None, str]] = [
    ("4.58 m/s^2", 4.5807, "m/s^2", {"rel": 0.01}, "correct"),
    ("16.5 km/h", 4.58, "m/s", None, "correct"),
    ("4.8 m/s^2", 4.5807, "m/s^2", None, "incorrect"),
    ("-2.37 m/s²", -2.3712, "m/s^2", None, "correct"),
    ("2.37 m/s^2", -2.3712, "m/s^2", None, "incorrect"),
    ("4.58", 4.5807, "m/s^2", None, "invalid"),
    ("1.61e13 rad/s", 1.6093e13, "rad/s", None, "correct"),
    ("4.58 m/s^2", 4.5807, "m/s^2", {"sigfigs": 3}, "correct"),
    ("0.0875", 0.08749, None, None, "correct"),
]

MEGABYTE = 1_000_000
# Hostile answers: huge powers, deep nesting, huge literals, oversized text, injection attempts.
HOSTILE_SYMBOLIC: list[str] = [
    "9^9^9",
    "(m+2)^10000",
    "(" * 100_000 + "m" + ")" * 100_000,
    "1e999999",
    "m*" * (MEGABYTE // 2) + "g",
    "(" * 990 + "m" + ")" * 990,
    "sin(" * 400 + "theta" + ")" * 400,
    "exp(exp(exp(exp(exp(exp(m))))))",  # held a worker to the time limit (in sympy evalf) before 2026-11-26
    "m^(m^(m^m))",
    "10^10^10^10 * m g",
    "factorial(10^10)",
    "sec(sinh(10^40)^2) m g",  # held a worker to the time limit (sympy's realness query) before 2026-11-26
    "__import__('os').system('echo pwned')",
    "'; DROP TABLE submissions; --",
    "<script>alert(1)</script>{{7*7}}${jndi:ldap://127.0.0.1/x}",
    "m\u0000g\u202esin(theta)",
]
HOSTILE_NUMERIC: list[str] = [
    "1e999999 m/s^2",
    "9^9^9 m/s^2",
    "4.58 " + "m/" * 900 + "s",
    "1" * 1999 + " m/s^2",
]


def check_calls() -> list[Call]:
    calls = [
        post(
            "/v1/check",
            {"kind": "symbolic", "answer": a, "expected": e, "symbols": s},
            expect=v,
        )
        for a, e, s, v in SYMBOLIC
    ]
    for answer, expected, units, tolerance, verdict in NUMERIC:
        body: dict[str, Any] = {"kind": "numeric", "answer": answer, "expected": expected}
        if units is not None:
            body["units"] = units
        if tolerance is not None:
            body["tolerance"] = tolerance
        calls.append(post("/v1/check", body, expect=verdict))
    return calls


def hostile_calls() -> list[Call]:
    wedge = SYMBOLIC[0]
    calls = [
        post(
            "/v1/check",
            {"kind": "symbolic", "answer": a, "expected": wedge[1], "symbols": wedge[2]},
            hostile=True,
        )
        for a in HOSTILE_SYMBOLIC
    ]
    calls += [
        post(
            "/v1/check",
            {"kind": "numeric", "answer": a, "expected": 4.5807, "units": "m/s^2"},
            hostile=True,
        )
        for a in HOSTILE_NUMERIC
    ]
    return calls


def mixed(honest: Sequence[Call], hostile: Sequence[Call], percent: float, rng: random.Random) -> list[Call]:
    """A long shuffled sequence in which `percent` % of the calls are hostile."""
    total = 1000
    bad = round(total * percent / 100)
    calls = [honest[i % len(honest)] for i in range(total - bad)] + [
        hostile[i % len(hostile)] for i in range(bad)
    ]
    rng.shuffle(calls)
    return calls


# Numeric submissions: the reference computed here from each student's own given values (units cancel
# or are the ones the part asks for; angles are given in degrees).
def wedge_acceleration(g: dict[str, float]) -> float:
    t = math.radians(g["theta"])
    return -g["m"] * g["g"] * math.sin(t) * math.cos(t) / (g["M"] + g["m"] * math.sin(t) ** 2)


def yoyo_acceleration(g: dict[str, float]) -> float:
    return g["g"] * g["r"] ** 2 / (g["r"] ** 2 + g["k"] ** 2)


def skier_acceleration(g: dict[str, float]) -> float:
    a = math.radians(g["alpha"])
    return g["g"] * (math.sin(a) - g["mu"] * math.cos(a))


# (problem, numeric part, its reference from the givens, [(symbolic part, answer, verdict), ...])
SUBMISSION_PROBLEMS: list[tuple[str, str, Any, list[tuple[str, str, str]]]] = [
    (
        "moving-wedge",
        "wedge_acceleration_numeric",
        wedge_acceleration,
        [
            ("wedge_acceleration", "-m g sin(θ)cos(θ)/(M + m sin^2 θ)", "correct"),
            ("wedge_acceleration", "-m g sin(theta) cos(theta)/M", "incorrect"),
            ("normal_force", "M m g cos(theta)/(M + m sin(theta)^2)", "correct"),
        ],
    ),
    (
        "yo-yo",
        "acceleration_numeric",
        yoyo_acceleration,
        [("acceleration", "g r^2/(r^2 + k^2)", "correct"), ("tension", "m g", "incorrect")],
    ),
    (
        "skier-friction",
        "acceleration_numeric",
        skier_acceleration,
        [
            ("acceleration", "g(sin α - μ cos α)", "correct"),
            ("friction_coefficient", "tan(alpha)", "correct"),
        ],
    ),
    ("lennard-jones", "", None, [("oscillation_frequency", "12 sqrt(U0/m)/r0", "correct")]),
    ("ballistic-pendulum", "", None, [("bullet_speed", "(m + M) sqrt(2 g L (1 - cos θ))/m", "correct")]),
]
STUDENTS = 12


async def submission_calls(client: httpx.AsyncClient, run: str) -> list[Call]:
    """Each student's submissions to the bank's problems; numeric ones need the student's givens."""
    calls: list[Call] = []
    for n in range(STUDENTS):
        student = f"bench-{run}-{n:02d}"
        for problem, numeric_part, reference, symbolic in SUBMISSION_PROBLEMS:
            base = f"/v1/problems/{problem}/parts"
            for part, answer, verdict in symbolic:
                calls.append(
                    post(f"{base}/{part}/submissions", {"answer": answer, "student": student}, expect=verdict)
                )
            if reference is None:
                continue
            response = await client.get(f"/v1/problems/{problem}", params={"student": student})
            response.raise_for_status()
            given = {name: float(q["value"]) for name, q in response.json()["given"].items()}
            value = reference(given)
            for answer, verdict in (
                (f"{value:.4g} m/s^2", "correct"),
                (f"{value * 1.2:.4g} m/s^2", "incorrect"),
            ):
                calls.append(
                    post(
                        f"{base}/{numeric_part}/submissions",
                        {"answer": answer, "student": student},
                        expect=verdict,
                    )
                )
    return calls


# --------------------------------------------------------------------------------------------------
# Driving the load


@dataclass
class Tally:
    latencies: list[float] = field(default_factory=list)
    statuses: Counter[str] = field(default_factory=Counter)
    verdicts: Counter[str] = field(default_factory=Counter)
    unexpected: Counter[str] = field(default_factory=Counter)


@dataclass
class Phase:
    name: str
    elapsed: float = 0.0
    honest: Tally = field(default_factory=Tally)
    hostile: Tally = field(default_factory=Tally)


def record(tally: Tally, call: Call, status: str, payload: bytes, seconds: float) -> None:
    tally.latencies.append(seconds)
    tally.statuses[status] += 1
    if status not in ("200", "201") or call.method != "POST":
        return
    try:
        answer = json.loads(payload)
        verdict, reason = str(answer["verdict"]), str(answer["reason"])
    except (ValueError, KeyError, TypeError):
        verdict, reason = "unreadable", "?"
    tally.verdicts[f"{verdict}/{reason}" if call.hostile else verdict] += 1
    if call.expect is not None and verdict != call.expect:
        tally.unexpected[f"{call.label}: {call.expect}, got {verdict}/{reason}"] += 1


async def drive(
    client: httpx.AsyncClient, name: str, calls: Sequence[Call], concurrency: int, seconds: float
) -> Phase:
    phase = Phase(name)
    source: Iterator[Call] = itertools.cycle(calls)
    deadline = time.monotonic() + seconds

    async def worker() -> None:
        while time.monotonic() < deadline:
            call = next(source)
            headers = {"content-type": "application/json"} if call.body is not None else None
            start = time.perf_counter()
            try:
                response = await client.request(call.method, call.path, content=call.body, headers=headers)
                status, payload = str(response.status_code), response.content
            except httpx.HTTPError as error:
                status, payload = type(error).__name__, b""
            took = time.perf_counter() - start
            record(phase.hostile if call.hostile else phase.honest, call, status, payload, took)

    started = time.perf_counter()
    await asyncio.gather(*(worker() for _ in range(concurrency)))
    phase.elapsed = time.perf_counter() - started
    return phase


def percentile(values: Sequence[float], p: float) -> float:
    """Nearest-rank percentile, in ms."""
    if not values:
        return math.nan
    ordered = sorted(values)
    return 1000 * ordered[max(0, math.ceil(p / 100 * len(ordered)) - 1)]


def row(label: str, tally: Tally, elapsed: float) -> str:
    n = len(tally.latencies)
    statuses = ", ".join(f"{s}: {c}" for s, c in sorted(tally.statuses.items()))
    return (
        f"{label:<30}{n:>9}{n / elapsed:>10.1f}{percentile(tally.latencies, 50):>10.1f}"
        f"{percentile(tally.latencies, 99):>10.1f}   {statuses}"
    )


def report(phase: Phase) -> None:
    both = Tally(
        phase.honest.latencies + phase.hostile.latencies,
        phase.honest.statuses + phase.hostile.statuses,
    )
    print(row(phase.name, both, phase.elapsed))
    parts = [("honest", phase.honest), ("hostile", phase.hostile)] if phase.hostile.latencies else []
    for label, tally in parts:
        print(row(f"  {label}", tally, phase.elapsed))
    for label, tally in parts or [("", phase.honest)]:
        if tally.verdicts:
            verdicts = ", ".join(f"{v} {c}" for v, c in tally.verdicts.most_common())
            print(f"    {label + ' ' if label else ''}verdicts: {verdicts}")
        if tally.unexpected:
            for what, count in tally.unexpected.most_common():
                print(f"    NOT THE EXPECTED VERDICT ({count}x): {what}")
    sys.stdout.flush()


async def bench(url: str, key: str, args: argparse.Namespace) -> None:
    rng = random.Random(SEED)
    limits = httpx.Limits(max_connections=args.concurrency, max_keepalive_connections=args.concurrency)
    async with httpx.AsyncClient(
        base_url=url,
        headers={"authorization": f"Bearer {key}"},
        timeout=REQUEST_TIMEOUT,
        limits=limits,
        trust_env=False,  # no proxy from the environment: loopback only
    ) as client:
        checks = check_calls()
        rng.shuffle(checks)
        submissions = await submission_calls(client, f"{os.getpid()}-{int(time.time())}")
        rng.shuffle(submissions)
        plan = [
            ("floor  GET /health", [Call("GET", "/health", None)]),
            ("check  POST /v1/check", checks),
            ("submit POST .../submissions", submissions),
            (
                f"check + {args.hostile_percent:g} % hostile",
                mixed(checks, hostile_calls(), args.hostile_percent, rng),
            ),
        ]
        print(
            f"{args.concurrency} concurrent clients, {args.duration:g} s per phase after {args.warmup:g} s "
            f"untimed warm-up, against {url}"
        )
        print(f"{'phase':<30}{'requests':>9}{'req/s':>10}{'p50 ms':>10}{'p99 ms':>10}   statuses")
        phases: list[Phase] = []
        for name, calls in plan:
            if args.warmup > 0:
                await drive(client, name, calls, args.concurrency, args.warmup)
            phase = await drive(client, name, calls, args.concurrency, args.duration)
            report(phase)
            phases.append(phase)
    floor = percentile(phases[0].honest.latencies, 50)
    ratios = [f"{p.name.split()[0]} {percentile(p.honest.latencies, 50) / floor:.1f}x" for p in phases[1:-1]]
    last = phases[-1]
    ratios.append(f"check+hostile, honest {percentile(last.honest.latencies, 50) / floor:.1f}x")
    if last.hostile.latencies:
        ratios.append(f"hostile {percentile(last.hostile.latencies, 50) / floor:.1f}x")
    print(f"p50 / floor p50 ({floor:.1f} ms): " + "; ".join(ratios))


# --------------------------------------------------------------------------------------------------
# The server under test


def free_port() -> int:
    with socket.socket() as s:
        s.bind((LOOPBACK, 0))
        return int(s.getsockname()[1])


def physcheck_command() -> list[str]:
    script = Path(sys.executable).with_name("physcheck")
    return [str(script)] if script.exists() else [sys.executable, "-m", "app.cli"]


def _new_session_dying_with_parent() -> None:
    """In the child before exec: its own process group, and SIGTERM if this bench dies even by SIGKILL."""
    os.setsid()
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):
            pr_set_pdeathsig = 1
            ctypes.CDLL(None, use_errno=True).prctl(pr_set_pdeathsig, signal.SIGTERM)


class OwnServer:
    """`physcheck serve` on a free loopback port with a fresh SQLite database, in its own process group."""

    def __init__(self, directory: Path, check_workers: int | None):
        self.port = free_port()
        self.url = f"http://{LOOPBACK}:{self.port}"
        self.log_path = directory / "server.log"
        self.env = {
            **os.environ,
            "PHYSCHECK_DATABASE_URL": f"sqlite:///{directory / 'bench.db'}",
            "PHYSCHECK_SECRET": "load-bench-secret",
            "PHYSCHECK_BASE_URL": self.url,
            "PHYSCHECK_RATE_LIMIT_PER_MINUTE": RATE_LIMIT,
            "PHYSCHECK_STUDENT_RATE_LIMIT_PER_MINUTE": RATE_LIMIT,
        }
        if check_workers is not None:
            self.env["PHYSCHECK_CHECK_WORKERS"] = str(check_workers)
        self.directory = directory
        self.process: subprocess.Popen[bytes] | None = None

    def create_key(self) -> str:
        done = subprocess.run(
            [*physcheck_command(), "keys", "create", "--role", "instructor", "--name", "load-bench"],
            env=self.env,
            cwd=self.directory,
            capture_output=True,
            check=True,
            timeout=READY_TIMEOUT,
        )
        return done.stdout.decode().strip().splitlines()[-1]

    def start(self) -> None:
        with self.log_path.open("ab") as log:
            self.process = subprocess.Popen(
                [*physcheck_command(), "serve", "--host", LOOPBACK, "--port", str(self.port)],
                env=self.env,
                cwd=self.directory,
                stdout=log,
                stderr=subprocess.STDOUT,
                preexec_fn=_new_session_dying_with_parent,  # no threads yet
            )

    def wait_ready(self) -> None:
        deadline = time.monotonic() + READY_TIMEOUT
        with httpx.Client(trust_env=False, timeout=2) as client:
            while time.monotonic() < deadline:
                if self.process is not None and self.process.poll() is not None:
                    raise RuntimeError(
                        f"the server exited with {self.process.returncode}:\n{self.log_tail()}"
                    )
                with contextlib.suppress(httpx.HTTPError):
                    if client.get(f"{self.url}/ready").status_code == 200:
                        return
                time.sleep(0.25)
        raise RuntimeError(f"the server was not ready in {READY_TIMEOUT:g} s:\n{self.log_tail()}")

    def stop(self) -> None:
        """SIGTERM the whole group (server and grading workers), SIGKILL what is left after 15 s."""
        process, self.process = self.process, None
        if process is None:
            return
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGTERM)
        with contextlib.suppress(subprocess.TimeoutExpired):
            process.wait(timeout=15)
        # Sweep stragglers in the group (a worker stuck on a hostile answer) even if the server exited.
        with contextlib.suppress(ProcessLookupError):
            os.killpg(process.pid, signal.SIGKILL)
        with contextlib.suppress(subprocess.TimeoutExpired):
            process.wait(timeout=5)

    def log_tail(self, lines: int = 30) -> str:
        try:
            return "\n".join(self.log_path.read_text(errors="replace").splitlines()[-lines:])
        except OSError:
            return "(no server log)"


_terminated: list[int] = []


def _terminate(signum: int, _frame: FrameType | None) -> None:
    """SIGTERM or SIGHUP: take the Ctrl-C path, which asyncio turns into a clean cancellation."""
    _terminated.append(signum)
    signal.raise_signal(signal.SIGINT)


def loopback_url(url: str) -> str:
    parts = urlsplit(url)
    if parts.scheme != "http" or parts.hostname != LOOPBACK:
        raise SystemExit(
            f"--url must be http://{LOOPBACK}:PORT (this benchmark only sends traffic to loopback)"
        )
    return url.rstrip("/")


def parse_args(argv: Sequence[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--duration", type=float, default=10.0, help="timed seconds per phase (default 10)")
    parser.add_argument("--concurrency", type=int, default=8, help="concurrent clients (default 8)")
    parser.add_argument(
        "--warmup", type=float, default=2.0, help="untimed seconds before each phase (default 2)"
    )
    parser.add_argument(
        "--hostile-percent", type=float, default=10.0, help="hostile share in phase 4 (default 10)"
    )
    parser.add_argument(
        "--check-workers",
        type=int,
        default=None,
        help="PHYSCHECK_CHECK_WORKERS of its own server (default: its own)",
    )
    parser.add_argument(
        "--url", default=None, help=f"drive this running server instead (http://{LOOPBACK}:PORT)"
    )
    parser.add_argument("--key", default=None, help="an instructor key of the server given by --url")
    parser.add_argument(
        "--server-log", type=Path, default=None, help="keep its own server's log in this file"
    )
    args = parser.parse_args(argv)
    if args.duration <= 0 or args.concurrency < 1 or args.warmup < 0 or not 0 <= args.hostile_percent <= 100:
        parser.error("need --duration > 0, --concurrency >= 1, --warmup >= 0, 0 <= --hostile-percent <= 100")
    if (args.url is None) != (args.key is None):
        parser.error("--url and --key go together")
    if args.url is not None:
        args.url = loopback_url(args.url)
    return args


def run_own_server(args: argparse.Namespace) -> None:
    with tempfile.TemporaryDirectory(prefix="physcheck-load-") as tmp:
        server = OwnServer(Path(tmp), args.check_workers)
        try:
            key = server.create_key()
            server.start()
            started = time.perf_counter()
            server.wait_ready()
            workers = args.check_workers or os.environ.get("PHYSCHECK_CHECK_WORKERS", "server default")
            print(
                f"own server {server.url} (SQLite in {tmp}, check workers: {workers}, "
                f"ready in {time.perf_counter() - started:.1f} s; {os.cpu_count()} CPUs shared with this client)"
            )
            asyncio.run(bench(server.url, key, args))
        except Exception:
            print(f"server log (tail):\n{server.log_tail()}", file=sys.stderr)
            raise
        finally:
            server.stop()
            if args.server_log is not None:
                shutil.copyfile(server.log_path, args.server_log)


def main(argv: Sequence[str] | None = None) -> int:
    args = parse_args(argv)
    # Ctrl-C must stop the run even where SIGINT came in ignored (started with `&` from a script).
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, _terminate)
    signal.signal(signal.SIGHUP, _terminate)
    try:
        if args.url is not None:
            asyncio.run(bench(args.url, args.key, args))
        else:
            run_own_server(args)
    except KeyboardInterrupt:
        print("interrupted" + ("; its own server is stopped" if args.url is None else ""), file=sys.stderr)
        return 128 + (_terminated[0] if _terminated else signal.SIGINT)
    return 0


if __name__ == "__main__":
    sys.exit(main())
