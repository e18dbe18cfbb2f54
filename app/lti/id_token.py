"""Verification of a platform's id_token: every check LTI 1.3 and OpenID Connect ask for, and a few
that common libraries skip (audience and azp, a leeway on both clock checks, a kid required)."""

from __future__ import annotations

import base64
import json
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from datetime import UTC, datetime, timedelta
from typing import TYPE_CHECKING, Any, Protocol

from app.lti.errors import MalformedRequest, UntrustedToken
from app.lti.keys import BadKey, verified_claims
from app.lti.platforms import PlatformRecord

if TYPE_CHECKING:
    from joserfc.jwk import RSAKey

LEEWAY = timedelta(seconds=60)
DEFAULT_MAX_AGE = timedelta(hours=1)  # the setting `lti_max_token_age_seconds`
RESOURCE_LINK_TYPE = "ltiResourceLink"
ALGORITHM = "RS256"
LTI_VERSION = "1.3.0"
RESOURCE_LINK_REQUEST = "LtiResourceLinkRequest"
DEEP_LINKING_REQUEST = "LtiDeepLinkingRequest"
MESSAGE_TYPES = frozenset({RESOURCE_LINK_REQUEST, DEEP_LINKING_REQUEST})
MAX_TOKEN_CHARS = 64 * 1024

LTI = "https://purl.imsglobal.org/spec/lti/claim/"
CLAIM_MESSAGE_TYPE = LTI + "message_type"
CLAIM_VERSION = LTI + "version"
CLAIM_DEPLOYMENT_ID = LTI + "deployment_id"
CLAIM_ROLES = LTI + "roles"
CLAIM_CUSTOM = LTI + "custom"
CLAIM_RESOURCE_LINK = LTI + "resource_link"
CLAIM_CONTEXT = LTI + "context"
CLAIM_AGS_ENDPOINT = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
CLAIM_DEEP_LINKING_SETTINGS = "https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings"
SCOPE_SCORE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"


class KeySource(Protocol):
    async def key_for(self, platform: PlatformRecord, kid: str) -> RSAKey: ...


@dataclass(frozen=True)
class LaunchClaims:
    """What a verified launch tells us; identity is (issuer, sub)."""

    issuer: str
    sub: str
    deployment_id: str
    message_type: str
    roles: tuple[str, ...]
    name: str
    nonce: str
    expires_at: datetime
    custom: Mapping[str, Any] = field(default_factory=dict)
    resource_link_id: str | None = None
    lineitem_url: str | None = None  # set only when the platform lets us post scores to it
    deep_link_return_url: str | None = None
    deep_link_data: Any = None  # opaque, echoed back in the response
    deep_link_accept_multiple: bool = False  # may the response carry several items
    context_id: str | None = None  # the LMS course (context) launched from, when the platform says
    context_title: str = ""


MAX_HEADER_CHARS = 2048


def read_header(token: str) -> dict[str, Any]:
    """The JOSE header, unverified, to learn `alg` and `kid` before choosing a key."""
    if len(token) > MAX_TOKEN_CHARS:
        raise MalformedRequest("token_too_large", "The id_token is too large.")
    parts = token.split(".")
    if len(parts) != 3:
        raise UntrustedToken(
            "malformed_token", "The id_token is not a signed JWT (three dot-separated parts)."
        )
    if len(parts[0]) > MAX_HEADER_CHARS:  # a real header is a few dozen characters
        raise UntrustedToken("malformed_token", "The id_token header is too large.")
    try:
        header = json.loads(base64.urlsafe_b64decode(parts[0] + "=" * (-len(parts[0]) % 4)))
    except (ValueError, UnicodeDecodeError, RecursionError) as error:
        raise UntrustedToken("malformed_token", "The id_token header cannot be read.") from error
    if not isinstance(header, dict):
        raise UntrustedToken("malformed_token", "The id_token header is not a JSON object.")
    return header


