"""Grading workers run this program's code wherever the server is started from.

The fork server starts as `python -c`, which puts the current directory first on sys.path: from a
directory holding another copy of the checker (a checkout of another version), the workers graded with
that copy's code while the server ran its own."""

from __future__ import annotations

import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
GRADE_ONE = textwrap.dedent(
    """
    import asyncio

    from app.grading.forkserver import start_early
    from app.grading.pool import GradingPool
    from app.schemas.check import CheckIn
    from pydantic import TypeAdapter

    def main():
        start_early()
        body = {"kind": "numeric", "answer": "4.58 m/s^2", "expected": "4.58", "units": "m/s^2"}
        job = TypeAdapter(CheckIn).validate_python(body).job()
        pool = GradingPool(workers=1, timeout=30.0, memory_mb=1024, max_tasks=10, queue_size=1)
        pool.start()
        try:
            print(asyncio.run(pool.check(job)).feedback)
        finally:
            pool.close()

    if __name__ == "__main__":
        main()
    """
)


@pytest.mark.slow
def test_workers_grade_with_the_servers_code_when_started_beside_another_copy(tmp_path: Path) -> None:
    elsewhere = tmp_path / "another-checkout"
    shutil.copytree(ROOT / "physics", elsewhere / "physics", ignore=shutil.ignore_patterns("__pycache__"))
    check = elsewhere / "physics" / "numeric" / "check.py"
    marked = check.read_text().replace('"Correct.")', '"Correct, says the other copy.")')
    assert marked != check.read_text()
    check.write_text(marked)
    script = tmp_path / "scripts" / "grade_one.py"
    script.parent.mkdir()
    script.write_text(GRADE_ONE)
    done = subprocess.run(
        [sys.executable, str(script)], cwd=elsewhere, capture_output=True, text=True, timeout=120, check=False
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().splitlines()[-1] == "Correct."


FIRST_CHECKS = textwrap.dedent(
    """
    import sys

    import app.grading.preload  # what the fork server runs before forking any worker
    from app.grading.worker import grade
    from physics.checking import SymbolDecl
    from problems.kinds.symbolic import SymbolicJob

    before = set(sys.modules)
    angle = SymbolDecl("theta", "1", range=("0", "pi/2"))
    wedge = (SymbolDecl("m", "kg"), SymbolDecl("M", "kg"), SymbolDecl("g", "m/s^2"), angle)
    rolling = (SymbolDecl("g", "m/s^2"), SymbolDecl("r", "m"), SymbolDecl("k", "m"))
    for answer, expected, symbols in [
        ("2g/3", "g*r**2/(r**2 + k**2)", rolling),
        ("g r^2/(r^2 + k^2)", "g/(1 + k**2/r**2)", rolling),
        ("M m g cos θ/(M + m sin^2 θ)", "M*m*g*sin(theta)/(M + m*sin(theta)**2)", wedge),
        ("sqrt(2 g M (1 - cos θ))", "2*sqrt(g*M)*sin(theta/2)", wedge),
    ]:
        grade(SymbolicJob(answer, expected, symbols))
    print(" ".join(sorted(name for name in set(sys.modules) - before if name.startswith("sympy"))))
    """
)


def test_a_fresh_workers_first_checks_import_nothing_of_sympy(tmp_path: Path) -> None:
    """sympy imports modules on first use (its first sum imports sympy.tensor and sympy.combinatorics,
    a quarter of a CPU-second): the fork server's warm-up has imported them, so no worker's first
    student waits for them, nor any worker's after its replacement."""
    script = tmp_path / "first_checks.py"
    script.write_text(FIRST_CHECKS)
    done = subprocess.run(
        [sys.executable, "-P", str(script)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == ""
