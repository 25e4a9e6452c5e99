"""Suites at once (-j N), locks, pools and exclusive suites, through the real runner.

The suites record when their fixture was set up and torn down (a Python fixture appends
"NAME start|end TIME [ITEM]" to a file under tmp_path): the tests read the intervals, they
never rely on how long something takes. The runner starts in the suites' folder and is given
every file by a relative path, as users run it."""
import json
import os
import re
import signal
import time
import xml.etree.ElementTree as ET

from conftest import leftover_processes, marked, plugin, run_runner, start_runner

STAMP_FIXTURE = """import time
import robottestingframework


class FixtureManager:
    def setup(self, param):
        words = param.split()
        self.log, self.name = words[0], words[1]
        self.item = words[2] if len(words) > 2 else "-"
        self.note("start")
        time.sleep(float(self.wait))
        return True

    wait = {wait}

    def note(self, what):
        with open(self.log, "a") as out:
            out.write("%s %s %.6f %s\\n" % (self.name, what, time.time(), self.item))

    def check(self):
        return True

    def tearDown(self):
        self.note("end")
"""


def stamp_fixture(folder, wait=0.3):
    path = folder / "stamp_fixture.py"
    path.write_text(STAMP_FIXTURE.format(wait=wait))
    return path


def write_suite(folder, name, body="", attributes="", tests=2, log=None, item=""):
    """A suite of `tests` passing tests whose fixture stamps its interval into `log`; returns
    the suite file's name (the runner starts in `folder`)."""
    fixture = ""
    if log is not None:
        fixture = (f'<fixture type="python" param="{log} {name} {item}">'
                   'stamp_fixture.py</fixture>')
    cases = "\n".join(f'  <test name="{name}-t{i}">{plugin("passing_test")}</test>'
                      for i in range(tests))
    path = folder / f"{name}.xml"
    path.write_text(f'<suite name="{name}"{attributes}>\n  {fixture}\n  {body}\n{cases}\n</suite>\n')
    return path.name


def intervals(log):
    """{suite: (start, end, item)} from the stamps."""
    found = {}
    for line in log.read_text().splitlines():
        name, what, when, item = line.split()
        start, end, _ = found.get(name, (None, None, None))
        if what == "start":
            start = float(when)
        else:
            end = float(when)
        found[name] = (start, end, item)
    return found


def overlap(a, b):
    return a[0] < b[1] and b[0] < a[1]


def junit_results(path):
    """[(suite, test, state)] in document order."""
    out = []
    for suite in ET.parse(path).getroot().iter("testsuite"):
        for case in suite.iter("testcase"):
            state = "passed"
            for child in case:
                if child.tag in ("failure", "error", "skipped"):
                    state = child.tag
            out.append((suite.get("name"), case.get("name"), state))
    return out


def mixed_suites(folder, log):
    """Suites with passing, failing, skipped and dependent tests, and a failing fixture: the
    runner's arguments, for a runner started in `folder`."""
    stamp_fixture(folder, wait=0.1)
    suites = [write_suite(folder, "alpha", log=log),
              write_suite(folder, "beta", body=f'<test name="beta-fails">{plugin("failing_test")}</test>'
                          f'\n  <test name="beta-after" depends="beta-fails">{plugin("passing_test")}</test>',
                          log=log),
              write_suite(folder, "gamma", body='<fixture>no_such_fixture</fixture>'),
              write_suite(folder, "delta", body=f'<test name="delta-dep" depends="alpha-t0">'
                          f'{plugin("passing_test")}</test>', log=log)]
    args = []
    for suite in suites:
        args += ["--suite", suite]
    return args


# Times, pids and the like differ from run to run; nothing else may.
TIMES = re.compile(r'(time|duration|timestamp|start|stop|hostname|id)="[^"]*"|'
                   r'"(duration|start|stop|time|timestamp)": *[0-9.e+-]+|'
                   r'\(\d+(\.\d+)? m?s\)|\d+\.\d+ ?m?s|duration_ms: *[0-9.]+|pid \d+|'
                   r'"(pid|hostname)": *"?[^",]*"?|\d{4}-\d\d-\d\dT[0-9:.]+Z?')


