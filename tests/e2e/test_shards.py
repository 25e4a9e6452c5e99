"""Shards through the real runner: --shard-index/--shard-count and the CI engines' variables,
--durations, --list, empty shards, --merge (JUnit and JSON, reruns), and their bad input."""
import json
import re
import subprocess
import xml.etree.ElementTree as ET

import pytest

from conftest import RUNNER, Run, junit_state, validate_ctrf, validate_junit
from shard_cases import engine_env, make_suites, normal_ctrf, normal_junit, write_script


def run(*args, cwd=None, timeout=120, **variables):
    """The runner with `args`, in an environment with `variables` and no other shard variable."""
    proc = subprocess.run([RUNNER, *map(str, args)], cwd=cwd, env=engine_env(**variables),
                          capture_output=True, text=True, timeout=timeout,
                          stdin=subprocess.DEVNULL)
    return Run(proc, proc.stdout, proc.stderr)


def suites_of(junit):
    """The suites of the run in a JUnit report (an empty shard's properties are in a
    <testsuite> with no id, which is none of them)."""
    return [suite.get("name") for suite in ET.parse(junit).getroot().iter("testsuite")
            if suite.get("id") is not None]


def shard_reports(tmp_path, suites, count, isolation="process", **variables_of_shard):
    """Runs the `count` shards with --shard-index/--shard-count; returns their JUnit and JSON."""
    xmls, jsons = [], []
    for index in range(count):
        xml, js = tmp_path / f"shard-{index}.xml", tmp_path / f"shard-{index}.json"
        r = run("--isolation", isolation, "--suites", suites, "--shard-index", index,
                "--shard-count", count, "-o", f"junit:{xml}", "-o", f"json:{js}")
        assert r.returncode in (0, 1), r
        xmls.append(xml)
        jsons.append(js)
    return xmls, jsons


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_shards_split_every_suite_once_and_merge_into_the_one_machine_run(tmp_path, isolation):
    suites = make_suites(tmp_path / "suites", broken_fixture=(4,))
    one = run("--isolation", isolation, "--suites", suites, "-o", f"junit:{tmp_path}/one.xml",
              "-o", f"json:{tmp_path}/one.json")
    assert one.returncode == 1, one
    extra = json.loads((tmp_path / "one.json").read_text())["results"]["extra"]["robotology.rtf"]
    assert [failure["suite"] for failure in extra["fixtureFailures"]] == ["s04"]
    xmls, jsons = shard_reports(tmp_path, suites, 3, isolation)
    names = [name for xml in xmls for name in suites_of(xml)]
    assert sorted(names) == [f"s{i:02d}" for i in range(7)]
    # Round-robin over the sorted ids: s00 s03 s06 | s01 s04 | s02 s05.
    assert [suites_of(xml) for xml in xmls] == [["s00", "s03", "s06"], ["s01", "s04"],
                                                ["s02", "s05"]]
    for xml, js in zip(xmls, jsons):
        validate_junit(xml)
        validate_ctrf(js)
    for kind, reports, one_file, normal in [("junit", xmls, "one.xml", normal_junit),
                                            ("json", jsons, "one.json", normal_ctrf)]:
        merged = tmp_path / f"merged.{kind}"
        r = run("--merge", f"{kind}:{merged}", "--expect-shards", 3, *reversed(reports))
        assert r.returncode == 0, r
        assert normal(merged) == normal(tmp_path / one_file)
    validate_junit(tmp_path / "merged.junit")
    validate_ctrf(tmp_path / "merged.json")


