"""``pixelpath playground``: a local web app to see every algorithm work (the ``web`` extra)."""

from __future__ import annotations

import argparse
import ipaddress
import os
import socket
import sys
import threading
import webbrowser
from typing import Any

from pixelpath.cli._common import CommandError, add_command, error_console

WEB_EXTRA = "pip install 'pixelpath[web]'"


def register(subparsers: Any) -> None:
    """Add the ``playground`` subcommand."""
    parser = add_command(
        subparsers,
        "playground",
        summary="start a local web app to play with clipping, shading, HSR, rays and colour",
        description=(
            "Start the playground, a web app on this machine: drag a polygon and a clipping "
            "window and step through Sutherland-Hodgman's table and Weiler-Atherton's pieces; "
            "move Phong's sliders and see a ball in flat, Gouraud and Phong shading; render "
            "the bundled scenes with any hidden-surface method and read its report; click a "
            "pixel to see its tree of rays; pick a colour and see it in every model. It "
            "listens on 127.0.0.1 only unless --host says otherwise, prints its address and "
            f"opens the browser when there is one. Needs the web extra: {WEB_EXTRA}."
        ),
        examples=[
            "pixelpath playground",
            "pixelpath playground --port 8765 --no-browser",
            "pixelpath playground --time-limit 120",
        ],
        run=run,
    )
    parser.add_argument("--host", default="127.0.0.1",
                        help="address to listen on (default 127.0.0.1: this machine only)")
    parser.add_argument("--port", type=int, default=0,
                        help="port to listen on (default: a free one, printed)")
    parser.add_argument("--no-browser", action="store_true", help="do not open a web browser")
    parser.add_argument("--time-limit", type=float, default=60.0,
                        help="seconds one computation may take (default 60)")


def run(args: argparse.Namespace) -> int:
    """Serve the playground until interrupted."""
    try:
        import uvicorn

        from pixelpath.web import Limits, create_app
    except ImportError as exc:
        raise CommandError(f"the playground needs the web extra ({exc}): {WEB_EXTRA}") from None
    if not 0 <= args.port <= 65535:
        raise CommandError(f"--port must lie in 0..65535, got {args.port}")
    if not args.time_limit > 0:
        raise CommandError(f"--time-limit must be a positive number of seconds, got "
                           f"{args.time_limit}")
    local = is_loopback(args.host)
    app = create_app(Limits(render_seconds=args.time_limit),
                     allowed_hosts=None if not local else _local_names(args.host))
    listener = _listen(args.host, args.port)
    url = address(args.host, listener.getsockname()[1])
    print(f"pixelpath playground: {url}  (Ctrl+C stops it)", flush=True)
    if not local:
        error_console().print(
            f"[bold yellow]warning:[/] listening on {args.host}: other machines can reach the "
            "playground")
    if not args.no_browser and browser_available():
        threading.Thread(target=webbrowser.open, args=(url,), daemon=True).start()
    config = uvicorn.Config(app, log_level="warning", lifespan="on")
    uvicorn.Server(config).run(sockets=[listener])
    return 0


def is_loopback(host: str) -> bool:
    """Whether ``host`` names this machine only.

    Examples
    --------
    >>> from pixelpath.cli.playground import is_loopback
    >>> is_loopback("127.0.0.1"), is_loopback("localhost"), is_loopback("0.0.0.0")
    (True, True, False)
    """
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def _local_names(host: str) -> list[str]:
    from pixelpath.web.app import LOCAL_HOSTS

    return sorted({*LOCAL_HOSTS, host})


def address(host: str, port: int) -> str:
    """Return the URL of the playground listening on ``host``, ``port``.

    Examples
    --------
    >>> from pixelpath.cli.playground import address
    >>> address("127.0.0.1", 8765), address("::1", 8765)
    ('http://127.0.0.1:8765/', 'http://[::1]:8765/')
    """
    shown = f"[{host}]" if ":" in host and not host.startswith("[") else host
    return f"http://{shown}:{port}/"


def _listen(host: str, port: int) -> socket.socket:
    """Bind and listen now, so that the printed address is the one that answers."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    listener = socket.socket(family, socket.SOCK_STREAM)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        listener.bind((host.strip("[]"), port))
    except OSError as exc:
        listener.close()
        raise CommandError(f"cannot listen on {host} port {port}: {exc.strerror}") from None
    listener.listen(64)
    return listener


def browser_available() -> bool:
    """Whether a graphical web browser can be opened (never a text browser in this terminal).

    Examples
    --------
    >>> from pixelpath.cli.playground import browser_available
    >>> isinstance(browser_available(), bool)
    True
    """
    if sys.platform.startswith("linux") and not (
        os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
    ):
        return False
    try:
        browser = webbrowser.get()
    except webbrowser.Error:
        return False
    return not isinstance(browser, webbrowser.GenericBrowser) or isinstance(
        browser, webbrowser.BackgroundBrowser)
