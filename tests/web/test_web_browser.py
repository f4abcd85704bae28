"""The playground's pages in headless Chromium: drag, slide, click, and see the new result.

Each test opens a page of a ``pixelpath playground`` served on 127.0.0.1, acts on it as a user
would (pointer drags, keyboard on sliders, clicks), waits for the page to show the new
result, checks that the browser logged no error, and keeps a screenshot of the page in
``$PIXELPATH_TEST_ARTIFACTS`` (a temporary folder when unset).
"""

from __future__ import annotations

import re

import pytest

pytest.importorskip("selenium", reason="the browser tests need selenium (the test extra)")
pytest.importorskip("uvicorn", reason="the playground needs the web extra (uvicorn)")

from playground_browser import (
    Playground,
    artifacts_folder,
    find_chromium,
    start_chromium,
)
from practice_answers import typed, typed_answer
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

from pixelpath import exercises

pytestmark = pytest.mark.slow

# First renders compile kernels when the cache is cold: waits are generous (nothing is timed).
WAIT_SECONDS = 300


@pytest.fixture(scope="module")
def chromium():
    found = find_chromium()
    if found is None:
        pytest.skip("the browser tests need chromium and chromedriver "
                    "(Debian: apt-get install chromium chromium-driver)")
    return found


@pytest.fixture(scope="module")
def playground():
    server = Playground()
    yield server
    server.close()


@pytest.fixture
def browser(chromium, tmp_path):
    driver = start_chromium(*chromium, tmp_path / "profile")
    driver.set_window_size(1400, 1000)
    yield driver
    driver.quit()


def wait_for(driver, condition, message):
    return WebDriverWait(driver, WAIT_SECONDS).until(lambda d: condition(d), message)


def text_of(driver, css: str) -> str:
    found = driver.find_elements(By.CSS_SELECTOR, css)
    return found[0].text if found else ""


def no_errors_logged(driver) -> None:
    errors = [entry for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]
    assert errors == []
    assert text_of(driver, "#error") == ""


def keep_screenshot(driver, name: str) -> None:
    driver.execute_script("window.scrollTo(0, 0)")
    path = artifacts_folder() / f"playground-{name}.png"
    assert driver.save_screenshot(str(path))


def open_page(driver, playground, path: str) -> None:
    driver.get(playground.url + path.lstrip("/"))
    wait_for(driver, lambda d: d.execute_script("return document.readyState") == "complete",
             f"{path} did not load")


def open_clipping(driver, playground) -> None:
    """Open the clipping page and wait for its first Sutherland-Hodgman table."""
    open_page(driver, playground, "/clipping")
    wait_for(driver, lambda d: d.find_elements(By.CSS_SELECTOR, "#sh-table tbody tr"),
             "the Sutherland-Hodgman table did not appear")


def test_home_page_links_every_page(browser, playground):
    open_page(browser, playground, "/")
    links = [a.get_attribute("href") for a in browser.find_elements(By.CSS_SELECTOR, "nav a")]
    assert [link.removeprefix(playground.url) for link in links] == [
        "", "clipping", "illumination", "hidden-surfaces", "ray-tracing", "colour", "practice"]
    no_errors_logged(browser)
    keep_screenshot(browser, "home")


def test_clipping_drag_a_vertex_and_step_through_the_table(browser, playground):
    open_clipping(browser, playground)
    wait_for(browser, lambda d: len(d.find_elements(By.CSS_SELECTOR, ".wa-piece")) == 2,
             "Weiler-Atherton's two pieces of the concave example did not appear")
    assert browser.find_elements(By.CSS_SELECTOR, "line.bridge")
    before = text_of(browser, "#sh-result")

    # Drag the subject's first vertex (1, 1) two units right and one up.
    handle = browser.find_element(By.CSS_SELECTOR, "circle.handle.subject[data-index='0']")
    ActionChains(browser).click_and_hold(handle).move_by_offset(40, -20).move_by_offset(
        40, -20).release().perform()
    wait_for(browser, lambda d: text_of(d, "#sh-result") != before,
             "the clipped polygon did not change after the drag")
    assert "(3, 2)" in text_of(browser, "#sh-table") or "(3, 2)" in text_of(browser, "#sh-result")

    # Step to the third (S, E) pair of the stage: its row is highlighted, its edge drawn.
    slider = browser.find_element(By.ID, "step")
    slider.send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT)
    wait_for(browser, lambda d: text_of(d, "#step-label").startswith("3 of"),
             "the step slider did not move")
    rows = browser.find_elements(By.CSS_SELECTOR, "#sh-table tbody tr")
    assert rows[2].get_attribute("class") == "current"

    # The next boundary's table.
    browser.find_element(By.XPATH, "//div[@id='stages']/button[text()='right']").click()
    wait_for(browser, lambda d: "right boundary" in text_of(d, "#sh-table caption"),
             "the right boundary's table did not appear")
    no_errors_logged(browser)
    keep_screenshot(browser, "clipping")


