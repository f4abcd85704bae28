"""The playground: a local web app to see every algorithm work (``pixelpath playground``).

Pages for clipping, illumination, hidden surfaces, ray tracing, colour and practice (seeded
exam questions, answers marked, worked solutions), served by a Starlette app
(:func:`create_app`) whose small JSON API calls the library's own functions.
It needs the ``web`` extra: ``pip install 'pixelpath[web]'``. ``import pixelpath`` does not
import this package.

Examples
--------
>>> from starlette.testclient import TestClient
>>> from pixelpath.web import create_app
>>> client = TestClient(create_app(), base_url="http://127.0.0.1")
>>> client.get("/api/scenes").json()["methods"][0]
'zbuffer'
"""

from __future__ import annotations

from pixelpath.web._limits import BadRequest, Limits
from pixelpath.web.app import create_app

__all__ = ["BadRequest", "Limits", "create_app"]
