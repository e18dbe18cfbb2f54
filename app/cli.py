"""The `physcheck` command: serve, keys, bank verify, problems, submissions, lti (API.md "Command line")."""

from __future__ import annotations

import argparse
import signal
import sys
import threading
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager, nullcontext
from pathlib import Path

from app.settings import Settings, get_settings
from physics.wording import counted

Handler = Callable[[argparse.Namespace, Settings], int]


def _serve(args: argparse.Namespace, settings: Settings) -> int:
    from app.heap import freeze_long_lived, pause_collection

    pause_collection()  # until the app is built: what is imported stays
    from app.grading.forkserver import start_early

    start_early()  # the workers' fork server loads the checker while this process imports the service
    import uvicorn

    from app.http_protocol import HttpProtocol
    from app.main import create_app
    from app.startup import Stopped, open_storage_when_reachable

    backend = settings.database_url.split(":", 1)[0]
    print(
        f"physcheck: serving http://{args.host}:{args.port} ({backend}; API docs at /docs)", file=sys.stderr
    )
    # Storage is opened before uvicorn takes the signals: while it waits for a database that does not
    # answer, SIGTERM and Ctrl-C stop it here (uvicorn would only note them until its start-up ends).
    stopping = threading.Event()
    with _stop_on_signals(stopping):
        try:
            storage = open_storage_when_reachable(settings, stopping)
        except Stopped as stopped:
            print(f"physcheck: {stopped}", file=sys.stderr)
            return 0
    if stopping.is_set():  # a signal after the database answered, before uvicorn listens
        storage.close()
        return 0
    app = create_app(settings, open_storage=lambda _: storage)
    freeze_long_lived()  # the modules and the app: what this process holds until it exits
    uvicorn.run(
        app,
        http=HttpProtocol,
        host=args.host,
        port=args.port,
        log_config=None,
        proxy_headers=True,
        timeout_graceful_shutdown=settings.shutdown_timeout_seconds,
    )
    return 0


@contextmanager
def _stop_on_signals(stopping: threading.Event) -> Iterator[None]:
    """SIGTERM and SIGINT set `stopping` (instead of killing the process or raising KeyboardInterrupt
    mid-query), then the previous handlers are back."""
    handled = (signal.SIGTERM, signal.SIGINT)
    previous = {sig: signal.signal(sig, lambda *_: stopping.set()) for sig in handled}
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def _keys_create(args: argparse.Namespace, settings: Settings) -> int:
    from app.keys import create_key
    from app.startup import open_database

    database = open_database(settings)
    try:
        plaintext, record = create_key(database, role=args.role, name=args.name, student=args.student)
    finally:
        database.dispose()
    print(
        f"Created {record.role} key {record.id} ({record.name or 'unnamed'}); it is shown only once:",
        file=sys.stderr,
    )
    print(plaintext)
    return 0


def _keys_revoke(args: argparse.Namespace, settings: Settings) -> int:
    from app.keys import revoke_key
    from app.startup import open_database

    database = open_database(settings)
    try:
        revoke_key(database, args.key_id)
    finally:
        database.dispose()
    print(f"Revoked key {args.key_id}.")
    return 0


def _bank_verify(args: argparse.Namespace, settings: Settings) -> int:
    from app.bank_verify import verify_command
    from app.shipped_bank import SHIPPED_BANK

    build = (Path(args.output) if args.output else SHIPPED_BANK) if args.build else None
    return verify_command(
        variants=args.variants, only=args.problem, bank_dir=settings.bank_dir, jobs=args.jobs, build=build
    )


def _bank_build(args: argparse.Namespace, settings: Settings) -> int:
    from app.shipped_bank import SHIPPED_BANK, build_bank

    output = Path(args.output) if args.output else SHIPPED_BANK
    faults = build_bank(
        output, settings.bank_dir, args.jobs or settings.derive_jobs, settings.check_memory_mb
    )
    for fault in faults:
        print(fault, file=sys.stderr)
    if faults:
        print(f"{counted(len(faults), 'problem')} did not derive; nothing written", file=sys.stderr)
        return 1
    print(f"wrote {output}")
    return 0


def _problems_import(args: argparse.Namespace, settings: Settings) -> int:
    from app.catalog import CompiledStore
    from app.startup import open_database
    from app.storage.sql import SqlCompiledCache, SqlProblemStore
    from app.transfer import import_problem
    from problems.errors import ProblemInvalid

    database = open_database(settings)
    try:
        seal = CompiledStore(SqlCompiledCache(database), settings.secret).entry
        for path in args.files:
            try:
                record = import_problem(SqlProblemStore(database), Path(path), seal)
            except ProblemInvalid as error:
                print(f"{path}: {counted(len(error.errors), 'error')}", file=sys.stderr)
                for where, message in error.errors:
                    print(f"  {where}: {message}", file=sys.stderr)
                return 1
            print(f"{path}: imported {record.id} version {record.version}")
    finally:
        database.dispose()
    return 0


