"""Problems as the service sees them: stored versions, read and compiled once per process, per variant."""

from __future__ import annotations

import logging
import threading
from collections import OrderedDict
from pathlib import Path
from typing import Any

from app.db import problems as problem_repository
from app.db.database import Database
from app.db.errors import ProblemExists, ProblemNotFound
from app.db.records import ProblemRecord
from physics.checking import CheckJob
from physics.figures import model_figure
from problems.compiled import CompiledProblem, compile_problem
from problems.loader import load_bank, parse_problem
from problems.modelinfo import load_doc_model
from problems.schema import ProblemDocument
from problems.symbols import symbol_table
from problems.variants import Variant, draw_variant, si_values, student_view

log = logging.getLogger("physcheck.catalog")


class Catalog:
    def __init__(
        self, database: Database, secret: str, bank_dir: Path | None = None, documents_cached: int = 256
    ):
        self._database = database
        self._bank_dir = bank_dir
        self._secret = secret
        self._documents: OrderedDict[str, ProblemDocument] = OrderedDict()
        self._limit = documents_cached
        self._lock = threading.Lock()
        self.warm = threading.Event()
        self._closing = threading.Event()
        self._compiling: dict[tuple[str, int, str], threading.Lock] = {}

    def sync_builtin(self) -> list[ProblemRecord]:
        """Store the built-in bank: unchanged files keep their version, edited ones get a new one."""
        saved = []
        for doc in load_bank(self._bank_dir):
            try:
                with self._database.session() as session:
                    saved.append(
                        problem_repository.save_builtin(session, doc.id, doc.model_dump(mode="json"))
                    )
            except ProblemExists:
                log.warning(
                    "an uploaded problem already uses the bank id %r; the bank's is not served", doc.id
                )
        return saved

    def warm_up(self) -> None:
        """Compile every live problem once (derivations take seconds); then the instance is ready."""
        try:
            for record in self.list():
                if self._closing.is_set():
                    return
                try:
                    self.compiled(record)
                except Exception:  # one broken problem must not keep the others cold
                    log.exception("could not compile problem %r version %d", record.id, record.version)
        finally:
            self.warm.set()

    def close(self) -> None:
        """Stop a warm-up still running (it would otherwise compile on after the app has shut down)."""
        self._closing.set()

    def get(self, problem_id: str, version: int | None = None) -> ProblemRecord:
        with self._database.session(read_only=True) as session:
            return problem_repository.get_problem(session, problem_id, version)

    def list(self) -> list[ProblemRecord]:
        with self._database.session(read_only=True) as session:
            return problem_repository.list_problems(session)

    def document(self, record: ProblemRecord) -> ProblemDocument:
        """The stored document, validated when it was stored, so only its shape is read again."""
        with self._lock:
            cached = self._documents.get(record.document_hash)
            if cached is not None:
                self._documents.move_to_end(record.document_hash)
                return cached
        doc = parse_problem(dict(record.document), "json", check_meaning=False)
        with self._lock:
            self._documents[record.document_hash] = doc
            while len(self._documents) > self._limit:
                self._documents.popitem(last=False)
        return doc

    def compiled(self, record: ProblemRecord) -> CompiledProblem:
        """Derivations and prepared references, cached by the bank's compiler per (id, version, hash).

        One compilation per problem version at a time: a burst of first requests waits for it rather
        than deriving the same model once per thread.
        """
        key = (record.id, record.version, record.document_hash)
        with self._lock:
            lock = self._compiling.setdefault(key, threading.Lock())
        try:
            with lock:
                return compile_problem(self.document(record), record.version)
        finally:
            with self._lock:  # later callers find the compiler's cache warm; no lock kept per version
                self._compiling.pop(key, None)

    def job(self, record: ProblemRecord, part_id: str, student: str, answer: str) -> CheckJob:
        """The check job for one student's answer: the student's own numbers for a numeric part.

        Sympy work (compiling, evaluating the numeric reference): call it off the event loop.
        """
        return self.compiled(record).job(part_id, answer, self.variant(record, student))

    def max_attempts(self, record: ProblemRecord, part_id: str) -> int | None:
        """The part's own limit, else the problem's; None: unlimited."""
        doc = self.document(record)
        limit = doc.part(part_id).max_attempts
        return limit if limit is not None else doc.max_attempts

    def student_view(self, problem_id: str, student: str) -> dict[str, Any]:
        """One student's variant of the latest version, as the API and the student page show it."""
        try:
            record = self.get(problem_id)
        except ProblemNotFound:
            raise LookupError(problem_id) from None
        view = student_view(self.document(record), self.variant(record, student))
        return {**view, "version": record.version, "student": student}

    def variant(self, record: ProblemRecord, student: str) -> Variant:
        return draw_variant(self.document(record), record.version, student, self._secret)

    def figure(self, problem_id: str, student: str) -> str | None:
        """The problem's figure (SVG) with this student's values; None for a problem with no model."""
        try:
            record = self.get(problem_id)
        except ProblemNotFound:
            return None
        doc = self.document(record)
        if doc.model is None:
            return None
        table = symbol_table(doc)
        values = si_values(doc, self.variant(record, student), table)
        model = load_doc_model(doc, table)
        return model_figure(model, {s.name: float(v) for s, v in values.items()}, title=doc.title)
