"""``pixelpath playground``: it serves on 127.0.0.1, prints its address, explains what it needs."""

from __future__ import annotations

import json
import sys
import urllib.error
import urllib.request

import pytest

from pixelpath.cli import main

pytest.importorskip("uvicorn", reason="the playground needs the web extra (uvicorn)")

from playground_browser import Playground


def test_playground_serves_on_localhost_and_prints_its_address():
    playground = Playground()
    try:
        assert playground.url.startswith("http://127.0.0.1:")
        with urllib.request.urlopen(playground.url + "api/scenes", timeout=60) as response:
            assert "showcase" in json.load(response)["scenes"]
        foreign = urllib.request.Request(playground.url + "api/scenes",
                                         headers={"Host": "evil.example"})
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(foreign, timeout=60)
        refused.value.close()
        assert refused.value.code == 400
    finally:
        playground.close()


def test_playground_without_the_web_extra_says_how_to_install_it(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "uvicorn", None)  # import uvicorn now fails
    assert main(["playground", "--no-browser"]) == 2
    assert "pip install 'pixelpath[web]'" in capsys.readouterr().err.replace("\n", "")


@pytest.mark.parametrize(("option", "message"), [
    (["--port", "70000"], "--port must lie in 0..65535"),
    (["--time-limit", "0"], "--time-limit must be a positive number"),
])
def test_playground_refuses_bad_options(capsys, option, message):
    assert main(["playground", "--no-browser", *option]) == 2
    assert message in capsys.readouterr().err.replace("\n", "")