def check_header(header: Mapping[str, Any]) -> str:
    """RS256 and a kid, or refusal; returns the kid."""
    alg = header.get("alg")
    if alg != ALGORITHM:
        raise UntrustedToken(
            "algorithm_not_allowed", f"The id_token must be signed with RS256; it says {str(alg)[:20]!r}."
        )
    kid = header.get("kid")
    if not isinstance(kid, str) or not kid:
        raise UntrustedToken("missing_kid", "The id_token header names no key (kid).")
    return kid


async def verify_id_token(
    token: str,
    platform: PlatformRecord,
    keys: KeySource,
    *,
    now: datetime,
    expected_nonce: str,
    max_age: timedelta = DEFAULT_MAX_AGE,
) -> LaunchClaims:
    """Signature by the platform's published key, then every claim; raises a LaunchRefused subclass."""
    kid = check_header(read_header(token))
    key = await keys.key_for(platform, kid)
    try:
        claims = verified_claims(token, key)
    except BadKey as error:
        raise UntrustedToken("bad_signature", "The id_token signature does not verify.") from error
    return check_claims(claims, platform, now=now, expected_nonce=expected_nonce, max_age=max_age)


def _timestamp(claims: Mapping[str, Any], name: str) -> datetime:
    value = claims.get(name)
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise UntrustedToken(f"missing_{name}", f"The id_token has no numeric '{name}' claim.")
    try:
        return datetime.fromtimestamp(value, UTC)
    except (OverflowError, OSError, ValueError) as error:
        raise UntrustedToken(f"bad_{name}", f"The id_token's '{name}' is out of range.") from error


def _string(claims: Mapping[str, Any], name: str, code: str, what: str) -> str:
    value = claims.get(name)
    if not isinstance(value, str) or not value:
        raise UntrustedToken(code, f"The id_token has no {what}.")
    return value


def check_audience(claims: Mapping[str, Any], client_id: str) -> None:
    """`aud` must contain our client_id; with several audiences `azp` must be present and ours, and an
    `azp` that is present must always be ours (OpenID Connect Core 3.1.3.7)."""
    aud = claims.get("aud")
    audiences = [aud] if isinstance(aud, str) else aud
    if not isinstance(audiences, list) or not audiences or not all(isinstance(a, str) for a in audiences):
        raise UntrustedToken("bad_audience", "The id_token has no audience.")
    if client_id not in audiences:
        raise UntrustedToken("wrong_audience", "The id_token is not addressed to this tool.")
    azp = claims.get("azp")
    if len(audiences) > 1 and azp is None:
        raise UntrustedToken(
            "missing_azp", "The id_token has several audiences but no authorized party (azp)."
        )
    if azp is not None and azp != client_id:
        raise UntrustedToken("wrong_azp", "The id_token's authorized party (azp) is not this tool.")


