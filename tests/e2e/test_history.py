"""--history FILE through the real runner: runs appended (both isolation modes, -j 2, retries),
the shards of one run appending at once, --history-report, --history-import of JUnit and CTRF
(this runner's and other tools'), --durations from the history, the HTML report's strips, a
damaged or foreign file, and a history that cannot be written (the reports still are)."""
import json
import sqlite3
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

from browser import chromium
from conftest import RUNNER, empty_environment, run_runner
from web_run import WebRun, request

SUITE = """<suite name="hist">
  <test type="exec" name="ok">ok.sh</test>
  <test type="exec" name="flip">flip.sh</test>
  <test type="exec" name="slow">slow.sh</test>
  <test type="exec" name="second-try">second_try.sh</test>
</suite>
"""


def write_script(path, body):
    path.write_text(body)
    path.chmod(0o755)


def make_suite(folder):
    """A suite in `folder`: ok passes; flip fails when FLIP is set; slow sleeps DELAY seconds;
    second-try fails the first time it runs in a run (a marker file tells), then passes."""
    folder.mkdir(parents=True, exist_ok=True)
    write_script(folder / "ok.sh", "#!/bin/sh\nexit 0\n")
    write_script(folder / "flip.sh", '#!/bin/sh\n[ -z "$FLIP" ]\n')
    write_script(folder / "slow.sh", '#!/bin/sh\nsleep "${DELAY:-0}"\n')
    write_script(folder / "second_try.sh",
                 "#!/bin/sh\nif [ -e tried ]; then rm -f tried; exit 0; fi\n"
                 "[ -n \"$ONCE\" ] || exit 0\ntouch tried\nexit 1\n")
    (folder / "hist.xml").write_text(SUITE)
    return folder


def history_rows(path, test):
    """(state, attempts) of `test` in each run of the history file, oldest first."""
    with sqlite3.connect(path) as db:
        return db.execute(
            "SELECT r.state, r.attempts FROM results r JOIN tests t ON t.id = r.test "
            "JOIN runs u ON u.id = r.run WHERE t.name = ? ORDER BY u.started, u.id",
            (test,)).fetchall()


def report_data(html):
    text = html.read_text()
    return json.loads(text.split('id="report-data">', 1)[1].split("</script>", 1)[0])


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_every_run_is_appended_and_the_report_finds_the_flaky_test(tmp_path, isolation):
    folder = make_suite(tmp_path / "suite")
    for flip in ["", "1", ""]:
        r = run_runner("--isolation", isolation, "--suite", "hist.xml", "--history", "h.db",
                       "--no-output", cwd=folder, env={"FLIP": flip})
        assert r.returncode == (1 if flip else 0), r
    assert history_rows(folder / "h.db", "hist/flip") == [("passed", 1), ("failed", 1),
                                                         ("passed", 1)]
    assert history_rows(folder / "h.db", "hist/ok") == [("passed", 1)] * 3
    with sqlite3.connect(folder / "h.db") as db:
        command, source = db.execute("SELECT command, source FROM runs").fetchone()
        assert "--history h.db" in command and source == "run"
        # The suite's time, for --durations.
        assert db.execute("SELECT count(*) FROM suites WHERE name = 'hist'").fetchone() == (3,)

    r = run_runner("--history", "h.db", "--history-report", cwd=folder)
    assert r.returncode == 0, r
    assert "in the last 3 runs" in r.stdout, r
    flakiest = r.stdout.split("Flakiest tests", 1)[1].split("Tests that failed every run", 1)[0]
    # Passed, failed, passed: two changes of outcome in three runs.
    assert "66.7 %  hist/flip" in flakiest, r
    assert "hist/ok" not in flakiest, r

    r = run_runner("--history", "h.db", "--history-report", "1", cwd=folder)
    assert r.returncode == 0, r
    assert "in the last 1 runs" in r.stdout and "hist/flip" not in r.stdout, r


@pytest.mark.skipif(not sys.platform.startswith("linux"),
                    reason="SQLite is loaded on first use on Linux; linked elsewhere")
