"""A real LTI 1.3 platform (lti1p3platform==0.1.8) playing the LMS, as a small FastAPI app.

GET  /auth                    OIDC authorization endpoint: answers the tool's login redirect with
                              the launch it was told to make next, as JSON {id_token, state, launch_url}
GET  /jwks                    the platform's public key
POST /token                   client-credentials grant with a client assertion
POST /lineitems/{id}/scores   the AGS score service; `fail_scores` makes it answer 503 for a while,
                              `refusals` scripts an outage
"""

from __future__ import annotations

import functools
import typing as t
from dataclasses import dataclass, field

from cryptography.hazmat.primitives import serialization
from cryptography.hazmat.primitives.asymmetric import rsa
from fastapi import FastAPI, Request
from fastapi.responses import JSONResponse, Response
from lti1p3platform.ltiplatform import LTI1P3PlatformConfAbstract
from lti1p3platform.message_launch import LTIAdvantageMessageLaunchAbstract
from lti1p3platform.registration import Registration
from lti1p3platform.request import Request as LtiRequest
from lti1p3platform.score import UpdateScoreStatus
from lti1p3platform.service_connector import AssignmentsGradesService

ISSUER = "https://lms.test"
CLIENT_ID = "physcheck-client"
DEPLOYMENT_ID = "deployment-1"
TOOL = "https://tool.test"
INSTRUCTOR = "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"
LEARNER = "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"
SCORE_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
DEEP_LINKING_SETTINGS = "https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings"


def new_private_key_pem() -> str:
    key = rsa.generate_private_key(public_exponent=65537, key_size=2048)
    return key.private_bytes(
        serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8, serialization.NoEncryption()
    ).decode()


@functools.cache
def platform_private_key_pem() -> str:
    """One platform key per test run: RSA generation is the slow part of every fixture."""
    return new_private_key_pem()


@functools.cache
def other_private_key_pem() -> str:
    """A second key, for forgeries and for the platform's key rotation."""
    return new_private_key_pem()


def public_pem(private_pem: str) -> str:
    key = serialization.load_pem_private_key(private_pem.encode(), password=None)
    return (
        key.public_key()
        .public_bytes(serialization.Encoding.PEM, serialization.PublicFormat.SubjectPublicKeyInfo)
        .decode()
    )


class PlatformConfig(LTI1P3PlatformConfAbstract):
    def init_platform_config(self, **kwargs: t.Any) -> None:
        self._registration = kwargs["registration"]

    def get_registration_by_params(self, **kwargs: t.Any) -> Registration:
        return self._registration


class DictRequest(LtiRequest):
    def build_metadata(self, request: t.Any) -> t.Any:
        return request


class MessageLaunch(LTIAdvantageMessageLaunchAbstract):
    def get_preflight_response(self) -> dict[str, t.Any]:
        return dict(self._request.get_data)

    def render_launch_form(self, launch_data: dict[str, t.Any], **kwargs: t.Any) -> dict[str, t.Any]:
        return launch_data


@dataclass
class NextLaunch:
    """What the platform's next launch carries."""

    user: str = "student-1"
    roles: list[str] = field(default_factory=lambda: [LEARNER])
    problem: str | None = "moving-wedge"
    lineitem: str | None = f"{ISSUER}/lineitems/1"
    deep_linking: bool = False
    accept_types: set[str] | None = None  # deep linking: what the platform takes (default: every type)
    accept_multiple: bool = True
    # The LMS course launched from (the LTI context claim) and custom parameters that replace
    # `problem`'s (e.g. a deep-linked assignment's {"assignment": "3"}).
    context: str | None = None
    custom: dict[str, str] | None = None


@dataclass
class ReceivedScore:
    line_item_id: str
    score: dict[str, t.Any]
    content_type: str