def normalised(text):
    return TIMES.sub("<t>", text)


def test_jobs_1_writes_what_the_default_writes(tmp_path):
    outputs = {}
    for label, extra in (("default", []), ("j1", ["--jobs", "1"]), ("j1short", ["-j", "1"])):
        folder = tmp_path / label
        folder.mkdir()
        args = mixed_suites(folder, folder / "stamps.log")
        files = {kind: folder / f"out.{kind}" for kind in ("txt", "xml", "tap", "json")}
        r = run_runner(*args, *extra, "-o", "text:out.txt", "-o", "junit:out.xml",
                       "-o", "tap:out.tap", "-o", "json:out.json", cwd=folder)
        assert r.returncode == 1, r
        outputs[label] = {kind: normalised(path.read_text().replace(str(folder), "F"))
                          for kind, path in files.items()}
        outputs[label]["console"] = normalised(r.stdout.replace(str(folder), "F"))
    for kind in ("txt", "xml", "tap", "json", "console"):
        assert outputs["j1"][kind] == outputs["default"][kind], kind
        assert outputs["j1short"][kind] == outputs["default"][kind], kind
    assert "delta-dep" in outputs["j1"]["xml"]


def test_jobs_n_gives_the_results_of_jobs_1_in_plan_order(tmp_path):
    results = {}
    for jobs in ("1", "3"):
        folder = tmp_path / f"j{jobs}"
        folder.mkdir()
        args = mixed_suites(folder, folder / "stamps.log")
        r = run_runner(*args, "-j", jobs, "-o", "junit:out.xml", "-o", "json:out.json",
                       cwd=folder)
        assert r.returncode == 1, r
        results[jobs] = junit_results(folder / "out.xml")
        report = json.loads((folder / "out.json").read_text())
        results[jobs + "json"] = [(t["name"], t["status"]) for t in report["results"]["tests"]]
    assert results["3"] == results["1"]
    assert results["3json"] == results["1json"]
    assert [r[0] for r in results["3"]][0] == "alpha"
    states = {test: state for _, test, state in results["3"]}
    assert states["beta-fails"] == "failure" and states["beta-after"] == "skipped"
    assert states["delta-dep"] == "passed"


def test_jobs_n_runs_suites_at_once_one_line_per_finished_test(tmp_path):
    log = tmp_path / "stamps.log"
    stamp_fixture(tmp_path, wait=1.0)
    args = []
    for name in ("s1", "s2", "s3", "s4"):
        args += ["--suite", write_suite(tmp_path, name, log=log)]
    r = run_runner(*args, "-j", "2", "--no-output", cwd=tmp_path)
    assert r.returncode == 0, r
    spans = intervals(log)
    assert len(spans) == 4
    pairs = [(a, b) for a in spans for b in spans if a < b and overlap(spans[a], spans[b])]
    assert pairs, spans  # two at once...
    for name in spans:  # ...but never three
        at = spans[name][0] + 0.01
        assert sum(1 for s in spans.values() if s[0] <= at <= s[1]) <= 2, spans
    lines = [line for line in r.stdout.splitlines() if re.match(r"\s+passed\s+\S+/", line)]
    assert len(lines) == 8, r.stdout
    for name in ("s1", "s2", "s3", "s4"):
        for i in range(2):
            assert sum(1 for line in lines if re.match(rf"\s+passed\s+{name}/{name}-t{i}  \(", line)) == 1, r.stdout
    assert "\r" not in r.stdout  # no live status line on a pipe
    assert "8 passed, 0 failed" in r.stdout, r


def test_jobs_auto_and_bad_jobs(tmp_path, suite_file):
    suite = suite_file(f'<suite name="one"><test>{plugin("passing_test")}</test></suite>')
    r = run_runner("--suite", suite.name, "--jobs", "auto", "--no-output", cwd=tmp_path)
    assert r.returncode == 0, r
    for bad in ("0", "-1", "two", "1.5", "100000"):
        r = run_runner("--suite", suite.name, "-j", bad, "--no-output", cwd=tmp_path)
        assert r.returncode == 2, r
        assert f"--jobs {bad}: expected a whole number" in r.stderr, r


