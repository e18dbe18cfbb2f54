"""A soak: a real server under steady load while faults are injected; prints counts, never asserts.

    .venv/bin/python bench/soak.py                         # = --duration 120 --concurrency 6 --database sqlite
    .venv/bin/python bench/soak.py --database postgres     # a throwaway database on the local server

Starts its own `physcheck serve` on a free 127.0.0.1 port (its own process group, warm-up off, rate
limits raised), with the database reached through a loopback proxy when it is PostgreSQL, creates an
instructor key, and sends a closed loop of checks, submissions (for 20 students) and listings. Every
`--fault-every` seconds it injects the next fault of the cycle:

    kill-worker      SIGKILL one of the server's child processes (a grading worker or the fork server)
    black-hole       the database accepts and never answers for `--fault-seconds` (PostgreSQL: the
                     proxy swallows everything; SQLite: another connection holds the write lock)
    cut-database     the proxy refuses and cuts every connection for `--fault-seconds` (PostgreSQL only)

Printed at the end: requests, the count of each status, 5xx apart (500s are bugs, 503s are the
expected answer during a fault), hung requests (no answer within --hung seconds), transport errors,
the faults injected, and whether every acknowledged submission (201) is stored.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import os
import random
import shutil
import signal
import socket
import sqlite3
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path
from typing import Any

import httpx

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from tests.service.tcp_proxy import TcpProxy  # noqa: E402 (after the path)

PHYSCHECK = Path(sys.executable).with_name("physcheck")
POSTGRES_ADMIN = os.environ.get(
    "PHYSCHECK_TEST_POSTGRES_URL", "postgresql+psycopg://postgres@127.0.0.1:5432/test"
)
STUDENTS = [f"soak-{n:02d}" for n in range(20)]
CHECKS = [
    {"kind": "numeric", "answer": "4.58 m/s^2", "expected": 4.5807, "units": "m/s^2"},
    {"kind": "symbolic", "answer": "m g sin(θ)", "expected": "m*g*sin(theta)",
     "symbols": {"m": {"dimension": "kg"}, "g": {"dimension": "m/s^2"}, "theta": {"dimension": "1"}}},
    {"kind": "symbolic", "answer": "9^9^9", "expected": "m", "symbols": {"m": {"dimension": "kg"}}},
]  # fmt: skip
SUBMIT = "/v1/problems/atwood/parts/acceleration/submissions"
ANSWERS = ["g (m2 - m1)/(m1 + m2)", "g", "(m2 - m1) g/m2", "m1 +"]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Soak:
    def __init__(self, args: argparse.Namespace, workdir: Path):
        self.args = args
        self.workdir = workdir
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.statuses: Counter[str] = Counter()
        self.hung = 0
        self.acknowledged: set[str] = set()
        self.faults: list[str] = []
        self.proxy: TcpProxy | None = None
        self.admin_url: str | None = None
        self.database_url = self._database()
        self.env = {
            **os.environ,
            "PHYSCHECK_DATABASE_URL": self.database_url,
            "PHYSCHECK_SECRET": "soak-secret-0123456789",
            "PHYSCHECK_WARM_UP": "false",
            "PHYSCHECK_RATE_LIMIT_PER_MINUTE": "100000000",
            "PHYSCHECK_STUDENT_RATE_LIMIT_PER_MINUTE": "100000000",
        }
        self.server: subprocess.Popen[bytes] | None = None

    def _database(self) -> str:
        if self.args.database == "sqlite":
            return f"sqlite:///{self.workdir / 'soak.db'}"
        from sqlalchemy import create_engine, text
        from sqlalchemy.engine import make_url
        from sqlalchemy.pool import NullPool

        name = f"physcheck_soak_{os.getpid()}"
        self.admin_url = POSTGRES_ADMIN
        engine = create_engine(POSTGRES_ADMIN, isolation_level="AUTOCOMMIT", poolclass=NullPool)
        with engine.connect() as connection:
            connection.execute(text(f'CREATE DATABASE "{name}"'))
        engine.dispose()
        real = make_url(POSTGRES_ADMIN).set(database=name)
        self.proxy = TcpProxy((real.host or "127.0.0.1", real.port or 5432), free_port()).up()
        return real.set(host="127.0.0.1", port=self.proxy.port).render_as_string(hide_password=False)

    def start(self) -> str:
        created = subprocess.run(
            [str(PHYSCHECK), "keys", "create", "--role", "instructor", "--name", "soak"],
            env=self.env,
            capture_output=True,
            text=True,
            check=True,
        )
        key = created.stdout.strip().splitlines()[-1]  # the key is the last line (it migrates first)
        log = (self.workdir / "server.log").open("ab")
        self.server = subprocess.Popen(
            [str(PHYSCHECK), "serve", "--port", str(self.port)],
            env=self.env,
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
        deadline = time.monotonic() + 180
        while time.monotonic() < deadline:
            with contextlib.suppress(httpx.TransportError):
                if httpx.get(f"{self.url}/ready", timeout=2).status_code == 200:
                    return key
            time.sleep(0.3)
        raise RuntimeError(f"the server was not ready in 180 s; see {self.workdir / 'server.log'}")

    def stop(self) -> None:
        if self.server is not None and self.server.poll() is None:
            os.killpg(self.server.pid, signal.SIGTERM)
            try:
                self.server.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.server.pid, signal.SIGKILL)
        if self.proxy is not None:
            self.proxy.down()
        if self.admin_url is not None:
            from sqlalchemy import create_engine, text
            from sqlalchemy.engine import make_url
            from sqlalchemy.pool import NullPool

            engine = create_engine(self.admin_url, isolation_level="AUTOCOMMIT", poolclass=NullPool)
            with engine.connect() as connection:
                name = make_url(self.database_url).database
                connection.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))
            engine.dispose()

    # ---- load -----------------------------------------------------------------------------------

    async def client(self, key: str, until: float) -> None:
        headers = {"Authorization": f"Bearer {key}"}
        rng = random.Random()
        async with httpx.AsyncClient(
            base_url=self.url, headers=headers, timeout=self.args.hung, trust_env=False
        ) as http:
            while time.monotonic() < until:
                roll = rng.random()
                try:
                    if roll < 0.5:
                        response = await http.post("/v1/check", json=rng.choice(CHECKS))
                    elif roll < 0.85:
                        body = {"answer": rng.choice(ANSWERS), "student": rng.choice(STUDENTS)}
                        response = await http.post(SUBMIT, json=body)
                        if response.status_code == 201:
                            self.acknowledged.add(response.json()["submission_id"])
                    else:
                        response = await http.get("/v1/problems")
                    self.statuses[str(response.status_code)] += 1
                    if response.status_code == 503:
                        await asyncio.sleep(0.2)
                except httpx.TimeoutException:
                    self.hung += 1
                    self.statuses["hung"] += 1
                except httpx.TransportError as error:
                    self.statuses[type(error).__name__] += 1
                    await asyncio.sleep(0.2)

    # ---- faults ---------------------------------------------------------------------------------

    async def faults_loop(self, until: float) -> None:
        cycle = ["kill-worker", "black-hole"] + (["cut-database"] if self.proxy is not None else [])
        while True:
            await asyncio.sleep(self.args.fault_every)
            if time.monotonic() + self.args.fault_seconds > until:
                return
            fault = cycle[len(self.faults) % len(cycle)]
            self.faults.append(fault)
            await getattr(self, fault.replace("-", "_"))()

    async def kill_worker(self) -> None:
        assert self.server is not None
        children = _children(self.server.pid)
        if children:
            with contextlib.suppress(ProcessLookupError):
                os.kill(random.choice(children), signal.SIGKILL)

    async def black_hole(self) -> None:
        if self.proxy is not None:
            self.proxy.black_hole()
            await asyncio.sleep(self.args.fault_seconds)
            self.proxy.forward()
            return
        path = self.database_url.removeprefix("sqlite:///")
        holder = sqlite3.connect(path, isolation_level=None, timeout=30, check_same_thread=False)
        try:
            await asyncio.to_thread(holder.execute, "BEGIN IMMEDIATE")  # waits for the server's writes
            await asyncio.sleep(self.args.fault_seconds)
        finally:
            holder.execute("ROLLBACK")
            holder.close()

    async def cut_database(self) -> None:
        assert self.proxy is not None
        self.proxy.down()
        await asyncio.sleep(self.args.fault_seconds)
        self.proxy.up()

    def stored(self, key: str) -> int:
        headers = {"Authorization": f"Bearer {key}"}
        found = 0
        for student in STUDENTS:
            cursor: str | None = None
            while True:
                params: dict[str, Any] = {
                    "student": student,
                    "limit": 1000,
                    **({"cursor": cursor} if cursor else {}),
                }
                page = httpx.get(
                    f"{self.url}/v1/submissions", params=params, headers=headers, timeout=60
                ).json()
                found += sum(1 for item in page["items"] if item["submission_id"] in self.acknowledged)
                cursor = page["next"]
                if cursor is None:
                    break
        return found


def _children(pid: int) -> list[int]:
    """Every descendant of `pid` (from /proc)."""
    parents: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            with contextlib.suppress(OSError, IndexError, ValueError):
                ppid = int((entry / "stat").read_text().rsplit(")", 1)[1].split()[1])
                parents.setdefault(ppid, []).append(int(entry.name))
    found, pending = [], [pid]
    while pending:
        for child in parents.get(pending.pop(), []):
            found.append(child)
            pending.append(child)
    return found


async def run(soak: Soak, key: str) -> None:
    until = time.monotonic() + soak.args.duration
    await asyncio.gather(
        soak.faults_loop(until), *(soak.client(key, until) for _ in range(soak.args.concurrency))
    )


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--duration", type=float, default=120)
    parser.add_argument("--concurrency", type=int, default=6)
    parser.add_argument("--database", choices=["sqlite", "postgres"], default="sqlite")
    parser.add_argument("--fault-every", type=float, default=15, help="seconds between faults")
    parser.add_argument("--fault-seconds", type=float, default=8, help="how long a database fault lasts")
    parser.add_argument("--hung", type=float, default=30, help="seconds without an answer that count as hung")
    parser.add_argument("--server-log", type=Path, help="keep the server's log here")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="physcheck-soak-") as workdir:
        soak = Soak(args, Path(workdir))
        try:
            key = soak.start()
            asyncio.run(run(soak, key))
            stored = soak.stored(key)
        finally:
            soak.stop()
            if args.server_log is not None:
                shutil.copyfile(Path(workdir) / "server.log", args.server_log)
        fivexx = {status: n for status, n in soak.statuses.items() if status.startswith("5")}
        print(f"duration {args.duration:.0f} s, {args.concurrency} clients, database {args.database}")
        print(f"requests: {sum(soak.statuses.values())}")
        print(f"statuses: {dict(sorted(soak.statuses.items()))}")
        print(f"5xx: {sum(fivexx.values())} {fivexx} (500s: {fivexx.get('500', 0)})")
        print(f"hung (no answer in {args.hung:.0f} s): {soak.hung}")
        print(f"faults: {len(soak.faults)} {dict(Counter(soak.faults))}")
        print(f"acknowledged submissions: {len(soak.acknowledged)}, stored: {stored}")


if __name__ == "__main__":
    main()
