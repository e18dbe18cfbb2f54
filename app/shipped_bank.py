"""The derived bank that travels with the program: a first start loads it instead of deriving the bank.

`physcheck bank build` derives every problem of the built-in bank (in derivation workers, as a start
would) and writes the packed compilations to one file beside the code (`SHIPPED_BANK`, package data:
built with the package and in the Docker image, never committed). The file names the engine digest it
was derived under and the digest of the engine's files (`problems.fingerprint`), and each payload's
SHA-256:

    physcheck shipped bank 1\\n
    {"engine": ..., "source": ..., "entries": [{"document": hash, "sha256": ..., "bytes": n}, ...],
     "bank": {"digest": ..., "documents": [document, ...]}}\\n
    payload bytes, in the order of the entries

"bank" holds the bank's documents as read from its files (`problems.loader.bank_digest`): a start whose
bank files and engine files are those the file was built from takes them from here instead of parsing
every YAML file again (a fifth of a CPU-second, before it can be ready).

At start the catalog uses an entry only for a stored document of the same hash, under the same engine
digest, and only when its bytes hash to the digest the manifest gives: a stale file (other code) is
ignored and the bank derived in workers; a damaged one (truncated, flipped bits, not this format) is
refused whole, before any of it is unpickled. The file is trusted as the code beside it is (whoever can
replace it can replace the code): the digests catch damage, not an attacker. What it provides is then
stored sealed under the server's secret like any derivation (`app.catalog.CompiledStore`).
"""

from __future__ import annotations

import functools
import hashlib
import json
import logging
from collections.abc import Mapping, Sequence
from concurrent.futures import Future, as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from problems.schema import ProblemDocument

log = logging.getLogger("physcheck.catalog")

SHIPPED_BANK = Path(__file__).resolve().parent / "data" / "bank.compiled"
_MAGIC = b"physcheck shipped bank 1\n"


class DamagedBank(Exception):
    """The file is not a whole shipped bank in this format."""


@dataclass(frozen=True)
class ShippedBank:
    engine: str  # the engine digest the payloads were derived under
    source: str  # the digest of the engine's files then (equal files: the same engine digest)
    payloads: Mapping[str, bytes]  # by document hash, each matching its manifest digest


@dataclass(frozen=True)
class BankRead:
    """The bank's documents as its files read, and the digest of those files."""

    digest: str
    documents: Sequence[ProblemDocument]


def write_bank(
    path: Path, engine: str, source: str, payloads: Mapping[str, bytes], bank: BankRead | None = None
) -> None:
    """Write the file whole, then move it into place (a reader never sees half of one)."""
    ordered = sorted(payloads.items())
    manifest: dict[str, Any] = {
        "engine": engine,
        "source": source,
        "entries": [
            {"document": key, "sha256": hashlib.sha256(payload).hexdigest(), "bytes": len(payload)}
            for key, payload in ordered
        ],
    }
    if bank is not None:
        manifest["bank"] = {
            "digest": bank.digest,
            "documents": [document.model_dump(mode="json") for document in bank.documents],
        }
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_name(path.name + ".partial")
    with partial.open("wb") as out:
        out.write(_MAGIC)
        out.write(json.dumps(manifest, sort_keys=True).encode() + b"\n")
        for _, payload in ordered:
            out.write(payload)
    partial.replace(path)


def read_bank(path: Path) -> ShippedBank | None:
    """The shipped bank, every payload checked against its digest; None when there is no file.
    Raises DamagedBank when the file is anything but a whole bank in this format."""
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return None
    engine, source, listed, position = _entries(_manifest(data))
    payloads: dict[str, bytes] = {}
    for document, digest, size in listed:
        payload = data[position : position + size]
        if size < 0 or len(payload) != size or hashlib.sha256(payload).hexdigest() != digest:
            raise DamagedBank(f"the compilation of document {document[:12]} does not match its digest")
        payloads[document] = payload
        position += size
    if position != len(data):
        raise DamagedBank("it holds more than its manifest lists")
    return ShippedBank(engine, source, payloads)


def _manifest(data: bytes) -> tuple[dict[str, Any], int]:
    """The manifest and where the payloads start; raises DamagedBank when the start of `data` is not a
    manifest in this format."""
    if not data.startswith(_MAGIC):
        raise DamagedBank("it does not start as a shipped bank")
    end = data.find(b"\n", len(_MAGIC))
    if end < 0:
        raise DamagedBank("its manifest has no end")
    return _parsed(data[len(_MAGIC) : end]), end + 1


