"""Reports to the standard output: `-` and `/dev/stdout` for every output kind, into a pipe (as
`| jq` reads it), and the JSON list of --list. The standard output then carries the report
alone: the console goes to the standard error (docs/reference/report-formats.md)."""
import json
import xml.etree.ElementTree as ET

import pytest

from conftest import plugin, run_runner

NAMES = ["-", "/dev/stdout"]


def _read(kind, text):
    """Fails unless `text` is one whole report of `kind`; returns what it says of the run."""
    if kind == "junit":
        root = ET.fromstring(text)
        return root.get("tests"), root.get("failures")
    if kind == "json":
        data = json.loads(text)
        return data["results"]["summary"]["tests"], data["results"]["summary"]["failed"]
    if kind == "tap":
        assert text.startswith("TAP version"), text[:200]
        assert text.count("\nnot ok ") == 1, text
        return None
    if kind == "html":
        assert text.lstrip().lower().startswith("<!doctype html>"), text[:200]
        assert text.rstrip().endswith("</html>"), text[-200:]
        return None
    assert "1 passed, 1 failed" in text, text
    return None


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("kind", ["text", "junit", "tap", "json", "html"])
def test_each_kind_of_report_goes_to_standard_output_into_a_pipe(tmp_path, kind, name):
    run = run_runner("-t", plugin("passing_test"), "-t", plugin("failing_test"),
                     "--output", f"{kind}:{name}", cwd=tmp_path)
    assert run.returncode == 1, run
    counts = _read(kind, run.stdout)
    if counts is not None:
        assert [int(c) for c in counts] == [2, 1], counts
    # The console (its test lines and closing line) went to the standard error.
    assert "FailingTest" in run.stderr and "1 failed" in run.stderr, run
    # Nothing was written in the folder: no file named "-", no result.txt; only the cache of
    # --lf, which a run with a failure writes (docs/how-to/selection-and-reruns.md).
    assert sorted(p.name for p in tmp_path.iterdir()) == [".rtf_cache"], list(tmp_path.iterdir())


def test_the_type_is_given_apart(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-o", "-", "--output-type", "junit",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert ET.fromstring(run.stdout).get("tests") == "1", run
    assert not (tmp_path / "-").exists()


def test_a_file_report_beside_the_standard_output_one(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-o", "json:-", "-o", "junit:r.xml",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert json.loads(run.stdout)["results"]["summary"]["passed"] == 1, run
    assert ET.parse(tmp_path / "r.xml").getroot().get("tests") == "1"


def test_two_outputs_cannot_share_the_standard_output(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-o", "json:-", "-o", "junit:/dev/stdout",
                     cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--output json:- goes to the standard output already" in run.stderr, run
    assert run.stdout == "", run


@pytest.mark.parametrize("name", NAMES)
def test_the_json_list_goes_to_standard_output_into_a_pipe(tmp_path, suite_file, name):
    suite_file(f"""<suite name="robot">
  <test type="dll">{plugin('passing_test')}</test>
  <test type="dll">{plugin('failing_test')}</test>
</suite>""")
    run = run_runner("--list", "-s", "suite.xml", "--output", f"json:{name}", cwd=tmp_path)
    assert run.returncode == 0, run
    listed = json.loads(run.stdout)  # the JSON alone: not the text list before it
    assert "passing_test" in json.dumps(listed) and "failing_test" in json.dumps(listed), listed
    assert sorted(p.name for p in tmp_path.iterdir()) == ["suite.xml"], list(tmp_path.iterdir())