def test_suites_sharing_a_lock_never_overlap_and_the_wait_is_said(tmp_path):
    log = tmp_path / "stamps.log"
    stamp_fixture(tmp_path, wait=0.5)
    args = []
    for name in ("arm1", "arm2", "arm3"):
        args += ["--suite", write_suite(tmp_path, name, log=log,
                                        body='<resource lock="robot:left-arm"/>\n  '
                                             '<resource lock="lab:camera"/>')]
    args += ["--suite", write_suite(tmp_path, "free", log=log)]
    r = run_runner(*args, "-j", "4", "--verbose", "--no-output", cwd=tmp_path)
    assert r.returncode == 0, r
    spans = intervals(log)
    locked = [spans[n] for n in ("arm1", "arm2", "arm3")]
    for i, a in enumerate(locked):
        for b in locked[i + 1:]:
            assert not overlap(a, b), spans
    assert any(overlap(spans["free"], s) for s in locked), spans
    assert re.search(r'suite "arm[23]" waits for lock lab:camera \(held by suite "arm\d"\)',
                     r.stdout), r.stdout


def test_pool_items_are_distinct_and_reach_the_suite(tmp_path):
    log = tmp_path / "stamps.log"
    stamp_fixture(tmp_path, wait=0.5)
    resources = tmp_path / "resources.json"
    resources.write_text(json.dumps({"version": {"major": 1, "minor": 0},
                                     "local": [{"ros_domain": [{"id": "11"}, {"id": "12"}]}]}))
    probe = tmp_path / "probe.sh"
    probe.write_text('#!/bin/sh\necho "$1 param=$2 env=$RTF_RESOURCE_ROS_DOMAIN" >> "$3"\n')
    probe.chmod(0o755)
    seen = tmp_path / "seen.txt"
    args = []
    for name in ("p1", "p2", "p3", "p4"):
        args += ["--suite", write_suite(
            tmp_path, name, log=log, item="${resource.ros_domain}",
            body=f'<resource pool="ros_domain" count="1"/>\n  <test type="exec" '
                 f'param="{name} ${{resource.ros_domain}} {seen}">./{probe.name}</test>')]
    r = run_runner(*args, "-j", "4", "--resources", resources.name, "--no-output", cwd=tmp_path)
    assert r.returncode == 0, r
    spans = intervals(log)
    assert {s[2] for s in spans.values()} == {"11", "12"}, spans
    for a in spans:
        for b in spans:
            if a < b and overlap(spans[a], spans[b]):
                assert spans[a][2] != spans[b][2], spans
    lines = seen.read_text().splitlines()
    assert len(lines) == 4
    for line in lines:
        name, param, env = line.split()
        assert param == "param=" + spans[name][2] and env == "env=" + spans[name][2], lines


def test_exclusive_suite_runs_alone(tmp_path):
    log = tmp_path / "stamps.log"
    stamp_fixture(tmp_path, wait=0.4)
    args = []
    for name in ("e1", "e2", "alone", "e3", "e4"):
        attributes = ' exclusive="true"' if name == "alone" else ""
        args += ["--suite", write_suite(tmp_path, name, log=log, attributes=attributes)]
    r = run_runner(*args, "-j", "4", "--no-output", cwd=tmp_path)
    assert r.returncode == 0, r
    spans = intervals(log)
    for name, span in spans.items():
        if name != "alone":
            assert not overlap(span, spans["alone"]), spans
    assert overlap(spans["e1"], spans["e2"]) or overlap(spans["e3"], spans["e4"]), spans


