"""Measurement plots (issue 22, items 2 and 5) through the real runner: the HTML report draws
each measurement of a test across its repetitions and retries, and across its last runs from
--history, with its limits as lines and the values outside them marked; the live page draws a
test's trend from the history beside the values of the run. Both checked in headless Chromium
(Debian's chromium through Selenium): the plots are there, their values (the SVG's data
attributes and the points' heights) are the measured ones, and the console has no error."""
import json
import sqlite3

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

from browser import chromium
from conftest import run_runner
from web_run import WebRun, request

# Measures "tracking error" (limits [0, 0.05] rad) once per run of the test: the value is the
# next of VALUES (a counter file tells which); and "loop rate" twice, without limits.
ARM = """import os
class TestCase:
    def run(self):
        n = int(open("count").read()) if os.path.exists("count") else 0
        open("count", "w").write(str(n + 1))
        values = [float(v) for v in os.environ["VALUES"].split(",")]
        robottestingframework.testMeasure("tracking error", values[n % len(values)], "rad", 0, 0.05)
        robottestingframework.testMeasure("loop rate", 100.0 + n, "Hz")
        robottestingframework.testMeasure("loop rate", 90.0 + n, "Hz")
"""
# No measurement: no plot data (10 000 such tests cost the page nothing).
PLAIN = "class TestCase:\n    def run(self):\n        pass\n"


def write_suite(folder, repetition=3):
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "arm.py").write_text(ARM)
    (folder / "plain.py").write_text(PLAIN)
    (folder / "m.xml").write_text(
        f'<suite name="m">\n  <test name="arm" repetition="{repetition}">arm.py</test>\n'
        '  <test name="plain">plain.py</test>\n</suite>\n')
    return folder


def run_once(folder, values, *more, isolation="none"):
    (folder / "count").unlink(missing_ok=True)
    return run_runner("--isolation", isolation, "--suite", "m.xml", *more, cwd=folder,
                      env={"VALUES": values})


def report_data(html):
    text = html.read_text()
    return json.loads(text.split('id="report-data">', 1)[1].split("</script>", 1)[0])


def by_name(data):
    return {t["name"]: t for s in data["suites"] for t in s["tests"]}


@pytest.fixture
def browser(tmp_path):
    with chromium(tmp_path, console_log=True) as driver:
        yield driver


def console_errors(driver):
    """The console's errors, but the browser's own request for a favicon (the live page has
    none)."""
    return [entry for entry in driver.get_log("browser")
            if entry["level"] == "SEVERE" and "/favicon.ico " not in entry["message"]]


def plot_values(plot):
    """The values a plot says it draws, and the checks that it draws them: one point per
    value, higher values higher up, the limits' lines where their values are."""
    values = json.loads(plot.get_attribute("data-values"))
    points = plot.find_elements(By.CSS_SELECTOR, "circle.point")
    assert [float(p.get_attribute("data-value")) for p in points] == values
    heights = [float(p.get_attribute("cy")) for p in points]
    for (a, ya) in zip(values, heights):
        for (b, yb) in zip(values, heights):
            if a > b:
                assert ya < yb, (values, heights)  # SVG's y grows downwards
    limits = {line.get_attribute("data-value"): float(line.get_attribute("y1"))
              for line in plot.find_elements(By.CSS_SELECTOR, "line.limit")}
    for value, height in zip(values, heights):
        for limit, y in limits.items():
            assert (value > float(limit)) == (height < y), (value, limit, height, y)
    return values, points