@functools.lru_cache(maxsize=2)
def _parsed(line: bytes) -> dict[str, Any]:
    """The manifest line read, once: a start reads it three times (the documents vouched for, the
    bank's documents, the payloads), and it is a quarter of a megabyte of JSON. Not to be mutated."""
    try:
        manifest = json.loads(line)
    except ValueError as error:
        raise DamagedBank(f"its manifest does not read: {error!r}") from None
    if not isinstance(manifest, dict):
        raise DamagedBank("its manifest is not a mapping")
    return manifest


def _entries(read: tuple[dict[str, Any], int]) -> tuple[str, str, list[tuple[str, str, int]], int]:
    """The engine and source digests, the entries (document hash, payload digest, size) and where the
    payloads start; raises DamagedBank when the manifest does not give them."""
    manifest, start = read
    try:
        engine, source, entries = manifest["engine"], manifest["source"], manifest["entries"]
        listed = [(str(e["document"]), str(e["sha256"]), int(e["bytes"])) for e in entries]
    except (ValueError, TypeError, KeyError) as error:
        raise DamagedBank(f"its manifest does not read: {error!r}") from None
    if not isinstance(engine, str) or not isinstance(source, str):
        raise DamagedBank("its manifest names no engine")
    return engine, source, listed, start


def _head(path: Path) -> bytes:
    """The magic line and the manifest line: all a reader of the manifest needs."""
    with path.open("rb") as file:
        return file.readline() + file.readline()


def vouched_documents(path: Path | None, source: str) -> frozenset[str]:
    """The hashes of the documents a shipped bank built from these very engine files (`source`, the
    source digest) holds: `build_bank` read them with their meaning checked, by this code, so a first
    start need not check them again (two thirds of its CPU). Only the manifest is read; an absent,
    stale or damaged file vouches for nothing (its payloads are checked when they are loaded)."""
    if path is None:
        return frozenset()
    try:
        _, built_from, listed, _ = _entries(_manifest(_head(path)))
    except (DamagedBank, OSError):
        return frozenset()
    return frozenset(document for document, _, _ in listed) if built_from == source else frozenset()


def shipped_documents(path: Path | None, bank: str, source: str) -> list[ProblemDocument] | None:
    """The bank's documents as the shipped bank holds them, when it was built from the bank files of
    digest `bank` by the engine files of digest `source` (this code: so they read as these files
    would); else None, and the files are parsed."""
    if path is None:
        return None
    try:
        manifest, _ = _manifest(_head(path))
        held = manifest.get("bank")
        if manifest.get("source") != source or not isinstance(held, dict) or held.get("digest") != bank:
            return None
        return [ProblemDocument.model_validate(document) for document in held["documents"]]
    except (DamagedBank, OSError, ValidationError, KeyError, TypeError):
        return None


def load_shipped(path: Path | None) -> ShippedBank | None:
    """`read_bank`, with a damaged file logged and refused (the bank is then derived in workers)."""
    if path is None:
        return None
    try:
        return read_bank(path)
    except (DamagedBank, OSError) as error:
        log.error("refusing the shipped bank %s: %s; deriving the bank instead", path, error)
        return None


# A build derives on whatever machine builds the image: a busy one may take minutes for a large problem.
BUILD_TIMEOUT_SECONDS = 900.0


def build_bank(
    path: Path, bank_dir: Path | None = None, jobs: int = 1, memory_mb: int = 2048, echo: bool = True
) -> list[str]:
    """Derive every problem of the bank in `jobs` derivation workers (as a first start would) and write
    the shipped bank to `path`; returns the faults (nothing is written unless every problem derived)."""
    from app.db.problems import document_hash
    from app.derivation import DerivationFailed, DerivationPool
    from problems.fingerprint import engine_digest, source_digest
    from problems.loader import bank_digest, load_bank

    bank = BankRead(bank_digest(bank_dir), load_bank(bank_dir))
    documents = [doc.model_dump(mode="json") for doc in bank.documents]
    pool = DerivationPool(jobs, BUILD_TIMEOUT_SECONDS, memory_mb)
    payloads: dict[str, bytes] = {}
    faults: list[str] = []
    try:
        pending: dict[Future[bytes], dict[str, object]] = {pool.submit(doc): doc for doc in documents}
        for done, future in enumerate(as_completed(pending), start=1):
            document = pending[future]
            try:
                payloads[document_hash(document)] = future.result()
            except DerivationFailed as error:
                faults.append(f"{document['id']}: {error}")
            if echo:
                print(f"derived {document['id']} ({done} of {len(documents)})", flush=True)
    finally:
        pool.close()
    if not faults:
        write_bank(path, engine_digest(), source_digest(), payloads, bank)
    return faults
