"""Storage: SQLAlchemy 2 tables, sessions and repositories; SQLite by default, PostgreSQL by URL."""