def test_each_shard_report_says_which_shard_it_is(tmp_path):
    suites = make_suites(tmp_path / "suites", count=2)
    xmls, jsons = shard_reports(tmp_path, suites, 2)
    # On each <testsuite>: junit-10.xsd (Jenkins' xUnit) has no <properties> under <testsuites>.
    root = ET.parse(xmls[1]).getroot()
    assert root.find("properties") is None, ET.tostring(root)
    # On the first suite only: xunitparser refuses a property name twice in a document.
    first, *others = root.iter("testsuite")
    # (Beside each suite's display names of its tests, "rtf.name.S.T".)
    properties = {p.get("name"): p.get("value") for p in first.find("properties")
                  if not p.get("name").startswith("rtf.name.")}
    # And the whole run's plan, the same in every shard's report (--merge checks it).
    assert re.fullmatch("[0-9a-f]{16}", properties.pop("rtf.shard.plan", "")), properties
    assert properties == {"rtf.shard.index": "1", "rtf.shard.count": "2"}
    assert all(not p.get("name").startswith("rtf.shard.")
               for suite in others for p in suite.iter("property")), ET.tostring(root)
    shard = json.loads(jsons[1].read_text())["results"]["extra"]["robotology.rtf"]["shard"]
    assert shard.pop("plan") == first.find("properties").find(
        "property[@name='rtf.shard.plan']").get("value")
    assert shard == {"index": 1, "count": 2}


def test_an_empty_shard_exits_0_with_valid_empty_reports(tmp_path):
    suites = make_suites(tmp_path / "suites", count=2, failing=())
    xml, js = tmp_path / "r.xml", tmp_path / "r.json"
    r = run("--suites", suites, "--shard-index", 3, "--shard-count", 4, "-o", f"junit:{xml}",
            "-o", f"json:{js}")
    assert r.returncode == 0, r
    assert "shard 3 of 4 has no suite to run" in r.stdout, r
    validate_junit(xml)
    assert suites_of(xml) == []
    (holder,) = ET.parse(xml).getroot().iter("testsuite")
    assert holder.get("tests") == "0" and holder.find("testcase") is None
    properties = {p.get("name"): p.get("value") for p in holder.find("properties")}
    assert re.fullmatch("[0-9a-f]{16}", properties.pop("rtf.shard.plan", "")), properties
    assert properties == {"rtf.shard.index": "3", "rtf.shard.count": "4"}
    assert validate_ctrf(js)["results"]["summary"]["tests"] == 0


def test_the_console_says_which_shard_and_from_where(tmp_path):
    suites = make_suites(tmp_path / "suites", count=4, failing=())
    r = run("--suites", suites, "--no-output", "--verbose", CI_NODE_INDEX=2, CI_NODE_TOTAL=4)
    assert r.returncode == 0, r
    assert ("shard 1 of 4 (from GitLab CI CI_NODE_INDEX=2 CI_NODE_TOTAL=4): 1 of 4 suites"
            in r.stdout), r
    assert "shard 1 runs suite s01" in r.stdout, r


def test_list_shows_the_shard_of_each_suite(tmp_path):
    suites = make_suites(tmp_path / "suites", count=3)
    listing = tmp_path / "list.json"
    r = run("--suites", suites, "--list", "--shard-index", 0, "--shard-count", 2, "-o",
            f"json:{listing}")
    assert r.returncode == 0, r
    assert "suite s00 (" in r.stdout and "[shard 0 of 2]" in r.stdout, r
    assert "[shard 1 of 2]" in r.stdout, r
    assert [s["shard"] for s in json.loads(listing.read_text())["suites"]] == [0, 1, 0]


@pytest.mark.parametrize("kind", ["junit", "json"])
def test_durations_put_the_longest_suite_alone(tmp_path, kind):
    suites = make_suites(tmp_path / "suites", count=4, failing=())
    # An earlier run, with the times of s00 and s03 made long (s01, s02 get the mean).
    earlier = tmp_path / f"earlier.{kind}"
    assert run("--suites", suites, "-o", f"{kind}:{earlier}").returncode == 0
    if kind == "junit":
        tree = ET.parse(earlier)
        for suite in tree.getroot().iter("testsuite"):
            suite.set("time", {"s00": "1.000", "s03": "30.000"}.get(suite.get("name"), "1.000"))
        tree.write(earlier)
    else:
        report = json.loads(earlier.read_text())
        for suite in report["results"]["extra"]["robotology.rtf"]["suites"]:
            suite["duration"] = 30000 if suite["name"] == "s03" else 1000
        earlier.write_text(json.dumps(report))
    r = run("--suites", suites, "--list", "--shard-index", 0, "--shard-count", 2,
            "--durations", earlier)
    assert r.returncode == 0, r
    assert "balanced by" in r.stdout, r
    shard_of = {line.split()[1]: line.rsplit("[shard ", 1)[1][0]
                for line in r.stdout.splitlines() if line.startswith("suite ")}
    assert shard_of == {"s03": "0", "s00": "1", "s01": "1", "s02": "1"}, r


