"""--output html:FILE: one self-contained page, checked in headless Chromium (Debian's chromium,
chromium-driver and python3-selenium) opened from file://."""
import os
import subprocess
import time
from pathlib import Path

import pytest
from selenium.common.exceptions import NoAlertPresentException
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

from browser import chromium
from conftest import BUILD_DIR, plugin, run_runner

ARTIFACTS = BUILD_DIR / "test-artifacts"
PROBE = "<img src=x onerror=alert(1)>"
SCRIPT_END = "end </script><script>alert(2)</script> end"


@pytest.fixture
def browser(tmp_path):
    with chromium(tmp_path) as driver:
        yield driver


def shown_rows(driver):
    return [row for row in driver.find_elements(By.CSS_SELECTOR, "details.test") if
            row.is_displayed()]


def open_row(driver, row):
    """Opens a test's row (a failing one is open already) and waits for its details, built
    when it opens."""
    if row.get_attribute("open") is None:
        row.find_element(By.TAG_NAME, "summary").click()
    WebDriverWait(driver, 10).until(lambda _: row.find_elements(By.CLASS_NAME, "detail"))
    return row.find_element(By.CLASS_NAME, "detail").text


def no_alert(driver):
    try:
        text = driver.switch_to.alert.text
    except NoAlertPresentException:
        return True
    pytest.fail(f"an alert opened: {text}")


def test_page_from_file_url_filters_searches_and_shows_test_text_as_text(tmp_path, suite_file,
                                                                          browser):
    suite = suite_file(f"""<suite name="alpha">
  <test>{plugin("passing_test")}</test>
  <test>{plugin("failing_test")}</test>
  <test name="{PROBE.replace('<', '&lt;').replace('>', '&gt;')}">{plugin("passing_test")}</test>
  <test name="{SCRIPT_END.replace('<', '&lt;').replace('>', '&gt;')}">{plugin("passing_test")}</test>
  <test>{plugin("nasty_text_test")}</test>
</suite>""")
    out = tmp_path / "r.html"
    run = run_runner("-s", suite.name, "-t", plugin("printing_test"), "-o", f"html:{out.name}",
                     cwd=tmp_path)
    assert run.returncode == 1, run
    html = out.read_text()
    # No address to fetch: the SVG namespace (the timeline's) is a name, never loaded.
    assert "http://" not in html.replace("http-equiv", "").replace(
        '"http://www.w3.org/2000/svg"', "") and "https://" not in html
    assert html.count("</script>") == 2, "test text closed a script element"

    browser.get(out.as_uri())
    no_alert(browser)
    assert browser.find_elements(By.TAG_NAME, "img") == []
    assert "6 tests" in browser.find_element(By.ID, "counts").text
    assert "2 failed" in browser.find_element(By.ID, "counts").text
    assert len(browser.find_elements(By.CSS_SELECTOR, "#bar div")) == 2
    # The suite with failures is open, the one without is not.
    suites = {s.find_element(By.TAG_NAME, "summary").text.split()[0]: s.get_attribute("open")
              for s in browser.find_elements(By.CSS_SELECTOR, "details.suite")}
    assert suites["alpha"] is not None and suites["tests"] is None, suites

    names = [row.find_element(By.CLASS_NAME, "name").text for row in shown_rows(browser)]
    assert PROBE in names and SCRIPT_END in names, names

    Select(browser.find_element(By.ID, "filter")).select_by_value("failing")
    rows = shown_rows(browser)
    assert sorted(r.find_element(By.CLASS_NAME, "name").text for r in rows) == \
        ["failing_test.so (FailingTest)", "nasty_text_test.so (NastyTextTest <&>)"]
    assert "2 of 6 tests shown" in browser.find_element(By.ID, "shown").text

    # A failing test opened: its message with file:line, what it printed.
    detail = open_row(browser, rows[0])
    assert "two and two make five" in detail and "failing_test.cpp:" in detail, detail

    Select(browser.find_element(By.ID, "filter")).select_by_value("all")
    search = browser.find_element(By.ID, "search")
    search.send_keys("onerror")
    rows = shown_rows(browser)
    assert [r.find_element(By.CLASS_NAME, "name").text for r in rows] == [PROBE]
    search.clear()
    search.send_keys("printing")
    rows = shown_rows(browser)
    assert [r.find_element(By.CLASS_NAME, "name").text for r in rows] == [
        "printing_test.so (PrintingTest)"]
    assert "printf line from the test" in open_row(browser, rows[0])

    # The slowest list follows the search (and the filter): the one test found.
    slowest = browser.find_elements(By.CSS_SELECTOR, "#slowest li")
    assert len(slowest) == 1 and "printing_test.so" in slowest[0].text, slowest

    theme = browser.find_element(By.ID, "theme")
    before = browser.execute_script("return document.documentElement.dataset.theme")
    theme.click()
    after = browser.execute_script("return document.documentElement.dataset.theme")
    assert {before, after} == {"light", "dark"}

    search.send_keys(Keys.CONTROL, "a")
    search.send_keys(Keys.BACKSPACE)  # clear() sends no input event
    assert "6 of 6 tests shown" in browser.find_element(By.ID, "shown").text
    theme.click()
    no_alert(browser)
    assert browser.find_elements(By.TAG_NAME, "img") == []
    ARTIFACTS.mkdir(exist_ok=True)
    browser.save_screenshot(str(ARTIFACTS / "html-report.png"))


