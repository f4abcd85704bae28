"""Helpers of the playground's browser tests: a served playground and a headless Chromium."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

CHROMIUM_FLAGS = (
    "--headless=new",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-dev-shm-usage",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--window-size=1400,1000",
)
ADDRESS = re.compile(r"(http://127\.0\.0\.1:\d+/)")


def find_chromium() -> tuple[str, str] | None:
    """Return the paths of Chromium and its driver, or None when either is missing."""
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver")
    return (browser, driver) if browser and driver else None


class Playground:
    """``pixelpath playground`` running in a subprocess on a free port of 127.0.0.1."""

    def __init__(self) -> None:
        # Standard error goes to a file: warnings (an unwritable kernel cache, say) must not
        # stand in the way of the address on standard output, nor fill a pipe nobody reads.
        self.errors = tempfile.TemporaryFile(mode="w+")
        self.process = subprocess.Popen(
            [sys.executable, "-m", "pixelpath", "playground", "--no-browser",
             "--time-limit", "600"],
            stdout=subprocess.PIPE, stderr=self.errors, text=True,
        )
        first_line = self.process.stdout.readline()
        match = ADDRESS.search(first_line)
        if match is None:
            self.errors.seek(0)
            complaint = self.errors.read()
            self.close()
            raise RuntimeError(f"pixelpath playground did not print its address: "
                               f"{first_line!r}; standard error: {complaint!r}")
        self.url = match.group(1)

    def close(self) -> None:
        self.process.terminate()
        try:
            self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.process.stdout.close()
        self.errors.close()


def start_chromium(browser: str, driver: str, profile: Path):
    """Return a Selenium driver of headless Chromium with a fresh profile and the console log."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = browser
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    options.add_argument(f"--user-data-dir={profile}")
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(driver), options=options)


def artifacts_folder() -> Path:
    """Where screenshots go: $PIXELPATH_TEST_ARTIFACTS, or a fresh temporary folder."""
    folder = os.environ.get("PIXELPATH_TEST_ARTIFACTS")
    path = Path(folder) if folder else Path(tempfile.mkdtemp(prefix="pixelpath-playground-"))
    path.mkdir(parents=True, exist_ok=True)
    return path
