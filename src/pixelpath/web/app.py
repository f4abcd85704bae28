"""The playground's Starlette application: pages, static files and the JSON API.

Safe by default:

* the pages and their scripts are files of the package, served from fixed routes; the
  Content-Security-Policy lets a page load nothing from anywhere else;
* a request's ``Host`` must name the machine the app listens on (``127.0.0.1``,
  ``localhost``, ``::1`` by default), which stops other web sites from reaching it through
  DNS rebinding;
* every API request is validated (:mod:`pixelpath.web._limits`); the computation runs in a
  small pool of worker threads, off the event loop, with a time limit;
* errors are answered as JSON ``{"error": message}`` with a 4xx status (5xx for a time-out
  or a fault of the app), never with a traceback.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from importlib import resources
from pathlib import Path
from typing import Any

from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import Request
from starlette.responses import FileResponse, JSONResponse, RedirectResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from pixelpath.web import api
from pixelpath.web._limits import BadRequest, Limits, parse_json

__all__ = ["LOCAL_HOSTS", "PAGES", "create_app"]

LOCAL_HOSTS = ("127.0.0.1", "localhost", "::1", "[::1]")

# Route -> (file under static/, title in the navigation bar).
PAGES = {
    "/clipping": ("clipping.html", "Clipping"),
    "/illumination": ("illumination.html", "Illumination"),
    "/hidden-surfaces": ("hidden-surfaces.html", "Hidden surfaces"),
    "/ray-tracing": ("ray-tracing.html", "Ray tracing"),
    "/colour": ("colour.html", "Colour"),
    "/practice": ("practice.html", "Practice"),
}

SECURITY_HEADERS = [
    (b"content-security-policy",
     b"default-src 'self'; img-src 'self' data:; style-src 'self'; script-src 'self'; "
     b"connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'"),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"no-referrer"),
]

log = logging.getLogger("pixelpath.web")


def static_folder() -> Path:
    """Return the folder of the pages, styles and scripts shipped in the package."""
    return Path(str(resources.files("pixelpath.web") / "static"))


def create_app(
    limits: Limits | None = None, *, allowed_hosts: Sequence[str] | None = LOCAL_HOSTS
) -> Starlette:
    """Return the playground as a Starlette application (serve it with uvicorn).

    Parameters
    ----------
    limits : Limits, optional
        Caps on images, polygons, request bodies and computing time (default: ``Limits()``).
    allowed_hosts : sequence of str or None
        Host names a request may be addressed to; None accepts any (only for an app that
        listens beyond this machine on purpose).

    Returns
    -------
    starlette.applications.Starlette

    Examples
    --------
    >>> from starlette.testclient import TestClient
    >>> from pixelpath.web import create_app
    >>> client = TestClient(create_app(), base_url="http://127.0.0.1")
    >>> client.post("/api/colour", json={"model": "rgb", "values": [1, 0, 0]}).json()["hex"]
    '#ff0000'
    >>> client.post("/api/colour", json={"model": "lab"}).status_code
    400
    """
    limits = Limits() if limits is None else limits
    runner = Runner(limits)
    folder = static_folder()
    routes = [
        Route("/", _file_endpoint(folder / "index.html")),
        *(Route(path, _file_endpoint(folder / name)) for path, (name, _) in PAGES.items()),
        *(Route(f"/api/{name}", _api_endpoint(handler, runner, limits), methods=["GET"])
          for name, handler in api.LISTINGS.items()),
        *(Route(f"/api/{name}", _api_endpoint(handler, runner, limits), methods=["POST"])
          for name, handler in api.ENDPOINTS.items()),
        Route("/favicon.ico", lambda request: RedirectResponse("/static/favicon.svg")),
        Mount("/static", StaticFiles(directory=folder), name="static"),
    ]
    middleware = [Middleware(SecurityHeaders)]
    if allowed_hosts is not None:
        middleware.insert(0, Middleware(TrustedHostMiddleware, allowed_hosts=list(allowed_hosts)))

    @contextlib.asynccontextmanager
    async def lifespan(app: Starlette):
        yield
        runner.close()

    return Starlette(
        routes=routes,
        middleware=middleware,
        exception_handlers={HTTPException: _http_error, Exception: _server_error},
        lifespan=lifespan,
    )


class Runner:
    """Runs the API's computations in a few worker threads, each with a time limit.

    A computation past its limit is answered with a 503; its thread cannot be stopped, so it
    finishes in the background (the first render of a method compiles its kernels, and the
    next request finds them ready).
    """

    def __init__(self, limits: Limits) -> None:
        self.seconds = limits.render_seconds
        self.executor = ThreadPoolExecutor(max_workers=limits.workers,
                                           thread_name_prefix="pixelpath-web")

    async def run(self, function: Callable[..., Any], *args: Any) -> Any:
        """Return ``function(*args)`` computed in a worker thread, or raise a 503 BadRequest."""
        future = asyncio.get_running_loop().run_in_executor(self.executor, function, *args)
        try:
            return await asyncio.wait_for(future, self.seconds)
        except TimeoutError:
            raise BadRequest(
                f"the computation took longer than the playground's limit of {self.seconds:g} s "
                "(a method's first run compiles its kernels: try again in a moment, or ask for "
                "a smaller image)", status=503) from None

    def close(self) -> None:
        """Stop taking work; computations already running finish on their own."""
        self.executor.shutdown(wait=False, cancel_futures=True)


def _api_endpoint(handler: Callable[[dict, Limits], dict], runner: Runner,
                  limits: Limits) -> Callable[[Request], Any]:
    async def endpoint(request: Request) -> Response:
        try:
            data = parse_json(await _body(request, limits), limits)
            answer = await runner.run(handler, data, limits)
        except BadRequest as exc:
            return _error(str(exc), exc.status)
        except (ValueError, TypeError) as exc:  # the library's own checks
            return _error(str(exc), 400)
        return JSONResponse(answer)

    endpoint.__name__ = handler.__name__
    return endpoint


async def _body(request: Request, limits: Limits) -> bytes:
    """Read the body, refusing it as soon as it is longer than the limit."""
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limits.max_body_bytes:
            raise BadRequest(f"the request body is larger than the {limits.max_body_bytes} bytes "
                             "allowed", status=413)
        chunks.append(chunk)
    return b"".join(chunks)


def _file_endpoint(path: Path) -> Callable[[Request], Any]:
    async def endpoint(request: Request) -> Response:
        return FileResponse(path, media_type="text/html")

    return endpoint


def _error(message: str, status: int) -> JSONResponse:
    return JSONResponse({"error": message}, status_code=status)


async def _http_error(request: Request, exc: HTTPException) -> Response:
    return _error(str(exc.detail), exc.status_code)


async def _server_error(request: Request, exc: Exception) -> Response:
    log.exception("pixelpath playground: %s %s failed", request.method, request.url.path)
    return _error("the playground failed on this request (a bug: please report it)", 500)


class SecurityHeaders:
    """ASGI middleware adding the Content-Security-Policy and friends to every response."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return

        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                message = {**message, "headers": [*message.get("headers", []),
                                                  *SECURITY_HEADERS]}
            await send(message)

        await self.app(scope, receive, send_with_headers)