def test_sqlite_is_loaded_only_by_a_run_with_a_history(tmp_path):
    """Start-up (issue 37): the runner does not link SQLite, so a run without --history does
    not load it (about a tenth of a one-test run's time); a run with --history loads it when
    the history is opened, and records the run."""
    ldd = subprocess.run(["ldd", RUNNER], capture_output=True, text=True, timeout=30)
    assert ldd.returncode == 0 and "libsqlite3" not in ldd.stdout, ldd.stdout
    folder = make_suite(tmp_path / "suite")
    # The dynamic loader names each library it loads (LD_DEBUG=files, on stderr).
    r = run_runner("--isolation", "none", "--suite", "hist.xml", "--no-output", cwd=folder,
                   env={"LD_DEBUG": "files"})
    assert r.returncode == 0, r
    assert "libsqlite3" not in r.stderr, r.stderr[-2000:]
    r = run_runner("--isolation", "none", "--suite", "hist.xml", "--no-output", "--history",
                   "h.db", cwd=folder, env={"LD_DEBUG": "files"})
    assert r.returncode == 0, r
    assert "file=libsqlite3.so.0" in r.stderr, r.stderr[-2000:]
    assert history_rows(folder / "h.db", "hist/ok") == [("passed", 1)]


def test_a_retried_test_is_recorded_flaky_with_its_attempts(tmp_path):
    folder = make_suite(tmp_path / "suite")
    r = run_runner("--suite", "hist.xml", "--retries", "2", "--history", "h.db", "--no-output",
                   cwd=folder, env={"ONCE": "1"})
    assert r.returncode == 0, r
    assert history_rows(folder / "h.db", "hist/second-try") == [("flaky", 2)]


def test_a_slowed_down_test_is_reported(tmp_path):
    folder = make_suite(tmp_path / "suite")
    for delay in ["0", "0", "0", "0", "0.4", "0.4"]:
        r = run_runner("--suite", "hist.xml", "--history", "h.db", "--no-output", cwd=folder,
                       env={"DELAY": delay})
        assert r.returncode == 0, r
    r = run_runner("--history", "h.db", "--history-report", cwd=folder)
    slowed = r.stdout.split("Most slowed", 1)[1].splitlines()
    # 0.4 s more: the first of the list whatever the machine's load does to the others.
    assert "hist/slow  (noise floor " in slowed[1], r


def test_jobs_2_records_every_suite(tmp_path):
    folder = make_suite(tmp_path / "suite")
    (folder / "other.xml").write_text(SUITE.replace('name="hist"', 'name="other"'))
    r = run_runner("-j", "2", "--suite", "hist.xml", "--suite", "other.xml", "--history",
                   "h.db", "--no-output", cwd=folder)
    assert r.returncode == 0, r
    with sqlite3.connect(folder / "h.db") as db:
        names = sorted(name for (name,) in db.execute("SELECT name FROM tests"))
    assert names == sorted(f"{suite}/{test}" for suite in ("hist", "other")
                           for test in ("ok", "flip", "slow", "second-try"))


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_the_shards_of_one_run_append_at_once(tmp_path, isolation):
    folder = tmp_path / "suites"
    folder.mkdir()
    write_script(folder / "ok.sh", "#!/bin/sh\nsleep 0.2\n")
    for i in range(8):
        tests = "\n".join(f'  <test type="exec" name="t{j}">ok.sh</test>' for j in range(3))
        (folder / f"s{i}.xml").write_text(f'<suite name="s{i}">\n{tests}\n</suite>\n')
    shards = [subprocess.Popen(
        [RUNNER, "--isolation", isolation, "-j", "2", "--suites", ".", "--shard-index", str(i),
         "--shard-count", "4", "--history", "h.db", "--no-output"],
        cwd=folder, env=empty_environment(RTF_RUN_ID="pipeline-42"),
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) for i in range(4)]
    for shard in shards:
        out, err = shard.communicate(timeout=120)
        assert shard.returncode == 0, out + err
        assert "history" not in err, err
    with sqlite3.connect(folder / "h.db") as db:
        runs = db.execute("SELECT run_key, shard_index, shard_count FROM runs "
                          "ORDER BY shard_index").fetchall()
        assert runs == [("pipeline-42", i, 4) for i in range(4)]
        assert db.execute("SELECT count(*) FROM results").fetchone() == (24,)
    r = run_runner("--history", "h.db", "--history-report", cwd=folder)
    assert "24 tests in the last 1 runs" in r.stdout, r


