"""The HTML report shows why at a glance (issue 22, item 4): a failing test's first message in
its row, params, tags, ids, start times, fixture durations, the run's metadata, flaky tests
under Failing, an order by duration, a slowest list that follows the filter, and a timeline
(SVG) with one lane per suite running at once. Checked in headless Chromium (Debian's chromium
and chromedriver) with no console errors, in both isolation modes and under -j 2; the
screenshot of the -j 2 run, in build/test-artifacts/, is docs/html-report.png."""
import json
import re

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

from browser import chromium
from conftest import BUILD_DIR, run_runner

ARTIFACTS = BUILD_DIR / "test-artifacts"


@pytest.fixture
def browser(tmp_path):
    with chromium(tmp_path, window="1200,1000", console_log=True) as driver:
        yield driver


def console_errors(driver):
    return [entry for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]


def write_suites(folder):
    """Two suites: "arm" with a slow test (param, tags), a failing one and a flaky one (fails
    its first run); "base" with a Python fixture that takes 0.4 s to be ready."""
    (folder / "slow.py").write_text("""import time
import robottestingframework
class TestCase:
    def run(self):
        time.sleep(0.5)
        robottestingframework.testReport("moved the arm")
""")
    (folder / "broken.py").write_text("""import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testReport("reading joint 3")
        robottestingframework.assertFail("joint 3 out of range: 97 deg > 90 deg")
""")
    counter = folder / "flaky.count"
    flaky = folder / "flaky.sh"
    flaky.write_text(f"""#!/bin/sh
n=$(cat '{counter}' 2>/dev/null || echo 0)
n=$((n + 1))
echo $n > '{counter}'
if [ $n -le 1 ]; then echo "lost the first packet" >&2; exit 3; fi
exit 0
""")
    flaky.chmod(0o755)
    (folder / "world.py").write_text("""import time
import robottestingframework
class FixtureManager:
    def setup(self, param):
        time.sleep(0.4)
        robottestingframework.testReport("world is ready after 0.4 s")
        return True
    def tearDown(self):
        time.sleep(0.2)
""")
    (folder / "quick.py").write_text("""import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testReport("quick look")
""")
    (folder / "arm.xml").write_text("""<suite name="arm">
  <test param="--speed 30" tags="slow,arm">slow.py</test>
  <test>broken.py</test>
  <test type="exec" name="flaky">flaky.sh</test>
</suite>
""")
    (folder / "base.xml").write_text("""<suite name="base">
  <fixture>world.py</fixture>
  <test>quick.py</test>
</suite>
""")


def report_data(path):
    html = path.read_text()
    found = re.search(r'<script type="application/json" id="report-data">(.*?)</script>',
                      html, re.S)
    return json.loads(found.group(1))


def shown_names(driver):
    return [row.find_element(By.CLASS_NAME, "name").text
            for row in driver.find_elements(By.CSS_SELECTOR, "details.test") if row.is_displayed()]


@pytest.mark.parametrize("mode", [["--isolation", "none"], ["--isolation", "process"],
                                  ["--isolation", "process", "-j", "2"]],
                         ids=["none", "process", "process-j2"])
def test_the_page_shows_why_when_and_how_long(tmp_path, browser, mode):
    write_suites(tmp_path)
    run = run_runner("--suite", "arm.xml", "--suite", "base.xml", "--retries", "1",
                     "--var", "robot=icub", "-o", "html:report.html", *mode, cwd=tmp_path,
                     timeout=120)
    assert run.returncode == 1, run
    data = report_data(tmp_path / "report.html")
    facts = dict(data["facts"])
    assert "--retries 1" in facts["command line"] and facts["variable robot"] == "icub", facts
    assert facts["isolation"] in ("none (in process)", "process") and facts["host"], facts
    base = next(s for s in data["suites"] if s["name"] == "base")
    # Under -j 2 too, where a suite's events wait while the scheduler's own thread runs the
    # other suite: they are timed when they happened, not when they were handed on.
    assert base["setup"] >= 0.35 and base["teardown"] >= 0.15, base

    browser.get((tmp_path / "report.html").as_uri())
    assert console_errors(browser) == []
    # The failing test is open, its first failure in its row; the flaky one is its own state.
    rows = {row.find_element(By.CLASS_NAME, "name").text: row
            for row in browser.find_elements(By.CSS_SELECTOR, "details.test")}
    broken = rows["broken.py"]
    assert "joint 3 out of range" in broken.find_element(By.CLASS_NAME, "reason").text
    assert broken.get_attribute("open") is not None
    detail = broken.find_element(By.CLASS_NAME, "detail").text
    assert "arm/broken.py" in detail and "reading joint 3" in detail, detail
    assert rows["flaky"].find_element(By.CLASS_NAME, "state").text == "flaky"
    # Params, tags and start time in the slow test's details.
    slow = rows["slow.py"]
    assert [t.text for t in slow.find_elements(By.CLASS_NAME, "tag")] == ["slow", "arm"]
    slow.find_element(By.TAG_NAME, "summary").click()
    detail = slow.find_element(By.CLASS_NAME, "detail").text
    assert "--speed 30" in detail and "moved the arm" in detail and "started" in detail, detail
    # Fixture durations in the suite's header.
    headers = [s.find_element(By.TAG_NAME, "summary").text
               for s in browser.find_elements(By.CSS_SELECTOR, "details.suite")]
    assert any("base" in h and "fixture setup" in h and "teardown" in h for h in headers), headers
    # The run's metadata.
    assert "icub" in browser.find_element(By.ID, "facts").get_attribute("textContent")

    # Failing: the failed test and the flaky one; the slowest list follows.
    Select(browser.find_element(By.ID, "filter")).select_by_value("failing")
    assert sorted(shown_names(browser)) == ["broken.py", "flaky"]
    slowest = [li.text for li in browser.find_elements(By.CSS_SELECTOR, "#slowest li")]
    assert len(slowest) == 2 and not any("slow.py" in s for s in slowest), slowest
    # Each named by its id, as --filter takes it (it said "broken.py  (arm)").
    assert all(s.split()[2].count("/") == 1 and "(" not in s for s in slowest), slowest
    Select(browser.find_element(By.ID, "filter")).select_by_value("all")
    Select(browser.find_element(By.ID, "sort")).select_by_value("slowest")
    assert shown_names(browser)[0] == "slow.py"

    # The timeline: a lane per suite, labelled by its name (issue 38, friction 11), each test
    # a bar with its details.
    lanes = browser.find_elements(By.CSS_SELECTOR, "#timeline .lane-label.suite-lane")
    assert sorted(lane.text for lane in lanes) == ["arm", "base"], [lane.text for lane in lanes]
    titles = [t.get_attribute("textContent")
              for t in browser.find_elements(By.CSS_SELECTOR, "#timeline title")]
    assert any(t.startswith("arm / broken.py: failed") for t in titles), titles
    assert any(t.startswith("base: fixture setup") for t in titles), titles
    assert any("world is ready after" in t for t in titles), titles
    assert any(t.startswith("base: fixture teardown") for t in titles), titles
    assert console_errors(browser) == []
    if "-j" in mode:
        Select(browser.find_element(By.ID, "sort")).select_by_value("run")
        browser.find_element(By.ID, "timeline-box").location_once_scrolled_into_view
        ARTIFACTS.mkdir(exist_ok=True)
        browser.execute_script("window.scrollTo(0, 0)")
        browser.save_screenshot(str(ARTIFACTS / "html-report-details.png"))
