"""`physcheck lti add-platform` and `lti rotate-keys`, through argparse as `app/cli.py` wires them."""

from __future__ import annotations

import argparse
from pathlib import Path

import pytest

from app.db.database import Database
from app.lti.cli import register_cli
from app.settings import Settings
from app.storage import sql_stores

ADD = [
    "lti", "add-platform", "--issuer", "https://canvas.test", "--client-id", "10000000000001",
    "--deployment-id", "1:abc", "--deployment-id", "2:def",
    "--auth-url", "https://canvas.test/api/lti/authorize_redirect",
    "--token-url", "https://canvas.test/login/oauth2/token",
    "--jwks-url", "https://canvas.test/api/lti/security/jwks",
]  # fmt: skip


def run(argv: list[str], settings: Settings) -> int:
    parser = argparse.ArgumentParser(prog="physcheck")
    register_cli(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args(argv)
    return int(args.handler(args, settings))


@pytest.fixture
def cli_settings(tmp_path: Path) -> Settings:
    # On SQL: the commands open (and migrate) the database the settings name; there is no fake to pass.
    return Settings(
        database_url=f"sqlite:///{tmp_path / 'cli.db'}",
        base_url="https://tool.test",
        secret="lti-cli-test-secret",
    )


def test_add_platform_registers_issuer_client_and_every_deployment(cli_settings: Settings):
    assert run(ADD, cli_settings) == 0
    database = Database(cli_settings.database_url)
    platforms = sql_stores(database).platforms
    platform = platforms.find("https://canvas.test", "10000000000001")
    assert platform.token_url == "https://canvas.test/login/oauth2/token"
    assert platforms.deployments(platform.id) == ["1:abc", "2:def"]
    database.dispose()


def test_add_platform_twice_adds_deployments_without_duplicating(cli_settings: Settings):
    assert run(ADD, cli_settings) == 0
    assert run([*ADD, "--deployment-id", "3:ghi"], cli_settings) == 0
    database = Database(cli_settings.database_url)
    platforms = sql_stores(database).platforms
    platform = platforms.find("https://canvas.test", None)
    assert platforms.deployments(platform.id) == ["1:abc", "2:def", "3:ghi"]
    database.dispose()


def test_add_platform_with_relative_url_fails_cleanly(
    cli_settings: Settings, capsys: pytest.CaptureFixture[str]
):
    argv = [value if value != "https://canvas.test/login/oauth2/token" else "/token" for value in ADD]
    assert run(argv, cli_settings) == 2
    assert "token_url" in capsys.readouterr().err


def test_rotate_keys_prints_new_kid(cli_settings: Settings, capsys: pytest.CaptureFixture[str]):
    assert run(["lti", "rotate-keys"], cli_settings) == 0
    assert "New signing key" in capsys.readouterr().out