def test_clipping_window_corner_drag_keeps_a_rectangle(browser, playground):
    open_clipping(browser, playground)
    corner = browser.find_element(By.CSS_SELECTOR, "rect.handle.corner[data-index='2']")
    ActionChains(browser).click_and_hold(corner).move_by_offset(80, 0).release().perform()
    # The window's right side moved from x = 6 to x = 8, so the bridge now lies on x = 8.
    wait_for(browser, lambda d: "(8, 3.5)" in text_of(d, "#sh-result"),
             "the clipped polygon did not follow the window")
    no_errors_logged(browser)


def test_illumination_slider_and_a_click_on_the_ball(browser, playground):
    open_page(browser, playground, "/illumination")
    wait_for(browser, lambda d: d.find_element(By.ID, "img-phong").get_attribute("src"),
             "the shaded balls did not appear")
    before = browser.find_element(By.ID, "img-phong").get_attribute("src")
    slider = browser.find_element(By.ID, "n")
    slider.send_keys(*[Keys.ARROW_RIGHT] * 30)
    wait_for(browser, lambda d: d.find_element(By.ID, "img-phong").get_attribute("src") != before,
             "the Phong ball was not rendered again after moving n")
    assert slider.get_attribute("value") == "50"

    ball = browser.find_element(By.ID, "img-phong")
    ActionChains(browser).move_to_element_with_offset(ball, 0, 0).click().perform()  # the centre
    wait_for(browser, lambda d: "ambient" in text_of(d, "#terms"),
             "the ambient/diffuse/specular breakdown did not appear")
    terms = text_of(browser, "#terms")
    assert "diffuse" in terms and "specular" in terms and "total" in terms
    assert "^50" in terms  # the exponent of the slider
    no_errors_logged(browser)
    keep_screenshot(browser, "illumination")


def test_hidden_surfaces_method_orbit_and_report(browser, playground):
    open_page(browser, playground, "/hidden-surfaces")
    wait_for(browser, lambda d: "what zbuffer did" in text_of(d, "#summary"),
             "the z-buffer's report did not appear")
    assert browser.find_element(By.ID, "figure-box").is_displayed()
    Select(browser.find_element(By.ID, "method")).select_by_value("warnock")
    wait_for(browser, lambda d: "what warnock did" in text_of(d, "#summary"),
             "Warnock's report did not appear")
    assert "subdivision levels" in text_of(browser, "#report")
    before = browser.find_element(By.ID, "image").get_attribute("src")
    browser.find_element(By.ID, "azimuth").send_keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT)
    wait_for(browser, lambda d: d.find_element(By.ID, "image").get_attribute("src") != before,
             "the image did not change when the camera orbited")
    no_errors_logged(browser)
    keep_screenshot(browser, "hidden-surfaces")


def test_ray_tracing_click_a_pixel_for_its_tree(browser, playground):
    open_page(browser, playground, "/ray-tracing")
    wait_for(browser, lambda d: d.find_element(By.ID, "image").get_attribute("src"),
             "the ray-traced image did not appear")
    image = browser.find_element(By.ID, "image")
    # The glass sphere of the showcase, right of the centre and below it.
    ActionChains(browser).move_to_element_with_offset(image, 60, 100).click().perform()
    wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#tree-root li"),
             "the tree of rays did not appear")
    assert text_of(browser, "#caption").startswith("pixel (")
    assert "primary ray" in text_of(browser, "#tree-root")
    assert browser.find_elements(By.CSS_SELECTOR, "#rays line.ray")
    no_errors_logged(browser)
    keep_screenshot(browser, "ray-tracing")


def test_colour_picker_slider_and_typed_values(browser, playground):
    open_page(browser, playground, "/colour")
    wait_for(browser, lambda d: "HSV (60, 1, 1)" in text_of(d, "#model-hsv"),
             "yellow's HSV card did not appear")
    browser.find_element(By.ID, "r").send_keys(*[Keys.ARROW_LEFT] * 50)
    wait_for(browser, lambda d: "RGB (0.5, 1, 0)" in text_of(d, "#summary"),
             "moving R did not convert the new colour")
    Select(browser.find_element(By.ID, "model")).select_by_value("cmyk")
    values = browser.find_element(By.ID, "values")
    values.clear()
    values.send_keys("0, 1, 1, 0.5", Keys.ENTER)
    wait_for(browser, lambda d: "#800000" in text_of(d, "#summary"),
             "typing a CMYK colour did not convert it")
    assert "K = min(C, M, Y)" in text_of(browser, "#model-cmyk")
    no_errors_logged(browser)
    keep_screenshot(browser, "colour")