def test_bad_resources_exit_2_naming_what_and_where(tmp_path, suite_file):
    def suite(body, attributes=""):
        return f'<suite name="bad"{attributes}>\n{body}\n<test>{plugin("passing_test")}</test></suite>'
    resources = tmp_path / "resources.json"
    resources.write_text(json.dumps({"version": {"major": 1, "minor": 0},
                                     "local": [{"gpus": [{"id": "0"}]}]}))
    cases = [
        (suite('<resource lock="left arm"/>'), [],
         'suite.xml:2: <resource lock="left arm">: a lock name has no spaces'),
        (suite('<resource pool="ros_domain"/>'), ["--resources", resources.name],
         'suite.xml:2: pool "ros_domain" does not exist in'),
        (suite('<resource pool="ros_domain"/>'), [],
         'suite.xml:2: pool "ros_domain" does not exist (no --resources'),
        (suite('<resource pool="gpus" count="2"/>'), ["--resources", resources.name],
         'suite.xml:2: pool "gpus" ('),
        (suite('<resource pool="port" default="a b/c"/>'), [],
         'suite.xml:2: default="...": item "b/c" is not an id'),
        (suite('<resource pool="port" default=" "/>'), [],
         'suite.xml:2: default="": give the pool\'s items'),
        (suite('<resource lock="arm" default="1"/>'), [],
         'suite.xml:2: <resource lock=...> takes no count nor default'),
        (suite('<resource lock="a" pool="b"/>'), [], "suite.xml:2: <resource> takes one of"),
        (suite('<resource pool="gpus" count="0"/>'), [],
         'suite.xml:2: count="0": expected a whole number'),
        (suite('', ' exclusive="yes"'), [], 'suite.xml:1: exclusive="yes": expected true or false'),
        (f'<suite name="bad">\n<test param="${{resource.gpus}}">{plugin("passing_test")}</test>'
         '</suite>', [], "suite.xml:2: ${resource.gpus} but the suite takes no item of pool gpus"),
    ]
    for text, extra, expected in cases:
        path = suite_file(text)
        r = run_runner("--suite", path.name, *extra, "--no-output", cwd=tmp_path)
        assert r.returncode == 2, (expected, r)
        assert expected in r.stderr, (expected, r)
    r = run_runner("--suite", suite_file(suite('<resource pool="gpus" count="2"/>')).name,
                   "--resources", resources.name, "--no-output", cwd=tmp_path)
    assert "and could never run" in r.stderr, r
    for text in ("{", '{"version": {"major": 2}, "local": [{}]}',
                 '{"version": {"major": 1}, "local": [{"gpus": [{"id": "a"}, {"id": "a"}]}]}'):
        resources.write_text(text)
        r = run_runner("--suite", suite_file(suite("")).name, "--resources", resources.name,
                       "--no-output", cwd=tmp_path)
        assert r.returncode == 2, r
        assert f"--resources {resources.name}:" in r.stderr, r


def test_ctrl_c_during_jobs_2_interrupts_both_and_leaves_nothing(tmp_path, marker):
    log = tmp_path / "stamps.log"
    stamp_fixture(tmp_path, wait=0.0)
    args = []
    for name in ("long1", "long2", "later"):
        args += ["--suite", write_suite(
            tmp_path, name, log=log, tests=0,
            body=f'<test name="{name}-wait" param="--seconds 60">{plugin("waiting_test")}</test>')]
    out = tmp_path / "out.xml"
    proc = start_runner(*args, "-j", "2", "-o", "junit:out.xml", cwd=tmp_path,
                        env=marked(marker))
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            if log.exists() and log.read_text().count(" start ") >= 2:
                break
            time.sleep(0.05)
        time.sleep(0.5)  # the tests are running
        proc.send_signal(signal.SIGINT)
        stdout, stderr = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    assert proc.returncode == 130, (stdout, stderr)
    results = junit_results(out)
    assert [r[1] for r in results] == ["long1-wait", "long2-wait", "later-wait"], results
    assert all(r[2] in ("error", "failure") for r in results), results
    assert "interrupted" in out.read_text()
    spans = intervals(log)
    assert spans["long1"][1] is not None and spans["long2"][1] is not None  # torn down
    assert "later" not in spans
    assert leftover_processes(marker) == []