def outside_places(points):
    return [i for i, p in enumerate(points) if "outside" in p.get_attribute("class")]


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_the_report_carries_each_measurements_history(tmp_path, isolation):
    folder = write_suite(tmp_path / "suite")
    for values in ["0.01,0.02,0.03", "0.02,0.02,0.02"]:
        r = run_once(folder, values, "--history", "h.db", "--no-output", isolation=isolation)
        assert r.returncode == 0, r
    r = run_once(folder, "0.01,0.08,0.02", "--history", "h.db", "-o", "html:r.html",
                 isolation=isolation)
    assert r.returncode == 1, r  # 0.08 is outside [0, 0.05]
    tests = by_name(report_data(folder / "r.html"))
    arm = tests["arm"]
    assert [m["value"] for m in arm["measurements"] if m["name"] == "tracking error"] == [
        0.01, 0.08, 0.02]
    trends = {m["name"]: m for m in arm["history"]["measurements"]}
    error = trends["tracking error"]
    assert error["values"] == [0.01, 0.02, 0.03, 0.02, 0.02, 0.02, 0.01, 0.08, 0.02]
    assert error["ago"] == [2, 2, 2, 1, 1, 1, 0, 0, 0]
    assert error["outside"] == [7]
    assert (error["unit"], error["low"], error["high"]) == ("rad", 0, 0.05)
    rate = trends["loop rate"]
    assert rate["values"] == [100, 90, 101, 91, 102, 92] * 3 and rate["outside"] == []
    assert "low" not in rate and "high" not in rate
    # The plain test measured nothing: no trend data for it.
    assert "measurements" not in tests["plain"]["history"]
    assert "measurements" not in tests["plain"]


def test_the_report_plots_repetitions_retries_and_history_in_a_browser(tmp_path, browser):
    folder = write_suite(tmp_path / "suite")
    for values in ["0.01,0.02,0.03", "0.02,0.02,0.02"]:
        assert run_once(folder, values, "--history", "h.db", "--no-output").returncode == 0
    r = run_once(folder, "0.01,0.08,0.02", "--history", "h.db", "-o", "html:r.html")
    assert r.returncode == 1, r
    with sqlite3.connect(folder / "h.db") as db:
        assert db.execute("SELECT count(*) FROM measurements").fetchone() == (27,)

    browser.get((folder / "r.html").as_uri())
    assert console_errors(browser) == []
    # The failing test is open by itself: its table, a row per measurement name.
    WebDriverWait(browser, 10).until(
        lambda _: browser.find_elements(By.CSS_SELECTOR, "tr.measure"))
    rows = {row.get_attribute("data-name"): row
            for row in browser.find_elements(By.CSS_SELECTOR, "tr.measure")}
    assert sorted(rows) == ["loop rate", "tracking error"]
    error = rows["tracking error"]
    assert "failing" in error.get_attribute("class")
    this_run = error.find_element(By.CSS_SELECTOR, "svg.measure-plot.repetitions")
    values, points = plot_values(this_run)
    assert values == [0.01, 0.08, 0.02]
    assert outside_places(points) == [1]
    assert sorted(line.get_attribute("data-value") for line in
                  this_run.find_elements(By.CSS_SELECTOR, "line.limit")) == ["0", "0.05"]
    history = error.find_element(By.CSS_SELECTOR, "svg.measure-plot.history")
    values, points = plot_values(history)
    assert values == [0.01, 0.02, 0.03, 0.02, 0.02, 0.02, 0.01, 0.08, 0.02]
    assert outside_places(points) == [7]
    # This run's points stand out; each says when it was measured.
    assert [i for i, p in enumerate(points) if "current" in p.get_attribute("class")] == [6, 7, 8]
    titles = [p.find_element(By.TAG_NAME, "title").get_attribute("textContent") for p in points]
    assert titles[0] == "tracking error = 0.01 rad (2 runs ago)", titles
    assert titles[7] == "tracking error = 0.08 rad (this run), outside its limits", titles
    rate = rows["loop rate"]
    assert plot_values(rate.find_element(By.CSS_SELECTOR, "svg.measure-plot.repetitions"))[0] == [
        100, 90, 101, 91, 102, 92]
    assert rate.find_elements(By.CSS_SELECTOR, "line.limit") == []
    # The test without measurements has no table; nothing went wrong on the way.
    plain = [row for row in browser.find_elements(By.CSS_SELECTOR, "details.test")
             if row.find_element(By.CSS_SELECTOR, ".name").text == "plain"][0]
    plain.find_element(By.TAG_NAME, "summary").click()
    assert plain.find_elements(By.CSS_SELECTOR, ".section-identity")
    assert plain.find_elements(By.CSS_SELECTOR, ".measures") == []
    assert console_errors(browser) == []


