"""`create_app` on the in-memory stores, for the tests that run the whole app without a database."""

from __future__ import annotations

from app.catalog import Catalog
from app.settings import Settings
from app.startup import DatabaseKeyStore, Storage, deriver
from app.storage import memory_stores


def memory_app_storage(settings: Settings) -> Storage:
    """What `create_app` opens, on fresh in-memory stores with the bank of `settings` stored."""
    stores = memory_stores()
    catalog = Catalog(stores, settings.secret, settings.bank_dir, deriver=deriver(settings))
    catalog.sync_builtin()
    return Storage(database=None, stores=stores, keys=DatabaseKeyStore(stores.keys), catalog=catalog)