def test_a_rerun_of_a_shard_replaces_its_failed_tests_in_the_merge(tmp_path):
    suites = make_suites(tmp_path / "suites", count=2, failing=())
    # s01's second test fails the first time only.
    flaky = write_script(tmp_path / "suites" / "flaky.sh",
                         f"#!/bin/sh\nif [ -e {tmp_path}/ran ]; then exit 0; fi\n"
                         f"touch {tmp_path}/ran\nexit 1\n")
    (tmp_path / "suites" / "suite-01.xml").write_text(
        f'<suite name="s01">\n  <test type="exec" name="flaky">{flaky}</test>\n'
        '  <test type="exec" name="ok">ok.sh</test>\n</suite>\n')
    xmls, jsons = shard_reports(tmp_path, suites, 2)
    again_xml, again_json = tmp_path / "again.xml", tmp_path / "again.json"
    r = run("--suites", suites, "--rerun-failed", xmls[1], "-o", f"junit:{again_xml}",
            "-o", f"json:{again_json}", "--shard-index", 1, "--shard-count", 2)
    assert r.returncode == 0, r
    assert "run again as they are" in r.stdout, r
    for kind, reports, again in [("junit", xmls, again_xml), ("json", jsons, again_json)]:
        merged = tmp_path / f"merged-{kind}"
        r = run("--merge", f"{kind}:{merged}", "--expect-shards", 2, *reports, again)
        assert r.returncode == 0, r
        if kind == "junit":
            validate_junit(merged)
            root = ET.parse(merged).getroot()
            assert root.get("failures") == "0" and root.get("tests") == "4"
            states = [junit_state(t) for t in root.iter("testcase")]
        else:
            report = validate_ctrf(merged)
            assert report["results"]["summary"]["failed"] == 0
            states = [t["extra"]["robotology.rtf"]["state"] for t in report["results"]["tests"]]
        assert states == ["passed"] * 4


@pytest.mark.parametrize("kind", ["junit", "json"])
def test_a_rerun_of_a_whole_run_merges_too(tmp_path, kind):
    suites = make_suites(tmp_path / "suites", count=2, failing=())
    flaky = write_script(tmp_path / "suites" / "flaky.sh",
                         f"#!/bin/sh\nif [ -e {tmp_path}/ran ]; then exit 0; fi\n"
                         f"touch {tmp_path}/ran\nexit 1\n")
    (tmp_path / "suites" / "suite-01.xml").write_text(
        f'<suite name="s01">\n  <test type="exec" name="flaky">{flaky}</test>\n</suite>\n')
    first, again, merged = (tmp_path / f"{name}.{kind}" for name in ("first", "again", "merged"))
    assert run("--suites", suites, "-o", f"{kind}:{first}").returncode == 1
    assert run("--suites", suites, "--rerun-failed", first, "-o",
               f"{kind}:{again}").returncode == 0
    r = run("--merge", f"{kind}:{merged}", first, again)
    assert r.returncode == 0, r
    if kind == "junit":
        validate_junit(merged)
        assert [junit_state(t) for t in ET.parse(merged).getroot().iter("testcase")] == [
            "passed"] * 3
    else:
        tests = validate_ctrf(merged)["results"]["tests"]
        assert [t["extra"]["robotology.rtf"]["state"] for t in tests] == ["passed"] * 3