def test_a_retried_test_plots_each_attempts_values(tmp_path, browser):
    folder = write_suite(tmp_path / "suite", repetition=1)
    # The first attempt measures 0.09 (outside: it fails), the retry 0.01: flaky.
    r = run_once(folder, "0.09,0.01", "--retries", "1", "-o", "html:r.html")
    assert r.returncode == 0, r
    arm = by_name(report_data(folder / "r.html"))["arm"]
    assert arm["state"] == "flaky", arm
    assert [m["value"] for m in arm["attempts"][0]["measurements"]
            if m["name"] == "tracking error"] == [0.09]
    browser.get((folder / "r.html").as_uri())
    row = [row for row in browser.find_elements(By.CSS_SELECTOR, "details.test")
           if row.find_element(By.CSS_SELECTOR, ".name").text == "arm"][0]
    row.find_element(By.TAG_NAME, "summary").click()
    plot = row.find_element(By.CSS_SELECTOR,
                            'tr.measure[data-name="tracking error"] svg.measure-plot.repetitions')
    values, points = plot_values(plot)
    assert values == [0.09, 0.01] and outside_places(points) == [0]
    titles = [p.find_element(By.TAG_NAME, "title").get_attribute("textContent") for p in points]
    assert titles == ["tracking error = 0.09 rad (attempt 1), outside its limits",
                      "tracking error = 0.01 rad (attempt 2)"], titles
    assert console_errors(browser) == []


def test_the_live_page_plots_the_history_beside_this_runs_values(tmp_path, browser):
    folder = write_suite(tmp_path / "suite", repetition=1)
    for values in ["0.01", "0.03"]:
        assert run_once(folder, values, "--history", "h.db", "--no-output").returncode == 0
    (folder / "count").unlink()
    run = WebRun("--suite", "m.xml", "--history", "h.db", "--web-linger", "60", cwd=folder,
                 env={"VALUES": "0.07"})
    try:
        run.wait_for_line("final page stays")
        snapshot = json.loads(request(run.port, "/snapshot")[2])
        arm = {t["name"]: t for t in snapshot["suites"][0]["tests"]}["arm"]
        assert [(m["name"], m["value"], m["passed"]) for m in arm["measurements"]] == [
            ("tracking error", 0.07, False), ("loop rate", 100, True), ("loop rate", 90, True)]
        trend = {m["name"]: m for m in arm["history"]["measurements"]}["tracking error"]
        assert trend["values"] == [0.01, 0.03] and trend["ago"] == [2, 1]
        browser.get(run.url)
        WebDriverWait(browser, 10).until(
            lambda _: len(browser.find_elements(By.CSS_SELECTOR, "tr.measure")) == 2)
        row = browser.find_element(By.CSS_SELECTOR, 'tr.measure[data-name="tracking error"]')
        assert row.find_element(By.CSS_SELECTOR, ".measure-value").text == "0.07 rad"
        values, points = plot_values(row.find_element(By.CSS_SELECTOR, "svg.measure-plot"))
        assert values == [0.01, 0.03, 0.07]
        assert outside_places(points) == [2]
        assert [i for i, p in enumerate(points) if "current" in p.get_attribute("class")] == [2]
        rate = browser.find_element(By.CSS_SELECTOR, 'tr.measure[data-name="loop rate"]')
        assert plot_values(rate.find_element(By.CSS_SELECTOR, "svg.measure-plot"))[0] == [
            100, 90, 100, 90, 100, 90]
        # The strip of earlier runs is drawn by the same code as the report's.
        assert len(browser.find_elements(By.CSS_SELECTOR, ".history .cell")) == 4
        assert console_errors(browser) == []
        run.proc.send_signal(2)
        assert run.wait(timeout=10) == 1
    finally:
        run.kill()
