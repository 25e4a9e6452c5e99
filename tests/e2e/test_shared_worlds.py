"""Shared worlds (<fixture type="process" scope="run">) through the installed runner, from the
suites' own folder: suites naming one world share one instance, started once before the first
of them and stopped after the last, several worlds stopped in the reverse order of their
starts; a world that fails to start fails exactly its suites; a world of one name declared
twice differently is exit 2; suites sharing a fixed-port world in private networks pass while
this machine holds that port. Loopback only; nothing is left behind."""
import json
import socket
import sys
import xml.etree.ElementTree as ET

import pytest

from conftest import leftover_processes, marked, run_runner


def world(folder, name, ready_after="0.3"):
    """A world whose process notes its start and its stop in journal.txt."""
    (folder / f"{name}.xml").write_text(f"""<world name="{name}" logdir="logs">
  <process name="{name}" command="sh -c 'echo start-{name} >> journal.txt; trap &quot;echo stop-{name} >> journal.txt; exit 0&quot; INT TERM; sleep {ready_after}; echo ready; while :; do sleep 0.05; done'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")


def suites(folder, names, worlds, own=""):
    note = folder / "note.py"
    note.write_text(f"#!{sys.executable}\nopen('journal.txt', 'a').write('test\\n')\n")
    note.chmod(0o755)
    args = []
    for suite in names:
        fixtures = "".join(f'  <fixture type="process" scope="run">{w}.xml</fixture>\n'
                           for w in worlds)
        (folder / f"{suite}.xml").write_text(f"""<suite name="{suite}">
{fixtures}{own}  <test type="exec">note.py</test>
  <test type="exec">note.py</test>
</suite>
""")
        args += ["-s", f"{suite}.xml"]
    return args


def journal(folder):
    return (folder / "journal.txt").read_text().split()


@pytest.mark.parametrize("jobs", ["1", "3"])
@pytest.mark.parametrize("isolation", ["process", "none"])
def test_three_suites_share_one_world_started_once(tmp_path, marker, jobs, isolation):
    world(tmp_path, "lab")
    args = suites(tmp_path, ["arm", "base", "head"], ["lab"])
    result = run_runner(*args, "-j", jobs, "--isolation", isolation, "--no-output",
                        cwd=tmp_path, env=marked(marker))
    assert result.returncode == 0, result.output
    assert "6 passed, 0 failed" in result.stdout
    # Started once, before every test; stopped once, after the last.
    assert journal(tmp_path) == ["start-lab"] + ["test"] * 6 + ["stop-lab"]
    assert "world 'lab' (shared by 3 suites) starting" in result.output
    assert "world 'lab' ready after" in result.output
    assert "world 'lab' stopped after" in result.output
    assert not leftover_processes(marker)


@pytest.mark.parametrize("jobs", ["1", "3"])
def test_two_shared_worlds_stop_in_the_reverse_order_of_their_starts(tmp_path, marker, jobs):
    world(tmp_path, "sim")
    world(tmp_path, "broker")
    args = suites(tmp_path, ["arm", "base", "head"], ["sim", "broker"])
    result = run_runner(*args, "-j", jobs, "--no-output", cwd=tmp_path, env=marked(marker))
    assert result.returncode == 0, result.output
    assert journal(tmp_path) == (["start-sim", "start-broker"] + ["test"] * 6 +
                                 ["stop-broker", "stop-sim"])
    assert not leftover_processes(marker)


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_world_that_fails_to_start_fails_exactly_its_suites(tmp_path, marker, isolation):
    (tmp_path / "broken.xml").write_text("""<world name="broken" logdir="logs">
  <process name="broken" command="sh -c 'echo broken-world-said-this; exit 3'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    args = suites(tmp_path, ["arm", "base"], ["broken"])
    args += suites(tmp_path, ["head"], [])
    result = run_runner(*args, "-j", "2", "--isolation", isolation, "-o", "json:report.json",
                        cwd=tmp_path, env=marked(marker))
    assert result.returncode == 1, result.output
    assert "suites: 3 (1 passed, 2 failed)" in result.stdout
    # Said whole once by each suite's error; each skipped test refers to it in a line, its
    # first (issue 38, friction 9).
    assert result.output.count("shared world 'broken' did not start") == 2 + 4, result.output
    skipped = [l.strip() for l in result.stdout.splitlines()
               if "skipped: the suite's fixture failed (see the suite's error): " in l]
    assert len(skipped) == 4, result.stdout
    assert all("shared world 'broken' did not start" in l for l in skipped), skipped
    assert "broken-world-said-this" in result.output  # the log's tail in the reason
    report = json.loads((tmp_path / "report.json").read_text())
    text = json.dumps(report)
    # The world's log attached to each suite that needed it.
    assert text.count('"description": "log of process broken"') == 2, text
    # Tried once.
    assert (tmp_path / "logs" / "broken.log").read_text().count("broken-world-said-this") == 1
    assert not leftover_processes(marker)


def test_a_shared_world_declared_twice_differently_is_exit_2(tmp_path):
    world(tmp_path, "lab")
    other = tmp_path / "other"
    other.mkdir()
    world(other, "lab")
    (tmp_path / "arm.xml").write_text(
        '<suite name="arm">\n  <fixture type="process" scope="run">lab.xml</fixture>\n'
        '  <test type="exec">/bin/true</test>\n</suite>\n')
    (tmp_path / "base.xml").write_text(
        '<suite name="base">\n\n  <fixture type="process" scope="run">other/lab.xml</fixture>\n'
        '  <test type="exec">/bin/true</test>\n</suite>\n')
    result = run_runner("-s", "arm.xml", "-s", "base.xml", "--no-output", cwd=tmp_path)
    assert result.returncode == 2, result.output
    assert "base.xml:3: a shared world declared twice with different contents: world 'lab'" \
        in result.stderr
    assert "also declared at" in result.stderr and "arm.xml:2" in result.stderr
    assert "passed" not in result.stdout

    # The same file with another param is another world of the same name.
    (tmp_path / "base.xml").write_text(
        '<suite name="base">\n  <fixture type="process" scope="run" param="--logdir other">'
        'lab.xml</fixture>\n  <test type="exec">/bin/true</test>\n</suite>\n')
    result = run_runner("-s", "arm.xml", "-s", "base.xml", "--no-output", cwd=tmp_path)
    assert result.returncode == 2, result.output
    assert 'param "" there, "--logdir other" here' in result.stderr


def test_variables_decide_the_identity_of_a_shared_world_only_where_it_reads_them(tmp_path,
                                                                                    marker):
    (tmp_path / "lab.xml").write_text("""<world name="lab" logdir="logs">
  <variable name="speed">1</variable>
  <process name="lab" command="sh -c 'echo start-${speed} >> journal.txt; echo ready; while :; do sleep 0.05; done'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")

    def suite(name, variables):
        given = "".join(f'  <variable name="{k}">{v}</variable>\n' for k, v in variables.items())
        (tmp_path / f"{name}.xml").write_text(
            f'<suite name="{name}">\n{given}'
            '  <fixture type="process" scope="run">lab.xml</fixture>\n'
            '  <test type="exec">/bin/true</test>\n</suite>\n')
        return ["-s", f"{name}.xml"]

    # Their tests' variables differ, the world's do not: one world.
    args = suite("arm", {"robot": "left", "speed": "2"}) + suite("base", {"robot": "right",
                                                                          "speed": "2"})
    result = run_runner(*args, "--no-output", cwd=tmp_path, env=marked(marker))
    assert result.returncode == 0, result.output
    assert journal(tmp_path) == ["start-2"]
    # A value the world reads differs: two worlds of one name, exit 2.
    args = suite("arm", {"speed": "2"}) + suite("head", {"speed": "3"})
    result = run_runner(*args, "--no-output", cwd=tmp_path, env=marked(marker))
    assert result.returncode == 2, result.output
    assert ('head.xml:3: a shared world declared twice with different contents: world \'lab\' '
            '(scope="run") is also declared at arm.xml:3 (param "--var speed=2" there, '
            '"--var speed=3" here)') in result.stderr
    assert not leftover_processes(marker)


def test_bad_scopes_are_exit_2_naming_file_and_line(tmp_path):
    (tmp_path / "suite.xml").write_text(
        '<suite name="s">\n  <fixture type="process"\n    scope="shard">lab.xml</fixture>\n'
        '  <test type="exec">/bin/true</test>\n</suite>\n')
    result = run_runner("-s", "suite.xml", "--no-output", cwd=tmp_path)
    assert result.returncode == 2, result.output
    assert ('suite.xml:2: <fixture scope="shard">: expected "suite" (the default: the suite\'s '
            'own) or "run"') in result.stderr
    (tmp_path / "suite.xml").write_text(
        '<suite name="s">\n  <fixture type="dll" scope="run">x</fixture>\n'
        '  <test type="exec">/bin/true</test>\n</suite>\n')
    result = run_runner("-s", "suite.xml", "--no-output", cwd=tmp_path)
    assert result.returncode == 2, result.output
    assert ('suite.xml:2: <fixture scope="run"> is for type="process" fixtures (world files) '
            'only') in result.stderr
    (tmp_path / "suite.xml").write_text(
        '<suite name="s">\n  <resource pool="ports" default="a b"/>\n'
        '  <fixture type="process" scope="run" param="--var p=${resource.ports}">lab.xml'
        '</fixture>\n  <test type="exec">/bin/true</test>\n</suite>\n')
    result = run_runner("-s", "suite.xml", "--no-output", cwd=tmp_path)
    assert result.returncode == 2, result.output
    assert ('suite.xml:3: <fixture scope="run"> with ${resource.NAME}: a shared world is the '
            "run's, not one suite's") in result.stderr


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_suites_sharing_a_fixed_port_world_share_its_private_network(tmp_path, marker,
                                                                      isolation):
    port = free_port()
    (tmp_path / "web.xml").write_text(f"""<world name="web" logdir="logs">
  <process name="web" command="{sys.executable} -m http.server {port} --bind 127.0.0.1">
    <ready timeout="20s"><port>{port}</port></ready>
  </process>
</world>
""")
    fetch = tmp_path / "fetch.py"
    fetch.write_text(f"""#!{sys.executable}
import socket
with socket.create_connection(("127.0.0.1", {port}), timeout=10) as s:
    s.sendall(b"GET / HTTP/1.0\\r\\n\\r\\n")
    answer = s.recv(100).decode(errors="replace")
print(answer.splitlines()[0] if answer else "(no answer)")
raise SystemExit(0 if answer.startswith("HTTP/1.0 200") else 1)
""")
    fetch.chmod(0o755)
    args = []
    for suite in ["arm", "base", "head"]:
        (tmp_path / f"{suite}.xml").write_text(
            f'<suite name="{suite}">\n  <fixture type="process" scope="run">web.xml</fixture>\n'
            '  <test type="exec">fetch.py</test>\n</suite>\n')
        args += ["-s", f"{suite}.xml"]
    # This machine's loopback holds the port: only the world's own network has it free.
    with socket.socket() as held:
        held.bind(("127.0.0.1", port))
        held.listen(8)
        result = run_runner(*args, "-j", "3", "--network", "private", "--isolation", isolation,
                            "-v", "--no-output", cwd=tmp_path, env=marked(marker))
    assert result.returncode == 0, result.output
    assert "3 passed, 0 failed" in result.stdout
    assert result.stdout.count("HTTP/1.0 200 OK") == 3, result.stdout
    assert result.output.count("world 'web' (shared by 3 suites) starting") == 1
    assert not leftover_processes(marker)


def test_the_html_report_shows_each_shared_world_as_a_lane(tmp_path, marker):
    from browser import chromium
    from selenium.webdriver.common.by import By

    world(tmp_path, "lab")
    (tmp_path / "broken.xml").write_text("""<world name="broken" logdir="logs">
  <process name="broken" command="sh -c 'exit 3'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    args = suites(tmp_path, ["arm", "base"], ["lab"])
    args += suites(tmp_path, ["head"], ["broken"])
    result = run_runner(*args, "-j", "2", "-o", "html:report.html", cwd=tmp_path,
                        env=marked(marker))
    assert result.returncode == 1, result.output
    with chromium(tmp_path) as driver:
        driver.get((tmp_path / "report.html").as_uri())
        lanes = {bar.get_attribute("data-world"): bar for bar in
                 driver.find_elements(By.CSS_SELECTOR, "#timeline g.world-bar")}
        assert sorted(lanes) == ["broken", "lab"]
        # Each world's lane is labelled by its name, each suite's by its own (issue 38, 11).
        labels = sorted(label.text for label in
                        driver.find_elements(By.CSS_SELECTOR, "#timeline .world-lane"))
        assert labels == ["broken", "lab"], labels
        labels = sorted(label.text for label in
                        driver.find_elements(By.CSS_SELECTOR, "#timeline .suite-lane"))
        assert labels == ["arm", "base", "head"], labels
        titles = {name: [t.get_attribute("textContent")
                         for t in bar.find_elements(By.TAG_NAME, "title")]
                  for name, bar in lanes.items()}
        driver.find_element(By.ID, "timeline-box").location_once_scrolled_into_view
        driver.save_screenshot(str(tmp_path / "timeline.png"))
    lab = " ".join(titles["lab"])
    assert "world lab (shared by 2 suites): started +" in lab, lab
    assert ", ready after " in lab and ", stopped +" in lab, lab
    broken = " ".join(titles["broken"])
    assert "world broken (shared by 1 suite): failed to start +" in broken, broken
    assert "exited with status 3 before it was ready" in broken, broken
    assert not leftover_processes(marker)


def test_the_live_page_shows_each_shared_world_as_a_lane(tmp_path, marker):
    import signal

    from browser import chromium
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait
    from web_run import WebRun

    world(tmp_path, "lab", ready_after="2")
    args = suites(tmp_path, ["arm", "base"], ["lab"])
    run = WebRun(*args, "-j", "2", "--web-linger", "120", cwd=tmp_path, env=marked(marker))

    def lane(driver):
        return driver.execute_script(
            "const lane = document.querySelector('#worlds .world[data-world=\"lab\"]');"
            "return lane ? [lane.className, lane.textContent] : null;")

    try:
        with chromium(tmp_path, window="1100,760", page_load_timeout=30) as driver:
            run.wait_for_line("world 'lab' (shared by 2 suites) starting")
            driver.get(run.url)
            wait = WebDriverWait(driver, 30, poll_frequency=0.05)
            first = wait.until(lane)
            assert "world lab" in first[1] and "shared by 2 suites" in first[1], first
            # Up for as long as its suites' quick tests: the page may see it ready, or only
            # stopped (a change replaced by a later one of the same world is not sent).
            ready = wait.until(lambda d: (lane(d) or [""])[0].endswith(
                ("world-ready", "world-stopped")) and lane(d))
            assert "ready after" in ready[1], ready
            stopped = wait.until(
                lambda d: (lane(d) or [""])[0].endswith("world-stopped") and lane(d))
            assert "stopped, up" in stopped[1], stopped
            driver.save_screenshot(str(tmp_path / "live.png"))
    finally:
        if run.proc.poll() is None:
            run.proc.send_signal(signal.SIGINT)
        status = run.wait(timeout=20)
    assert status == 0, run.output()
    assert not leftover_processes(marker)


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_collapse_interrupts_the_running_suites_and_fails_the_pending_ones(tmp_path, marker,
                                                                             isolation):
    (tmp_path / "dies.xml").write_text("""<world name="dies" logdir="logs">
  <process name="dies" command="sh -c 'echo ready; sleep 1.5; exit 4'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    slow = tmp_path / "slow.py"
    slow.write_text(f"#!{sys.executable}\nimport time\ntime.sleep(1)\n")
    slow.chmod(0o755)
    args = []
    for suite in ["arm", "base", "head"]:
        (tmp_path / f"{suite}.xml").write_text(
            f'<suite name="{suite}">\n  <fixture type="process" scope="run">dies.xml</fixture>\n'
            '  <test type="exec">slow.py</test>\n  <test type="exec">slow.py</test>\n</suite>\n')
        args += ["-s", f"{suite}.xml"]
    result = run_runner(*args, "-j", "2", "--isolation", isolation, "--no-output", cwd=tmp_path,
                        env=marked(marker))
    assert result.returncode == 1, result.output
    assert "suites: 3 (0 passed, 3 failed)" in result.stdout
    assert "fixture collapsed: shared world 'dies' collapsed: process 'dies' exited with " \
           "status 4" in result.output
    # head waited for a place (-j 2; one at a time in the runner's process) and came after
    # the collapse.
    assert "error: fixture dies (shared world) failed: collapsed before this suite: " \
           "shared world 'dies' collapsed" in result.output
    assert not leftover_processes(marker)


def test_a_failed_stop_is_an_error_of_the_last_suite_that_needed_the_world(tmp_path, marker):
    (tmp_path / "stubborn.xml").write_text("""<world name="stubborn" logdir="logs">
  <process name="stubborn" command="sh -c 'trap &quot;&quot; INT TERM; echo ready; while :; do sleep 0.05; done'">
    <ready timeout="20s"><output>ready</output></ready>
    <stop signal="SIGTERM" grace="0.3s"/>
  </process>
</world>
""")
    args = suites(tmp_path, ["arm", "base"], ["stubborn"])
    result = run_runner(*args, "-j", "1", "-o", "junit:report.xml", cwd=tmp_path,
                        env=marked(marker))
    assert result.returncode == 1, result.output
    # The last suite stopped the world: its tear-down failed, and only its.
    failed = "fixture stubborn (shared world) tearDown failed: shared world 'stubborn':"
    assert result.output.count(failed) == 1, result.output
    assert "suites: 2 (1 passed, 1 failed)" in result.stdout
    report = ET.parse(tmp_path / "report.xml").getroot()
    holding = [suite.get("name") for suite in report.iter("testsuite")
               if failed in ET.tostring(suite, encoding="unicode")]
    assert holding == ["base"], ET.tostring(report, encoding="unicode")
    assert not leftover_processes(marker)