def _problems_export(args: argparse.Namespace, settings: Settings) -> int:
    from app.startup import open_database
    from app.storage.sql import SqlProblemStore
    from app.transfer import export_problem

    database = open_database(settings)
    try:
        export_problem(SqlProblemStore(database), args.problem_id, args.format, sys.stdout)
    finally:
        database.dispose()
    return 0


def _submissions_export(args: argparse.Namespace, settings: Settings) -> int:
    from app.courses.access import enrolled_anywhere
    from app.startup import open_database
    from app.storage.sql import SqlSubmissionStore
    from app.storage.sql_courses import SqlCourseStore
    from app.transfer import export_submissions

    database = open_database(settings)
    try:
        with (
            open(args.output, "w", newline="", encoding="utf-8")
            if args.output
            else nullcontext(sys.stdout) as out
        ):
            # named from the rosters, as an instructor's CSV names them (app/instructor/router.py)
            person = enrolled_anywhere(SqlCourseStore(database))
            rows = export_submissions(SqlSubmissionStore(database), args.problem, out, person=person)
    finally:
        database.dispose()
    print(f"{counted(rows, 'submission')} exported", file=sys.stderr)
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="physcheck", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)

    serve = commands.add_parser("serve", help="apply migrations, load the bank, serve the API and pages")
    serve.add_argument("--host", default="127.0.0.1")
    serve.add_argument("--port", type=int, default=8000)
    serve.set_defaults(handler=_serve)

    keys = commands.add_parser("keys", help="API keys").add_subparsers(dest="keys_command", required=True)
    create = keys.add_parser("create", help="create a key and print it as the last line (shown once)")
    create.add_argument("--role", choices=["instructor", "student"], required=True)
    create.add_argument("--name", default=None)
    create.add_argument(
        "--student", default=None, help="identity a student key files submissions under (default: a fresh id)"
    )
    create.set_defaults(handler=_keys_create)
    revoke = keys.add_parser("revoke", help="revoke a key by its id")
    revoke.add_argument("key_id", type=int)
    revoke.set_defaults(handler=_keys_revoke)

    bank = commands.add_parser("bank", help="the built-in problem bank").add_subparsers(
        dest="bank_command", required=True
    )
    verify = bank.add_parser("verify", help="re-derive and self-test every problem; non-zero exit on failure")
    verify.add_argument("--variants", type=int, default=20, help="random student variants per problem")
    verify.add_argument("--problem", action="append", default=None, help="only this problem (repeatable)")
    verify.add_argument(
        "--jobs", type=int, default=None, help="problems derived at once (default: one per core)"
    )
    verify.add_argument(
        "--build",
        action="store_true",
        help="when every problem passes, also write the derived bank as `bank build` does (derived once)",
    )
    verify.add_argument(
        "--output", default=None, help="with --build: file to write (default: the package's own)"
    )
    verify.set_defaults(handler=_bank_verify)
    build = bank.add_parser(
        "build", help="derive the bank into the file shipped with the program (a first start loads it)"
    )
    build.add_argument("--output", default=None, help="file to write (default: the package's own)")
    build.add_argument(
        "--jobs", type=int, default=None, help="problems derived at once (default: one per core)"
    )
    build.set_defaults(handler=_bank_build)

    problems = commands.add_parser("problems", help="problem files").add_subparsers(
        dest="problems_command", required=True
    )
    imports = problems.add_parser(
        "import", help="vet and store problem files (YAML or JSON); a known id gets a new version"
    )
    imports.add_argument("files", nargs="+")
    imports.set_defaults(handler=_problems_import)
    exports = problems.add_parser("export", help="print a problem's latest version")
    exports.add_argument("problem_id")
    exports.add_argument("--format", choices=["yaml", "json"], default="yaml")
    exports.set_defaults(handler=_problems_export)

    submissions = commands.add_parser("submissions", help="submissions").add_subparsers(
        dest="submissions_command", required=True
    )
    csv_export = submissions.add_parser("export", help="submissions as CSV, oldest first")
    csv_export.add_argument("--problem", default=None)
    csv_export.add_argument("--output", "-o", default=None, help="file to write (default: standard output)")
    csv_export.set_defaults(handler=_submissions_export)

    from app.lti.cli import register_cli

    register_cli(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    handler: Handler = args.handler
    return handler(args, get_settings())


if __name__ == "__main__":
    sys.exit(main())