def test_import_of_junit_and_ctrf_reports_of_this_runner_and_others(tmp_path):
    folder = make_suite(tmp_path / "suite")
    r = run_runner("--suite", "hist.xml", "-o", "junit:ours.xml", "-o", "json:ours.json",
                   cwd=folder, env={"FLIP": "1"})
    assert r.returncode == 1, r
    (folder / "pytest.xml").write_text(
        '<?xml version="1.0" encoding="utf-8"?><testsuites><testsuite name="pytest" '
        'timestamp="2024-01-02T03:04:05">'
        '<testcase classname="test_x" name="test_a" time="0.5"/>'
        '<testcase classname="test_x" name="test_b" time="1.5"><failure message="no"/></testcase>'
        '<testcase classname="test_x" name="test_c" time="0"><skipped/></testcase>'
        '</testsuite></testsuites>')
    (folder / "jest.json").write_text(json.dumps({"results": {
        "tool": {"name": "jest"}, "summary": {"start": 1700000000000},
        "tests": [{"name": "adds", "status": "passed", "duration": 250, "suite": ["math"]},
                  {"name": "retries", "status": "passed", "duration": 10, "flaky": True,
                   "retries": 2}]}}))
    r = run_runner("--history", "h.db", "--history-import", "ours.xml", "ours.json",
                   "pytest.xml", "jest.json", cwd=folder)
    assert r.returncode == 0, r
    assert "pytest.xml: 3 tests loaded into h.db" in r.stdout, r
    assert history_rows(folder / "h.db", "hist/flip") == [("failed", 1), ("failed", 1)]
    assert history_rows(folder / "h.db", "pytest/test_b") == [("failed", 1)]
    assert history_rows(folder / "h.db", "pytest/test_c") == [("skipped", 1)]
    assert history_rows(folder / "h.db", "math/adds") == [("passed", 1)]
    assert history_rows(folder / "h.db", "retries") == [("flaky", 3)]
    with sqlite3.connect(folder / "h.db") as db:
        (seconds,) = db.execute(
            "SELECT r.duration FROM results r JOIN tests t ON t.id = r.test "
            "WHERE t.name = 'pytest/test_b'").fetchone()
        assert seconds == 1.5
        sources = [s for (s,) in db.execute("SELECT source FROM runs ORDER BY id")]
        assert sources == ["ours.xml", "ours.json", "pytest.xml", "jest.json"]

    (folder / "notes.txt").write_text("not a report\n")
    r = run_runner("--history", "h.db", "--history-import", "notes.txt", cwd=folder)
    assert r.returncode == 2 and "notes.txt" in r.stderr, r


def test_durations_balance_the_shards_by_the_history(tmp_path):
    folder = tmp_path / "suites"
    folder.mkdir()
    write_script(folder / "ok.sh", "#!/bin/sh\nexit 0\n")
    for name in "abc":
        (folder / f"{name}.xml").write_text(
            f'<suite name="{name}"><test type="exec" name="t">ok.sh</test></suite>\n')
    # Suite a took 5 s, b and c 1 s each: balanced, a is alone on its shard. (Round-robin by
    # name would put a and c together.)
    (tmp_path / "old.xml").write_text(
        "<testsuites>" + "".join(
            f'<testsuite name="{name}"><testcase name="t" time="{seconds}"/></testsuite>'
            for name, seconds in [("a", 5), ("b", 1), ("c", 1)]) + "</testsuites>")
    r = run_runner("--history", "h.db", "--history-import", "../old.xml", cwd=folder)
    assert r.returncode == 0, r
    r = run_runner("--suites", ".", "--shard-index", "0", "--shard-count", "2", "--durations",
                   "h.db", "--history", "h.db", "-o", "junit:../shard-0.xml", cwd=folder)
    assert r.returncode == 0, r
    assert "balanced by h.db" in r.output, r
    suites = [s.get("name") for s in ET.parse(tmp_path / "shard-0.xml").getroot().iter("testsuite")
              if s.get("id") is not None]
    assert suites == ["a"], r


def test_the_html_report_shows_each_tests_last_runs(tmp_path):
    folder = make_suite(tmp_path / "suite")
    for flip in ["1", ""]:
        r = run_runner("--suite", "hist.xml", "--history", "h.db", "-o", "html:r.html",
                       cwd=folder, env={"FLIP": flip})
    assert r.returncode == 0, r
    html = folder / "r.html"
    assert "window.rtfTrends = " in html.read_text()  # trends.js, which draws the strips
    tests = {t["name"]: t for t in report_data(html)["suites"][0]["tests"]}
    assert tests["flip"]["history"]["states"] == ["failed", "passed"]
    assert len(tests["flip"]["history"]["durations"]) == 2
    assert tests["flip"]["history"]["flakyRate"] == 0.5
    assert tests["ok"]["history"]["flakyRate"] == 0

    r = run_runner("--suite", "hist.xml", "-o", "html:plain.html", cwd=folder)
    assert r.returncode == 0, r
    assert "history" not in report_data(folder / "plain.html")["suites"][0]["tests"][0]


