"""The live web page in a real browser (Debian's headless Chromium through Selenium): a test
moves from running to passed without a reload, the final summary shows, and test names and
messages that look like HTML stay text."""
import os
import signal
from xml.sax.saxutils import escape

import pytest
from selenium.common.exceptions import NoAlertPresentException
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

from browser import chromium
from conftest import BUILD_DIR
from web_run import WebRun, quick_test, waiting_test

ARTIFACTS = BUILD_DIR / "tests" / "e2e" / "artifacts"
PROBE_NAME = "<img src=x onerror=alert(1)>"
PROBE_SUITE = "arm </script><img src=x onerror=alert(3)>"


@pytest.fixture
def browser(tmp_path):
    with chromium(tmp_path, window="1100,760", page_load_timeout=30) as driver:
        yield driver


def row_state(driver, name_part):
    return driver.execute_script(
        "for (const row of document.querySelectorAll('tr.test')) {"
        "  if (row.querySelector('.test-name').textContent.includes(arguments[0]))"
        "    return row.dataset.state; }"
        "return null;", name_part)


def test_page_follows_the_run_and_shows_hostile_names_as_text(tmp_path, suite_file, browser):
    go = tmp_path / "go"
    waiting = waiting_test(tmp_path, "move arm", go, body="echo 'arm moved'\n")
    probe = quick_test(tmp_path, PROBE_NAME,
                       "echo '</script><script>alert(2)</script><b>bold</b>' >&2\nexit 1\n")
    skipped = quick_test(tmp_path, "needs robot", "echo 'no robot attached' >&2\nexit 77\n")
    suite = suite_file(f"""<suite name="{escape(PROBE_SUITE)}">
  <test type="exec">{escape(str(waiting))}</test>
  <test type="exec">{escape(str(probe))}</test>
  <test type="exec">{escape(str(skipped))}</test>
</suite>""")
    run = WebRun("-s", suite.name, "--web-linger", "120", cwd=tmp_path)
    try:
        browser.get(run.url)
        wait = WebDriverWait(browser, 30, poll_frequency=0.05)
        wait.until(lambda d: row_state(d, "move arm") == "running")
        assert row_state(browser, PROBE_NAME) == "not run"
        browser.execute_script("window.rtfSamePage = true;")  # gone if the page reloads

        go.touch()
        wait.until(lambda d: row_state(d, "move arm") == "passed")
        wait.until(lambda d: d.find_element(By.ID, "summary").text.startswith("Finished"))
        assert browser.execute_script("return window.rtfSamePage === true;"), "page reloaded"
        summary = browser.find_element(By.ID, "summary").text
        assert "1 passed, 1 failed, 1 skipped of 3" in summary, summary
        assert row_state(browser, PROBE_NAME) == "failed"
        assert row_state(browser, "needs robot") == "skipped"

        # The probes are text on the page, not elements.
        body = browser.find_element(By.TAG_NAME, "body").text
        assert PROBE_NAME in body and PROBE_SUITE in body, body
        assert "</script><script>alert(2)</script><b>bold</b>" in body, body
        assert browser.execute_script("return document.images.length;") == 0
        assert browser.execute_script("return document.scripts.length;") == 1
        assert browser.execute_script("return document.querySelectorAll('b').length;") == 0
        with pytest.raises(NoAlertPresentException):
            browser.switch_to.alert.text

        ARTIFACTS.mkdir(parents=True, exist_ok=True)
        assert browser.save_screenshot(str(ARTIFACTS / "web_page.png"))
        assert (ARTIFACTS / "web_page.png").stat().st_size > 1000
        run.wait_for_line("final page stays")
    finally:
        go.touch()
        if run.proc.poll() is None:
            run.proc.send_signal(signal.SIGINT)
        status = run.wait(timeout=20)
    assert status == 1, run.output()  # the probe test failed


def test_page_opened_after_the_run_shows_the_final_result(tmp_path, browser):
    test = quick_test(tmp_path, "quick one")
    run = WebRun("-t", test.name, "--web-linger", "120", cwd=tmp_path)
    try:
        run.wait_for_line("final page stays")
        browser.get(run.url)
        wait = WebDriverWait(browser, 30, poll_frequency=0.05)
        wait.until(lambda d: d.find_element(By.ID, "summary").text.startswith("Finished"))
        assert row_state(browser, "quick one") == "passed"
        assert "the run has ended" in browser.find_element(By.ID, "connection").text
    finally:
        if run.proc.poll() is None:
            run.proc.send_signal(signal.SIGINT)
        status = run.wait(timeout=20)
    assert status == 0, run.output()


def elapsed_text(driver, selector):
    return driver.execute_script(
        "const node = document.querySelector(arguments[0]);"
        "return node ? node.textContent : null;", selector)


def seconds_in(text):
    return float(text.rsplit(" ", 2)[-2])


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_running_fixtures_and_tests_tick_their_elapsed_time(tmp_path, suite_file, browser,
                                                            isolation):
    """Issue 22, item 6: a fixture setting up and a test running show how long they have been
    at it, counting up on the page between the run's events."""
    fixture_go, test_go = tmp_path / "fixture-go", tmp_path / "test-go"
    (tmp_path / "world.py").write_text(f"""import os, time
class FixtureManager:
    def setup(self, param):
        for _ in range(1200):
            if os.path.exists({str(fixture_go)!r}):
                break
            time.sleep(0.05)
        return True
""")
    waiting = waiting_test(tmp_path, "move arm", test_go)
    suite = suite_file(f"""<suite name="arm">
  <fixture>{escape(str(tmp_path / "world.py"))}</fixture>
  <test type="exec">{escape(str(waiting))}</test>
</suite>""")
    run = WebRun("-s", suite.name, "--isolation", isolation, "--web-linger", "120", cwd=tmp_path)
    try:
        browser.get(run.url)
        wait = WebDriverWait(browser, 30, poll_frequency=0.05)
        title = "section.suite h2 .elapsed"
        wait.until(lambda d: (elapsed_text(d, title) or "").startswith("fixture setting up"))
        first = seconds_in(elapsed_text(browser, title))
        wait.until(lambda d: seconds_in(elapsed_text(d, title) or "x 0 s") >= first + 0.5)

        fixture_go.touch()
        cell = "tr.test td.elapsed"
        wait.until(lambda d: (elapsed_text(d, cell) or "").startswith("running"))
        first = seconds_in(elapsed_text(browser, cell))
        wait.until(lambda d: seconds_in(elapsed_text(d, cell) or "x 0 s") >= first + 0.5)
        assert not elapsed_text(browser, title).startswith("fixture"), elapsed_text(browser, title)

        test_go.touch()
        wait.until(lambda d: row_state(d, "move arm") == "passed")
        wait.until(lambda d: d.find_element(By.ID, "summary").text.startswith("Finished"))
        assert browser.find_elements(By.CSS_SELECTOR, ".elapsed") == []
        run.wait_for_line("final page stays")
    finally:
        fixture_go.touch()
        test_go.touch()
        if run.proc.poll() is None:
            run.proc.send_signal(signal.SIGINT)
        status = run.wait(timeout=20)
    assert status == 0, run.output()