def new_exercise(driver, topic: str, seed: str = "") -> int:
    """Make an exercise of ``topic`` on the practice page; return its seed (drawn if blank)."""
    Select(driver.find_element(By.ID, "topic")).select_by_value(topic)
    seed_box = driver.find_element(By.ID, "seed")
    seed_box.clear()
    seed_box.send_keys(seed)
    # Blank the title first, so that the exercise shown before the click (the page's first,
    # of a drawn seed such as 3228, which begins with "3") cannot pass for the new one.
    driver.execute_script("document.getElementById('title').textContent = ''")
    driver.find_element(By.ID, "new").click()
    title = exercises.topic_title(topic)
    wanted = f"{title} · seed {seed} · " if seed else f"{title} · seed "
    wait_for(driver, lambda d: text_of(d, "#title").startswith(wanted),
             f"the {topic} exercise did not appear")
    return int(re.search(r"seed (\d+)", text_of(driver, "#title")).group(1))


def answer_with(driver, values: dict[str, str]) -> None:
    """Type ``values`` into the answer boxes (clearing every box first) and press Check."""
    for box in driver.find_elements(By.CSS_SELECTOR, "#answers input"):
        box.clear()
        box.send_keys(values.get(box.get_attribute("name"), ""))
    driver.find_element(By.ID, "check").click()


def test_practice_answer_right_then_wrong_and_read_the_solution(browser, playground):
    open_page(browser, playground, "/practice")
    wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#answers input"),
             "the first exercise did not appear")
    seed = new_exercise(browser, "rgb-hsv")
    exercise = exercises.make("rgb-hsv", seed, "standard")
    labels = text_of(browser, "#answers")
    assert all(f"{field.name}: {field.label}" in labels for field in exercise.fields)

    answer_with(browser, typed_answer(exercise))
    wait_for(browser, lambda d: text_of(d, "#verdict") == "correct",
             "the right answer was not marked correct")
    assert text_of(browser, "#feedback") == "Correct."

    saturation = exercise.answer["s"]
    wrong = {**typed_answer(exercise), "s": typed("number", (saturation + 0.5) % 1)}
    answer_with(browser, wrong)
    wait_for(browser, lambda d: text_of(d, "#verdict") == "not yet",
             "the wrong answer was not marked")
    assert text_of(browser, "#feedback").startswith("s is not right: look at step 6")
    row = browser.find_element(By.ID, "field-s")
    assert row.get_attribute("class") == "wrong first-wrong" and row.text.endswith("✗")
    assert browser.find_element(By.ID, "field-h").text.endswith("✓")

    assert not browser.find_element(By.ID, "solution-box").is_displayed()
    browser.find_element(By.ID, "show-solution").click()
    wait_for(browser, lambda d: d.find_element(By.ID, "solution-box").is_displayed(),
             "the worked solution was not shown")
    assert "Step 1. Cmax" in text_of(browser, "#solution")
    assert "s: the saturation S" in text_of(browser, "#solution table")
    no_errors_logged(browser)
    keep_screenshot(browser, "practice")


def test_practice_figures_of_the_question_and_the_solution(browser, playground):
    open_page(browser, playground, "/practice")
    wait_for(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#answers input"),
             "the first exercise did not appear")
    assert new_exercise(browser, "sutherland-hodgman", "3") == 3
    drawn = "return arguments[0].complete && arguments[0].naturalWidth > 0"
    figure = browser.find_element(By.CSS_SELECTOR, "#question img.figure")
    wait_for(browser, lambda d: d.execute_script(drawn, figure), "the figure was not drawn")
    assert not browser.find_element(By.ID, "figure-box").is_displayed()  # shown once, inline

    answer_with(browser, {})
    wait_for(browser, lambda d: "missing" in text_of(d, "#feedback"),
             "an empty answer was not marked as missing")
    browser.find_element(By.ID, "show-solution").click()
    solved = browser.find_element(By.ID, "solved-figure")
    wait_for(browser, lambda d: d.execute_script(drawn, solved) and solved.is_displayed(),
             "the solved figure was not drawn")
    no_errors_logged(browser)
    keep_screenshot(browser, "practice-figures")
