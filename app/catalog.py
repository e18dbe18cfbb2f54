"""Problems as the service sees them: stored versions, read and compiled once, per variant.

A compiled problem (derivations, prepared references, sample points) is persisted in the database,
keyed by the version's content hash and the engine's digest (`problems.fingerprint`: what the code does,
not its docstrings), so a restarted or new instance loads it in milliseconds instead of deriving the
bank again for minutes, and only a changed version (or a change to what the code does) is compiled again.

This process never derives: an upload arrives compiled by its vetting worker and is stored so with its
version; whatever is not stored is derived by `app.derivation`'s worker processes, under their limits.
"""

from __future__ import annotations

import hashlib
import hmac
import logging
import threading
import time
from collections import OrderedDict
from collections.abc import Callable, Mapping
from concurrent.futures import FIRST_COMPLETED, Future, wait
from pathlib import Path
from typing import Any, TypeVar

from app.db.errors import ProblemExists, ProblemNotFound
from app.db.problems import document_hash
from app.db.records import ProblemRecord
from app.derivation import DerivationFailed, DerivationPool, DerivationRefused, unpack
from app.errors import GraderFault, Unavailable
from app.grading.processes import PoolError
from app.instructor.worked import body_captions
from app.shipped_bank import ShippedBank, load_shipped, shipped_documents, vouched_documents
from app.storage import CompiledCache, CompiledEntry, Stores
from physics.checking import CheckJob
from physics.engine.model import Model
from physics.figures import model_figure
from physics.figures.free_body import free_body_figure
from physics.wording import counted
from problems.compiled import CompiledProblem, document_digest
from problems.errors import ProblemInvalid
from problems.fingerprint import engine_digest, source_digest
from problems.loader import BANK_DIR, bank_digest, load_bank, parse_problem
from problems.modelinfo import load_doc_model
from problems.schema import ProblemDocument
from problems.semantics import semantic_errors
from problems.student import needs_compiled, student_view
from problems.symbols import symbol_table
from problems.variants import Variant, draw_variant, si_values

log = logging.getLogger("physcheck.catalog")
T = TypeVar("T")


_MEANING_CHECKED: set[str] = set()  # digests (document and code files) found sound in this process


_BANKS_READ: dict[Path, tuple[str, list[ProblemDocument]]] = {}  # by directory: its files' digest, documents


def _bank_documents(bank_dir: Path | None, shipped: Path | None) -> list[ProblemDocument]:
    """The bank's documents (shape checked), parsed again only when a file changed: every app in one
    process (each test's fresh database) stores the same bank, and parsing it is most of a start-up's
    storage work. A new process takes them from the shipped bank when it was built from these very
    files by this code."""
    root = (bank_dir or BANK_DIR).resolve()
    digest = bank_digest(root)
    found = _BANKS_READ.get(root)
    if found is not None and found[0] == digest:
        return list(found[1])
    documents = shipped_documents(shipped, digest, source_digest())
    if documents is None:
        documents = load_bank(root, check_meaning=False)
    _BANKS_READ[root] = (digest, documents)
    return list(documents)


def _meaning_faults(doc: ProblemDocument) -> list[tuple[str, str]]:
    """semantic_errors, remembered when sound: another app in this process (a test's fresh database)
    stores the same bank without reading every expression again."""
    digest = f"{document_digest(doc)}:{source_digest()}"
    if digest in _MEANING_CHECKED:
        return []
    faults = semantic_errors(doc)
    if not faults:
        _MEANING_CHECKED.add(digest)
    return faults