@pytest.fixture
def browser(tmp_path):
    with chromium(tmp_path) as driver:
        yield driver


def test_the_strips_are_drawn_in_a_browser(tmp_path, browser):
    folder = make_suite(tmp_path / "suite")
    for flip in ["", "", "1"]:  # the last run fails: its suite opens by itself
        r = run_runner("--suite", "hist.xml", "--history", "h.db", "-o", "html:r.html",
                       cwd=folder, env={"FLIP": flip})
    assert r.returncode == 1, r
    browser.get((folder / "r.html").as_uri())
    WebDriverWait(browser, 10).until(
        lambda _: len(browser.find_elements(By.CSS_SELECTOR, "details.test")) == 4)
    rows = {row.find_element(By.CSS_SELECTOR, ".name").text: row
            for row in browser.find_elements(By.CSS_SELECTOR, "details.test")}
    flip = rows["flip"]
    cells = flip.find_elements(By.CSS_SELECTOR, ".history .cell")
    assert [c.get_attribute("class") for c in cells] == ["cell passed", "cell passed",
                                                         "cell failing"]
    assert flip.find_elements(By.CSS_SELECTOR, ".history svg polyline")
    assert flip.find_element(By.CSS_SELECTOR, ".flaky-rate").text == "flaky 33%"
    assert rows["ok"].find_element(By.CSS_SELECTOR, ".flaky-rate").text == "flaky 0%"


def test_the_live_page_shows_each_tests_earlier_runs(tmp_path, browser):
    folder = make_suite(tmp_path / "suite")
    for flip in ["1", ""]:
        r = run_runner("--suite", "hist.xml", "--history", "h.db", "--no-output", cwd=folder,
                       env={"FLIP": flip})
    run = WebRun("--suite", "hist.xml", "--history", "h.db", "--web-linger", "60", cwd=folder)
    try:
        run.wait_for_line("final page stays")
        snapshot = json.loads(request(run.port, "/snapshot")[2])
        tests = {t["name"]: t for t in snapshot["suites"][0]["tests"]}
        assert tests["flip"]["history"]["states"] == ["failed", "passed"]
        assert tests["flip"]["history"]["flakyRate"] == 0.5
        browser.get(run.url)
        WebDriverWait(browser, 10).until(
            lambda _: len(browser.find_elements(By.CSS_SELECTOR, ".history .cell")) == 8)
        rates = [e.text for e in browser.find_elements(By.CSS_SELECTOR, ".flaky-rate")]
        assert sorted(rates) == ["flaky 0%"] * 3 + ["flaky 50%"], rates
        run.proc.send_signal(2)
        assert run.wait(timeout=10) == 0
    finally:
        run.kill()


@pytest.mark.parametrize("content", [b"garbage, not a database" * 10, b"SQLite format 3\0" + b"x" * 200])
def test_a_damaged_history_file_is_an_error_naming_it(tmp_path, content):
    folder = make_suite(tmp_path / "suite")
    (folder / "h.db").write_bytes(content)
    r = run_runner("--suite", "hist.xml", "--history", "h.db", "-o", "junit:r.xml", cwd=folder)
    assert r.returncode == 2, r
    assert "--history h.db: not a history file" in r.stderr, r
    assert not (folder / "r.xml").exists()  # nothing ran
    assert (folder / "h.db").read_bytes() == content  # and the file is as it was
    r = run_runner("--history", "h.db", "--history-report", cwd=folder)
    assert r.returncode == 2 and "h.db" in r.stderr, r


def test_a_file_another_run_is_still_making_is_appended_to(tmp_path):
    """What a run meets when another one has just made the file: WAL set (so the file is no
    longer empty) but no tables yet. Not "an empty file": the run makes them and appends."""
    folder = make_suite(tmp_path / "suite")
    with sqlite3.connect(folder / "h.db") as db:
        assert db.execute("PRAGMA journal_mode=WAL").fetchone() == ("wal",)
    assert (folder / "h.db").stat().st_size > 0
    r = run_runner("--suite", "hist.xml", "--history", "h.db", "--no-output", cwd=folder)
    assert r.returncode == 0, r
    assert "history" not in r.stderr, r
    assert history_rows(folder / "h.db", "hist/ok") == [("passed", 1)]