class FakeLms:
    def __init__(self) -> None:
        self.private_pem = platform_private_key_pem()
        self.registration = (
            Registration()
            .set_iss(ISSUER)
            .set_client_id(CLIENT_ID)
            .set_deployment_id(DEPLOYMENT_ID)
            .set_oidc_login_url(f"{TOOL}/lti/login")
            .set_launch_url(f"{TOOL}/lti/launch")
            .set_deeplink_launch_url(f"{TOOL}/lti/launch")
            .set_platform_private_key(self.private_pem)
            .set_platform_public_key(public_pem(self.private_pem))
        )
        self.next_launch = NextLaunch()
        self.scores: list[ReceivedScore] = []
        self.fail_scores = 0  # answer this many score posts with 503 first
        self.score_status: int | None = None  # force a status (e.g. 422) for every score post
        self.token_requests = 0
        self.jwks_down = False
        self.assertions: list[str] = []  # client assertions received at the token endpoint
        self.token_lifetime: int | None = None  # override the platform's expires_in
        self.retry_after: str | None = None  # sent with the 503s
        # An outage script: score posts are answered with these (status, Retry-After) first, in turn.
        self.refusals: list[tuple[int, str | None]] = []
        self.app = self._build_app()

    @property
    def kid(self) -> str:
        kid = self.registration.get_kid()
        assert kid
        return kid

    def config(self) -> PlatformConfig:
        return PlatformConfig(registration=self.registration)

    def trust_tool_keys(self, jwks: dict[str, t.Any]) -> None:
        self.registration.set_tool_key_set(jwks)

    def _build_app(self) -> FastAPI:
        app = FastAPI()

        @app.get("/auth")
        def auth(request: Request) -> dict[str, t.Any]:
            spec = self.next_launch
            launch = MessageLaunch(DictRequest({"get_data": dict(request.query_params)}), self.config())
            launch.set_user_data(spec.user, spec.roles, full_name=f"User {spec.user}")
            launch.set_resource_link_claim("link-1", title="Problem")
            if spec.custom is not None:
                launch.set_custom_parameters_claim(dict(spec.custom))
            elif spec.problem is not None:
                launch.set_custom_parameters_claim({"problem": spec.problem})
            if spec.context is not None:
                launch.set_launch_context_claim(spec.context, context_title=f"Physics ({spec.context})")
            if spec.lineitem is not None:
                launch.set_ags(lineitems_url=f"{ISSUER}/lineitems", lineitem_url=spec.lineitem)
            if spec.deep_linking:
                launch.set_dl(
                    f"{ISSUER}/deep-link-return",
                    title="Pick",
                    accept_types=spec.accept_types,
                    extra_data={"course": "physics-1"},
                )
                claim = t.cast(dict[str, t.Any], launch._deep_linking_launch_data)
                claim[DEEP_LINKING_SETTINGS]["accept_multiple"] = spec.accept_multiple
            return t.cast(dict[str, t.Any], launch.lti_launch())

        @app.get("/jwks")
        def jwks() -> t.Any:
            if self.jwks_down:
                return JSONResponse({"error": "down"}, status_code=500)
            return {"keys": self.registration.get_jwks()}

        @app.post("/token")
        async def token(request: Request) -> Response:
            self.token_requests += 1
            form = dict((await request.form()).items())
            self.assertions.append(str(form.get("client_assertion")))
            config = self.config()
            config.get_registration()
            try:
                answer = dict(config.get_access_token(form))
                if self.token_lifetime is not None:
                    answer["expires_in"] = self.token_lifetime
                return JSONResponse(answer)
            except Exception as error:
                return JSONResponse({"error": "invalid_client", "detail": str(error)}, status_code=401)

        @app.post("/lineitems/{line_item_id}/scores")
        async def scores(line_item_id: str, request: Request) -> Response:
            if self.refusals:
                status, retry_after = self.refusals.pop(0)
                headers = {"Retry-After": retry_after} if retry_after else None
                return JSONResponse({"error": "unavailable"}, status_code=status, headers=headers)
            if self.fail_scores > 0:
                self.fail_scores -= 1
                headers = {"Retry-After": self.retry_after} if self.retry_after else None
                return JSONResponse({"error": "down"}, status_code=503, headers=headers)
            if self.score_status is not None:
                return JSONResponse({"error": "refused by test"}, status_code=self.score_status)
            lms = self
            body = await request.json()

            class Service(AssignmentsGradesService):
                def find_lineitems(self, *a: t.Any, **k: t.Any) -> t.Any:
                    raise NotImplementedError

                def find_lineitem(self, *a: t.Any, **k: t.Any) -> t.Any:
                    raise NotImplementedError

                def create_lineitem(self, *a: t.Any, **k: t.Any) -> t.Any:
                    raise NotImplementedError

                def update_lineitem(self, *a: t.Any, **k: t.Any) -> t.Any:
                    raise NotImplementedError

                def delete_lineitem(self, *a: t.Any, **k: t.Any) -> t.Any:
                    raise NotImplementedError

                def get_results(self, *a: t.Any, **k: t.Any) -> t.Any:
                    raise NotImplementedError

                def update_score(self, line_item_id: str, score: t.Any) -> UpdateScoreStatus:
                    lms.scores.append(
                        ReceivedScore(line_item_id, dict(score), request.headers.get("content-type", ""))
                    )
                    return UpdateScoreStatus.SUCCESS

            config = self.config()
            config.get_registration()
            lti_request = DictRequest(
                {"method": "POST", "headers": request.headers, "json": body, "get_data": {}, "form_data": {}}
            )
            service = Service(
                lti_request, config, f"{ISSUER}/lineitems", f"{ISSUER}/lineitems/{line_item_id}"
            )
            result = service.handle_resp(service.handle_update_score, line_item_id=line_item_id)
            return JSONResponse({"message": result.message}, status_code=result.code)

        return app


def register_fake_lms(where: t.Any) -> None:
    """What an administrator does with `physcheck lti add-platform` for this LMS, in a `Database` or
    in `Stores`."""
    from app.db.database import Database
    from app.lti.platforms import add_platform
    from app.storage import sql_stores

    stores = sql_stores(where) if isinstance(where, Database) else where
    add_platform(
        stores.platforms,
        ISSUER,
        CLIENT_ID,
        [DEPLOYMENT_ID],
        f"{ISSUER}/auth",
        f"{ISSUER}/token",
        f"{ISSUER}/jwks",
    )