def test_fixture_collapse_during_jobs_2_stops_only_its_suite(tmp_path, marker):
    collapsing = tmp_path / "collapsing.xml"
    collapsing.write_text(f'''<suite name="collapsing">
  <fixture>{plugin("fixture_collapse")}</fixture>
  <test name="c-wait" param="--seconds 30">{plugin("waiting_test")}</test>
  <test name="c-next">{plugin("passing_test")}</test>
</suite>''')
    steady = tmp_path / "steady.xml"
    steady.write_text(f'''<suite name="steady">
  <test name="s-wait" param="--seconds 1">{plugin("waiting_test")}</test>
  <test name="s-next">{plugin("passing_test")}</test>
</suite>''')
    out = tmp_path / "out.xml"
    r = run_runner("--suite", collapsing.name, "--suite", steady.name, "-j", "2",
                   "-o", "junit:out.xml", cwd=tmp_path, env=marked(marker), timeout=90)
    assert r.returncode == 1, r
    states = {test: state for _, test, state in junit_results(out)}
    assert states["s-wait"] == "passed" and states["s-next"] == "passed", states
    assert states["c-next"] == "skipped", states
    assert "the simulator fell over" in r.stdout, r
    assert leftover_processes(marker) == []


def test_fail_fast_with_jobs_starts_no_suite_after_a_failure(tmp_path, suite_file):
    first = suite_file(f'<suite name="first"><test>{plugin("failing_test")}</test></suite>',
                       name="first.xml")
    rest = [suite_file(f'<suite name="rest{i}"><test>{plugin("passing_test")}</test></suite>',
                       name=f"rest{i}.xml") for i in range(3)]
    out = tmp_path / "out.xml"
    args = ["--suite", first.name]
    for path in rest:
        args += ["--suite", path.name]
    r = run_runner(*args, "-j", "1", "--fail-fast", "-o", "junit:out.xml", cwd=tmp_path)
    assert r.returncode == 1, r
    assert [s for _, _, s in junit_results(out)] == ["failure", "skipped", "skipped", "skipped"]