def check_claims(
    claims: Mapping[str, Any],
    platform: PlatformRecord,
    *,
    now: datetime,
    expected_nonce: str,
    max_age: timedelta = DEFAULT_MAX_AGE,
) -> LaunchClaims:
    """Everything after the signature. Deployment registration is checked by the caller (a database
    look-up), as is the nonce's single use."""
    if claims.get("iss") != platform.issuer:
        raise UntrustedToken("wrong_issuer", "The id_token was issued by another platform.")
    check_audience(claims, platform.client_id)
    expires_at = _timestamp(claims, "exp")
    if expires_at + LEEWAY < now:
        raise UntrustedToken("expired", "The id_token has expired.")
    issued_at = _timestamp(claims, "iat")
    if issued_at - LEEWAY > now:
        raise UntrustedToken("issued_in_future", "The id_token claims to be issued in the future.")
    if issued_at + max_age + LEEWAY < now:
        # A far-future `exp` must not make an old token good for ever.
        raise UntrustedToken(
            "token_too_old", "The id_token was issued too long ago; open the activity again."
        )
    nonce = claims.get("nonce")
    if not isinstance(nonce, str) or nonce != expected_nonce:
        raise UntrustedToken("nonce_mismatch", "The id_token's nonce is not the one this login issued.")
    sub = _string(claims, "sub", "missing_sub", "user (sub); anonymous launches are not supported")
    deployment_id = _string(claims, CLAIM_DEPLOYMENT_ID, "missing_deployment_id", "deployment_id")
    message_type = claims.get(CLAIM_MESSAGE_TYPE)
    if message_type not in MESSAGE_TYPES:
        raise UntrustedToken(
            "unsupported_message_type", "This tool accepts resource link and deep linking launches."
        )
    if claims.get(CLAIM_VERSION) != LTI_VERSION:
        raise UntrustedToken("unsupported_version", "This tool speaks LTI 1.3.0.")
    roles = claims.get(CLAIM_ROLES)
    if not isinstance(roles, list) or not all(isinstance(role, str) for role in roles):
        raise UntrustedToken("missing_roles", "The id_token has no roles claim.")
    custom = claims.get(CLAIM_CUSTOM) or {}
    if not isinstance(custom, dict):
        raise UntrustedToken("bad_custom", "The id_token's custom claim is not an object.")
    name = next((claims[k] for k in ("name", "given_name") if isinstance(claims.get(k), str)), "")
    launch = LaunchClaims(
        issuer=platform.issuer,
        sub=sub,
        deployment_id=deployment_id,
        message_type=str(message_type),
        roles=tuple(roles),
        name=str(name)[:200],
        nonce=nonce,
        expires_at=expires_at,
        custom=custom,
    )
    context = claims.get(CLAIM_CONTEXT)
    if isinstance(context, dict) and isinstance(context.get("id"), str) and 0 < len(context["id"]) <= 255:
        title = next((context[k] for k in ("title", "label") if isinstance(context.get(k), str)), "")
        launch = replace(launch, context_id=context["id"], context_title=str(title)[:200])
    if message_type == RESOURCE_LINK_REQUEST:
        return _with_resource_link(launch, claims)
    return _with_deep_linking(launch, claims)


def _with_resource_link(launch: LaunchClaims, claims: Mapping[str, Any]) -> LaunchClaims:
    link = claims.get(CLAIM_RESOURCE_LINK)
    if not isinstance(link, dict) or not isinstance(link.get("id"), str):
        raise UntrustedToken("missing_resource_link", "The launch names no resource link.")
    lineitem: str | None = None
    endpoint = claims.get(CLAIM_AGS_ENDPOINT)
    if isinstance(endpoint, dict):
        scopes = endpoint.get("scope")
        url = endpoint.get("lineitem")
        if isinstance(url, str) and isinstance(scopes, list) and SCOPE_SCORE in scopes:
            lineitem = url
    return replace(launch, resource_link_id=link["id"], lineitem_url=lineitem)


def _with_deep_linking(launch: LaunchClaims, claims: Mapping[str, Any]) -> LaunchClaims:
    settings = claims.get(CLAIM_DEEP_LINKING_SETTINGS)
    if not isinstance(settings, dict) or not isinstance(settings.get("deep_link_return_url"), str):
        raise UntrustedToken("missing_deep_linking_settings", "The deep linking launch has no return URL.")
    accepted = settings.get("accept_types")
    if not isinstance(accepted, list) or RESOURCE_LINK_TYPE not in accepted:
        shown = ", ".join(str(t)[:40] for t in accepted[:10]) if isinstance(accepted, list) else "nothing"
        raise MalformedRequest(
            "resource_links_not_accepted",
            f"Here the LMS accepts only {shown}; physcheck problems are added as LTI resource links. "
            "Add the tool where the LMS offers external tool (LTI) links, e.g. as an assignment.",
        )
    return replace(
        launch,
        deep_link_return_url=settings["deep_link_return_url"],
        deep_link_data=settings.get("data"),
        # Absent means the platform did not say it takes several: one is always safe.
        deep_link_accept_multiple=settings.get("accept_multiple") is True,
    )