class CompiledStore:
    """Compiled problems in the database, sealed with an HMAC under the server's secret.

    They are pickles (sympy trees pickle; they have no other faithful format), and unpickling runs
    code, so only bytes that this service wrote may be opened: a row whose MAC does not verify (edited
    in the database, or written under another secret) is ignored and compiled again.
    """

    def __init__(self, cache: CompiledCache, secret: str):
        self._cache = cache
        self._mac_key = hashlib.sha256(b"physcheck compiled problems\0" + secret.encode()).digest()
        self._engine: str | None = None
        self._engine_lock = threading.Lock()

    def key(self, record: ProblemRecord) -> str:
        return self._key(record.document_hash)

    def _key(self, document_hash: str) -> str:
        return hashlib.sha256(f"{document_hash}:{self.engine()}".encode()).hexdigest()

    def engine(self) -> str:
        """The engine's digest, remembered in the store under the digest of its files: computing it
        parses every engine module (half a CPU-second), which a restart of unchanged code skips."""
        with self._engine_lock:
            if self._engine is None:
                self._engine = self._stored_engine()
                if self._engine is None:
                    self._engine = engine_digest()
                    self._put(self._engine_key(), self._engine.encode(), "the engine digest")
            return self._engine

    def engine_is_stored(self) -> bool:
        """Whether the running code's engine digest is known without parsing it (not a first start)."""
        with self._engine_lock:
            if self._engine is None:
                self._engine = self._stored_engine()
            return self._engine is not None

    def adopt_engine(self, source: str, engine: str) -> bool:
        """Take `engine` as the engine digest when `source` is the digest of the running code's files
        (the same bytes and libraries: the same syntax trees), sparing a first start the parse."""
        if source != source_digest():
            return False
        with self._engine_lock:
            if self._engine is None:
                self._engine = engine
                self._put(self._engine_key(), engine.encode(), "the engine digest")
            return self._engine == engine

    @staticmethod
    def _engine_key() -> str:
        # Hashed as compiled entries' keys are (the column holds 64 characters), from another kind of
        # text: "engine:" and a digest, theirs a document hash, ":" and a digest.
        return hashlib.sha256(f"engine:{source_digest()}".encode()).hexdigest()

    def _stored_engine(self) -> str | None:
        key = self._engine_key()
        found = self._cache.get(key)
        if found is not None and self._verifies(key, *found):
            return found[0].decode()
        return None

    def _mac(self, key: str, payload: bytes) -> str:
        return hmac.new(self._mac_key, key.encode() + b"\0" + payload, hashlib.sha256).hexdigest()

    def load(self, record: ProblemRecord) -> CompiledProblem | None:
        key = self.key(record)
        found = self._cache.get(key)
        if found is None:
            return None
        payload, mac = found
        if not self._verifies(key, payload, mac):
            log.warning("ignoring a stored compilation of %r that fails its check", record.id)
            return None
        return self.open(record, payload)

    def sealed(self, records: list[ProblemRecord]) -> dict[str, bytes]:
        """The stored payload of each record whose compilation is stored and verifies, by key, in one
        query and without opening any: the MAC proves it is this service's compilation of that content."""
        keys = {self.key(record): record for record in records}
        found = self._cache.get_many(keys)
        return {key: payload for key, (payload, mac) in found.items() if self._verifies(key, payload, mac)}

    def _verifies(self, key: str, payload: bytes, mac: str) -> bool:
        return hmac.compare_digest(mac, self._mac(key, payload))

    @staticmethod
    def open(record: ProblemRecord, payload: bytes) -> CompiledProblem | None:
        """A verified payload unpickled (sympy trees: tens of milliseconds for a large problem)."""
        return unpack(payload, record.version)

    def save(self, record: ProblemRecord, payload: bytes) -> None:
        self._put(self.key(record), payload, f"the compilation of {record.id!r}")

    def entry(self, document: Mapping[str, Any], payload: bytes) -> CompiledEntry:
        """A vetted upload's compilation, sealed, to be stored with its version (in one transaction)."""
        key = self._key(document_hash(document))
        return CompiledEntry(key, payload, self._mac(key, payload))

    def _put(self, key: str, payload: bytes, what: str) -> None:
        try:
            self._cache.put(key, payload, self._mac(key, payload))
        except Exception as error:  # a cache: another instance may have written it meanwhile
            log.warning("could not store %s: %s", what, error)


