"""The web service: HTTP API, storage, authentication and LTI, around the physics core."""