def test_the_example_run_as_a_page(tmp_path, browser):
    """The C++ and script example suites of `./run.sh example` (the robot's world is left to
    test_examples.py); its screenshot is build/test-artifacts/example-report.png (docs/
    html-report.png is test_report_html_details.py's, of a -j 2 run)."""
    examples = BUILD_DIR / "examples"
    run = run_runner("--suite", examples / "example.xml", "--suite", examples / "scripts.xml",
                     "--output", "html:example.html", cwd=tmp_path, timeout=60)
    assert run.returncode == 0, run
    browser.get((tmp_path / "example.html").as_uri())
    no_alert(browser)
    assert "6 passed" in browser.find_element(By.ID, "counts").text
    suites = browser.find_elements(By.CSS_SELECTOR, "details.suite")
    assert len(suites) == 2
    suites[1].find_element(By.TAG_NAME, "summary").click()  # its rows are built as it opens
    WebDriverWait(browser, 10).until(lambda _: len(shown_rows(browser)) == 4)
    ARTIFACTS.mkdir(exist_ok=True)
    browser.save_screenshot(str(ARTIFACTS / "example-report.png"))


def test_ten_thousand_tests_build_the_page_lazily(tmp_path, browser):
    program = Path(os.environ.get("RTF_BIN_DIR", BUILD_DIR / "bin")) / "rtf-many-tests-report"
    page = tmp_path / "many.html"
    subprocess.run([str(program), "10000", str(page)], check=True, timeout=120)
    started = time.monotonic()
    browser.get(page.as_uri())
    loaded = time.monotonic() - started
    assert "10000 tests" in browser.find_element(By.ID, "counts").text
    assert "100 failed" in browser.find_element(By.ID, "counts").text
    # The suite has failures, so it is open: its first page of rows only, and a button for more.
    rows = browser.find_elements(By.CSS_SELECTOR, "details.test")
    assert len(rows) == 200, len(rows)
    assert browser.execute_script("return document.getElementsByTagName('*').length") < 2000
    more = browser.find_element(By.CSS_SELECTOR, ".tests > button")
    assert "Show 200 more of 9800" in more.text
    more.click()
    assert len(browser.find_elements(By.CSS_SELECTOR, "details.test")) == 400
    # Filtering and searching work on all 10 000, not just the rows built.
    Select(browser.find_element(By.ID, "filter")).select_by_value("failing")
    assert "100 of 10000 tests shown" in browser.find_element(By.ID, "shown").text
    search = browser.find_element(By.ID, "search")
    search.send_keys("test 9900")
    rows = shown_rows(browser)
    assert [r.find_element(By.CLASS_NAME, "name").text for r in rows] == ["test 9900"]
    # A log longer than the page keeps is cut, with a note.
    Select(browser.find_element(By.ID, "filter")).select_by_value("all")
    search.clear()
    search.send_keys("test 1")
    detail = open_row(browser, shown_rows(browser)[0])
    assert "output cut: " in detail, detail
    assert loaded < 30, f"the page took {loaded:.1f} s to load"
