"""Real `physcheck serve` processes on loopback, for tests that kill, restart or multiply servers."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import IO

import httpx

PHYSCHECK = Path(sys.executable).with_name("physcheck")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class LiveServer:
    """One server in its own process group, so a kill takes its grading workers down with it."""

    def __init__(self, database_url: str, log: Path, port: int | None = None, **settings: str):
        self.port = port or free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self._log_path = log
        self._env = {
            **os.environ,
            "PHYSCHECK_DATABASE_URL": database_url,
            "PHYSCHECK_SECRET": "live-server-test-secret",
            "PHYSCHECK_CHECK_WORKERS": "1",
            **{f"PHYSCHECK_{k.upper()}": v for k, v in settings.items()},
        }
        self.process: subprocess.Popen[bytes] | None = None
        self._log: IO[bytes] | None = None

    def start_in_background(self) -> LiveServer:
        """Start the process and return at once (not waiting for it to be ready)."""
        self._log = self._log_path.open("ab")
        self.process = subprocess.Popen(
            [str(PHYSCHECK), "serve", "--port", str(self.port)],
            env=self._env,
            stdout=self._log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
        return self

    def start(self, timeout: float = 120) -> LiveServer:
        self.start_in_background()
        assert self.process is not None
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"server exited with {self.process.returncode}; see {self._log_path}")
            try:
                if httpx.get(f"{self.url}/ready", timeout=1).status_code == 200:
                    return self
            except httpx.TransportError:
                pass
            time.sleep(0.2)
        self.kill()
        raise RuntimeError(f"server not ready in {timeout} s; see {self._log_path}")

    def kill(self) -> None:
        """SIGKILL the server and its workers: no shutdown hooks, no flushing, like a crash."""
        if self.process is not None and self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait(timeout=10)
        self._close()

    def _close(self) -> None:
        self.process = None
        if self._log is not None:
            self._log.close()
            self._log = None

    def stop(self) -> None:
        if self.process is not None and self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGTERM)
            try:
                self.process.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.kill()
        self._close()