@pytest.mark.parametrize("args,variables,why", [
    (["--shard-index", 2, "--shard-count", 2], {},
     "--shard-index '2': expected a whole number from 0 to 1"),
    (["--shard-index", "one", "--shard-count", 2], {}, "--shard-index 'one'"),
    (["--shard-index", 0], {}, "--shard-index needs --shard-count"),
    ([], {"TEST_SHARD_INDEX": 1, "TEST_TOTAL_SHARDS": 2, "CI_NODE_INDEX": 1, "CI_NODE_TOTAL": 2},
     "conflicting shard variables"),
    ([], {"GTEST_SHARD_INDEX": 5, "GTEST_TOTAL_SHARDS": 3},
     "GTEST_SHARD_INDEX '5': expected a whole number from 0 to 2"),
    ([], {"JOB_COMPLETION_INDEX": 0, "RTF_SHARD_COUNT": "x"}, "RTF_SHARD_COUNT 'x'"),
])
def test_bad_shard_settings_exit_2_naming_them(tmp_path, args, variables, why):
    suites = make_suites(tmp_path / "suites", count=1)
    r = run("--suites", suites, "--no-output", *args, **variables)
    assert r.returncode == 2, r
    assert why in r.stderr, r


@pytest.mark.edited_reports
def test_a_bad_durations_report_exits_2_naming_file_and_line(tmp_path):
    suites = make_suites(tmp_path / "suites", count=2)
    report = tmp_path / "durations.xml"
    report.write_text('<testsuites name="RobotTestingFramework">\n'
                      '  <testsuite name="s00" tests="1" time="soon" id="0"/>\n</testsuites>\n')
    r = run("--suites", suites, "--no-output", "--shard-index", 0, "--shard-count", 2,
            "--durations-from", report)
    assert r.returncode == 2, r
    assert f"--durations-from {report}:2: expected <testsuite>" in r.stderr, r


def test_merge_bad_input_exits_2(tmp_path):
    suites = make_suites(tmp_path / "suites", count=3)
    xmls, jsons = shard_reports(tmp_path, suites, 3)
    out = tmp_path / "merged.xml"
    r = run("--merge", f"junit:{out}", "--expect-shards", 3, xmls[0], xmls[2])
    assert r.returncode == 2 and "no report of shard 1" in r.stderr, r
    r = run("--merge", f"junit:{out}", "--expect-shards", 3, *xmls, xmls[1])
    assert r.returncode == 2 and "are both shard 1 of 3" in r.stderr, r
    r = run("--merge", f"junit:{out}", xmls[0], jsons[1])
    assert r.returncode == 2 and "a JSON report; expected JUnit" in r.stderr, r
    r = run("--merge", f"tap:{out}", xmls[0])
    assert r.returncode == 2 and "expected junit:FILE or json:FILE" in r.stderr, r
    for count in ("0", "x", "-1"):
        r = run("--merge", f"junit:{out}", "--expect-shards", count, *xmls)
        assert r.returncode == 2 and f"--expect-shards '{count}': expected a whole" in r.stderr, r
    r = run("--merge", f"junit:{out}", "--expect-shards", "", *xmls)
    assert r.returncode == 2 and "--expect-shards: the value is empty" in r.stderr, r
    r = run("--suites", suites, "--expect-shards", 3)
    assert r.returncode == 2 and "--expect-shards needs --merge" in r.stderr, r
    assert not out.exists()


@pytest.mark.parametrize("edit,why", [
    (lambda report: report.pop("specVersion") and report["results"]["tests"][0].pop("status"),
     "results.tests[0]: expected a test with a name, a CTRF status"),
    (lambda report: report["results"]["summary"].update(start="soon"),
     "results.summary.start: expected milliseconds since the Unix epoch"),
    (lambda report: report["results"]["extra"]["robotology.rtf"].update(fixtureFailures=[1, 2]),
     "results.extra.robotology.rtf.fixtureFailures[0]: expected an object naming its suite"),
])
def test_merge_of_a_json_report_edited_out_of_shape_exits_2_naming_it(tmp_path, edit, why):
    # Found by fuzzing the merge: these reached the merge and read past a JSON object's end.
    suites = make_suites(tmp_path / "suites", count=2)
    _, jsons = shard_reports(tmp_path, suites, 2)
    report = json.loads(jsons[1].read_text())
    edit(report)
    jsons[1].write_text(json.dumps(report))
    out = tmp_path / "merged.json"
    r = run("--merge", f"json:{out}", "--expect-shards", 2, *jsons)
    assert r.returncode == 2, r
    assert f"--merge {jsons[1]}: {why}" in r.stderr, r
    assert not out.exists()