class Catalog:
    def __init__(
        self,
        stores: Stores,
        secret: str,
        bank_dir: Path | None = None,
        documents_cached: int = 256,
        compiled_cached: int = 256,
        deriver: DerivationPool | None = None,
        shipped: Path | None = None,
    ):
        """`deriver`: the worker processes that derive what is not stored (this process never does);
        the catalog closes it. By default one worker under the default limits. `shipped`: the derived
        bank that came with the program (`app.shipped_bank`), used for what is not stored yet."""
        self._problems = stores.problems
        self._bank_dir = bank_dir
        self._secret = secret
        self._documents: OrderedDict[str, ProblemDocument] = OrderedDict()
        self._limit = documents_cached
        self._compiled: OrderedDict[tuple[str, int, str], CompiledProblem] = OrderedDict()
        self._compiled_limit = compiled_cached
        self._store = CompiledStore(stores.compiled, secret)
        self._lock = threading.Lock()
        self._store_lock = threading.Lock()
        self.warm = threading.Event()
        self._closing = threading.Event()
        self._compiling: dict[tuple[str, int, str], threading.Lock] = {}
        self._sealed: dict[str, bytes] = {}  # verified stored compilations not opened yet, by store key
        self._deriver = deriver or DerivationPool()
        self._shipped = shipped
        # Stored versions the running engine refuses (vetted by older code), by (id, version): why.
        self._refused: dict[tuple[str, int], str] = {}
        self._deriving: tuple[int, int] | None = None  # a warm-up's derivations: (done, of)

    def sync_builtin(self) -> list[ProblemRecord]:
        """Store the built-in bank: unchanged files keep their version, edited ones get a new one.

        Only a new or edited document has its meaning checked (a restart reads the bank's shape only:
        the stored version was checked when it was stored), unless the shipped bank built from this
        code holds it (checked when the bank was built).
        """
        listed = {record.id: record for record in self.list()}
        documents = _bank_documents(self._bank_dir, self._shipped)
        hashes = {doc.id: document_hash(doc.model_dump(mode="json")) for doc in documents}
        unchanged = {
            doc.id
            for doc in documents
            if doc.id in listed and listed[doc.id].builtin and listed[doc.id].document_hash == hashes[doc.id]
        }
        vouched = vouched_documents(self._shipped, source_digest())
        faults = [
            (f"{doc.id}:{path}", message)
            for doc in documents
            if doc.id not in unchanged and hashes[doc.id] not in vouched
            for path, message in _meaning_faults(doc)
        ]
        if faults:
            raise ProblemInvalid(faults, "the built-in bank")
        saved = []
        for doc in documents:
            if doc.id in unchanged:  # stored as this very document already: nothing to write
                saved.append(listed[doc.id])
                continue
            try:
                saved.append(self._problems.save_builtin(doc.id, doc.model_dump(mode="json")))
            except ProblemExists:
                log.warning(
                    "an uploaded problem already uses the bank id %r; the bank's is not served", doc.id
                )
        return saved

    def warm_up(self) -> None:
        """Make every live problem ready to grade, then set `warm` (the instance is ready).

        A problem whose compilation is stored (and verifies) counts at once: one query finds them all,
        and they are opened after `warm` is set (or by the first request that needs one). The others are
        derived in the deriver's worker processes (seconds each), stored, and left sealed, before `warm`
        is set. One that fails is logged once and left to the first request that needs it. What the
        shipped bank holds under the running engine is stored from it instead of derived.
        """
        failed: set[str] = set()  # not derived again (nor logged again) by the opening below
        try:
            shipped: ShippedBank | None = None
            read = False  # the shipped bank's file (read once at most, and only when something is cold)
            if self._shipped is not None and not self._stored(self._store.engine_is_stored):
                # A first start (or new code): the shipped bank's file digest may spare parsing the engine.
                shipped, read = load_shipped(self._shipped), True
                if shipped is not None:
                    self._stored(lambda: self._store.adopt_engine(shipped.source, shipped.engine))
            records = self.list()
            sealed = self._stored(lambda: self._store.sealed(records)) or {}
            with self._lock:
                self._sealed.update(sealed)
            cold = [record for record in records if self._store.key(record) not in sealed]
            if cold and self._shipped is not None:
                cold = self._from_shipped(cold, shipped if read else load_shipped(self._shipped))
            if cold:
                log.info(
                    "deriving %s not stored yet, %d at a time in worker processes",
                    counted(len(cold), "problem"),
                    min(self._deriver.workers, len(cold)),
                )
                started = time.monotonic()
                failed = self._derive_all(cold)
                if not self._closing.is_set():
                    log.info(
                        "derived %s in %.1f s", counted(len(cold), "problem"), time.monotonic() - started
                    )
        finally:
            self.warm.set()
        for record in records:  # opened now rather than by a student's first request
            if self._closing.is_set():
                return
            if record.id not in failed:
                self._compile_logged(record)

    def _from_shipped(self, cold: list[ProblemRecord], shipped: ShippedBank | None) -> list[ProblemRecord]:
        """Store what the shipped bank holds of `cold` under the running engine, sealed like a
        derivation; returns the records it does not hold."""
        if shipped is None:
            return cold
        if shipped.engine != self._store.engine():
            log.info("the shipped bank was derived by other code; deriving what is not stored")
            return cold
        left = []
        for record in cold:
            payload = shipped.payloads.get(record.document_hash)
            if payload is None:
                left.append(record)
                continue
            self._stored(lambda: self._store.save(record, payload))  # noqa: B023 - called at once
            with self._lock:
                self._sealed[self._store.key(record)] = payload
        if len(left) < len(cold):
            log.info("loaded %s from the shipped bank", counted(len(cold) - len(left), "problem"))
        return left

    @property
    def deriving(self) -> tuple[int, int] | None:
        """While the warm-up derives what is not stored: how many of how many are done (failed ones
        too); None otherwise."""
        return None if self.warm.is_set() else self._deriving

    def _derive_all(self, records: list[ProblemRecord]) -> set[str]:
        """Each record derived by the deriver, stored, and left sealed for the opening after `warm`;
        returns the ids of those that failed."""
        failed: set[str] = set()
        derived = 0
        pending: dict[Future[bytes], ProblemRecord] = {}
        for index, record in enumerate(records):
            try:
                pending[self._deriver.submit(record.document)] = record
            except PoolError as error:  # closing, or no worker could start: the first request tries again
                left = records[index:]
                if not self._closing.is_set():
                    log.error("could not derive %s: %s", counted(len(left), "problem"), error)
                failed.update(skipped.id for skipped in left)
                break
        while pending and not self._closing.is_set():
            done, _ = wait(pending, timeout=0.5, return_when=FIRST_COMPLETED)
            for future in done:
                record = pending.pop(future)
                self._deriving = (len(records) - len(pending), len(records))
                try:
                    payload = future.result()
                except DerivationRefused as error:
                    self._note_refused(record, error)
                    failed.add(record.id)
                    continue
                except Exception as error:  # one broken problem must not keep the others cold
                    if not self._closing.is_set():
                        log.error(
                            "could not compile problem %r version %d: %s", record.id, record.version, error
                        )
                    failed.add(record.id)
                    continue
                self._stored(lambda: self._store.save(record, payload))  # noqa: B023 - called at once
                with self._lock:
                    self._sealed[self._store.key(record)] = payload
                derived += 1
                log.info("derived %r (%d of %d)", record.id, derived, len(records))
        return failed

    def _compile_logged(self, record: ProblemRecord) -> bool:
        try:
            self.compiled(record)
        except Exception:  # one broken problem must not keep the others cold
            if not self._closing.is_set():
                log.exception("could not compile problem %r version %d", record.id, record.version)
            return False
        return True

    def close(self) -> None:
        """Stop a warm-up still running (it would otherwise compile on after the app has shut down);
        returns once no thread uses the database any more."""
        self._closing.set()
        self._deriver.close()  # its workers killed: a shutdown mid-derivation leaves no process behind
        with self._store_lock:
            pass

    def is_stored(self, record: ProblemRecord) -> bool:
        """Whether the version's compilation is in the database (and verifies) under the running code."""
        return bool(self._store.sealed([record]))

    def entry(self, document: Mapping[str, Any], payload: bytes) -> CompiledEntry:
        """A vetted upload's compilation (a vetting worker's bytes), sealed to be stored with it."""
        return self._store.entry(document, payload)

    def get(self, problem_id: str, version: int | None = None) -> ProblemRecord:
        return self._problems.get(problem_id, version)

    def list(self) -> list[ProblemRecord]:
        return self._problems.list()

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
        """Derivations and prepared references: kept in memory per (id, version, hash), else loaded from
        the database, else compiled (and stored there).

        One compilation per problem version at a time: a burst of first requests waits for it rather
        than deriving the same model once per thread.
        """
        key = (record.id, record.version, record.document_hash)
        found = self._remembered(key)
        if found is not None:
            return found
        with self._lock:
            lock = self._compiling.setdefault(key, threading.Lock())
        try:
            with lock:
                found = self._remembered(key)
                if found is None:
                    found = self._opened(record)
                if found is None:
                    found = self._stored(lambda: self._store.load(record))
                if found is None:
                    found = self._derived(record)
                with self._lock:
                    self._compiled[key] = found
                    while len(self._compiled) > self._compiled_limit:
                        self._compiled.popitem(last=False)
                return found
        finally:
            with self._lock:  # later callers find the cache warm; no lock kept per version
                self._compiling.pop(key, None)

    def _derived(self, record: ProblemRecord) -> CompiledProblem:
        """Derived in a worker process, stored, opened. 503 when no worker can derive it now (a fault, a
        shutdown), 500 when it does not derive: it was vetted, so the code changed under it."""
        try:
            payload = self._deriver.submit(record.document, urgent=True).result()
        except PoolError as error:
            log.error("could not derive problem %r version %d: %r", record.id, record.version, error)
            raise Unavailable(
                "The problem is being prepared after a fault; try again in a moment.", retry_after=2
            ) from error
        except DerivationRefused as error:
            self._note_refused(record, error)
            raise GraderFault(
                "This problem cannot be graded by this version of physcheck: its model is refused now "
                "(its author can see why on the problem's page). Nothing was recorded."
            ) from error
        except DerivationFailed as error:
            log.error("could not derive problem %r version %d: %s", record.id, record.version, error)
            raise GraderFault(
                "This problem could not be prepared for grading; it has been logged. Nothing was recorded."
            ) from error
        self._stored(lambda: self._store.save(record, payload))
        found = self._store.open(record, payload)
        if found is None:
            raise GraderFault("This problem could not be prepared for grading; it has been logged.")
        return found

    def refusal(self, record: ProblemRecord) -> tuple[str, ...] | None:
        """Why the running engine refuses this stored version (each fault at its path), if it does."""
        with self._lock:
            why = self._refused.get((record.id, record.version))
        return None if why is None else tuple(why.splitlines())

    def _note_refused(self, record: ProblemRecord, error: DerivationRefused) -> None:
        """Kept for the author's pages; logged once per version (a student's request for it is a 500)."""
        with self._lock:
            known = (record.id, record.version) in self._refused
            self._refused[(record.id, record.version)] = str(error)
        if not known and not self._closing.is_set():
            log.error(
                "problem %r version %d is refused by this code, which it does not derive under "
                "(vetted by older code, its author must edit it): %s",
                record.id,
                record.version,
                "; ".join(str(error).splitlines()),
            )

    def _opened(self, record: ProblemRecord) -> CompiledProblem | None:
        """A payload found sealed at warm-up, unpickled now (each is opened once)."""
        with self._lock:
            payload = self._sealed.pop(self._store.key(record), None)
        return None if payload is None else self._store.open(record, payload)

    def _stored(self, use: Callable[[], T]) -> T | None:
        """Use the store unless closing: a warm-up still compiling must not reach a disposed database."""
        with self._store_lock:
            return None if self._closing.is_set() else use()

    def _remembered(self, key: tuple[str, int, str]) -> CompiledProblem | None:
        with self._lock:
            found = self._compiled.get(key)
            if found is not None:
                self._compiled.move_to_end(key)
            return found

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
        document = self.document(record)
        compiled = self.compiled(record) if needs_compiled(document) else None
        view = student_view(document, self.variant(record, student), compiled)
        return {**view, "version": record.version, "student": student}

    def variant(self, record: ProblemRecord, student: str) -> Variant:
        return draw_variant(self.document(record), record.version, student, self._secret)

    def figure(self, problem_id: str, student: str) -> str | None:
        """The problem's figure (SVG) with this student's values; None for a problem with no model."""
        drawn = self._model_and_values(problem_id, student)
        if drawn is None:
            return None
        model, values, title = drawn
        return model_figure(model, values, title=title)

    def free_body_figures(self, problem_id: str, student: str) -> tuple[tuple[str, str], ...]:
        """One free-body diagram per body of the problem's model, with this student's values: (its
        caption, the body's words as the worked solutions say them (Markdown); the SVG)."""
        drawn = self._model_and_values(problem_id, student)
        if drawn is None:
            return ()
        model, values, title = drawn
        captions = body_captions(self.document(self.get(problem_id)), model)
        return tuple(
            (captions[body.name], free_body_figure(model, body.name, values, title=title))
            for body in model.bodies
        )

    def _model_and_values(self, problem_id: str, student: str) -> tuple[Model, dict[str, float], str] | None:
        try:
            record = self.get(problem_id)
        except ProblemNotFound:
            return None
        doc = self.document(record)
        return model_and_values(doc, self.variant(record, student))


def model_and_values(doc: ProblemDocument, variant: Variant) -> tuple[Model, dict[str, float], str] | None:
    """The document's model as loaded (not derived: figures need its bodies and loads) with a
    variant's values in SI, and the title; None for a problem with no model."""
    if doc.model is None:
        return None
    table = symbol_table(doc)
    values = si_values(doc, variant, table)
    model = load_doc_model(doc, table)
    return model, {s.name: float(v) for s, v in values.items()}, doc.title
