"""LTI 1.3 / LTI Advantage tool: platform registration, our signing keys, OIDC login and launch,
Deep Linking 2.0, and grade passback (Assignment and Grade Services) through a durable outbox.

What the rest of the app uses:
- `app.lti.router.router`: the HTTP routes (`/lti/...`, `/.well-known/jwks.json`).
- `app.lti.context.LtiContext` kept in `app.state.lti` (or `get_lti_context` overridden).
- `app.lti.sessions.principal_from_session(request)`: the session cookie as a Principal.
- `app.lti.outbox.OutboxWorker` and the outbox's rules; storage is `app.storage`'s (no module here
  opens a database session).
- `app.lti.cli.register_cli(subparsers)`: `physcheck lti add-platform | rotate-keys`.
"""
