"""`physcheck lti add-platform ...` and `physcheck lti rotate-keys` (API.md "Command line")."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from app.settings import Settings


def _open(settings: Settings) -> Any:
    from app.startup import open_database  # migrates first

    return open_database(settings)


def _add_platform(args: argparse.Namespace, settings: Settings) -> int:
    from app.lti.platforms import add_platform
    from app.storage import sql_stores

    database = _open(settings)
    try:
        record = add_platform(
            sql_stores(database).platforms,
            args.issuer,
            args.client_id,
            args.deployment_id,
            args.auth_url,
            args.token_url,
            args.jwks_url,
        )
    except ValueError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    finally:
        database.dispose()
    base = settings.base_url.rstrip("/")
    print(f"Registered platform {record.id}: issuer {record.issuer}, client_id {record.client_id}.")
    print(f"Tool values for the LMS: login {base}/lti/login, launch (redirect) {base}/lti/launch, ")
    print(f"deep linking {base}/lti/launch, keyset {base}/lti/jwks")
    return 0


def _rotate_keys(args: argparse.Namespace, settings: Settings) -> int:
    from app.storage import sql_stores

    database = _open(settings)
    try:
        kid = sql_stores(database).tool_keys.rotate()
    finally:
        database.dispose()
    print(f"New signing key {kid}; the previous key stays published until the next rotation.")
    return 0


def register_cli(subparsers: Any) -> None:
    """Add `lti add-platform` and `lti rotate-keys` to the top-level argparse subparsers; each handler
    takes `(args, settings)` and returns the exit status."""
    lti = subparsers.add_parser("lti", help="LTI 1.3: LMS registration and tool keys")
    commands = lti.add_subparsers(dest="lti_command", required=True)
    add = commands.add_parser("add-platform", help="register an LMS (LTI 1.3 platform)")
    add.add_argument("--issuer", required=True)
    add.add_argument("--client-id", required=True)
    add.add_argument("--deployment-id", action="append", required=True, help="repeat for several deployments")
    add.add_argument("--auth-url", required=True, help="the platform's OIDC authorization endpoint")
    add.add_argument("--token-url", required=True, help="the platform's OAuth2 token endpoint")
    add.add_argument("--jwks-url", required=True, help="the platform's public keyset URL")
    add.set_defaults(handler=_add_platform)
    rotate = commands.add_parser("rotate-keys", help="new signing key; the previous one stays published")
    rotate.set_defaults(handler=_rotate_keys)