PYTHON_CLEAN_ENV = """import os
import robottestingframework
NAMES = %r
class TestCase:
    def setup(self, param):
        return True
    def run(self):
        seen = [name for name in NAMES if name in os.environ]
        robottestingframework.testCheck(not seen, "shard variables reached the test: %%s" %% seen)
"""


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_shard_variables_never_reach_the_tests(tmp_path, isolation):
    from shard_cases import SHARD_VARIABLES
    suites = make_suites(tmp_path / "suites", count=1, failing=())
    (suites / "clean_env.py").write_text(PYTHON_CLEAN_ENV % SHARD_VARIABLES)
    (suites / "suite-00.xml").write_text(
        '<suite name="s00">\n  <test type="exec" name="exec">clean_env.sh</test>\n'
        '  <test type="python" name="python">clean_env.py</test>\n</suite>\n')
    status, xml = tmp_path / "status", tmp_path / "bazel.xml"
    # Every convention at once, agreeing: shard 0 of 1.
    r = run("--isolation", isolation, "--suites", suites, "--no-output", "--verbose",
            TEST_SHARD_INDEX=0, TEST_TOTAL_SHARDS=1, TEST_SHARD_STATUS_FILE=status,
            XML_OUTPUT_FILE=xml, GTEST_SHARD_INDEX=0, GTEST_TOTAL_SHARDS=1, CI_NODE_INDEX=1,
            CI_NODE_TOTAL=1, JOB_COMPLETION_INDEX=0, RTF_SHARD_COUNT=1)
    assert r.returncode == 0, r
    assert "shard 0 of 1 (from Bazel" in r.stdout, r
    assert "2 passed, 0 failed" in r.stdout, r
    assert status.exists()
    validate_junit(xml)
    assert suites_of(xml) == ["s00"]


def test_suites_sharing_a_lock_go_to_the_same_shard(tmp_path):
    # Round-robin would put s00 and s01 on different shards; their common lock keeps them
    # together (and s02, which shares another lock with s01, follows them).
    suites = make_suites(tmp_path / "suites", count=4, failing=())
    locks = {0: ["robot:arm"], 1: ["robot:arm", "robot:base"], 2: ["robot:base"], 3: []}
    for i, names in locks.items():
        path = suites / f"suite-{i:02d}.xml"
        resources = "".join(f'  <resource lock="{name}"/>\n' for name in names)
        path.write_text(path.read_text().replace(">\n", ">\n" + resources, 1))
    listing = tmp_path / "list.json"
    r = run("--suites", suites, "--list", "--shard-index", 0, "--shard-count", 2, "-o",
            f"json:{listing}")
    assert r.returncode == 0, r
    shard = [s["shard"] for s in json.loads(listing.read_text())["suites"]]
    assert shard[0] == shard[1] == shard[2], shard
    assert shard[3] != shard[0], shard
    # And the runs of both shards hold every suite once.
    xmls, _ = shard_reports(tmp_path, suites, 2)
    assert sorted(name for xml in xmls for name in suites_of(xml)) == ["s00", "s01", "s02", "s03"]