def test_pool_item_reaches_python_tests_and_tests_in_the_runners_process(tmp_path, suite_file):
    resources = tmp_path / "resources.json"
    resources.write_text(json.dumps({"version": {"major": 1, "minor": 0},
                                     "local": [{"ros_domain": [{"id": "42"}]}]}))
    script = tmp_path / "probe.py"
    script.write_text("""import os
import robottestingframework


class TestCase:
    def run(self):
        robottestingframework.testReport("domain=%s param=%s" % (
            os.environ.get("RTF_RESOURCE_ROS_DOMAIN"), robottestingframework.getParam()))
""")
    suite = suite_file(f"""<suite name="py">
  <resource pool="ros_domain"/>
  <test param="${{resource.ros_domain}}">{script.name}</test>
</suite>""")
    for isolation in ("process", "none"):
        r = run_runner("--suite", suite.name, "--resources", resources.name,
                       "--isolation", isolation, "-v", "--no-output", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "domain=42 param=42" in r.stdout, (isolation, r)
    assert "RTF_RESOURCE_ROS_DOMAIN" not in os.environ


def test_live_status_line_only_on_a_terminal(tmp_path):
    import pty
    import subprocess
    from conftest import RUNNER, terminal_environment
    log = tmp_path / "stamps.log"
    stamp_fixture(tmp_path, wait=0.5)
    args = []
    for name in ("t1", "t2"):
        args += ["--suite", write_suite(tmp_path, name, log=log)]
    leader, follower = pty.openpty()
    proc = subprocess.Popen([RUNNER, *map(str, args), "-j", "2", "--no-output"],
                            cwd=tmp_path, stdout=follower, stderr=follower,
                            stdin=subprocess.DEVNULL, start_new_session=True,
                            env={**os.environ, **terminal_environment()})
    os.close(follower)
    seen = b""
    deadline = time.monotonic() + 60
    try:
        while time.monotonic() < deadline:
            try:
                chunk = os.read(leader, 65536)
            except OSError:
                break  # the runner closed its end
            if not chunk:
                break
            seen += chunk
        proc.wait(timeout=30)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
        os.close(leader)
    text = seen.decode(errors="replace")
    assert proc.returncode == 0, text
    # The progress line (test_progress_line.py has the rest): k of the 4 tests.
    assert re.search(r"\[\d/4\]", text), text
    assert "\r\x1b[K" in text, text
    assert "4 passed, 0 failed" in text, text


SERVER_OF_WORKER = """#!/bin/sh
# Appends "SUITE SERVER": the worker that runs this test is our parent, the fork server its.
read -r _ _ _ server _ < /proc/$PPID/stat
echo "$1 $server" >> "$2"
"""


def test_each_suite_running_at_once_forks_its_workers_from_a_fork_server_of_its_own(
        tmp_path, marker):
    # With -j 2, two suites at once do not queue for one fork server's forks: each lane has
    # its own (started with the run, ended with it); with -j 1 one server forks every worker.
    script = tmp_path / "server_of_worker.sh"
    script.write_text(SERVER_OF_WORKER)
    script.chmod(0o755)
    servers = tmp_path / "servers.txt"
    args = []
    for name in ("s1", "s2", "s3", "s4"):
        (tmp_path / f"{name}.xml").write_text(
            f'<suite name="{name}">\n' + "".join(
                f'  <test type="exec" name="{name}-t{i}" param="{name} servers.txt">'
                f'server_of_worker.sh</test>\n' for i in range(3)) + "</suite>\n")
        args += ["--suite", f"{name}.xml"]
    by_jobs = {}
    for jobs in ("1", "2"):
        servers.unlink(missing_ok=True)
        r = run_runner(*args, "-j", jobs, "--no-output", cwd=tmp_path, env=marked(marker))
        assert r.returncode == 0 and "12 passed, 0 failed" in r.stdout, r
        lines = [line.split() for line in servers.read_text().splitlines()]
        assert len(lines) == 12, lines
        by_suite = {}
        for suite, server in lines:
            by_suite.setdefault(suite, set()).add(int(server))
        assert all(len(pids) == 1 for pids in by_suite.values()), by_suite  # one per suite
        by_jobs[jobs] = set().union(*by_suite.values())
        assert leftover_processes(marker) == []
        for pid in by_jobs[jobs]:
            assert not os.path.exists(f"/proc/{pid}"), f"fork server {pid} outlived the run"
    assert len(by_jobs["1"]) == 1, by_jobs
    assert len(by_jobs["2"]) == 2, by_jobs


def test_a_pool_taken_twice_by_one_suite_exits_2_saying_what_to_write(tmp_path, suite_file):
    # Issue 39, 1: each <resource> alone fits the one-item pool, both together never do; the
    # run waited for ever (also with -j 1), --list passed. Bounded: a hang fails the test.
    path = suite_file('<suite name="s">\n'
                      '  <resource pool="p" default="1"/>\n'
                      '  <resource pool="p" default="1"/>\n'
                      f'  <test>{plugin("passing_test")}</test>\n</suite>\n')
    for extra in ([], ["-j", "1"], ["--list"]):
        r = run_runner("--suite", path.name, "--no-output", *extra, cwd=tmp_path, timeout=30)
        assert r.returncode == 2, (extra, r)
        assert ('suite.xml:3: pool "p" is taken a second time (first at line 2); write one '
                '<resource pool="p" count="2"/>') in r.stderr, (extra, r)


def test_a_repeated_item_in_default_exits_2_naming_the_line(tmp_path, suite_file):
    # Issue 39, 10 and issue 40, 3: default="7 7" gave two suites item 7 at once, and
    # default="1 1 1" with count="2" handed out 1,1; a --resources file refuses the same.
    for resource in ('<resource pool="ports" default="7 7"/>',
                     '<resource pool="ports" default="1 1 1" count="2"/>'):
        path = suite_file(f'<suite name="s">\n  {resource}\n'
                          f'  <test>{plugin("passing_test")}</test>\n</suite>\n')
        for extra in ([], ["--list"]):
            r = run_runner("--suite", path.name, "--no-output", *extra, cwd=tmp_path, timeout=30)
            assert r.returncode == 2, (resource, extra, r)
            assert 'suite.xml:2: default="...": item "' in r.stderr, (resource, r)
            assert "is given twice" in r.stderr, (resource, r)