def test_another_programs_database_is_refused(tmp_path):
    folder = make_suite(tmp_path / "suite")
    with sqlite3.connect(folder / "h.db") as db:
        db.execute("CREATE TABLE contacts(name TEXT)")
    r = run_runner("--suite", "hist.xml", "--history", "h.db", "--no-output", cwd=folder)
    assert r.returncode == 2, r
    assert "h.db: an SQLite database of another program" in r.stderr, r


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_history_that_cannot_be_written_loses_no_report(tmp_path, isolation):
    folder = make_suite(tmp_path / "suite")
    # A folder that does not exist: the file cannot be made (whoever runs the test, root too).
    r = run_runner("--isolation", isolation, "--suite", "hist.xml", "--history",
                   "gone/h.db", "-o", "junit:r.xml", "-o", "html:r.html", cwd=folder,
                   env={"FLIP": "1"})
    assert r.returncode == 1, r  # the run's own status
    assert "warning: this run is not in the history" in r.stderr and "gone/h.db" in r.stderr, r
    assert (folder / "r.xml").is_file() and (folder / "r.html").is_file()
    r = run_runner("--isolation", isolation, "--suite", "hist.xml", "--history",
                   "gone/h.db", "-o", "junit:r2.xml", cwd=folder)
    assert r.returncode == 0, r


def test_reading_a_history_leaves_no_sqlite_file_beside_it(tmp_path):
    """Clutter (issue 38, the first hour): --history-report, --history-html and
    --durations-from read the history; SQLite makes its -wal and -shm files beside a WAL
    database to read it, and a read-only connection never removes them. After any command,
    the folder holds the history file alone."""
    folder = make_suite(tmp_path / "suite")
    r = run_runner("--suite", "hist.xml", "--history", "h.db", "--no-output", cwd=folder)
    assert r.returncode == 0, r
    beside = sorted(p.name for p in folder.glob("h.db*"))
    assert beside == ["h.db"], beside
    for args in (["--history", "h.db", "--history-report"],
                 ["--history", "h.db", "--history-report", "--history-html", "h.html"],
                 ["--suite", "hist.xml", "--durations-from", "h.db", "--no-output"],
                 ["--suite", "hist.xml", "--history", "h.db", "--no-output"]):
        r = run_runner(*args, cwd=folder)
        assert r.returncode == 0, (args, r)
        beside = sorted(p.name for p in folder.glob("h.db*"))
        assert beside == ["h.db"], (args, beside)
    assert history_rows(folder / "h.db", "hist/ok") == [("passed", 1)] * 2


def test_history_commands_need_a_history_file(tmp_path):
    for args in (["--history-report"], ["--history-import", "r.xml"],
                 ["--history", "h.db", "--history-report", "0"],
                 ["--history", "h.db", "--history-import"]):
        r = run_runner(*args, cwd=tmp_path)
        assert r.returncode == 2, (args, r)
    r = run_runner("--history", "h.db", "--history-report", cwd=tmp_path)
    assert r.returncode == 2 and "h.db" in r.stderr, r
    assert not (tmp_path / "h.db").exists()


MEASURING = """class TestCase:
    def run(self):
        robottestingframework.testMeasure("tracking error", 0.012, "rad", 0, 0.05)
        robottestingframework.testMeasure("rate", 100.0, "Hz")
"""


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_each_runs_measurements_are_kept_with_its_results(tmp_path, isolation):
    (tmp_path / "arm.py").write_text(MEASURING)
    (tmp_path / "m.xml").write_text('<suite name="m">\n  <test name="arm">arm.py</test>\n'
                                    '</suite>\n')
    for _ in range(2):
        r = run_runner("--isolation", isolation, "--suite", "m.xml", "--history", "h.db",
                       "--no-output", cwd=tmp_path)
        assert r.returncode == 0, r
    with sqlite3.connect(tmp_path / "h.db") as db:
        rows = db.execute(
            "SELECT m.run, t.name, m.name, m.value, m.unit, m.low, m.high FROM measurements m "
            "JOIN tests t ON t.id = m.test ORDER BY m.run, m.rowid").fetchall()
    runs = sorted({row[0] for row in rows})
    assert len(runs) == 2, rows
    for run in runs:
        assert [row[1:] for row in rows if row[0] == run] == [
            ("m/arm", "tracking error", 0.012, "rad", 0.0, 0.05),
            ("m/arm", "rate", 100.0, "Hz", None, None)], rows