def linked_suites(folder):
    """Suites a (test "base"), b (a test that depends on "base") and c, in `folder`."""
    folder.mkdir(parents=True, exist_ok=True)
    write_script(folder / "ok.sh", "#!/bin/sh\necho fine\nexit 0\n")
    (folder / "a.xml").write_text('<suite name="a">\n  <test type="exec" name="base">ok.sh</test>'
                                  '\n</suite>\n')
    (folder / "b.xml").write_text('<suite name="b">\n  <test type="exec" name="uses" '
                                  'depends="base">ok.sh</test>\n</suite>\n')
    (folder / "c.xml").write_text('<suite name="c">\n  <test type="exec" name="alone">ok.sh'
                                  '</test>\n</suite>\n')
    return ["--suite", "a.xml", "--suite", "b.xml", "--suite", "c.xml"]


def test_suites_linked_by_depends_go_to_the_same_shard(tmp_path):
    # Issue 39, 7: round-robin put a and b on different shards, and b's test was always
    # skipped ("depends on base, which did not run") while every shard exited 0.
    folder = tmp_path / "suites"
    suites = linked_suites(folder)
    r = run(*suites, "--list", "--shard-index", 0, "--shard-count", 2, "-o", "json:list.json",
            cwd=folder)
    assert r.returncode == 0, r
    shard = [s["shard"] for s in json.loads((folder / "list.json").read_text())["suites"]]
    assert shard[0] == shard[1] != shard[2], shard
    one = run(*suites, "-o", "junit:one.xml", cwd=folder)
    assert one.returncode == 0, one
    for index in range(2):
        r = run(*suites, "--shard-index", index, "--shard-count", 2, "-o",
                f"junit:shard-{index}.xml", cwd=folder)
        assert r.returncode == 0, r
        assert "did not run" not in r.stdout, r
    r = run("--merge", "junit:merged.xml", "--expect-shards", 2, "shard-0.xml", "shard-1.xml",
            cwd=folder)
    assert r.returncode == 0, r
    assert normal_junit(folder / "merged.xml") == normal_junit(folder / "one.xml")
    assert {case.get("name"): junit_state(case) for case in
            ET.parse(folder / "merged.xml").getroot().iter("testcase")} == {
        "base": "passed", "uses": "passed", "alone": "passed"}


def test_merge_refuses_a_shard_of_another_run_naming_it(tmp_path):
    # Issue 39, 6: shard 1 of a run over other suites merged with shards 0 and 2 of run A
    # gave exit 0 and a report silently short of A's suites.
    first = make_suites(tmp_path / "first", count=6, failing=())
    other = make_suites(tmp_path / "other", count=4, failing=())
    for name, folder in (("A", first), ("B", other)):
        for index in range(3):
            for kind in ("xml", "json"):
                r = run("--suites", ".", "--shard-index", index, "--shard-count", 3, "-o",
                        f"{'junit' if kind == 'xml' else 'json'}:../{name}{index}.{kind}",
                        cwd=folder)
                assert r.returncode == 0, r
    for kind, out in (("xml", "junit"), ("json", "json")):
        for given, foreign in ((["A0", "B1", "A2"], "B1"), (["B0", "A1", "A2"], "B0")):
            r = run("--merge", f"{out}:merged.{kind}", "--expect-shards", 3,
                    *[f"{report}.{kind}" for report in given], cwd=tmp_path)
            assert r.returncode == 2, (given, r)
            assert f"--merge {foreign}.{kind}: a report of another run" in r.stderr, (given, r)
            assert not (tmp_path / f"merged.{kind}").exists()
        # The shards of one run merge as before.
        r = run("--merge", f"{out}:merged.{kind}", "--expect-shards", 3,
                *[f"A{index}.{kind}" for index in range(3)], cwd=tmp_path)
        assert r.returncode == 0, r
    # Each shard report carries the plan, the same on all three.
    plans = set()
    for index in range(3):
        root = ET.parse(tmp_path / f"A{index}.xml").getroot()
        first_suite = next(root.iter("testsuite"))
        properties = {p.get("name"): p.get("value") for p in first_suite.find("properties")}
        plans.add(properties["rtf.shard.plan"])
        shard = json.loads((tmp_path / f"A{index}.json").read_text())["results"]["extra"][
            "robotology.rtf"]["shard"]
        assert shard["plan"] == properties["rtf.shard.plan"], shard
    assert len(plans) == 1, plans
