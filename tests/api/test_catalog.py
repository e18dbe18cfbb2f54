"""The catalog compiles each problem version once, however many requests arrive first."""

from __future__ import annotations

import threading
import time

from app import catalog as catalog_module
from app.catalog import Catalog


def test_concurrent_first_requests_compile_a_problem_once(db, monkeypatch):
    catalog = Catalog(db, "secret-for-the-test")
    catalog.sync_builtin()
    record = catalog.get("atwood")
    running, most = [0], [0]
    guard = threading.Lock()
    real = catalog_module.compile_problem

    def slow_compile(doc, version):
        with guard:
            running[0] += 1
            most[0] = max(most[0], running[0])
        time.sleep(0.2)
        try:
            return real(doc, version)
        finally:
            with guard:
                running[0] -= 1

    monkeypatch.setattr(catalog_module, "compile_problem", slow_compile)
    results = []
    threads = [threading.Thread(target=lambda: results.append(catalog.compiled(record))) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert most[0] == 1
    assert len(results) == 4 and len({id(r) for r in results}) == 1
